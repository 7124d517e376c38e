// What the mock solvers' mixed-control solves share: one increment per point
// solved on a COPY of the point's state at the start of the increment (the
// Caller's committed start, abi/caller.hpp), then committed. Each component
// is displacement- or traction-controlled (scenes/targets.hpp); the
// traction-controlled separations are the unknowns of a Newton iteration,
// whose linear system is solve_on_free below. The two solvers differ in where
// the Jacobian comes from and how a hard increment is rescued:
//  - solvers/mixed_control_solver.hpp, on any Caller (vuinteraction_'s block returns
//    no tangent): forward differences, backtracking, and bracketing of a
//    stalled component; through uinter_'s caller it gives the same curve
//    (tests/harness/solvers/test_mixed_control.cpp);
//  - solvers/implicit_solver.hpp, on uinter_'s caller: the routine's DDSDDR,
//    and Abaqus/Standard's cut-backs (PNEWDT, divergence, cycling).
#pragma once

#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "scenes/targets.hpp"

namespace mortar::harness {

struct MixedControlOptions {
  double traction_tolerance = 1e-9;  // |sigma_j - target_j| accepted [MPa], absolute
  int max_iterations = 40;           // Newton updates per increment
  int max_halvings = 30;             // backtracking halvings per update
  int max_doublings = 30;            // bracketing: growth of the search step, per direction
  int max_refinements = 200;         // bracketing: Illinois iterations
  int max_sweeps = 5;                // bracketing sweeps per point and increment
};

// A point after a committed increment (law signs: sigma_n > 0 tension).
struct PointResult {
  Eigen::Vector3d separation = Eigen::Vector3d::Zero();
  Eigen::Vector3d traction = Eigen::Vector3d::Zero();
  Eigen::Vector3d start_traction = Eigen::Vector3d::Zero();  // at the start of the last increment
  Eigen::Vector3d increment = Eigen::Vector3d::Zero();  // last committed separation increment
  double elastic_energy = 0;         // sed
  double dissipation_increment = 0;  // spd
  int iterations = 0;                // Newton updates of the last increment
  double traction_residual = 0;      // max over traction-controlled components [MPa]
};

// A call that failed or an increment that could not be solved; the message
// names the point (1-based), the increment and the reason.
class RunFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The size of a residual: its largest component [MPa].
inline double max_abs(const Eigen::Vector3d& v) { return v.cwiseAbs().maxCoeff(); }

// The Newton update's linear system on the free (traction-controlled)
// components F of the first n_dir: solves K_FF x_F = rhs_F, x = 0 elsewhere
// (identity rows there, so a point with few free components is not singular).
Eigen::Vector3d solve_on_free(const PointTargets& t, const Eigen::Matrix3d& K, const Eigen::Vector3d& rhs,
                              int n_dir = 3);

// "point 3, step 2, increment 17: " (point 0-based in, 1-based out).
std::string failure_location(int point, int step, long increment);

}  // namespace mortar::harness
