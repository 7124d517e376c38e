// The yield surface of the mortar joint (Eqs. 2-6), its flow direction
// (Eq. 10 regularised, Eq. 17) and the work rates (Eqs. 7-9), with their
// derivatives (docs/model.md 4-5). Pure functions of (traction, works); they
// know nothing of integration schemes.
//
// One surface today. A second one (a compression cap) would come in as a
// further surface evaluated by the same pattern, and the integration asks
// which surfaces are active through ActiveSurfaces (below).
#pragma once

#include <algorithm>
#include <cassert>
#include <cmath>

#include <Eigen/Core>

#include "mortar/elastic.hpp"
#include "mortar/parameters.hpp"
#include "mortar/physics/norms.hpp"
#include "mortar/state.hpp"

namespace mortar {


// Current size of the surface, from the inelastic works.
struct Surface {
  double s_raw = 1;   // 1 - wI/GIC - wII/GIIC (may go below 0)
  double s = 1;       // softening factor, Eqs. 4-5: max(0, s_raw)
  double tan_phi = 0; // Eq. 6
  double tan_psi = 0; // Eq. 6 with psi, n (text after Eq. 10)
  double a = 0, b = 0;    // alpha/s and beta/s for this tan_phi (Eq. 3)
  double da = 0, db = 0;  // their derivatives with respect to tan_phi
  double alpha = 0, beta = 0;
  bool has_psi = true;  // tan_psi evaluated (shape_of leaves it to with_psi)
};

// The surface without tan_psi, which only the flow (Eq. 10) reads: F (Eq. 2)
// and the error estimate of a substep's end need no exp(-n wIII); with_psi
// adds it where a flow is evaluated there.
//
// shape_into writes every member of an existing surface in place: a surface
// returned by value and assigned to one would be copied with wide loads just
// after its members' stores, which wait for them (no store forwarding).
inline void shape_into(const Model& M, double wI, double wII, double wIII, Surface& S) {
  const Parameters& p = M.p;
  S.has_psi = false;
  S.tan_psi = 0;
  S.s_raw = 1.0 - wI / p.GIC - wII / p.GIIC;
  S.s = std::max(0.0, S.s_raw);
  S.tan_phi = tan_phi_of(M, wIII);
  // Eq. 3 solved for alpha, beta: beta - alpha = ft*tanphi,
  // beta + alpha = c^2/(ft*tanphi); with ft = s*ft0, c = s*c0 both scale with s.
  const double t = S.tan_phi, C = M.cohesion_term, f = p.ft0;
  S.a = 0.5 * (C / t - f * t);
  S.b = 0.5 * (C / t + f * t);
  S.da = 0.5 * (-C / (t * t) - f);
  S.db = 0.5 * (-C / (t * t) + f);
  S.alpha = S.s * S.a;
  S.beta = S.s * S.b;
}
inline Surface shape_of(const Model& M, double wI, double wII, double wIII) {
  Surface S;
  shape_into(M, wI, wII, wIII, S);
  return S;
}
// Eq. 6 with psi, n, for a surface of works with this wIII.
inline void with_psi(const Model& M, Surface& S, double wIII) {
  if (S.has_psi) return;
  S.tan_psi = M.tan_psir + (M.tan_psi0 - M.tan_psir) * exp_or_zero(-M.p.n * wIII);
  S.has_psi = true;
}
inline Surface surface_of(const Model& M, double wI, double wII, double wIII) {
  Surface S = shape_of(M, wI, wII, wIII);
  with_psi(M, S, wIII);
  return S;
}
inline Surface surface_of(const Model& M, const State& y) { return surface_of(M, y.wI, y.wII, y.wIII); }
inline Surface shape_of(const Model& M, const State& y) { return shape_of(M, y.wI, y.wII, y.wIII); }

inline double shear_norm(const Vec3& sigma) { return hypot_of(sigma[1], sigma[2]); }

// |tau| and R = sqrt(alpha^2 + tau^2) of a traction on a surface: what the
// yield function (Eq. 2) and the flow (Eq. 10) share, so that a caller
// needing both at one point evaluates them once.
struct ShearRadius {
  double tau = 0, R = 0;
};
inline ShearRadius shear_radius(const Vec3& sigma, const Surface& S) {
  const double tau = shear_norm(sigma);
  return {tau, hypot_of(S.alpha, tau)};
}

// Eq. 2: F = sqrt(alpha^2 + tau^2) + sigma_n tan(phi) - beta.
inline double yield_function(const Vec3& sigma, const Surface& S, const ShearRadius& r) {
  return r.R + sigma[0] * S.tan_phi - S.beta;
}
inline double yield_function(const Vec3& sigma, const Surface& S) {
  return yield_function(sigma, S, shear_radius(sigma, S));
}

// Tolerance on F: relative to the traction, floored at the tensile strength
// (FTOL, docs/model.md 7.4).
inline double yield_tolerance(const Model& M, const Vec3& sigma) {
  return M.controls.ftol * std::max(sigma.norm(), M.stress_scale);
}

// The surfaces a traction lies on or beyond (within FTOL). With the one
// surface of Eq. 2 this is a single flag; a compression cap would add one.
struct ActiveSurfaces {
  bool shear_tension = false;  // Eq. 2
  bool any() const { return shear_tension; }
};
inline ActiveSurfaces active_surfaces(const Model& M, const Vec3& sigma, const Surface& S) {
  return {yield_function(sigma, S) > yield_tolerance(M, sigma)};
}

// Everything the plastic rate equations need at one (sigma, surface), per unit
// plastic multiplier lambda.
struct Flow {
  Vec3 dF;        // dF/dsigma = (tan phi, tau/R)                  Eq. 2
  Vec3 m;         // flow direction dG/dsigma (normal part blended) Eq. 10
  Vec3 k_A_m;     // kbar (I + h b) m: traction change per unit lambda (rate statement)
  double gI = 0, gII = 0, gIII = 0;  // dw/dlambda, Eqs. 7-9 with delta_in = (I + b) m lambda
  double hardening = 0;  // dF/dkappa . dkappa/dlambda (> 0 when the surface shrinks)
  double denominator = 0;  // dF . kbar A m - hardening (consistency condition)
};

// The yield function, flow direction and works per unit lambda at (sigma,
// kappa = works) with their derivatives. Values are those of flow_of (the
// same evaluation); derivatives are one-sided at the kinks (sigma_n = 0,
// sigma_n = ft, s = 0) and zero where the subgradient is taken (apex,
// tau = 0).
struct LocalDerivatives {
  double F = 0;
  Vec3 F_sigma = Vec3::Zero(), F_kappa = Vec3::Zero();
  Vec3 m = Vec3::Zero();
  Mat3 m_sigma = Mat3::Zero(), m_kappa = Mat3::Zero();  // d m_i / d sigma_j, d m_i / d kappa_j
  Vec3 g = Vec3::Zero();
  Mat3 g_sigma = Mat3::Zero(), g_kappa = Mat3::Zero();
};

// The intermediate quantities of one evaluation, shared by the values and
// the derivatives so that both read the very same arithmetic.
struct FlowEvaluation {
  double tau = 0, R = 0, ratio = 0, shear_dir = 0;  // |tau|, sqrt(alpha^2 + tau^2), dR/dalpha, tau/R
  double ft = 0, w = 0, m_n = 0;                   // tension cut-off, blend weight, normal flow
  double din_s = 0, tension = 0, pressure = 0;
};

// The derivatives part of flow_of, from the same intermediate quantities.
void fill_derivatives(const Model& M, const Vec3& sigma, const Surface& S, const Flow& f, const FlowEvaluation& v,
                      LocalDerivatives& d);

// R = sqrt(alpha^2 + tau^2); tau/R is taken as 0 where R = 0 (alpha = 0 and
// tau = 0: the apex of the fully softened cone, where any subgradient with a
// zero shear part is admissible).
//
// k_flow is the stiffness that multiplies the flow in the rate statement:
// the traction changes by -k_flow . m per unit lambda (see RateStiffness).
// The rest: docs/numerics.md, section 17.
inline Flow flow_of(const Model& M, const Vec3& sigma, const Surface& S, const Vec3& k_flow, const ShearRadius& radius,
                    LocalDerivatives* derivatives = nullptr) {
  assert(S.has_psi);
  const Parameters& p = M.p;
  Flow f;
  FlowEvaluation v;
  v.tau = radius.tau;
  v.R = radius.R;
  const double tau = v.tau, R = v.R;
  const double e1 = R > 0 ? sigma[1] / R : 0.0, e2 = R > 0 ? sigma[2] / R : 0.0;
  v.shear_dir = R > 0 ? tau / R : 0.0;  // |dG/dtau|

  // Normal flow: tan(psi) under compression, blended linearly to the
  // associated tan(phi) at the tension cut-off sigma_n = ft (docs/model.md
  // 5, degenerate flow). Continuous across sigma_n = 0, so a joint crossing
  // from closed to open keeps its flow direction.
  v.ft = p.ft0 * S.s;
  if (sigma[0] > 0) v.w = v.ft > 0 ? std::min(1.0, sigma[0] / v.ft) : 1.0;
  v.m_n = S.tan_psi + (S.tan_phi - S.tan_psi) * v.w;

  f.dF = Vec3(S.tan_phi, e1, e2);
  f.m = Vec3(v.m_n, e1, e2);
  // From the scalars rather than from f.m in memory: a vector load over its
  // pending stores waits for them (no store forwarding).
  f.k_A_m = Vec3(k_flow[0] * v.m_n, k_flow[1] * e1, k_flow[2] * e2);

  // Works per unit lambda (Eqs. 7-9); the inelastic increment includes the
  // crack part in every regime (Eq. 17).
  const double din_n = (1 + p.bn) * v.m_n;
  v.din_s = (1 + p.bs) * v.shear_dir;
  v.tension = std::max(sigma[0], 0.0);
  v.pressure = std::max(-sigma[0], 0.0);
  f.gI = v.tension * din_n;
  f.gII = (tau - v.pressure * S.tan_phi) * v.din_s;
  f.gIII = v.pressure * std::abs(S.tan_phi - M.tan_phir) * v.din_s;

  // Hardening term of the consistency condition (Eq. 19, first part).
  const double ds_dl = S.s_raw > 0 ? -(f.gI / p.GIC + f.gII / p.GIIC) : 0.0;
  const double dt_dl = -p.m * (S.tan_phi - M.tan_phir) * f.gIII;
  v.ratio = R > 0 ? S.alpha / R : 1.0;  // d R / d alpha
  const double dF_ds = v.ratio * S.a - S.b;
  const double dF_dt = v.ratio * S.s * S.da + sigma[0] - S.s * S.db;
  f.hardening = dF_ds * ds_dl + dF_dt * dt_dl;
  f.denominator = f.dF.dot(f.k_A_m) - f.hardening;
  if (derivatives) fill_derivatives(M, sigma, S, f, v, *derivatives);
  return f;
}
inline Flow flow_of(const Model& M, const Vec3& sigma, const Surface& S, const Vec3& k_flow,
                    LocalDerivatives* derivatives = nullptr) {
  return flow_of(M, sigma, S, k_flow, shear_radius(sigma, S), derivatives);
}

// F, m, g and their derivatives at (sigma, kappa).
LocalDerivatives local_derivatives(const Model& M, const Vec3& sigma, const Vec3& kappa);

}  // namespace mortar
