// Stress integration of one increment for one interface point (docs/model.md
// 7): the public entry of the law. The physics is in physics/, the schemes,
// the substepper and the return mapping in integration/ (docs/architecture.md).
#pragma once

#include "mortar/failure.hpp"
#include "mortar/parameters.hpp"
#include "mortar/result.hpp"
#include "mortar/integration/local_problem.hpp"
#include "mortar/state.hpp"
#include "mortar/physics/elasticity.hpp"
#include "mortar/physics/yield_surface.hpp"

namespace mortar {

// The first rule the state breaks, or nullptr: finite values, 0 <= d <= 1,
// works >= 0, open flag 0 or 1.
const char* check_state(const State& s);

// Integrates the separation increment d_separation (law signs) from `state`
// and overwrites `state` with the end state. Where the chosen scheme fails on
// a valid state and a finite increment, the fallback chain integrates the
// increment again from the start state (docs/model.md 9) and the status says
// so (IntegrationStatus::fell_back()). On failure (bad input, a non-finite
// result, or no rung of the chain succeeded) the state is left as it was and
// the result holds the start traction; nothing returned is ever NaN or
// infinite.
IncrementResult integrate_increment(const Model& model, State& state, const Vec3& d_separation);

// The same, and, when `tangent` is not null, the tangent d traction_end /
// d d_separation (law signs) of this update (docs/model.md 7.5):
//   - implicit scheme: the consistent (algorithmic) tangent of the backward
//     Euler update, through the elastic-plastic intersection, every plastic
//     substep (linearised local residuals at convergence) and the secant
//     damage rule; exact except where status.tangent_approximate says;
//   - explicit schemes: the continuum elastic-plastic tangent (Eq. 20) at the
//     end point after plastic flow, else the secant stiffness;
//   - elastic increment: the secant stiffness K(d, h) (Eq. 21);
//   - increment integrated by the fallback chain: the tangent of its last
//     piece, approximate;
//   - failed increment: the secant stiffness of the start state.
// Fixed-size, allocates nothing.
IncrementResult integrate_increment(const Model& model, State& state, const Vec3& d_separation, Mat3* tangent);

// The continuum (rate) tangent of Eq. 20 at a state and its traction, on the
// damage-growing branch: kS - (kF o m)(dF o kS)^T / denominator when the
// point is on the surface and the denominator is positive, else K(d, h).
Mat3 continuum_tangent(const Model& model, const State& state, const Vec3& traction);

}  // namespace mortar
