// Damage and the unilateral regime (docs/model.md 6): the secant damage rule,
// which branch of the open regime a plastic increment is on, and the
// disintegration of a joint with no strength left. Knows nothing of
// integration schemes.
#pragma once

#include <cmath>

#include "mortar/elastic.hpp"
#include "mortar/parameters.hpp"
#include "mortar/physics/norms.hpp"
#include "mortar/state.hpp"

namespace mortar {

// Whether the open-regime growing branch keeps the secant damage from
// decreasing for a plastic increment dp: d (dd - dp) <= b dp along the
// elastic separation (docs/model.md 6).
inline bool damage_grows_normal(const Model& M, const State& y, const Vec3& dd, const Vec3& dp) {
  const double e = y.elastic_separation()[0];
  if (!(e > 0)) return true;
  return y.dn * (dd[0] - dp[0]) <= M.p.bn * dp[0] + 1e-14 * std::abs(dd[0]);
}

// Slip applied against the elastic slip (docs/model.md 6, Decision -
// unloading slip on the tension cap): the shear unloads on its secant
// towards the plastic slip, whatever the plastic flow does; on the growing
// branch it would unload towards the inelastic slip instead, and the secant
// damage would jump towards 1 while the elastic slip is still positive.
inline bool slip_reverses(const State& y, const Vec3& dd) {
  const Vec3 e = y.elastic_separation();
  return dd[1] * e[1] + dd[2] * e[2] < 0;
}

inline bool damage_grows_shear(const Model& M, const State& y, const Vec3& dd, const Vec3& dp) {
  const Vec3 e = y.elastic_separation();
  const double es = hypot_of(e[1], e[2]);
  if (!(es > 0)) return true;
  if (slip_reverses(y, dd)) return false;
  const double de = ((dd[1] - dp[1]) * e[1] + (dd[2] - dp[2]) * e[2]) / es;
  const double dcr = M.p.bs * (dp[1] * e[1] + dp[2] * e[2]) / es;
  return y.ds * de <= dcr + 1e-14 * hypot_of(dd[1], dd[2]);
}

// The strength below which an open joint is completely separated
// (docs/model.md 6, Decision - complete separation). The softening factor
// only approaches 0 asymptotically on a mode-I path (s ~ exp(-delta/u)), so
// an exact s = 0 is reached only by an integration overshoot, at a place that
// depends on how the increment is cut. At 1e-7 the traction left is below
// 1e-7 ft0 (under the 1e-6-of-peak splitting tolerance) and the separation is ...
// The rest: docs/numerics.md, section 13.
constexpr double kSeparated = 1e-7;

// The normal traction taken as none on the growing branch, relative to a
// traction scale (Substepper::normal_completion; docs/model.md 6, Decision -
// complete normal damage inside a substep). Like kSeparated, it sets no
// answer at engineering scale (follow_opening; the tolerance table of
// docs/model.md 6).
constexpr double kNormalComplete = 1e-7;

// Whether an open joint's strength s_raw has reached kSeparated (within the
// relative round-off of the substep that lands on it, substepper.cpp).
inline bool separated(double s_raw) { return s_raw <= kSeparated * (1 + 2e-9); }

// An open joint with no strength left (s_raw <= kSeparated) can only carry
// zero traction: its surface is (within kSeparated ft0) the apex of the cone,
// so the damage is complete (d = 1), which freezes its plastic and crack
// slips while open (rate stiffness 0, docs/model.md 6); the normal ones
// follow the opening (follow_opening) until contact at delta_n = delta_p_n.
// The elastic energy this releases is booked as damage dissipation.
void disintegrate_if_no_strength(const Model& M, State& y);

// An open joint whose normal traction, falling on its damage-growing branch,
// has reached what is taken as none (Substepper::normal_completion;
// docs/model.md 6, Decision - complete normal damage inside a substep):
// dn = 1, the elastic energy of the normal released as damage dissipation.
void complete_normal_damage(const Model& M, State& y);

// The switch of the unilateral regime at the current separation (Eq. 13;
// docs/model.md 6, Correction - closure without created energy). Closing,
// the part d o delta_e of the elastic separation that the damaged secant does
// not carry becomes plastic (taken from the crack separation, so delta_in is
// unchanged) and the full stiffness gives the same traction,
// kbar (1 - d) delta_e; opening, the stiffness falls to the secant. Returns
// the elastic energy released: 1/2 kbar d (1 - d) delta_e^2 closing,
// 1/2 kbar d delta_e^2 opening, in closed form so that it is never negative.
double switch_unilateral_regime(const Model& M, State& y);

// An open joint whose normal damage is complete (dn = 1), opened past its
// inelastic opening delta_in_n = delta_p_n + delta_cr_n: the limit dn -> 1 of
// the growing branch (Eqs. 16-17 with sigma_n -> 0), which keeps
// delta_in_n = delta_n, delta_p_n moving by 1/(1 + bn) of the opening and
// delta_cr_n by bn/(1 + bn), at zero traction, so nothing is dissipated
// (docs/model.md 6, Decision - opening past complete normal damage). Where
// the normal completed then does not set where contact is regained.
void follow_opening(const Model& M, State& y);

// Which components of an open joint are on their damage-growing branch in a
// substep (docs/model.md 6, Decision - open-regime branches); a component on
// its frozen secant keeps its damage exactly.
struct Branches {
  bool normal = true;
  bool shear = true;
};

// After plastic flow: damage follows the secant through the plastic
// displacement while the joint is open (docs/model.md 6), never decreases,
// and the traction `sigma` is then re-derived from Eq. 1 so that traction
// and state always agree. The energy released by the damage growth is booked
// as damage dissipation, 1/2 kbar (delta_e)^2 dd, trapezoidal in delta_e from
// e_start (the elastic separation at the start of the step).
// The rest: docs/numerics.md, section 14.
void settle(const Model& M, State& y, Vec3& sigma, const Vec3& e_start, Branches grow = {});

// crosses(open, e_n): the regime boundary test, mortar/elastic.hpp.

}  // namespace mortar
