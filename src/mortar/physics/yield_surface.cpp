#include "mortar/physics/yield_surface.hpp"

namespace mortar {

// Derivatives of the surface size (Eqs. 3-6), the flow direction (Eq. 10)
// and the work rates (Eqs. 7-9) with respect to traction and works.
void fill_derivatives(const Model& M, const Vec3& sigma, const Surface& S, const Flow& f, const FlowEvaluation& v,
                      LocalDerivatives& d) {
  const Parameters& p = M.p;
  d.m = f.m;
  d.g = Vec3(f.gI, f.gII, f.gIII);

  // Surface size (Eqs. 3-6) with respect to the works.
  const Vec3 s_k = S.s_raw > 0 ? Vec3(-1 / p.GIC, -1 / p.GIIC, 0) : Vec3::Zero();
  const double t = S.tan_phi, tp = S.tan_psi;
  const Vec3 t_k(0, 0, -p.m * (t - M.tan_phir));
  const Vec3 tp_k(0, 0, -p.n * (tp - M.tan_psir));
  const Vec3 alpha_k = S.a * s_k + S.s * S.da * t_k;
  const Vec3 beta_k = S.b * s_k + S.s * S.db * t_k;

  const double sn = sigma[0], t1 = sigma[1], t2 = sigma[2];
  const double tau = v.tau, R = v.R, ratio = v.ratio;

  // Eq. 2: F = R + sigma_n tan(phi) - beta.
  d.F_sigma = f.dF;
  d.F_kappa = ratio * alpha_k + sn * t_k - beta_k;

  // Shear part of the flow, e = tau/R (Eq. 10 regularised).
  Eigen::Matrix<double, 2, 2> e_tau = Eigen::Matrix<double, 2, 2>::Zero();
  Eigen::Matrix<double, 2, 3> e_k = Eigen::Matrix<double, 2, 3>::Zero();
  if (R > 0) {
    const Eigen::Vector2d ts(t1, t2);
    e_tau = Eigen::Matrix2d::Identity() / R - ts * ts.transpose() / (R * R * R);
    e_k = -ts * (ratio / (R * R)) * alpha_k.transpose();
  }
  d.m_sigma.setZero();
  d.m_kappa.setZero();
  d.m_sigma.block<2, 2>(1, 1) = e_tau;
  d.m_kappa.block<2, 3>(1, 0) = e_k;

  // Normal part: m_n = tan(psi) + (tan(phi) - tan(psi)) w, w = clamp(sigma_n/ft, 0, 1).
  const double ft = v.ft, w = v.w;
  const bool inner = sn > 0 && ft > 0 && sn < ft;
  const double w_sn = inner ? 1 / ft : 0.0;
  const Vec3 w_k = inner ? Vec3(-sn / (ft * ft) * p.ft0 * s_k) : Vec3::Zero();
  d.m_sigma(0, 0) = (t - tp) * w_sn;
  d.m_kappa.row(0) = (tp_k * (1 - w) + t_k * w + (t - tp) * w_k).transpose();

  // Works per unit lambda, Eqs. 7-9 with delta_in = (1 + b) m lambda.
  const double tension = v.tension, pressure = v.pressure;
  const double din_n = (1 + p.bn) * v.m_n;
  const double din_s = v.din_s;
  Vec3 q_s = Vec3::Zero(), q_k = Vec3::Zero();  // of q = |e| = tau/R
  Vec3 tau_s = Vec3::Zero();                    // d|tau|/dsigma
  if (tau > 0) tau_s = Vec3(0, t1 / tau, t2 / tau);
  if (R > 0) {
    q_s = tau_s * (S.alpha * S.alpha / (R * R * R));
    q_k = -(tau / (R * R)) * ratio * alpha_k;
  }
  // gI = <sigma_n> (1 + bn) m_n
  d.g_sigma.row(0) = tension * (1 + p.bn) * d.m_sigma.row(0);
  if (sn > 0) d.g_sigma(0, 0) += din_n;
  d.g_kappa.row(0) = tension * (1 + p.bn) * d.m_kappa.row(0);
  // gII = (|tau| - <-sigma_n> tan(phi)) (1 + bs) q
  const double A = tau - pressure * t;
  Vec3 A_s = tau_s;
  if (sn < 0) A_s[0] = t;
  const Vec3 A_k = -pressure * t_k;
  d.g_sigma.row(1) = (A_s * din_s + A * (1 + p.bs) * q_s).transpose();
  d.g_kappa.row(1) = (A_k * din_s + A * (1 + p.bs) * q_k).transpose();
  // gIII = <-sigma_n> (tan(phi) - tan(phir)) (1 + bs) q
  const double wear = t - M.tan_phir;
  Vec3 g3_s = pressure * wear * (1 + p.bs) * q_s;
  if (sn < 0) g3_s[0] -= wear * din_s;
  d.g_sigma.row(2) = g3_s.transpose();
  d.g_kappa.row(2) = (pressure * din_s * t_k + pressure * wear * (1 + p.bs) * q_k).transpose();
}

LocalDerivatives local_derivatives(const Model& M, const Vec3& sigma, const Vec3& kappa) {
  const Surface S = surface_of(M, kappa[0], kappa[1], kappa[2]);
  LocalDerivatives d;
  flow_of(M, sigma, S, Vec3::Ones(), &d);
  d.F = yield_function(sigma, S);
  return d;
}

}  // namespace mortar
