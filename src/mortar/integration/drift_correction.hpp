// Drift correction after an accepted explicit substep (Sloan et al. 2001;
// docs/model.md 7.1).
#pragma once

#include "mortar/integration/point.hpp"

namespace mortar {

// The consistent correction along the flow direction, with the hardening it
// implies; where that does not reduce F, a projection normal to the surface,
// realised as a plastic displacement so that Eq. 1 still holds. Only a state
// outside the surface is corrected: one that ends inside (F < 0) is
// admissible, and pulling it out would need a negative plastic multiplier,
// i.e. works and damage that decrease.
// `grow`: the damage branches of the substep being corrected.
void correct_drift(const Model& M, Point& P, Branches grow = {});
// The same with the surface at P (surface_at(M, P)), which on return is the
// surface at the corrected P.
void correct_drift(const Model& M, Point& P, SurfaceAt& at, Branches grow = {});

}  // namespace mortar
