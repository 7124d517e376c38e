// The mixed-control solver: one increment of a group of points (a block of
// vuinteraction_, or uinter_'s point) through a Caller (abi/caller.hpp). Each
// component of each point is either displacement-controlled (its separation
// at the end of the increment is given) or traction-controlled (its traction
// at the end of the increment is given and its separation increment is
// unknown). The unknown increments are found the way an implicit solver
// finds them: Newton iterations with a forward-difference Jacobian and
// backtracking, every trial a call from the committed start of the
// increment; the converged trial is then committed. `--solver explicit` runs
// it over blocks of vuinteraction_ (solvers/explicit_run.hpp).
//
// Every decision (convergence, step length, fall-backs) is taken per point
// from that point's own numbers, so a point's result does not depend on the
// block it is in or on its neighbours (invariant 8, block invariance: docs/model.md 10).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "abi/caller.hpp"
#include "abi/vuinteraction_call.hpp"
#include "solvers/mixed_control.hpp"

namespace mortar::harness {

class MixedControlSolver {
 public:
  // Points first_point .. first_point + n_points - 1 of the scene through
  // vuinteraction_ (abi/vuinteraction_caller.hpp).
  MixedControlSolver(const AbiSetup& setup, int first_point, int n_points, const MixedControlOptions& options);
  // Through any caller; `elastic_stiffness` (kn, ks, ks) is the fall-back Jacobian.
  MixedControlSolver(std::unique_ptr<Caller> caller, int first_point, const Eigen::Vector3d& elastic_stiffness,
              const MixedControlOptions& options);

  int size() const { return caller_->size(); }
  int first_point() const { return first_point_; }

  // Abaqus's first sight of the points: zero penetration, zero slip; the
  // routine takes this as the reference state. Committed.
  void reference_call(const CallTime& info);

  // Solves one increment for every point (targets[k] for point k of the
  // block) and commits it. Throws RunFailure.
  void advance(const PointTargets* targets, const CallTime& info);

  const PointResult& result(int k) const { return results_[k]; }
  const double* state(int k) const { return caller_->state(k); }
  long calls() const { return calls_; }

 private:
  using Vec3 = Eigen::Vector3d;
  using Mat3 = Eigen::Matrix3d;

  void evaluate(const std::vector<Vec3>& candidate, const CallTime& info);
  void keep(int k);  // the last evaluation of point k becomes its accepted result
  void commit();
  Vec3 residual_of(int k, const PointTargets& t) const;
  void start(const PointTargets* targets, const CallTime& info);
  void newton_step(const PointTargets* targets, const CallTime& info);
  void bracket_sweep(const PointTargets* targets, const CallTime& info);
  void bracket_component(int j, const PointTargets* targets, const CallTime& info);
  [[noreturn]] void fail(int k, const CallTime& info, const std::string& why) const;

  std::unique_ptr<Caller> caller_;
  int first_point_;
  Eigen::Vector3d elastic_stiffness_;  // kn, ks, ks: a fall-back Jacobian
  MixedControlOptions options_;
  long calls_ = 0;

  // Per-point results, and the traction of the accepted trial.
  std::vector<PointResult> results_;
  std::vector<Vec3> accepted_traction_;

  // Work arrays of the Newton iterations, allocated once.
  std::vector<Vec3> d_, dx_, trial_, trial_traction_, residual_;
  std::vector<Mat3> jacobian_;
  std::vector<double> lambda_;
  std::vector<char> ok_, converged_, pending_, use_elastic_, stalled_;
  std::vector<int> iterations_, sweeps_;
  // The search for the root of one free traction of one point, along its
  // separation increment x with the other components fixed.
  struct Bracket {
    enum Phase { idle, expanding, refining, done, failed } phase = idle;
    double x0 = 0, f0 = 0;       // where the search started and the residual there
    double step = 0;             // current expansion step from x0
    int direction = 1, doublings = 0, turns = 0;
    double a = 0, fa = 0, b = 0, fb = 0;  // bracket: fa and fb of opposite signs
    int refinements = 0;
    double x = 0;                // the trial of the current evaluation
  };
  std::vector<Bracket> brackets_;
};

}  // namespace mortar::harness
