// Stress integration of one increment for one interface point (docs/model.md
// 7): the law's entry. With mortar/batch.hpp (the elastic kernel over a batch
// of points) the whole boundary the adapters and the harness see; the
// physics and the schemes behind it are the law's own (docs/architecture.md).
#pragma once

#include <array>

#include "mortar/elastic.hpp"
#include "mortar/failure.hpp"
#include "mortar/finite.hpp"
#include "mortar/parameters.hpp"
#include "mortar/result.hpp"
#include "mortar/state.hpp"

namespace mortar {

// The values check_state requires finite: SDV 1-18 but the open flag.
inline std::array<double, 17> finite_state_values(const State& s) {
  return {s.plastic[0], s.plastic[1], s.plastic[2], s.crack[0], s.crack[1], s.crack[2], s.wI, s.wII, s.wIII, s.dn,
          s.ds, s.separation[0], s.separation[1], s.separation[2], s.dissipation_plastic, s.dissipation_damage,
          s.energy_unilateral};
}

// The rules of a state's ranges (docs/model.md 3), written once, as one test
// without a branch per rule: 0 <= d <= 1, works >= 0, damage dissipation
// >= 0, for one point (T = double) or the points in vector lanes (T =
// lanes::D, a mask). With finite values (state_valid) they are every rule of
// the state but the open flag's, a bool here (the adapters check its slot);
// check_state names the rule a state breaks.
template <class T>
auto ranges_hold(T dn, T ds, T wI, T wII, T wIII, T dissipation_damage) {
  return (dn >= 0.0) & (dn <= 1.0) & (ds >= 0.0) & (ds <= 1.0) & (wI >= 0.0) & (wII >= 0.0) & (wIII >= 0.0) &
         (dissipation_damage >= 0.0);
}
inline bool state_in_range(const State& s) {
  return ranges_hold(s.dn, s.ds, s.wI, s.wII, s.wIII, s.dissipation_damage);
}
inline bool state_valid(const State& s) {
  const std::array<double, 17> v = finite_state_values(s);
  const bool finite = all_finite(v.data(), int(v.size())), in_range = state_in_range(s);
  // The cap's kappa_c (SDV 36): finite and >= 0 (NaN fails both).
  const bool cap = (s.kappa_c >= 0.0) & (s.kappa_c <= 1.7976931348623157e308);
  return finite & in_range & cap;
}

// The first rule the state breaks, or nullptr (state_valid's rules).
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
// The rest: docs/numerics.md, section 2.
IncrementResult integrate_increment(const Model& model, State& state, const Vec3& d_separation, Mat3* tangent);

// integrate_increment without a tangent and without the elastic shortcut
// (mortar/elastic.hpp): the same result, for a caller that has tried the
// shortcut itself or whose point most likely starts on the surface.
IncrementResult integrate_full(const Model& model, State& state, const Vec3& d_separation);

// F / FTOL's scale (Eq. 2, docs/model.md 7) of a traction at a state: at most
// 1 on or inside the surface within the tolerance.
double yield_ratio(const Model& model, const State& state, const Vec3& traction);
// The softening factor s = max(0, 1 - wI/GIC - wII/GIIC) (Eqs. 4-5).
double softening_factor(const Model& model, const State& state);

// The continuum (rate) tangent of Eq. 20 at a state and its traction, on the
// damage-growing branch, for separation increments in the direction of dd:
// kS - (kF o m)(dF o kS)^T / denominator when the point is on the surface and
// the denominator is positive, else K(d, h). kS and kF are the rate
// stiffnesses over dd (rate_stiffness_over): an open joint closed against its
// elastic opening (dd_n < 0, delta_e_n > 0) takes the closing on the normal
// secant kn (1 - dn) (docs/model.md 6, Decision - closing on the tension cap).
Mat3 continuum_tangent(const Model& model, const State& state, const Vec3& traction, const Vec3& dd);

}  // namespace mortar
