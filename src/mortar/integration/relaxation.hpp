// The return to the surface at fixed separation (docs/model.md 6-7): where no
// strain-driven solution exists (a closure that jumps the shear stiffness
// back to ks, or a snap-back where softening outruns the elastic relaxation)
// and where a substep starts outside the surface.
#pragma once

#include "mortar/integration/point.hpp"
#include "mortar/result.hpp"

namespace mortar {

// March along the flow direction (Heun in lambda) with steps that change the
// traction and the strength by at most 5 %, capped by the Newton estimate
// F / denominator, and stop at the first crossing of F = 0, located by
// Pegasus inside the last step, so the return never overshoots the surface
// or passes the apex. For a snap-back (the surface shrinks faster than the
// traction relaxes: consistency denominator <= 0, so F grows along the flow)
// The rest: docs/numerics.md, section 7.
bool relax(const Model& M, Point& P, IntegrationStatus& st, bool snapback);

}  // namespace mortar
