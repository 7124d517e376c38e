#include "mortar/integration/increment.hpp"

#include <algorithm>
#include <cmath>

#include "mortar/integration/cap.hpp"
#include "mortar/integration/relaxation.hpp"
#include "mortar/integration/root_finder.hpp"

namespace mortar {

Failure IncrementIntegration::run(const Vec3& d) {
  double left = 1;  // fraction of d still to integrate
  SegmentCount count;
  while (left > 1e-15) {
    if (const Failure f = count.check(M_.controls); f != Failure::none) return f;
    const double e_n = P_.y.elastic_separation()[0];
    const double eps = boundary_eps(M_, P_.y);
    // Regime flag inconsistent with the sign of delta_e_n (beyond round-off):
    // switch before integrating.
    if ((P_.y.open && e_n < -eps) || (!P_.y.open && e_n > eps)) {
      ++count.switches;
      if (!switch_regime()) return Failure::relaxation_failed;
      continue;
    }
    const Vec3 rest = left * d;
    // Where an elastic path would cross delta_e_n = 0.
    double frac = 1;
    bool boundary = false;
    if (crosses(P_.y.open, e_n + rest[0]) && std::abs(e_n + rest[0]) > eps) {
      frac = std::clamp(-e_n / rest[0], 0.0, 1.0);
      boundary = true;
    }
    const double done = segment(rest, frac, boundary);
    if (!st_.ok()) return st_.failure;
    left *= 1 - done;
    if (!at_boundary_) {
      ++count.restarts;  // a restart, unless nothing is left (the loop then ends)
      continue;
    }
    ++count.switches;
    if (!switch_regime()) return Failure::relaxation_failed;
  }
  return Failure::none;
}

// One segment of constant regime over the separation increment `rest`. An
// elastic path would reach the regime boundary at the fraction `frac` (1 when
// it does not); the plastic part is integrated over all of `rest` and finds
// its own boundary crossing. Returns the fraction of `rest` done; sets
// at_boundary_ when it stopped on the boundary.
double IncrementIntegration::segment(const Vec3& rest, double frac, bool boundary) {
  at_boundary_ = false;
  const Vec3 K = secant_stiffness(M_, P_.y.dn, P_.y.ds, P_.y.open);
  const Vec3 e0 = P_.y.elastic_separation();
  // S is the start surface: at.S, built in place (a copy of a surface just
  // computed would load it over its pending stores: no store forwarding),
  // until a relaxation replaces `at` below, after S's last use.
  SurfaceAt at = surface_at(M_, P_);
  const Surface& S = at.S;
  capped_ = cap_applies(M_, P_.y);
  kappa_c_ = P_.y.kappa_c;
  auto F_at = [&](double a) { return trial_yield(K.cwiseProduct(e0 + a * rest), S); };
  auto tol_at = [&](double a) { return yield_tolerance(M_, K.cwiseProduct(e0 + a * rest)); };
  auto sample = [&](double a) { return RootSample{F_at(a), tol_at(a)}; };
  const double F0 = capped_ ? trial_yield(P_.sigma, S) : yield_of(P_, at), tol0 = tol_at(0);
  const Vec3 n = flow_of(M_, P_.sigma, S, rate_stiffness(M_, P_.y).on_flow, at.radius).dF;
  const Vec3 dsig = K.cwiseProduct(rest);
  const bool on_surface = std::abs(F0) <= tol0;
  bool loading = n.dot(dsig) > 0;
  if (capped_) {
    // Loading from the surface: a surface the point is on (within FTOL)
    // rises along the secant trial (docs/model.md 12).
    const bool on1 = yield_of(P_, at) >= -tol0, onc = cap_function(M_, P_.sigma, kappa_c_) >= -tol0;
    const double sc = cap_gradient(M_, P_.sigma).dot(dsig);
    loading = (on1 && n.dot(dsig) > 0) || (onc && sc > 0);
  }
  // On the surface, loading is decided by the direction of the secant
  // (elastic) predictor, dF . K dd > 0, however small its rise: the same for
  // every cut of the increment and every scheme (docs/model.md 7.1, Decision -
  // loading from the surface).
  if (!(on_surface && loading) && F_at(frac) <= tol_at(frac)) {
    P_.y.separation += frac * rest;
    follow_opening(M_, P_.y);
    P_.sigma = traction_of(M_, P_.y);
    if (tangent_) {
      tangent_.D->separation += frac * (Mat3::Identity() - tangent_.D->separation);
      secant_sensitivity(M_, P_.y, *tangent_.D);
    }
    ended_plastic_ = false;
    at_boundary_ = boundary;
    return frac;
  }
  double a_y = 0;
  const bool relaxed = F0 > tol0 && scheme_.traits.relaxes_start_outside;
  if (relaxed) {
    if (!(capped_ ? return_to_surfaces() : relax(M_, P_, st_, false))) {
      st_.failure = Failure::relaxation_failed;
      return 0;
    }
  } else if (F0 < -tol0) {
    a_y = pegasus(sample, 0, F0, frac, F_at(frac), 100);
  } else if (on_surface && (capped_ ? !loading : n.dot(dsig) < -1e-9 * n.norm() * dsig.norm())) {
    // On the surface but unloading first, and outside at the end: the
    // secant trial re-enters the surface where a finely cut path yields
    // again (docs/model.md 7.1, Decision - unloading, then reloading).
    a_y = reentry(frac, rest, K, e0, S);
  }
  if (a_y > 0 && scheme_.traits.refines_intersection) a_y = refine_intersection(a_y, frac, rest, K, e0, S);
  if (a_y > 0) {
    P_.y.separation += a_y * rest;
    P_.sigma = traction_of(M_, P_.y);
    if (tangent_) {
      const bool on_cap = capped_ && cap_function(M_, P_.sigma, kappa_c_) > yield_function(P_.sigma, S);
      intersection_sensitivity(M_, P_.y, P_.sigma, a_y, rest, K, *tangent_.D, on_cap);
    }
  }
  // The return at fixed separation changes the works; the elastic part only
  // the traction.
  if (relaxed) {
    at = surface_at(M_, P_);
  } else if (a_y > 0) {
    at.radius = shear_radius(P_.sigma, S);
  }
  st_.plastic = true;
  ended_plastic_ = true;
  const double done = substepper_.run((1 - a_y) * rest, at);
  at_boundary_ = substepper_.at_boundary();
  return a_y + (1 - a_y) * done;
}

// Where the secant trial from a point on the surface that unloads first
// comes back to it (0: it stays within FTOL). F is convex along the trial
// (Eq. 2: |(alpha, tau)| plus a linear term), so its slope changes sign once,
// at the minimum: where the scan misses, bisection on the slope until a
// fraction lies inside by more than FTOL, then Pegasus from there
// (docs/model.md 7.1, Decision - unloading, then reloading).
double IncrementIntegration::reentry(double frac, const Vec3& rest, const Vec3& K, const Vec3& e0,
                                     const Surface& S) const {
  auto F_at = [&](double x) { return trial_yield(K.cwiseProduct(e0 + x * rest), S); };
  auto sample = [&](double x) { return RootSample{F_at(x), yield_tolerance(M_, K.cwiseProduct(e0 + x * rest))}; };
  // A dip of more than a tenth: found on a ten-point scan, as before
  // (its answers unchanged to the bit), then the same root by Pegasus.
  for (int i = 1; i <= 10; ++i) {
    const RootSample f = sample(0.1 * i * frac);
    if (f.value < -f.tolerance) return pegasus(sample, 0.1 * i * frac, f.value, frac, F_at(frac), 100);
  }
  const Vec3 dsig = K.cwiseProduct(rest);
  double lo = 0, hi = frac;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * frac; ++it) {
    const double a = 0.5 * (lo + hi);
    const RootSample f = sample(a);
    if (f.value < -f.tolerance) return pegasus(sample, a, f.value, frac, F_at(frac), 100);
    const double slope = trial_slope(K.cwiseProduct(e0 + a * rest), S, K, dsig);
    (slope < 0 ? lo : hi) = a;
  }
  return 0;
}

// Newton on the intersection fraction, from Pegasus's answer (within FTOL)
// to round-off, so that the update is a smooth function of the increment and
// its tangent can be checked by finite differences (docs/model.md 7.5).
double IncrementIntegration::refine_intersection(double a, double frac, const Vec3& rest, const Vec3& K,
                                                 const Vec3& e0, const Surface& S) const {
  auto F_at = [&](double x) { return trial_yield(K.cwiseProduct(e0 + x * rest), S); };
  double f = F_at(a);
  for (int it = 0; it < 4 && f != 0; ++it) {
    const Vec3 sigma = K.cwiseProduct(e0 + a * rest);
    const double slope = trial_slope(sigma, S, K, K.cwiseProduct(rest));
    if (!(slope > 0)) break;
    const double an = std::clamp(a - f / slope, 0.0, frac);
    const double fn = F_at(an);
    if (!(std::abs(fn) < std::abs(f))) break;
    a = an;
    f = fn;
  }
  return a;
}

// Switch of the unilateral regime at the current separation (Eq. 13). On
// opening the stiffness falls to the secant and the traction with it; on
// closing the secant's share of the elastic separation becomes plastic, so
// the traction is continuous (docs/model.md 6, Decision - closure without
// created energy). Either way the elastic energy can only fall; what it loses
// is booked as unilateral energy. A point that lands outside the surface (a
// start state already outside it) returns to it at fixed separation.
bool IncrementIntegration::switch_regime() {
  tangent_.forget(st_);
  P_.y.energy_unilateral += switch_unilateral_regime(M_, P_.y);
  ++st_.regime_switches;
  disintegrate_if_no_strength(M_, P_.y);
  P_.sigma = traction_of(M_, P_.y);
  capped_ = cap_applies(M_, P_.y);
  if (outside_surface(M_, P_) || (capped_ && cap_function(M_, P_.sigma, P_.y.kappa_c) > yield_tolerance(M_, P_.sigma))) {
    // The return depends on where the switch happened: treated as fixed.
    tangent_.lost = true;
    return return_to_surfaces();
  }
  return true;
}

// F of a secant trial traction: Eq. 2's, or the larger of it and the cap's
// on a closed joint with a cap (kappa_c fixed along the elastic part).
double IncrementIntegration::trial_yield(const Vec3& sigma, const Surface& S) const {
  const double F = yield_function(sigma, S);
  return capped_ ? std::max(F, cap_function(M_, sigma, kappa_c_)) : F;
}
// Its slope along dsig: that of the surface that gives trial_yield.
double IncrementIntegration::trial_slope(const Vec3& sigma, const Surface& S, const Vec3& K, const Vec3& dsig) const {
  if (capped_ && cap_function(M_, sigma, kappa_c_) > yield_function(sigma, S))
    return cap_gradient(M_, sigma).dot(dsig);
  return flow_of(M_, sigma, S, K).dF.dot(dsig);
}

// The return at fixed separation onto Eq. 2 (relax), then onto the cap where
// it applies (return_to_cap, the corner included).
bool IncrementIntegration::return_to_surfaces() {
  if (outside_surface(M_, P_) && !relax(M_, P_, st_, false)) return false;
  if (!cap_applies(M_, P_.y)) return true;
  return return_to_cap(M_, P_, st_);
}

}  // namespace mortar
