// Stress integration of one increment for one interface point (docs/model.md
// 7): the public entry of the law. The physics is in physics/, the schemes,
// the substepper and the return mapping in integration/ (docs/architecture.md).
#pragma once

#include <array>

#include "mortar/failure.hpp"
#include "mortar/finite.hpp"
#include "mortar/parameters.hpp"
#include "mortar/result.hpp"
#include "mortar/integration/elastic_lanes.hpp"
#include "mortar/integration/elastic_shortcut.hpp"
#include "mortar/integration/local_problem.hpp"
#include "mortar/state.hpp"
#include "mortar/physics/elasticity.hpp"
#include "mortar/physics/yield_surface.hpp"

namespace mortar {

// The values check_state requires finite: SDV 1-18 but the open flag.
inline std::array<double, 17> finite_state_values(const State& s) {
  return {s.plastic[0], s.plastic[1], s.plastic[2], s.crack[0], s.crack[1], s.crack[2], s.wI, s.wII, s.wIII, s.dn,
          s.ds, s.separation[0], s.separation[1], s.separation[2], s.dissipation_plastic, s.dissipation_damage,
          s.energy_unilateral};
}

// The rules of a state (docs/model.md 3) as one test without a branch per
// rule, for the path every increment takes: finite values, 0 <= d <= 1,
// works >= 0, damage dissipation >= 0 (the open flag is a bool here; the
// adapters check its slot). check_state names the rule a state breaks;
// state_in_range is the rest when the values are known to be finite.
inline bool state_in_range(const State& s) {
  return (s.dn >= 0) & (s.dn <= 1) & (s.ds >= 0) & (s.ds <= 1) & (s.wI >= 0) & (s.wII >= 0) & (s.wIII >= 0) &
         (s.dissipation_damage >= 0);
}
inline bool state_valid(const State& s) {
  const std::array<double, 17> v = finite_state_values(s);
  const bool finite = all_finite(v.data(), int(v.size())), in_range = state_in_range(s);
  return finite & in_range;
}

// The first rule the state breaks, or nullptr (state_valid's rules).
const char* check_state(const State& s);

// elastic_increment (integration/elastic_shortcut.hpp), inline here for the
// adapters' per-point loops: from a state state_valid() accepts, an increment
// it books is integrate_increment's result without a tangent, bit for bit (it
// is the first thing integrate_increment tries); false, the state untouched,
// for every other increment. lanes::elastic_increment_lanes
// (integration/elastic_lanes.hpp): the same for two unworn points at once.

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

// integrate_increment without a tangent for an increment elastic_increment
// has declined from the same state: the same result, without trying the
// shortcut a second time (the adapters' full path, after their elastic path).
IncrementResult integrate_declined_increment(const Model& model, State& state, const Vec3& d_separation);

// The continuum (rate) tangent of Eq. 20 at a state and its traction, on the
// damage-growing branch, for separation increments in the direction of dd:
// kS - (kF o m)(dF o kS)^T / denominator when the point is on the surface and
// the denominator is positive, else K(d, h). kS and kF are the rate
// stiffnesses over dd (rate_stiffness_over): an open joint closed against its
// elastic opening (dd_n < 0, delta_e_n > 0) takes the closing on the normal
// secant kn (1 - dn) (docs/model.md 6, Decision - closing on the tension cap).
Mat3 continuum_tangent(const Model& model, const State& state, const Vec3& traction, const Vec3& dd);

}  // namespace mortar
