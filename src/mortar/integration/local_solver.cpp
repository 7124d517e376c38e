// Newton's method for the local problem of the backward-Euler step, with the
// starts and the bracketing fallback of solve_local() (docs/model.md 7.5).
#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "mortar/integration/local_problem.hpp"

namespace mortar {

namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
// Every row and unknown but the consistency row and the multiplier.
constexpr int kRows6[6] = {unknown::sigma_n, unknown::tau_1, unknown::tau_2,
                           unknown::work_I,  unknown::work_II, unknown::work_III};

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
  x[unknown::multiplier] = dl;
  if (!solve_at_multiplier(M, lp, x, iterations)) return false;
  f = local_residual(M, lp, x)[unknown::multiplier];
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
  const LocalUnknowns t = LocalUnknowns::of(trial);
  const LocalDerivatives d = local_derivatives(M, t.sigma, t.kappa);
  const double slope = d.F_sigma.dot(lp.k_flow.cwiseProduct(d.m)) * lp.row_scale[unknown::multiplier];
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

LocalSolution solve_local(const Model& M, const LocalProblem& lp, double tolerance, const Vec7* predictor,
                          int max_iterations) {
  // A negative multiplier is not a plastic solution (works and damage would
  // decrease): such a root counts as a failure of that start.
  auto plastic = [](const LocalSolution& s) { return s.converged && s.x[unknown::multiplier] >= 0; };
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
      const Vec7 x = LocalUnknowns{tip, dl, lp.kappa_start + dl * d.g}.vector();
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

double softening_raw(const Model& M, const Vec7& x) {
  return 1.0 - x[unknown::work_I] / M.p.GIC - x[unknown::work_II] / M.p.GIIC;
}

// Bounds the solution satisfies: dl >= 0, and wI, wIII never below their
// start values (gI, gIII >= 0, Eqs. 7 and 9). Iterates are projected onto
// them: an iterate with a negative wear work, say, blows up exp(-n wIII) in
// tan(psi) and derails the iteration (large increments, small surfaces).
Vec7 project(const LocalProblem& lp, Vec7 x) {
  using namespace unknown;
  x[multiplier] = std::max(x[multiplier], 0.0);
  x[work_I] = std::max(x[work_I], lp.kappa_start[0]);
  x[work_III] = std::max(x[work_III], lp.kappa_start[2]);
  if (lp.to_boundary) x[theta] = std::clamp(x[theta], 0.0, 1.0);
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
