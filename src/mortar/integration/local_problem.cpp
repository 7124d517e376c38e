#include "mortar/integration/local_problem.hpp"

#include <algorithm>
#include <cmath>

namespace mortar {

LocalProblem make_local_problem(const Model& M, const Vec3& sigma_start, const Vec3& sigma_trial,
                                const Vec3& k_flow, const Vec3& kappa_start) {
  LocalProblem lp;
  lp.sigma_trial = sigma_trial;
  lp.k_flow = k_flow;
  lp.kappa_start = kappa_start;
  const double stress = std::max({sigma_trial.norm(), sigma_start.norm(), M.stress_scale});
  // The wear work enters only through exp(-m wIII) and exp(-n wIII): its
  // natural scale is 1/max(m, n); with m = n = 0 it does not matter at all.
  const double wear_rate = std::max(M.p.m, M.p.n);
  const double wear = wear_rate > 0 ? 1.0 / wear_rate : M.p.GIIC;
  lp.row_scale << 1 / stress, 1 / stress, 1 / stress, 1 / stress,
      1 / std::max(M.p.GIC, std::abs(kappa_start[0])), 1 / std::max(M.p.GIIC, std::abs(kappa_start[1])),
      1 / std::max(wear, std::abs(kappa_start[2]));
  return lp;
}

LocalProblem make_boundary_problem(const Model& M, const Vec3& sigma_start, const Vec3& k_dd, const Vec3& k_flow,
                                   const Vec3& kappa_start) {
  LocalProblem lp = make_local_problem(M, sigma_start, sigma_start + k_dd, k_flow, kappa_start);
  lp.to_boundary = true;
  lp.sigma_start = sigma_start;
  lp.k_dd = k_dd;
  // Where the elastic normal traction reaches zero.
  lp.theta_guess = k_dd[0] != 0 ? std::clamp(-sigma_start[0] / k_dd[0], 0.0, 1.0) : 1.0;
  return lp;
}

Vec7 local_residual(const Model& M, const LocalProblem& lp, const Vec7& x, Mat7* jacobian) {
  using namespace unknown;
  const LocalUnknowns u = LocalUnknowns::of(x);
  Vec3 sigma = u.sigma;
  Vec3 trial = lp.sigma_trial;
  if (lp.to_boundary) {
    sigma[0] = 0;
    trial = lp.sigma_start + x[theta] * lp.k_dd;
  }
  const double dl = u.dl;
  const Vec3 kappa = u.kappa;
  const LocalDerivatives d = local_derivatives(M, sigma, kappa);
  Vec7 r;
  r.segment<3>(sigma_n) = sigma - trial + dl * lp.k_flow.cwiseProduct(d.m);
  r[multiplier] = d.F;
  r.segment<3>(work_I) = kappa - lp.kappa_start - dl * d.g;
  if (jacobian) {
    Mat7& J = *jacobian;
    J.setZero();
    const Mat3 kf = lp.k_flow.asDiagonal();
    J.block<3, 3>(sigma_n, sigma_n) = Mat3::Identity() + dl * kf * d.m_sigma;
    J.block<3, 1>(sigma_n, multiplier) = lp.k_flow.cwiseProduct(d.m);
    J.block<3, 3>(sigma_n, work_I) = dl * kf * d.m_kappa;
    J.block<1, 3>(multiplier, sigma_n) = d.F_sigma.transpose();
    J.block<1, 3>(multiplier, work_I) = d.F_kappa.transpose();
    J.block<3, 3>(work_I, sigma_n) = -dl * d.g_sigma;
    J.block<3, 1>(work_I, multiplier) = -d.g;
    J.block<3, 3>(work_I, work_I) = Mat3::Identity() - dl * d.g_kappa;
    if (lp.to_boundary) {  // only the trial depends on theta
      J.col(theta).setZero();
      J.block<3, 1>(sigma_n, theta) = -lp.k_dd;
    }
    J = lp.row_scale.asDiagonal() * J;
  }
  return lp.row_scale.cwiseProduct(r);
}

Vec7 trial_point(const LocalProblem& lp) {
  LocalUnknowns u;
  if (lp.to_boundary) {
    u.sigma << lp.theta_guess, (lp.sigma_start + lp.theta_guess * lp.k_dd).tail<2>();
  } else {
    u.sigma = lp.sigma_trial;
  }
  u.dl = 0.0;
  u.kappa = lp.kappa_start;
  return u.vector();
}

}  // namespace mortar
