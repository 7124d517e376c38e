// Backward-Euler (implicit) return mapping of the mortar-joint law, MODEL.md
// section 7.3: the local problem of one plastic substep, its residual, the
// analytic Jacobian, and the Newton solver with a backtracking line search.
// The substepping, the regime logic and the consistent tangent of the whole
// increment live in integrator.cpp (Stepper::plastic_implicit); the
// derivation is in docs/model.md section 7.5.
#pragma once

#include <Eigen/Core>

#include "mortar/parameters.hpp"
#include "mortar/state.hpp"

namespace mortar {

using Mat3 = Eigen::Matrix3d;
using Vec7 = Eigen::Matrix<double, 7, 1>;
using Mat7 = Eigen::Matrix<double, 7, 7>;

// One backward-Euler step of the rate statement (docs/model.md section 6)
// from a point P over the separation increment dd, in a fixed regime and on
// fixed branches of the open regime:
//
//   sigma = sigma_P + k_sep o dd - dl k_flow o m(sigma, kappa)     (Eq. 16-17, end-point flow)
//   F(sigma, kappa) = 0                                            (Eq. 2, consistency at the end)
//   kappa = kappa_P + dl g(sigma, kappa)                           (Eqs. 7-9 at the end point)
//
// with kappa = (wI, wII, wIII), m the flow direction of Eq. 10 (regularised,
// normal part blended; surface.hpp flow_of) and g the works per unit lambda.
// Unknowns x = (sigma_n, tau_1, tau_2, dl, wI, wII, wIII).
struct LocalProblem {
  Vec3 sigma_trial = Vec3::Zero();  // sigma_P + k_sep o dd
  Vec3 k_flow = Vec3::Zero();       // stiffness multiplying m dl (rate_stiffness().on_flow)
  Vec3 kappa_start = Vec3::Zero();  // works at P
  // Row scales of the residual (set by make_local_problem): the residual is
  // dimensionless, so one norm measures convergence of all rows.
  Vec7 row_scale = Vec7::Ones();
  // The step that ends on the regime boundary (sigma_n = 0 at the end, i.e.
  // delta_e_n = 0): x[0] is then the fraction theta of the step, not
  // sigma_n, and the trial is sigma_start + theta k_dd.
  bool to_boundary = false;
  Vec3 sigma_start = Vec3::Zero();
  Vec3 k_dd = Vec3::Zero();   // k_sep o dd
  double theta_guess = 1;     // start of Newton for theta
};

// Sets the trial, stiffness, start works and row scales: traction rows and
// the consistency row by max(|sigma_trial|, |sigma_P|, ft0); the works by
// their own scales (GIC, GIIC, and 1/max(m, n) for the wear work, each at
// least the start value so that a large accumulated work is compared
// relatively).
LocalProblem make_local_problem(const Model& M, const Vec3& sigma_start, const Vec3& sigma_trial,
                                const Vec3& k_flow, const Vec3& kappa_start);
// The problem of the step that ends on the regime boundary: the part theta
// of the step dd (k_dd = k_sep o dd) after which sigma_n = 0.
LocalProblem make_boundary_problem(const Model& M, const Vec3& sigma_start, const Vec3& k_dd, const Vec3& k_flow,
                                   const Vec3& kappa_start);

// Yield function, flow direction and works per unit lambda at (sigma, kappa)
// with their derivatives. Values are those of surface.hpp (yield_function,
// flow_of); derivatives are one-sided at the kinks (sigma_n = 0, sigma_n =
// ft, s = 0) and zero where the subgradient is taken (apex, tau = 0).
struct LocalDerivatives {
  double F = 0;
  Vec3 F_sigma = Vec3::Zero(), F_kappa = Vec3::Zero();
  Vec3 m = Vec3::Zero();
  Mat3 m_sigma = Mat3::Zero(), m_kappa = Mat3::Zero();  // d m_i / d sigma_j, d m_i / d kappa_j
  Vec3 g = Vec3::Zero();
  Mat3 g_sigma = Mat3::Zero(), g_kappa = Mat3::Zero();
};
LocalDerivatives local_derivatives(const Model& M, const Vec3& sigma, const Vec3& kappa);

// Scaled residual of the local problem at x, and optionally its analytic
// Jacobian d residual / d x.
Vec7 local_residual(const Model& M, const LocalProblem& lp, const Vec7& x, Mat7* jacobian = nullptr);

// Solves the local problem for a root with dl >= 0. Newton's method with a
// backtracking (Armijo) line search on 1/2 |r|^2, converged when the scaled
// residual is below 1e-12, or below `tolerance` once it stops falling
// (round-off). Starts, in turn, until one converges:
//   1. from `predictor` if given (the integrator passes the forward-Euler
//      predictor, O(dd^2) from the solution on a smooth path);
//   2. from the trial point (sigma_trial, dl = 0, kappa_start);
//   3. bisection fallback: the multiplier bracketed on the reduced problem
//      f(dl) = F(sigma(dl), kappa(dl)), the traction and work rows solved for
//      fixed dl, f(0) > 0 marched up to a sign change and closed by regula
//      falsi with bisection; then Newton again from there.
// `iterations` counts every Newton iteration, inner ones included.
struct LocalSolution {
  Vec7 x = Vec7::Zero();
  Mat7 jacobian = Mat7::Zero();  // at x (for the consistent tangent)
  double residual = 0;           // max-norm of the scaled residual at x
  int iterations = 0;
  bool converged = false;
};
LocalSolution solve_local(const Model& M, const LocalProblem& lp, double tolerance, const Vec7* predictor = nullptr,
                          int max_iterations = 50);

}  // namespace mortar
