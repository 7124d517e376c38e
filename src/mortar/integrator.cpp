// The public entry of the law's stress integration (docs/model.md 7): checks
// the inputs, picks the scheme once per increment, runs the segments
// (integration/increment.hpp) and books the energy terms and the tangent.
#include "mortar/integrator.hpp"

#include <algorithm>
#include <cmath>

#include "mortar/integration/cap.hpp"
#include "mortar/integration/increment.hpp"
#include "mortar/physics/elasticity.hpp"
#include "mortar/physics/yield_surface.hpp"

namespace mortar {

const char* check_state(const State& s) {
  if (state_valid(s)) return nullptr;
  const std::array<double, 17> v = finite_state_values(s);
  if (!all_finite(v.data(), int(v.size()))) return "every state variable must be finite";
  // The rule broken, named: ranges_hold of one variable, the others at 0.
  if (!(s.kappa_c >= 0.0 && std::isfinite(s.kappa_c))) return "the cap's kappa_c (SDV 36) must be a finite number >= 0";
  if (!ranges_hold(s.dn, 0.0, 0.0, 0.0, 0.0, 0.0)) return "damage d_n (SDV 10) must lie in [0, 1]";
  if (!ranges_hold(0.0, s.ds, 0.0, 0.0, 0.0, 0.0)) return "damage d_s (SDV 11) must lie in [0, 1]";
  if (!ranges_hold(0.0, 0.0, s.wI, 0.0, 0.0, 0.0)) return "work w_I (SDV 7) must be >= 0";
  // A negative w_II would raise the strength above its initial value (s > 1, Eq. 4).
  if (!ranges_hold(0.0, 0.0, 0.0, s.wII, 0.0, 0.0)) return "work w_II (SDV 8) must be >= 0";
  if (!ranges_hold(0.0, 0.0, 0.0, 0.0, s.wIII, 0.0)) return "work w_III (SDV 9) must be >= 0";
  // The damage dissipation only grows from 0 (docs/model.md 6, energy booking).
  if (!ranges_hold(0.0, 0.0, 0.0, 0.0, 0.0, s.dissipation_damage)) return "damage dissipation (SDV 17) must be >= 0";
  return nullptr;
}

Mat3 continuum_tangent(const Model& M, const State& y, const Vec3& sigma, const Vec3& dd) {
  const Vec3 K = secant_stiffness(M, y.dn, y.ds, y.open);
  const Surface S = surface_of(M, y);
  // The stiffness of the rate statement over dd, as the stages and the
  // implicit step take it: a closing of the elastic opening on the normal
  // secant (docs/model.md 6, Decision - closing on the tension cap).
  const RateStiffness k = rate_stiffness_over(M, y, dd);
  const Flow f = flow_of(M, sigma, S, k.on_flow);
  if (cap_applies(M, y)) {
    // On the cap: Eq. 20 with its flow, or with both at the corner
    // (docs/model.md 12).
    Mat3 D;
    if (capped_tangent(M, y, sigma, S, f, D)) return D;
  }
  if (yield_function(sigma, S) < -yield_tolerance(M, sigma) || !(f.denominator > 0)) return K.asDiagonal();
  // Eq. 20: dsigma = kS (dd - m dl), dl = dF . kS dd / denominator.
  const Mat3 Ks = k.separation_matrix();
  return Ks - f.k_A_m * (f.dF.transpose() * Ks) / f.denominator;
}

IncrementResult integrate_increment(const Model& M, State& state, const Vec3& d) {
  return integrate_increment(M, state, d, nullptr);
}

namespace {

// The failed increment: the start state is kept, with the failure in SDV 21
// (docs/model.md 9); `res` holds the failure and the start traction.
void fail(const Model& M, State& state, IncrementResult& res, Failure f, Mat3* tangent) {
  IntegrationStatus& st = res.status;
  st.failure = f;
  state.status = static_cast<int>(f);
  state.substeps_accepted = st.substeps_accepted;
  state.substeps_rejected = st.substeps_rejected;
  // The start values, when they are finite (a state that obeys every rule
  // can still hold separations whose traction or energy overflows).
  const bool valid = check_state(state) == nullptr;
  const Vec3 sigma0 = valid ? traction_of(M, state) : Vec3::Zero();
  const double energy0 = valid ? elastic_energy(M, state) : 0.0;
  res.traction = sigma0.allFinite() ? sigma0 : Vec3::Zero();
  res.elastic_energy = std::isfinite(energy0) ? energy0 : 0.0;
  if (tangent) {
    // The secant of the start state: finite, and the stiffness a solver
    // that cuts the increment back will meet first.
    *tangent = valid ? Mat3(secant_stiffness(M, state.dn, state.ds, state.open).asDiagonal())
                     : Mat3(Vec3(M.p.kn, M.p.ks, M.p.ks).asDiagonal());
    st.tangent_approximate = true;
  }
}

// The increment with one scheme, from a valid state and a finite increment,
// into `res` (the caller's result object itself, so that the result is
// written once, where the adapter reads it: a copy of a struct just filled
// field by field would wait on those stores).
// `state` is written only at the end: the end state on success, else the
// failure's three slots (fail()), which integrate() relies on.
void integrate_with(const Model& M, State& state, const Vec3& d, Mat3* tangent, SubstepScheme& scheme,
                    IncrementResult& res, TangentTracker& tracker) {
  IntegrationStatus& st = res.status;
  Point P{state, traction_of(M, state)};
  Sensitivity sensitivity;
  if (tangent && scheme.traits.consistent_tangent) tracker.D = &sensitivity;
  const Vec3 sep_end = state.separation + d;
  IncrementIntegration increment(M, P, st, tracker, scheme);
  if (const Failure f = increment.run(d); f != Failure::none) return fail(M, state, res, f, tangent);
  // The pieces add up to d up to round-off; land exactly on the end point.
  if (P.y.separation != sep_end) {
    P.y.separation = sep_end;
    P.sigma = traction_of(M, P.y);
  }
  // Eq. 8 on the fully softened cone (s = 0) is |tau| - <-sigma_n> tan(phi)
  // = 0 up to round-off, which can leave w_II a few ulps below zero; w_II no
  // longer affects the strength there, and check_state() requires w_II >= 0.
  if (P.y.wII < 0) P.y.wII = 0;
  if (check_state(P.y) != nullptr || !P.sigma.allFinite())
    return fail(M, state, res, Failure::non_finite_result, tangent);
  // Finite separations can still give an elastic energy or a dissipation
  // increment beyond double's range (increments near 1e155 mm). The sum is
  // IncrementResult::d_inelastic()'s, in its order: the double adapter stores
  // it unchecked.
  const double energy_end = elastic_energy(M, P.y);
  const double d_plastic = P.y.dissipation_plastic - state.dissipation_plastic;
  const double d_damage = P.y.dissipation_damage - state.dissipation_damage;
  const double d_unilateral = P.y.energy_unilateral - state.energy_unilateral;
  if (!std::isfinite(energy_end) || !std::isfinite(d_plastic + d_damage + d_unilateral))
    return fail(M, state, res, Failure::non_finite_result, tangent);

  if (tangent) {
    if (tracker) {
      *tangent = sensitivity.sigma;
      st.tangent_approximate = tracker.lost;
    } else {
      // The last piece of d has d's direction: the tangent of increments that
      // go on the same way.
      *tangent = increment.ended_plastic() ? continuum_tangent(M, P.y, P.sigma, d)
                                           : Mat3(secant_stiffness(M, P.y.dn, P.y.ds, P.y.open).asDiagonal());
      st.tangent_approximate = increment.ended_plastic();
    }
    if (!tangent->allFinite()) return fail(M, state, res, Failure::non_finite_result, tangent);
  }
  res.d_dissipation_plastic = d_plastic;
  res.d_dissipation_damage = d_damage;
  res.d_energy_unilateral = d_unilateral;
  P.y.substeps_accepted = st.substeps_accepted;
  P.y.substeps_rejected = st.substeps_rejected;
  P.y.status = 0;
  if (st.min_substep_hit) st.flags |= integration_flag::floor_above_stol;
  P.y.integration_flags |= st.flags;
  state = P.y;
  res.traction = P.sigma;
  res.elastic_energy = energy_end;
}

// One attempt at the increment with the scheme of M.controls, from a valid
// state and a finite increment, into `res` (a default result: the counts
// start at 0).
// With `shortcut`, an increment elastic_increment() proves elastic is booked
// without the machinery (the explicit routines ask for no tangent; most of
// their increments, and the fallback chain's pieces, are elastic).
void attempt(const Model& M, State& state, const Vec3& d, Mat3* tangent, IncrementResult& res, bool shortcut = true) {
  if (MORTAR_FAST_PATHS && shortcut && !tangent && elastic_increment(M, state, d, res)) return;
  TangentTracker tracker;
  // The scheme is chosen once per increment; each lives on the stack.
  switch (M.controls.scheme) {
    case Scheme::forward_euler: {
      ForwardEuler scheme;
      return integrate_with(M, state, d, tangent, scheme, res, tracker);
    }
    case Scheme::implicit: {
      BackwardEuler scheme(M, res.status, tracker, true);
      return integrate_with(M, state, d, tangent, scheme, res, tracker);
    }
    case Scheme::modified_euler:
      break;
  }
  ModifiedEuler scheme(M, res.status);
  return integrate_with(M, state, d, tangent, scheme, res, tracker);
}

// Whether another way through the same increment can succeed where the
// chosen scheme failed (docs/model.md 9). The budgets (substeps, Newton
// iterations, regime segments, relaxation steps) are per increment, and the
// step the schemes or the return at fixed separation could not take may be
// within reach of a shorter piece or of another scheme: the law's answer does
// not depend on how the path is cut. Bad input (an invalid state, a ...
// The rest: docs/numerics.md, section 11.
bool can_fall_back(Failure f) {
  switch (f) {
    case Failure::too_many_substeps:
    case Failure::relaxation_failed:
    case Failure::too_many_switches:
    case Failure::local_solve_failed:
      return true;
    case Failure::none:
    case Failure::non_finite_increment:
    case Failure::invalid_state:
    case Failure::non_finite_result:
      return false;
  }
  return false;
}

// One rung of the fallback chain: a scheme over the increment cut into
// `pieces` equal pieces. Measured on 1.19 million random point-increments
// (docs/model.md 9): modified Euler over 8 pieces integrates every
// backward-Euler failure and most modified-Euler ones, 64 pieces most of the
// rest, and forward Euler, which has no error control to exhaust, the few
// left. Backward Euler itself (cut or not) and a tighter STOL integrate fewer ...
// The rest: docs/numerics.md, section 12.
struct Rung {
  Scheme scheme;
  int pieces;
  int flag;
  bool checked;
};
constexpr Rung kChain[] = {
    {Scheme::modified_euler, 8, integration_flag::fallback_rung_1, false},
    {Scheme::modified_euler, 64, integration_flag::fallback_rung_2, false},
    {Scheme::forward_euler, 1024, integration_flag::fallback_rung_3, true},
};

// Whether a rung's end point (state and traction) is on or inside the
// surface within 10 FTOL.
bool on_or_inside(const Model& M, const State& end, const Vec3& traction) {
  return yield_function(traction, surface_of(M, end)) <= 10 * yield_tolerance(M, traction);
}
// The substeps (accepted + rejected) and relaxation steps the whole chain may
// spend, in units of Controls::max_substeps: the bound on its cost. Worst case
// of one call: the first attempt (its own budgets), then at most
// 4 x max_substeps steps of the explicit schemes over at most 8 + 64 + 1024
// pieces (each with the per-increment bounds on segments and crossing cuts);
// measured at most 0.36 s for one increment, almost all of it the implicit
// scheme's own Newton budget in the first attempt. Nothing is allocated.
constexpr long kFallbackBudget = 4;

// Adds a piece's counts to the rung's.
void add_counts(IntegrationStatus& sum, const IntegrationStatus& piece) {
  sum.substeps_accepted += piece.substeps_accepted;
  sum.substeps_rejected += piece.substeps_rejected;
  sum.regime_switches += piece.regime_switches;
  sum.relaxations += piece.relaxations;
  sum.relaxation_steps += piece.relaxation_steps;
  sum.newton_iterations += piece.newton_iterations;
  sum.plastic = sum.plastic || piece.plastic;
  sum.min_substep_hit = sum.min_substep_hit || piece.min_substep_hit;
  sum.flags |= piece.flags;
  sum.failure = piece.failure;
}

// The increment d from `start` as `pieces` equal increments, each one call
// of the law with the controls of R, its substep budget cut to what is left
// of `budget` (which the pieces spend). On success `end` and the summed
// result; on failure the counts so far and the failure.
IncrementResult run_pieces(Model R, const State& start, State& end, const Vec3& d, int pieces, Mat3* tangent,
                           long& budget) {
  IncrementResult total;
  end = start;
  const long allowed = R.controls.max_substeps;
  for (int i = 1; i <= pieces; ++i) {
    if (budget < 1) {
      total.status.failure = Failure::too_many_substeps;
      return total;
    }
    R.controls.max_substeps = int(std::min(allowed, budget));
    // Piece i ends where the fraction i/pieces of d does, so that no
    // round-off accumulates; the last ends exactly at start + d.
    const Vec3 target = start.separation + (i == pieces ? d : Vec3((double(i) / pieces) * d));
    IncrementResult r;
    attempt(R, end, target - end.separation, i == pieces ? tangent : nullptr, r);
    add_counts(total.status, r.status);
    budget -= r.status.work();
    if (!r.status.ok()) return total;
    total.traction = r.traction;
    total.elastic_energy = r.elastic_energy;
  }
  // The pieces add up to d up to round-off; land exactly on the end point.
  if (const Vec3 sep_end = start.separation + d; end.separation != sep_end) {
    end.separation = sep_end;
    total.traction = traction_of(R, end);
    total.elastic_energy = elastic_energy(R, end);
  }
  total.d_dissipation_plastic = end.dissipation_plastic - start.dissipation_plastic;
  total.d_dissipation_damage = end.dissipation_damage - start.dissipation_damage;
  total.d_energy_unilateral = end.energy_unilateral - start.energy_unilateral;
  return total;
}

// The chosen scheme failed on an integrable point: the fallback chain from the
// unchanged start state, rung by rung, until one integrates the increment.
// The first success is returned, flagged, its tangent the last piece's
// (approximate); when none succeeds, `first` (the chosen scheme's failure).
IncrementResult fall_back(const Model& M, const State& start, State& state, const Vec3& d, Mat3* tangent,
                          const IncrementResult& first) {
  long budget = kFallbackBudget * M.controls.max_substeps;
  Mat3 T;
  for (const Rung& rung : kChain) {
    Model R = M;
    R.controls.scheme = rung.scheme;
    State end;
    IncrementResult r = run_pieces(R, start, end, d, rung.pieces, tangent ? &T : nullptr, budget);
    if (!r.status.ok()) continue;
    if (rung.checked && !on_or_inside(R, end, r.traction)) continue;
    if (tangent) *tangent = T;
    r.status.first_failure = first.status.failure;
    r.status.fallback_scheme = rung.scheme;
    r.status.fallback_pieces = rung.pieces;
    r.status.tangent_approximate = true;
    r.status.flags |= rung.flag;
    end.integration_flags |= rung.flag;
    end.substeps_accepted = r.status.substeps_accepted;
    end.substeps_rejected = r.status.substeps_rejected;
    state = end;
    return r;
  }
  return first;
}

// integrate_increment, with or without the elastic shortcut.
IncrementResult integrate(const Model& M, State& state, const Vec3& d, Mat3* tangent, bool shortcut) {
  // One result object, returned from every path (no copy of it: see
  // integrate_with).
  IncrementResult res;
  if (check_state(state)) {
    fail(M, state, res, Failure::invalid_state, tangent);
    return res;
  }
  if (!d.allFinite()) {
    fail(M, state, res, Failure::non_finite_increment, tangent);
    return res;
  }
  if (MORTAR_FAST_PATHS && shortcut && !tangent && elastic_increment(M, state, d, res)) return res;
  // A failed attempt has left the start state as it was but for the three
  // slots fail() writes: the fallback chain's start is copied only when
  // the chain runs.
  const int status = state.status, accepted = state.substeps_accepted, rejected = state.substeps_rejected;
  attempt(M, state, d, tangent, res, false);
  if (res.status.ok() || !can_fall_back(res.status.failure)) return res;
  State start = state;
  start.status = status;
  start.substeps_accepted = accepted;
  start.substeps_rejected = rejected;
  res = fall_back(M, start, state, d, tangent, res);
  return res;
}

}  // namespace

IncrementResult integrate_increment(const Model& M, State& state, const Vec3& d, Mat3* tangent) {
  return integrate(M, state, d, tangent, true);
}

IncrementResult integrate_full(const Model& M, State& state, const Vec3& d) {
  return integrate(M, state, d, nullptr, false);
}

double yield_ratio(const Model& M, const State& y, const Vec3& sigma) {
  return yield_function(sigma, surface_of(M, y)) / yield_tolerance(M, sigma);
}

double softening_factor(const Model& M, const State& y) { return surface_of(M, y).s; }

}  // namespace mortar
