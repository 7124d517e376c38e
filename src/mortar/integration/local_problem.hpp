// The local problem of one backward-Euler step (docs/model.md 7.5): its
// named unknowns, residual and analytic Jacobian, and the Newton solver with
// its fallbacks (local_solver.cpp).
#pragma once

#include <Eigen/Core>

#include "mortar/parameters.hpp"
#include "mortar/physics/yield_surface.hpp"
#include "mortar/state.hpp"

namespace mortar {

using Vec7 = Eigen::Matrix<double, 7, 1>;
using Mat7 = Eigen::Matrix<double, 7, 7>;

// Positions of the unknowns in Newton's vector, and of the residual rows
// (row i is the equation that fixes unknown i): the one mapping between the
// named unknowns and the Eigen vector.
namespace unknown {
enum : int {
  sigma_n = 0, tau_1 = 1, tau_2 = 2,  // end traction (rows: the rate statement)
  theta = 0,                          // the boundary step: the fraction of dd in place of sigma_n (= 0)
  multiplier = 3,                     // dl (row: consistency, F = 0)
  work_I = 4, work_II = 5, work_III = 6,  // end works kappa (rows: Eqs. 7-9)
  count = 7
};
}  // namespace unknown

// The unknowns by name.
struct LocalUnknowns {
  Vec3 sigma = Vec3::Zero();  // end traction; on the boundary step sigma[0] holds theta
  double dl = 0;              // plastic multiplier increment
  Vec3 kappa = Vec3::Zero();  // end works (wI, wII, wIII)

  static LocalUnknowns of(const Vec7& x) {
    return {x.segment<3>(unknown::sigma_n), x[unknown::multiplier], x.segment<3>(unknown::work_I)};
  }
  Vec7 vector() const {
    Vec7 x;
    x.segment<3>(unknown::sigma_n) = sigma;
    x[unknown::multiplier] = dl;
    x.segment<3>(unknown::work_I) = kappa;
    return x;
  }
};

// One backward-Euler step of the rate statement (docs/model.md 6) from a
// point P over the separation increment dd, in a fixed regime and on fixed
// branches of the open regime:
//
//   sigma = sigma_P + k_sep o dd - dl k_flow o m(sigma, kappa)     (Eq. 16-17, end-point flow)
//   F(sigma, kappa) = 0                                            (Eq. 2, consistency at the end)
// The rest: docs/numerics.md, section 4.
struct LocalProblem {
  Vec3 sigma_trial = Vec3::Zero();  // sigma_P + k_sep o dd
  Vec3 k_flow = Vec3::Zero();       // stiffness multiplying m dl (rate_stiffness().on_flow)
  Vec3 kappa_start = Vec3::Zero();  // works at P
  // Row scales of the residual (set by make_local_problem): the residual is
  // dimensionless, so one norm measures convergence of all rows.
  Vec7 row_scale = Vec7::Ones();
  // The step that ends on the regime boundary (sigma_n = 0 at the end, i.e.
  // delta_e_n = 0): the unknown theta is then the fraction of the step, not
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

// The start of Newton at the trial point (dl = 0, works unchanged).
Vec7 trial_point(const LocalProblem& lp);

// Scaled residual of the local problem at x, and optionally its analytic
// Jacobian d residual / d x.
Vec7 local_residual(const Model& M, const LocalProblem& lp, const Vec7& x, Mat7* jacobian = nullptr);

// Solves the local problem for a root with dl >= 0. Newton's method with a
// backtracking (Armijo) line search on 1/2 |r|^2, converged when the scaled
// residual is below 1e-12, or below `tolerance` once it stops falling
// (round-off). Starts, in turn, until one converges:
// The rest: docs/numerics.md, section 5.
struct LocalSolution {
  Vec7 x = Vec7::Zero();
  Mat7 jacobian = Mat7::Zero();  // at x (for the consistent tangent)
  double residual = 0;           // max-norm of the scaled residual at x
  int iterations = 0;
  bool converged = false;
  LocalUnknowns unknowns() const { return LocalUnknowns::of(x); }
};
LocalSolution solve_local(const Model& M, const LocalProblem& lp, double tolerance, const Vec7* predictor = nullptr,
                          int max_iterations = 50);

}  // namespace mortar
