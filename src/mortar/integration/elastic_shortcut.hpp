// The elastic increment without the integration machinery: most points of an
// Abaqus/Explicit analysis are elastic at most increments, and for them the
// full path (integrator.cpp: scheme, segments, intersection search) ends in
// one elastic segment, separation += d and the traction of Eq. 1. This test
// proves that outcome from the start and end tractions alone, with no
// transcendental function on the common path; the caller then books it with
// the very same arithmetic (bit for bit the full path's result). A point the
// test cannot prove elastic (near or on the surface, at a regime boundary)
// takes the full path, which decides exactly.
#pragma once

#include <algorithm>
#include <cmath>

#include "mortar/integration/lanes.hpp"
#include "mortar/integration/substepper.hpp"
#include "mortar/physics/damage.hpp"
#include "mortar/physics/elasticity.hpp"
#include "mortar/result.hpp"

namespace mortar {

// The shortcut's two tests, over one point (T = double, a bool each) or over
// the points in the lanes of a vector (T = lanes::D, integration/
// elastic_lanes.hpp): one source, so that both decide alike, bit for bit.
inline double magnitude(double x) { return std::abs(x); }
inline double larger(double a, double b) { return std::max(a, b); }

// The regime is consistent at the start (normal elastic separation e_n) and
// not crossed at its end e_n_end beyond the boundary's eps (run(), the same
// expressions).
template <class T, class B>
B regime_kept(B open, T e_n, T e_n_end, T eps) {
  const B consistent = !((open && e_n < -eps) || (!open && e_n > eps));
  const B crossed = crosses(open, e_n_end) && magnitude(e_n_end) > eps;
  return consistent && !crossed;
}

// A traction (s0, s1, s2) lies inside the surface (alpha, beta, tan(phi) =
// t) by more than FTOL, proved from upper bounds, not from F itself: with
// q = beta - sigma_n tan(phi) - (FTOL bound) - margin, F < -(FTOL bound)
// whenever q > 0 and alpha^2 + tau^2 < q^2, where alpha, beta and tan(phi)
// are computed as surface_of() does, the squares spare the square roots of F
// and of FTOL's norm (its bound uses the 1-norm), and the margin, 1e-12 of
// the terms' size, is a thousand times the round-off by which this
// evaluation and hypot()'s can differ. A point within that margin of the
// surface takes the full path.
template <class T, class Tt>
auto inside_by_bounds(const Model& M, T alpha, T beta, Tt t, T s0, T s1, T s2) {
  const T tn = s0 * t;
  const T abs_sum = magnitude(s0) + magnitude(s1) + magnitude(s2);
  const T ftol = M.controls.ftol * larger(abs_sum, M.stress_scale) * (1 + 1e-12);
  const T size = magnitude(alpha) + magnitude(s1) + magnitude(s2) + magnitude(tn) + beta + ftol;
  const T q = beta - tn - ftol - 1e-12 * size;
  return q > 0.0 && alpha * alpha + s1 * s1 + s2 * s2 < q * q;
}

// An increment d from a valid state y is certainly elastic by the rule of
// IncrementIntegration: the regime is consistent at the start and not crossed
// (regime_kept), and both the start traction and the elastic end traction
// K (delta_e + d) lie inside the surface by more than FTOL
// (inside_by_bounds), so that the segment is neither on the surface nor
// reaches it (segment()).
inline bool certainly_elastic(const Model& M, const State& y, const Vec3& d) {
  const double e_n = y.separation[0] - y.plastic[0];
  if (!regime_kept(y.open, e_n, e_n + d[0], boundary_eps(M, y))) return false;
  // Opening past the inelastic opening of a completed normal moves delta_p_n
  // (follow_opening): the full path's, in its very arithmetic.
  if (y.open && y.dn >= 1 && ((y.separation[0] + d[0]) - y.plastic[0]) - y.crack[0] > 0) return false;

  const Parameters& p = M.p;
  const double s = std::max(0.0, 1.0 - y.wI / p.GIC - y.wII / p.GIIC);
  const bool worn = y.wIII > 0;
  const double t = worn ? M.tan_phir + (M.tan_phi0 - M.tan_phir) * exp_or_zero(-p.m * y.wIII) : M.tan_phi0;
  const double C_t = worn ? M.cohesion_term / t : M.cohesion_over_tan_phi0;
  const double alpha = s * 0.5 * (C_t - p.ft0 * t), beta = s * 0.5 * (C_t + p.ft0 * t);
  auto inside = [&](const Vec3& sigma) { return inside_by_bounds(M, alpha, beta, t, sigma[0], sigma[1], sigma[2]); };
  const Vec3 K = secant_stiffness(M, y.dn, y.ds, y.open);
  const Vec3 e0 = y.elastic_separation();
  return inside(K.cwiseProduct(e0)) && inside(K.cwiseProduct(e0 + d));
}

// An increment certainly_elastic() proves elastic, booked as integrate_with()
// books one elastic segment over all of d, whatever the scheme: the same sum
// and the same functions of the end state, no dissipation (x - x = +0, the
// result's defaults), no substeps. False (state untouched) when it cannot
// prove it or the end lies beyond double's range (the full path reports that).
// Inline: the adapters' per-point loops call it (vuinteraction/adapter).
inline bool elastic_increment(const Model& M, State& state, const Vec3& d, IncrementResult& res) {
  if (!certainly_elastic(M, state, d)) return false;
  const Vec3 separation0 = state.separation;
  state.separation += d;
  res.traction = traction_of(M, state);
  res.elastic_energy = elastic_energy(M, state);
  const double finite = state.separation.sum() + res.traction.sum() + res.elastic_energy;
  if (!(finite - finite == 0)) {
    state.separation = separation0;
    res = IncrementResult{};
    return false;
  }
  state.substeps_accepted = state.substeps_rejected = state.status = 0;
  return true;
}

}  // namespace mortar
