// The fully softened normal (docs/model.md 6, Decision - sliding on the
// cone): an open joint with dn = 1 carries sigma_n = 0, its surface in tau
// is |tau| = s c0, and sliding along its elastic slip is one-dimensional in
// the inelastic slip y, solved by one scalar Newton iteration per increment
// instead of substeps. The substepper hands such a run to it, every scheme.
#pragma once

#include "mortar/integration/point.hpp"
#include "mortar/result.hpp"

namespace mortar {

// What cone_step did: `done` is the fraction of d integrated (0: it does not
// apply, the substeps go on; 1; or less when the joint separates there).
struct ConeStep {
  double done = 0;
  bool separates = false;
};

// From P on the surface (`at`), over the separation increment d, on the
// damage branches `grow` of the first stage. Applies where P is open with
// dn = 1, ds < 1, s_raw above kSeparated, the slip increment along the
// elastic slip (within round-off), loading, with a positive consistency
// denominator, and the joint stays open to the end; then P is the exact end
// point (settled, on the surface, the damage dissipation from the energy
// balance of the closed form).
ConeStep cone_step(const Model& M, Point& P, const SurfaceAt& at, const Vec3& d, Branches grow);

}  // namespace mortar
