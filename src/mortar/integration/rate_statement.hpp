// The rate statement of the law (Eqs. 16-18, docs/model.md 6) evaluated as
// one explicit stage: the increments of traction, plastic and crack
// separations, works and plastic dissipation over a separation increment,
// with the plastic multiplier from the consistency condition (Eq. 19).
#pragma once

#include "mortar/integration/point.hpp"

namespace mortar {

// Increments of everything the rate statement integrates, over one stage.
struct Rates {
  Vec3 dsigma = Vec3::Zero(), dplastic = Vec3::Zero(), dcrack = Vec3::Zero();
  double dwI = 0, dwII = 0, dwIII = 0, dDp = 0;
  bool snapback = false;  // no strain-driven solution: consistency denominator <= 0
  bool plastic = false;   // the stage flows (else secant elasticity, or a snap-back)
  Branches grow;          // open regime: the components on their damage-growing branch
  double dkappa_c = 0;    // the compression cap's multiplier (docs/model.md 12)
};

// P += w r (everything but the separation, which the caller moves). Inline:
// the Heun pair adds its stages three times a substep.
inline void add(Point& P, const Rates& r, double w) {
  P.sigma += w * r.dsigma;
  P.y.plastic += w * r.dplastic;
  P.y.crack += w * r.dcrack;
  P.y.wI += w * r.dwI;
  P.y.wII += w * r.dwII;
  P.y.wIII += w * r.dwIII;
  P.y.dissipation_plastic += w * r.dDp;
  P.y.kappa_c += w * r.dkappa_c;
}

// Plastic increments for a plastic-multiplier increment dl along the flow.
Rates along_flow(const Model& M, const Vec3& sigma, const Flow& f, double dl);

// No strain-driven solution: the consistency denominator is not positive
// although the flow changes the traction (softening outruns the elastic
// relaxation: a snap-back of the material point, docs/model.md 6).
inline bool snaps_back(const Flow& f) {
  const double scale = f.dF.dot(f.k_A_m);
  return scale > 0 && f.denominator <= 1e-12 * scale;
}

// One stage of the rate statement over dd from P. In the open regime each
// component is on the damage-growing branch unless the damage it implies
// would decrease (d (dd - dp) > dcr along the component); such a component
// follows its frozen secant instead. Where the frozen branch has no
// strain-driven solution, the growing branch stands (settle keeps the damage
// from decreasing).
// The rest: docs/numerics.md, section 6.
Rates stage(const Model& M, const Point& P, const Vec3& dd, Branches allowed = {});
// The same with the surface at P, surface_at(M, P), which the substepper
// carries from one substep to the next.
Rates stage(const Model& M, const Point& P, const SurfaceAt& at, const Vec3& dd, Branches allowed = {});

}  // namespace mortar
