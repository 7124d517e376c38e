#include "mortar/integration/sensitivity.hpp"

#include <cmath>

#include <Eigen/LU>

#include "mortar/physics/compression_cap.hpp"
#include "mortar/physics/norms.hpp"

namespace mortar {

using Mat73 = Eigen::Matrix<double, 7, 3>;

void secant_sensitivity(const Model& M, const State& y, Sensitivity& D) {
  const Vec3 K = secant_stiffness(M, y.dn, y.ds, y.open);
  D.sigma = K.asDiagonal() * (D.separation - D.plastic);
  if (y.open) {
    const Vec3 e = y.elastic_separation();
    D.sigma.row(0) -= M.p.kn * e[0] * D.damage.row(0);
    D.sigma.row(1) -= M.p.ks * e[1] * D.damage.row(1);
    D.sigma.row(2) -= M.p.ks * e[2] * D.damage.row(1);
  }
}

void settle_sensitivity(const Model& M, const State& pre, const Vec3& sigma, const State& post, Sensitivity& D) {
  // Zero elastic slip (pure opening): settle() leaves d_s alone, but for any
  // slip perturbation the secant damage jumps to its directional limit
  // 1 - (d tau/d slip)/(ks d delta_e_s/d slip), the same in every direction
  // of the plane; the traction that follows is the step's own tau (unclamped
  // limit), the old secant (limit below d_old) or zero (limit at 1).
  enum class ShearLimit { none, step, zero } shear_limit = ShearLimit::none;
  Eigen::Matrix<double, 2, 3> step_shear = D.sigma.bottomRows<2>();
  if (pre.open) {
    const Vec3 e = pre.elastic_separation();
    const Mat3 De = D.separation - D.plastic;
    const double es = hypot_of(e[1], e[2]);  // as settle() measures the elastic slip
    if (es == 0 && De(1, 1) > 0 && post.ds < 1) {
      const double raw = 1.0 - D.sigma(1, 1) / (M.p.ks * De(1, 1));
      if (raw >= 1) shear_limit = ShearLimit::zero;
      else if (!(raw < pre.ds)) shear_limit = ShearLimit::step;
    }
    if (e[0] > 0) {
      const double k = M.p.kn * e[0];
      const double raw = 1.0 - sigma[0] / k;
      if (raw >= 1) D.damage.row(0).setZero();
      else if (!(raw < pre.dn)) D.damage.row(0) = -D.sigma.row(0) / k + (sigma[0] / (k * e[0])) * De.row(0);
    }
    if (es > 0) {
      const double tau = shear_norm(sigma);
      const double k = M.p.ks * es;
      const double raw = 1.0 - tau / k;
      if (raw >= 1) {
        D.damage.row(1).setZero();
      } else if (!(raw < pre.ds)) {
        Eigen::RowVector3d dtau = Eigen::RowVector3d::Zero();
        if (tau > 0) dtau = (sigma[1] * D.sigma.row(1) + sigma[2] * D.sigma.row(2)) / tau;
        const Eigen::RowVector3d des = (e[1] * De.row(1) + e[2] * De.row(2)) / es;
        D.damage.row(1) = -dtau / k + (tau / (k * es)) * des;
      }
    }
    if (post.dn >= 1) D.damage.row(0).setZero();
    if (post.ds >= 1) D.damage.row(1).setZero();
  }
  secant_sensitivity(M, post, D);
  if (shear_limit == ShearLimit::step) D.sigma.bottomRows<2>() = step_shear;
  if (shear_limit == ShearLimit::zero) D.sigma.bottomRows<2>().setZero();
}

Sensitivity backward_euler_sensitivity(const Model& M, const Point& P, const Vec3& dd, const BackwardEulerStep& b,
                                       const Sensitivity& DP, const Mat3& Ddd) {
  Sensitivity D = DP;
  D.separation = DP.separation + Ddd;
  if (!b.plastic) {
    secant_sensitivity(M, b.N.y, D);
    return D;
  }
  // The step's stiffnesses depend on P's state (rate_stiffness_over): a
  // component on the secant k (1 - d) (frozen, or the normal closing against
  // its elastic opening) through the damage at P; the growing shear's drop
  // across the elastic slip through ds and the slip's direction at P.
  Mat3 Dsep = Mat3::Zero(), Dflow = Mat3::Zero();  // of kS o dd and of kF
  if (P.y.open) {
    const Vec3 e = P.y.elastic_separation();
    if (P.y.dn < 1 && (!b.grow_n || (dd[0] < 0 && e[0] > 0))) Dsep.row(0) = -M.p.kn * dd[0] * DP.damage.row(0);
    if (!b.grow_n && P.y.dn < 1) Dflow.row(0) = -M.p.kn * DP.damage.row(0);
    if (!b.grow_s && P.y.ds < 1) {
      for (int i = 1; i < 3; ++i) {
        Dsep.row(i) = -M.p.ks * dd[i] * DP.damage.row(1);
        Dflow.row(i) = -M.p.ks * DP.damage.row(1);
      }
    }
    if (b.k.across_drop > 0) {
      const Eigen::Vector2d u(b.k.axis[0], b.k.axis[1]), v(dd[1], dd[2]);
      const Eigen::Matrix<double, 2, 3> De = (DP.separation - DP.plastic).bottomRows<2>();
      const Eigen::Matrix<double, 2, 3> Du = (Eigen::Matrix2d::Identity() - u * u.transpose()) * De / hypot_of(e[1], e[2]);
      const double vu = v.dot(u);
      Dsep.bottomRows<2>() += -M.p.ks * (v - vu * u) * DP.damage.row(1) +
                              b.k.across_drop * (u * (v.transpose() * Du) + vu * Du);
    }
  }
  const double dl = b.solution.unknowns().dl;
  const Mat3 Dtrial = DP.sigma + b.k.separation_matrix() * Ddd + Dsep;
  Mat73 B = Mat73::Zero();
  B.middleRows<3>(unknown::sigma_n) = -Dtrial + dl * b.end.m.asDiagonal() * Dflow;
  B.middleRows<3>(unknown::work_I) = -DP.kappa;
  B = b.problem.row_scale.asDiagonal() * B;
  const Mat73 Dx = -Eigen::FullPivLU<Mat7>(b.solution.jacobian).solve(B);
  D.sigma = Dx.middleRows<3>(unknown::sigma_n);
  D.kappa = Dx.middleRows<3>(unknown::work_I);
  const Eigen::RowVector3d Ddl = Dx.row(unknown::multiplier);
  const Mat3 Dm = b.end.m_sigma * D.sigma + b.end.m_kappa * D.kappa;
  D.plastic = DP.plastic + b.end.m * Ddl + dl * Dm;
  return D;
}

void intersection_sensitivity(const Model& M, const State& y, const Vec3& sigma, double a, const Vec3& rest,
                              const Vec3& K, Sensitivity& D, bool on_cap) {
  D.separation += a * (Mat3::Identity() - D.separation);
  secant_sensitivity(M, y, D);  // at fixed a
  const Vec3 k_rest = K.cwiseProduct(rest);
  // dF = F_sigma . D sigma + (the hardening's part), F of the surface met.
  Vec3 F_sigma;
  Eigen::RowVector3d dF_hardening;
  if (on_cap) {
    F_sigma = cap_gradient(M, sigma);
    dF_hardening = -cap_strength(M, y.kappa_c).slope * D.kappa_c;
  } else {
    const LocalDerivatives ld = local_derivatives(M, sigma, Vec3(y.wI, y.wII, y.wIII));
    F_sigma = ld.F_sigma;
    dF_hardening = ld.F_kappa.transpose() * D.kappa;
  }
  const double slope = F_sigma.dot(k_rest);
  if (!(std::abs(slope) > 0)) return;
  const Eigen::RowVector3d da = -(F_sigma.transpose() * D.sigma + dF_hardening) / slope;
  D.separation += rest * da;
  D.sigma += k_rest * da;
}

}  // namespace mortar
