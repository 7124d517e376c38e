// Local problem of the backward-Euler return mapping (docs/model.md 7.5).
#include "mortar/return_mapping.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "mortar/surface.hpp"

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

LocalDerivatives local_derivatives(const Model& M, const Vec3& sigma, const Vec3& kappa) {
  const Parameters& p = M.p;
  const Surface S = surface_of(M, kappa[0], kappa[1], kappa[2]);
  LocalDerivatives d;
  // Values exactly as the explicit schemes see them.
  const Flow f = flow_of(M, sigma, S, Vec3::Ones());
  d.F = yield_function(sigma, S);
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
  const double tau = shear_norm(sigma);
  const double R = std::hypot(S.alpha, tau);
  const double ratio = R > 0 ? S.alpha / R : 1.0;  // dR/dalpha, as flow_of takes it at the apex

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
  d.m_sigma.block<2, 2>(1, 1) = e_tau;
  d.m_kappa.block<2, 3>(1, 0) = e_k;

  // Normal part: m_n = tan(psi) + (tan(phi) - tan(psi)) w, w = clamp(sigma_n/ft, 0, 1).
  const double ft = p.ft0 * S.s;
  double w = 0;
  if (sn > 0) w = ft > 0 ? std::min(1.0, sn / ft) : 1.0;
  const bool inner = sn > 0 && ft > 0 && sn < ft;
  const double w_sn = inner ? 1 / ft : 0.0;
  const Vec3 w_k = inner ? Vec3(-sn / (ft * ft) * p.ft0 * s_k) : Vec3::Zero();
  d.m_sigma(0, 0) = (t - tp) * w_sn;
  d.m_kappa.row(0) = (tp_k * (1 - w) + t_k * w + (t - tp) * w_k).transpose();

  // Works per unit lambda, Eqs. 7-9 with delta_in = (1 + b) m lambda.
  const double tension = std::max(sn, 0.0), pressure = std::max(-sn, 0.0);
  const double m_n = d.m[0];
  const double din_n = (1 + p.bn) * m_n;
  const double q = R > 0 ? tau / R : 0.0;  // |e|
  const double din_s = (1 + p.bs) * q;
  Vec3 q_s = Vec3::Zero(), q_k = Vec3::Zero();
  Vec3 tau_s = Vec3::Zero();  // d|tau|/dsigma
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
  return d;
}

Vec7 local_residual(const Model& M, const LocalProblem& lp, const Vec7& x, Mat7* jacobian) {
  Vec3 sigma = x.head<3>();
  Vec3 trial = lp.sigma_trial;
  if (lp.to_boundary) {
    sigma[0] = 0;
    trial = lp.sigma_start + x[0] * lp.k_dd;
  }
  const double dl = x[3];
  const Vec3 kappa = x.tail<3>();
  const LocalDerivatives d = local_derivatives(M, sigma, kappa);
  Vec7 r;
  r.head<3>() = sigma - trial + dl * lp.k_flow.cwiseProduct(d.m);
  r[3] = d.F;
  r.tail<3>() = kappa - lp.kappa_start - dl * d.g;
  if (jacobian) {
    Mat7& J = *jacobian;
    J.setZero();
    const Mat3 kf = lp.k_flow.asDiagonal();
    J.block<3, 3>(0, 0) = Mat3::Identity() + dl * kf * d.m_sigma;
    J.block<3, 1>(0, 3) = lp.k_flow.cwiseProduct(d.m);
    J.block<3, 3>(0, 4) = dl * kf * d.m_kappa;
    J.block<1, 3>(3, 0) = d.F_sigma.transpose();
    J.block<1, 3>(3, 4) = d.F_kappa.transpose();
    J.block<3, 3>(4, 0) = -dl * d.g_sigma;
    J.block<3, 1>(4, 3) = -d.g;
    J.block<3, 3>(4, 4) = Mat3::Identity() - dl * d.g_kappa;
    if (lp.to_boundary) {  // x[0] = theta: only the trial depends on it
      J.col(0).setZero();
      J.block<3, 1>(0, 0) = -lp.k_dd;
    }
    J = lp.row_scale.asDiagonal() * J;
  }
  return lp.row_scale.cwiseProduct(r);
}

namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
constexpr int kRows6[6] = {0, 1, 2, 4, 5, 6};  // every row and unknown but the consistency / dl

// For a fixed multiplier dl, solves the traction and work rows for (sigma,
// kappa) by Newton from x (updated in place). Well conditioned: the block is
// I + dl (...), the identity at dl = 0.
bool solve_at_multiplier(const Model& M, const LocalProblem& lp, Vec7& x, int& iterations) {
  for (int it = 0; it < 40; ++it) {
    Mat7 J;
    const Vec7 r = local_residual(M, lp, x, &J);
    Vec6 r6;
    Mat6 J6;
    for (int i = 0; i < 6; ++i) {
      r6[i] = r[kRows6[i]];
      for (int j = 0; j < 6; ++j) J6(i, j) = J(kRows6[i], kRows6[j]);
    }
    const double rn = r6.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(rn)) return false;
    if (rn <= 1e-13) return true;
    const Eigen::FullPivLU<Mat6> lu(J6);
    if (!lu.isInvertible()) return false;
    const Vec6 dy = -lu.solve(r6);
    double a = 1;
    bool accepted = false;
    for (int k = 0; k < 30 && !accepted; ++k, a *= 0.5) {
      Vec7 xt = x;
      for (int i = 0; i < 6; ++i) xt[kRows6[i]] += a * dy[i];
      const Vec7 rt = local_residual(M, lp, xt);
      double n6 = 0;
      for (int i = 0; i < 6; ++i) n6 = std::max(n6, std::abs(rt[kRows6[i]]));
      if (std::isfinite(n6) && n6 < rn) {
        x = xt;
        accepted = true;
      }
    }
    ++iterations;
    if (!accepted) return rn <= 1e-10;
  }
  return false;
}

// Scaled consistency residual F(sigma(dl), kappa(dl)) of the reduced problem.
bool reduced_yield(const Model& M, const LocalProblem& lp, double dl, Vec7& x, double& f, int& iterations) {
  x[3] = dl;
  if (!solve_at_multiplier(M, lp, x, iterations)) return false;
  f = local_residual(M, lp, x)[3];
  return std::isfinite(f);
}

// Bisection fallback: the yield function at the trial is positive (dl = 0);
// march dl up (doubling from the perfectly plastic estimate) until it turns
// negative, then close the bracket by regula falsi (Illinois) with bisection
// every third step. Returns a point near the root for Newton to polish.
bool bracket_multiplier(const Model& M, const LocalProblem& lp, const Vec7& trial, Vec7& x, int& iterations) {
  Vec7 lo_x = trial;
  double f_lo = 0;
  if (!reduced_yield(M, lp, 0.0, lo_x, f_lo, iterations) || !(f_lo > 0)) return false;
  const LocalDerivatives d = local_derivatives(M, trial.head<3>(), trial.tail<3>());
  const double slope = d.F_sigma.dot(lp.k_flow.cwiseProduct(d.m)) * lp.row_scale[3];
  double dl_hi = slope > 0 ? f_lo / slope : 1e-6 * M.stress_scale / std::max(lp.k_flow.maxCoeff(), 1e-300);
  if (!(dl_hi > 0) || !std::isfinite(dl_hi)) return false;
  double lo = 0, hi = 0, f_hi = 0;
  Vec7 hi_x = lo_x;
  bool found = false;
  for (int k = 0; k < 60 && !found; ++k, dl_hi *= 2) {
    Vec7 xt = lo_x;
    double ft = 0;
    if (!reduced_yield(M, lp, dl_hi, xt, ft, iterations)) return false;
    if (ft <= 0) {
      hi = dl_hi;
      f_hi = ft;
      hi_x = xt;
      found = true;
    } else {
      lo = dl_hi;
      f_lo = ft;
      lo_x = xt;
    }
  }
  if (!found) return false;
  for (int k = 0; k < 100; ++k) {
    if (f_hi == 0 || hi - lo <= 1e-12 * hi) break;
    double dl = (k % 3 == 2) ? 0.5 * (lo + hi) : hi - f_hi * (hi - lo) / (f_hi - f_lo);
    if (!(dl > lo && dl < hi)) dl = 0.5 * (lo + hi);
    Vec7 xt = f_lo > -f_hi ? hi_x : lo_x;
    double ft = 0;
    if (!reduced_yield(M, lp, dl, xt, ft, iterations)) return false;
    if (std::abs(ft) <= 1e-13) {
      hi_x = xt;
      break;
    }
    if (ft > 0) {
      lo = dl;
      f_lo = ft;
      lo_x = xt;
      f_hi *= 0.5;  // Illinois: keep the stale end from stalling the secant
    } else {
      hi = dl;
      f_hi = ft;
      hi_x = xt;
      f_lo *= 0.5;
    }
  }
  x = hi_x;
  return true;
}

LocalSolution newton(const Model& M, const LocalProblem& lp, const Vec7& guess, double tolerance,
                     int max_iterations);

}  // namespace

Vec7 trial_point(const LocalProblem& lp) {
  Vec7 x;
  if (lp.to_boundary) {
    x << lp.theta_guess, (lp.sigma_start + lp.theta_guess * lp.k_dd).tail<2>(), 0.0, lp.kappa_start;
  } else {
    x << lp.sigma_trial, 0.0, lp.kappa_start;
  }
  return x;
}

LocalSolution solve_local(const Model& M, const LocalProblem& lp, double tolerance, const Vec7* predictor,
                          int max_iterations) {
  // A negative multiplier is not a plastic solution (works and damage would
  // decrease): such a root counts as a failure of that start.
  auto plastic = [](const LocalSolution& s) { return s.converged && s.x[3] >= 0; };
  int iterations = 0;
  LocalSolution out;
  if (predictor) {
    out = newton(M, lp, *predictor, tolerance, max_iterations);
    iterations += out.iterations;
    if (plastic(out)) {
      out.iterations = iterations;
      return out;
    }
  }
  // The classical start of a return mapping: the trial point (dl = 0, works
  // unchanged), whose first iteration is the consistent linearisation there.
  const Vec7 trial = trial_point(lp);
  out = newton(M, lp, trial, tolerance, max_iterations);
  iterations += out.iterations;
  if (!plastic(out) && !lp.to_boundary) {
    // A trial far beyond a small surface (late softening, s << 1) returns to
    // near the tip of the hyperbola, sigma = (ft, 0, 0): start there, with
    // dl from the normal row (m_n = tan(phi) at the tip) and the shear
    // returned radially with R = alpha.
    const Surface S = surface_of(M, lp.kappa_start[0], lp.kappa_start[1], lp.kappa_start[2]);
    const double ft = M.p.ft0 * S.s;
    if (ft > 0 && lp.sigma_trial[0] > ft && lp.k_flow[0] > 0) {
      const double dl = (lp.sigma_trial[0] - ft) / (lp.k_flow[0] * S.tan_phi);
      const Vec3 shear(0, lp.sigma_trial[1], lp.sigma_trial[2]);
      const Vec3 tip = Vec3(ft, 0, 0) + shear / (1 + dl * lp.k_flow[1] / std::max(S.alpha, 1e-300));
      const LocalDerivatives d = local_derivatives(M, tip, lp.kappa_start);
      Vec7 x;
      x << tip, dl, lp.kappa_start + dl * d.g;
      if (x.allFinite()) {
        out = newton(M, lp, x, tolerance, max_iterations);
        iterations += out.iterations;
      }
    }
  }
  if (!plastic(out)) {
    // Newton failed (typically a nearly singular Jacobian where the
    // consistency denominator is close to zero, or a kink in the way):
    // bracket the multiplier on the reduced problem, then polish.
    Vec7 x;
    if (bracket_multiplier(M, lp, trial, x, iterations)) {
      out = newton(M, lp, x, tolerance, max_iterations);
      iterations += out.iterations;
    }
  }
  out.converged = plastic(out);
  out.iterations = iterations;
  return out;
}

namespace {

double softening_raw(const Model& M, const Vec7& x) { return 1.0 - x[4] / M.p.GIC - x[5] / M.p.GIIC; }

// Bounds the solution satisfies: dl >= 0, and wI, wIII never below their
// start values (gI, gIII >= 0, Eqs. 7 and 9). Iterates are projected onto
// them: an iterate with a negative wear work, say, blows up exp(-n wIII) in
// tan(psi) and derails the iteration (large increments, small surfaces).
Vec7 project(const LocalProblem& lp, Vec7 x) {
  x[3] = std::max(x[3], 0.0);
  x[4] = std::max(x[4], lp.kappa_start[0]);
  x[6] = std::max(x[6], lp.kappa_start[2]);
  if (lp.to_boundary) x[0] = std::clamp(x[0], 0.0, 1.0);
  return x;
}

LocalSolution newton(const Model& M, const LocalProblem& lp, const Vec7& guess, double tolerance,
                     int max_iterations) {
  constexpr double kTight = 1e-12;  // what Newton reaches in a few iterations when it converges
  constexpr double kArmijo = 1e-4;
  constexpr int kMaxHalvings = 30;
  LocalSolution out;
  Vec7 x = project(lp, guess);
  Mat7 J;
  Vec7 r = local_residual(M, lp, x, &J);
  double rn = r.allFinite() ? r.lpNorm<Eigen::Infinity>() : INFINITY;
  double previous = INFINITY;
  for (int it = 0;; ++it) {
    out.iterations = it;
    if (!std::isfinite(rn)) return out;
    // Converged: tight, or within the tolerance once the residual stagnates
    // at round-off (it no longer falls by a factor of 4 per iteration).
    if (rn <= kTight || (rn <= tolerance && rn > 0.25 * previous)) {
      out.x = x;
      out.jacobian = J;
      out.residual = rn;
      out.converged = true;
      return out;
    }
    if (it >= max_iterations) return out;
    // Full pivoting: the Jacobian mixes rows of very different origin
    // (traction, consistency, works); fixed size, so nothing is allocated.
    const Eigen::FullPivLU<Mat7> lu(J);
    if (!lu.isInvertible()) return out;
    const Vec7 dx = -lu.solve(r);
    if (!dx.allFinite()) return out;
    // Backtracking on phi = 1/2 |r|^2: along the Newton direction the slope
    // of phi is -|r|^2, so Armijo asks phi(x + a dx) <= (1 - 2 c a) phi(x).
    const double phi = 0.5 * r.squaredNorm();
    double a = 1;
    // Fraction to the boundary on the softening factor (Eqs. 4-5): with
    // s > 0 at the start, the backward-Euler solution keeps s > 0 (the work
    // rates vanish with s, so s_end = s_start / (1 + x)); a Newton iterate
    // that jumps past s = 0 lands on the kink of max(0, s), where dF/dw
    // vanishes and the line search stalls. Let s fall by at most 90 % per
    // iteration instead.
    const double sr = softening_raw(M, x), dsr = softening_raw(M, x + dx) - sr;
    if (sr > 0 && sr + dsr < 0.1 * sr) a = 0.9 * sr / -dsr;
    bool accepted = false;
    for (int k = 0; k < kMaxHalvings; ++k) {
      const Vec7 xt = project(lp, x + a * dx);
      Mat7 Jt;
      const Vec7 rt = local_residual(M, lp, xt, &Jt);
      if (rt.allFinite() && 0.5 * rt.squaredNorm() <= (1 - 2 * kArmijo * a) * phi) {
        x = xt;
        r = rt;
        J = Jt;
        accepted = true;
        break;
      }
      a *= 0.5;
    }
    if (!accepted) {
      // No descent left along the Newton direction: at round-off this is
      // convergence, otherwise a failure (the caller substeps).
      if (rn <= tolerance) {
        out.x = x;
        out.jacobian = J;
        out.residual = rn;
        out.converged = true;
      }
      return out;
    }
    previous = rn;
    rn = r.lpNorm<Eigen::Infinity>();
  }
}

}  // namespace

}  // namespace mortar
