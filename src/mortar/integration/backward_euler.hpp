// The backward-Euler step of the implicit scheme (docs/model.md 7.5): one
// step of the rate statement with end-point flow and works, on the branches
// of the open regime the explicit stage() would take, and the closed-regime
// step that ends on the regime boundary.
#pragma once

#include "mortar/integration/point.hpp"
#include "mortar/result.hpp"
#include "mortar/integration/local_problem.hpp"

namespace mortar {

// One backward-Euler step of the rate statement from P over dd.
struct BackwardEulerStep {
  bool ok = false;
  bool plastic = false;
  Point N;                  // the end point, before settle()
  LocalProblem problem;     // when plastic: the problem that was solved
  LocalSolution solution;
  LocalDerivatives end;     // flow and works at the end point
  RateStiffness k{Vec3::Zero(), Vec3::Zero()};  // branch stiffnesses used
  bool grow_n = true, grow_s = true;
};

// One step from P over dd: elastic (the secant trial stays inside, or the
// rate statement unloads), plastic (the local problem solved on the branches
// of stage()), or not ok when the local solve failed (the caller halves).
// Without stage_branches the growing branches come first and one freeze pass
// follows (the apex zone's steps of the explicit schemes, docs/model.md 7.5).
BackwardEulerStep backward_euler(const Model& M, const Point& P, const Vec3& dd, IntegrationStatus& st,
                                 bool stage_branches = true);

// N (P with its separation moved) at the end of a plastic step of Eq. 2:
// traction sigma, plastic increment dp (crack by Eq. 17), works kappa, the
// dissipation trapezoidal in the traction.
void end_plastic_step(const Model& M, const Point& P, Point& N, const Vec3& sigma, const Vec3& dp,
                      const Vec3& kappa);

// The closed-regime step that ends on the regime boundary delta_e_n = 0
// (sigma_n = 0): the part theta of dd after which the backward-Euler end point
// has zero normal traction. Used where a closed step whose trial is tensile
// has no solution in the closed regime: on the fully softened cone (s = 0)
// every admissible point has sigma_n <= 0, so a step that opens the joint
// cannot end in the closed regime, and the crossing bracket never sees a
// crossing point. Returns ok with N = the boundary point and `theta` set, or
// not ok.
struct BoundaryStep {
  bool ok = false;
  double theta = 0;
  Point N;
};
BoundaryStep backward_euler_to_boundary(const Model& M, const Point& P, const Vec3& dd, IntegrationStatus& st);

}  // namespace mortar
