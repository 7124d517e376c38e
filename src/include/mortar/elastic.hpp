// The elastic kernel, written once: the secant stiffness (Eq. 21), the
// traction (Eq. 1), the elastic energy, and the proof that an increment is
// elastic, as templates over one point (T = double) or the points in the
// lanes of a vector (T = lanes::D, mortar/batch.hpp). The law's elastic
// segments (physics/elasticity.hpp), the shortcut below and the lanes all
// instantiate it, so they agree bit for bit by construction.
// The rest: docs/numerics.md, section 1.
#pragma once

#include <cmath>

#include "mortar/lanes.hpp"
#include "mortar/parameters.hpp"
#include "mortar/result.hpp"
#include "mortar/state.hpp"

#ifndef MORTAR_FAST_PATHS
#define MORTAR_FAST_PATHS 1  // the shortcut and the lanes (CMake: MJ_FAST_PATHS)
#endif

namespace mortar {

// exp(x), +0 below ln(2^-1075), where exp would underflow to +0 anyway.
inline double exp_or_zero(double x) { return x < -745.14 ? 0.0 : std::exp(x); }
// tan(phi) after the wear w_III (Eq. 6).
inline double tan_phi_of(const Model& M, double wIII) {
  return M.tan_phir + (M.tan_phi0 - M.tan_phir) * exp_or_zero(-M.p.m * wIII);
}

// Eq. 21: the secant stiffness with the unilateral factor h (1 open, 0 closed).
template <class T, class H>
void secant_stiffness_of(const Parameters& p, T dn, T ds, H h, T (&K)[3]) {
  K[0] = p.kn * (1 - dn * h);
  K[1] = p.ks * (1 - ds * h);
  K[2] = K[1];
}
// Eq. 1, sigma = K (delta - delta_p), and the energy 1/2 sigma . (delta - delta_p).
template <class T>
void traction_of(const T (&K)[3], const T (&e)[3], T (&sigma)[3]) {
  for (int i = 0; i < 3; ++i) sigma[i] = K[i] * e[i];
}
template <class T>
T elastic_energy_of(const T (&sigma)[3], const T (&e)[3]) {
  return 0.5 * (sigma[0] * e[0] + sigma[1] * e[1] + sigma[2] * e[2]);
}

// The kernel for the law's Vec3 (Eq. 21).
inline Vec3 secant_stiffness(const Model& M, double dn, double ds, bool open) {
  double K[3];
  secant_stiffness_of(M.p, dn, ds, open ? 1.0 : 0.0, K);
  return Vec3(K[0], K[1], K[2]);
}

// Eq. 1: the traction is always the secant relation of the current state.
inline Vec3 traction_of(const Model& M, const State& y) {
  const Vec3 K = secant_stiffness(M, y.dn, y.ds, y.open), e = y.elastic_separation();
  const double k[3] = {K[0], K[1], K[2]}, ev[3] = {e[0], e[1], e[2]};
  double sigma[3];
  traction_of(k, ev, sigma);
  return Vec3(sigma[0], sigma[1], sigma[2]);
}

// Elastic energy per unit area, 1/2 sigma . (delta - delta_p).
inline double elastic_energy(const Model& M, const State& y) {
  const Vec3 K = secant_stiffness(M, y.dn, y.ds, y.open), e = y.elastic_separation();
  const double k[3] = {K[0], K[1], K[2]}, ev[3] = {e[0], e[1], e[2]};
  double sigma[3];
  traction_of(k, ev, sigma);
  return elastic_energy_of(sigma, ev);
}

// Whether a normal elastic separation e_n lies across the regime boundary
// from a joint in the given regime (Eq. 13: h = 1 for e_n > 0).
template <class B, class T>
B crosses(B open, T e_n) {
  return open ? e_n < 0.0 : e_n > 0.0;
}
// Round-off scale of the regime boundary delta_e_n = 0.
template <class T>
T boundary_eps_of(const Model& M, T separation_n, T plastic_n) {
  return 1e-12 * max_of(max_of(abs_of(separation_n), abs_of(plastic_n)), M.separation_floor);
}

// The regime is consistent at the start and not crossed at the end beyond eps.
template <class T, class B>
B regime_kept(B open, T e_n, T e_n_end, T eps) {
  const B consistent = !((open && e_n < -eps) || (!open && e_n > eps));
  const B crossed = crosses(open, e_n_end) && abs_of(e_n_end) > eps;
  return consistent && !crossed;
}

// The traction (s0, s1, s2) lies inside the surface (alpha, beta, tan(phi) =
// t) by more than FTOL, proved from bounds without square roots; the margin,
// 1e-12 of the terms' size, covers the round-off between this evaluation and
// F's (docs/numerics.md, section 19).
template <class T, class Tt>
auto inside_by_bounds(const Model& M, T alpha, T beta, Tt t, T s0, T s1, T s2) {
  const T tn = s0 * t;
  const T abs_sum = abs_of(s0) + abs_of(s1) + abs_of(s2);
  const T ftol = M.controls.ftol * max_of(abs_sum, M.stress_scale) * (1 + 1e-12);
  const T size = abs_of(alpha) + abs_of(s1) + abs_of(s2) + abs_of(tn) + beta + ftol;
  const T q = beta - tn - ftol - 1e-12 * size;
  return q > 0.0 && alpha * alpha + s1 * s1 + s2 * s2 < q * q;
}

// The traction lies inside the compression cap by more than FTOL whatever
// its kappa_c: the cap never shrinks below its residual fc/7 (docs/model.md
// 12), so the proof needs no state of the cap; a point between fc/7 and its
// cap goes the full path.
template <class T>
auto inside_cap_by_bounds(const Model& M, T s0, T s1, T s2) {
  const T abs_sum = abs_of(s0) + abs_of(s1) + abs_of(s2);
  const T ftol = M.controls.ftol * max_of(abs_sum, M.stress_scale) * (1 + 1e-12);
  const T r = M.cap_residual - ftol;
  return r > 0.0 && s0 * s0 + M.cap.Cs * (s1 * s1 + s2 * s2) < r * r * (1 - 1e-12);
}

// An elastic increment's start: what Eq. 1 and the proof read (law signs).
template <class T>
struct ElasticStart {
  T plastic[3], separation[3], wI, wII, dn, ds;
  T h;  // 1 open, 0 closed
  T d[3];
};
// Its end: separation, traction (Eq. 1), elastic energy.
template <class T>
struct ElasticEnd {
  T separation[3], traction[3], energy;
};

// The kernel: the end of one elastic segment over all of d, and whether the
// increment is proved elastic (the caller's conditions `taken`, regime kept,
// start and end tractions inside the surface by more than FTOL, a finite end)
// for a surface of friction tan(phi) = t and C / tan(phi) = C_t. `open` and
// `taken` are bools or masks. The tests come before the end values: in the
// lanes fewer vectors are then live at once.
template <class T, class B>
MORTAR_KERNEL_INLINE B elastic_end(const Model& M, const ElasticStart<T>& y, B open, B taken, double t, double C_t,
                                   ElasticEnd<T>& r) {
  const Parameters& p = M.p;
  const T e_n = y.separation[0] - y.plastic[0];
  const B kept = taken && regime_kept(open, e_n, e_n + y.d[0], boundary_eps_of(M, y.separation[0], y.plastic[0]));
  const T s_raw = 1.0 - y.wI / p.GIC - y.wII / p.GIIC;
  const T s = 0.0 < s_raw ? s_raw : T{};  // Eq. 5: max(0, s_raw)
  const T alpha = s * 0.5 * (C_t - p.ft0 * t), beta = s * 0.5 * (C_t + p.ft0 * t);
  T K[3], start[3], end[3], e[3];
  secant_stiffness_of(p, y.dn, y.ds, y.h, K);
  for (int i = 0; i < 3; ++i) {
    const T e0 = y.separation[i] - y.plastic[i];
    start[i] = K[i] * e0;
    end[i] = K[i] * (e0 + y.d[i]);
  }
  B inside = kept && inside_by_bounds(M, alpha, beta, t, start[0], start[1], start[2]) &&
             inside_by_bounds(M, alpha, beta, t, end[0], end[1], end[2]);
  // A closed joint with a cap: inside it too, at both ends (F_c is convex
  // along the elastic path).
  if (M.cap.on())
    inside = inside && (open || (inside_cap_by_bounds(M, start[0], start[1], start[2]) &&
                                 inside_cap_by_bounds(M, end[0], end[1], end[2])));
  for (int i = 0; i < 3; ++i) {
    r.separation[i] = y.separation[i] + y.d[i];
    e[i] = r.separation[i] - y.plastic[i];
  }
  traction_of(K, e, r.traction);
  r.energy = elastic_energy_of(r.traction, e);
  const T sum = r.separation[0] + r.separation[1] + r.separation[2] +
                (r.traction[0] + r.traction[1] + r.traction[2]) + r.energy;
  return inside && sum - sum == 0.0;
}

// The shortcut for one point from a state the rules accept: true, the
// increment booked exactly as the full path books one elastic segment (no
// dissipation, no substeps); false, nothing written, when it is not proved.
MORTAR_KERNEL_INLINE bool elastic_increment(const Model& M, State& state, const Vec3& d, IncrementResult& res) {
  // Opening past a completed normal's inelastic opening moves delta_p_n
  // (docs/model.md 6): the full path's.
  if (state.open && state.dn >= 1 && ((state.separation[0] + d[0]) - state.plastic[0]) - state.crack[0] > 0)
    return false;
  const ElasticStart<double> y = {{state.plastic[0], state.plastic[1], state.plastic[2]},
                                  {state.separation[0], state.separation[1], state.separation[2]},
                                  state.wI, state.wII, state.dn, state.ds, state.open ? 1.0 : 0.0,
                                  {d[0], d[1], d[2]}};
  const bool worn = state.wIII > 0;
  const double t = worn ? tan_phi_of(M, state.wIII) : M.tan_phi0;
  const double C_t = worn ? M.cohesion_term / t : M.cohesion_over_tan_phi0;
  ElasticEnd<double> r;
  if (!elastic_end(M, y, state.open, true, t, C_t, r)) return false;
  state.separation = Vec3(r.separation[0], r.separation[1], r.separation[2]);
  res.traction = Vec3(r.traction[0], r.traction[1], r.traction[2]);
  res.elastic_energy = r.energy;
  state.substeps_accepted = state.substeps_rejected = state.status = 0;
  return true;
}

}  // namespace mortar
