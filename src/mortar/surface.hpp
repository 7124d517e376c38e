// Yield surface (Eqs. 2-6), flow direction (Eq. 10 regularised, Eq. 17) and
// work rates (Eqs. 7-9) of the mortar-joint law. Pure functions, no state.
#pragma once

#include <algorithm>
#include <cmath>

#include "mortar/parameters.hpp"
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
};

inline Surface surface_of(const Model& M, double wI, double wII, double wIII) {
  const Parameters& p = M.p;
  Surface S;
  S.s_raw = 1.0 - wI / p.GIC - wII / p.GIIC;
  S.s = std::max(0.0, S.s_raw);
  S.tan_phi = M.tan_phir + (M.tan_phi0 - M.tan_phir) * std::exp(-p.m * wIII);
  S.tan_psi = M.tan_psir + (M.tan_psi0 - M.tan_psir) * std::exp(-p.n * wIII);
  // Eq. 3 solved for alpha, beta: beta - alpha = ft*tanphi,
  // beta + alpha = c^2/(ft*tanphi); with ft = s*ft0, c = s*c0 both scale with s.
  const double t = S.tan_phi, C = M.cohesion_term, f = p.ft0;
  S.a = 0.5 * (C / t - f * t);
  S.b = 0.5 * (C / t + f * t);
  S.da = 0.5 * (-C / (t * t) - f);
  S.db = 0.5 * (-C / (t * t) + f);
  S.alpha = S.s * S.a;
  S.beta = S.s * S.b;
  return S;
}
inline Surface surface_of(const Model& M, const State& y) { return surface_of(M, y.wI, y.wII, y.wIII); }

inline double shear_norm(const Vec3& sigma) { return std::hypot(sigma[1], sigma[2]); }

// Eq. 2: F = sqrt(alpha^2 + tau^2) + sigma_n tan(phi) - beta.
inline double yield_function(const Vec3& sigma, const Surface& S) {
  return std::hypot(S.alpha, shear_norm(sigma)) + sigma[0] * S.tan_phi - S.beta;
}

// Tolerance on F: relative to the traction, floored at the tensile strength.
inline double yield_tolerance(const Model& M, const Vec3& sigma) {
  return M.controls.ftol * std::max(sigma.norm(), M.stress_scale);
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

// R = sqrt(alpha^2 + tau^2); tau/R is taken as 0 where R = 0 (alpha = 0 and
// tau = 0: the apex of the fully softened cone, where any subgradient with a
// zero shear part is admissible).
//
// k_flow is the stiffness that multiplies the flow in the rate statement:
// the traction changes by -k_flow . m per unit lambda (see RateStiffness).
inline Flow flow_of(const Model& M, const Vec3& sigma, const Surface& S, const Vec3& k_flow) {
  const Parameters& p = M.p;
  Flow f;
  const double tau = shear_norm(sigma);
  const double R = std::hypot(S.alpha, tau);
  const double e1 = R > 0 ? sigma[1] / R : 0.0, e2 = R > 0 ? sigma[2] / R : 0.0;
  const double shear_dir = R > 0 ? tau / R : 0.0;  // |dG/dtau|

  // Normal flow: tan(psi) under compression, blended linearly to the
  // associated tan(phi) at the tension cut-off sigma_n = ft (docs/model.md
  // "Degenerate flow"). Continuous across sigma_n = 0, so a joint crossing
  // from closed to open keeps its flow direction.
  const double ft = p.ft0 * S.s;
  double w = 0;
  if (sigma[0] > 0) w = ft > 0 ? std::min(1.0, sigma[0] / ft) : 1.0;
  const double m_n = S.tan_psi + (S.tan_phi - S.tan_psi) * w;

  f.dF = Vec3(S.tan_phi, e1, e2);
  f.m = Vec3(m_n, e1, e2);
  f.k_A_m = k_flow.cwiseProduct(f.m);

  // Works per unit lambda (Eqs. 7-9); the inelastic increment includes the
  // crack part in every regime (Eq. 17).
  const double din_n = (1 + p.bn) * m_n;
  const double din_s = (1 + p.bs) * shear_dir;
  const double tension = std::max(sigma[0], 0.0), pressure = std::max(-sigma[0], 0.0);
  f.gI = tension * din_n;
  f.gII = (tau - pressure * S.tan_phi) * din_s;
  f.gIII = pressure * std::abs(S.tan_phi - M.tan_phir) * din_s;

  // Hardening term of the consistency condition (Eq. 19, first part).
  const double ds_dl = S.s_raw > 0 ? -(f.gI / p.GIC + f.gII / p.GIIC) : 0.0;
  const double dt_dl = -p.m * (S.tan_phi - M.tan_phir) * f.gIII;
  const double ratio = R > 0 ? S.alpha / R : 1.0;  // d R / d alpha
  const double dF_ds = ratio * S.a - S.b;
  const double dF_dt = ratio * S.s * S.da + sigma[0] - S.s * S.db;
  f.hardening = dF_ds * ds_dl + dF_dt * dt_dl;
  f.denominator = f.dF.dot(f.k_A_m) - f.hardening;
  return f;
}

// Stiffnesses of the rate statement (MODEL.md section 6), per component:
//   closed:                 dsigma = kbar (dd - m dl)
//   open, damage growing:   dsigma = kbar (dd - (1 + b) m dl)   (the paper's Eq. 16-17)
//   open, damage frozen:    dsigma = kbar (1 - d) (dd - m dl)   (secant, Eq. 1)
// The open "growing" branch holds while the secant damage it implies does not
// decrease; where it would, damage is frozen (it never decreases) and the
// component follows its secant. A component whose damage is complete carries
// no traction in the open regime, so both of its stiffnesses are zero.
struct RateStiffness {
  Vec3 on_separation;  // multiplies the separation increment
  Vec3 on_flow;        // multiplies m dl
};
inline RateStiffness rate_stiffness(const Model& M, const State& y, bool grow_n = true, bool grow_s = true) {
  const Parameters& p = M.p;
  if (!y.open) return {Vec3(p.kn, p.ks, p.ks), Vec3(p.kn, p.ks, p.ks)};
  auto component = [](double k, double b, double d, bool grow, double& on_sep, double& on_flow) {
    if (d >= 1) { on_sep = on_flow = 0; return; }
    on_sep = grow ? k : k * (1 - d);
    on_flow = grow ? k * (1 + b) : k * (1 - d);
  };
  RateStiffness r;
  component(p.kn, p.bn, y.dn, grow_n, r.on_separation[0], r.on_flow[0]);
  component(p.ks, p.bs, y.ds, grow_s, r.on_separation[1], r.on_flow[1]);
  r.on_separation[2] = r.on_separation[1];
  r.on_flow[2] = r.on_flow[1];
  return r;
}

// Elastic stiffness of Eq. 21 with the unilateral factor h of the regime.
inline Vec3 secant_stiffness(const Model& M, double dn, double ds, bool open) {
  const double h = open ? 1.0 : 0.0;
  return Vec3(M.p.kn * (1 - dn * h), M.p.ks * (1 - ds * h), M.p.ks * (1 - ds * h));
}

// Eq. 1: the traction is always the secant relation of the current state.
inline Vec3 traction_of(const Model& M, const State& y) {
  return secant_stiffness(M, y.dn, y.ds, y.open).cwiseProduct(y.elastic_separation());
}

// Elastic energy per unit area, 1/2 sigma . (delta - delta_p).
inline double elastic_energy(const Model& M, const State& y) {
  const Vec3 e = y.elastic_separation();
  return 0.5 * secant_stiffness(M, y.dn, y.ds, y.open).cwiseProduct(e).dot(e);
}

}  // namespace mortar
