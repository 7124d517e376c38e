// The implicit mock solver: one interface point driven through UINTER the way
// Abaqus/Standard drives a contact point. Per (sub)increment, global Newton
// iterations on the unknown (traction-controlled) components of RDISP with
// the returned DDSDDR as the Jacobian; every call starts from the state at the
// start of the increment (the routine must not commit; the solver commits the
// converged call's outputs); PNEWDT < 1 abandons the attempt and retries it
// with PNEWDT times the size, at most `max_cuts` times per program increment.
//
// One attempt, in Abaqus's variables (STRESS, RDISP; abi/uinter_call.hpp):
//   0. the stiffness call: RDISP at the start of the increment, DRDISP = 0
//      (what Abaqus/Standard's first iteration passes, docs/abaqus.md); its
//      DDSDDR is the predictor's Jacobian (skipped when nothing is free);
//   1. predictor: the displacement-controlled components at their targets,
//      the free ones from K_FF dx_F = (P_F - STRESS_F) - K_FD dx_D;
//   k. call at the iterate; residual r_k = max_F |STRESS_j - P_j| (P the
//      applied traction, C_j target_j); converged when r_k <= the traction
//      tolerance, else the Newton update dx_F = -K_FF^-1 R_F with this
//      call's DDSDDR; once the residual rises, with the secant Jacobian
//      (Broyden's update, attempt() in implicit_solver.cpp). No line search.
// An attempt is abandoned and retried on a smaller piece from the same start
// when the routine asks for it (PNEWDT < 1: PNEWDT times the size), and, with
// Abaqus/Standard's divergence cut-back factor D_f = 0.25 (its *CONTROLS default,
// as transcribed, not checked against a manual here), when the residual
// grows in two consecutive iterations or is not finite, when Newton repeats a
// two-iterate cycle (both before the secant takes over), or after
// `max_iterations`. The cut-backs of one program
// increment are bounded by `max_cuts` and `min_fraction`; then the run fails
// with the last attempt's outcome and residual.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "abi/uinter_caller.hpp"
#include "solvers/mixed_control.hpp"

namespace mortar::harness {

struct ImplicitOptions {
  double traction_tolerance = 1e-9;  // |sigma_j - target_j| accepted [MPa], absolute
  int max_iterations = 16;           // equilibrium iterations per attempt (the harness's choice)
  int max_cuts = 5;                  // cut-backs per program increment (Abaqus/Standard's default I_A = 5)
  double divergence_cut = 0.25;      // size factor after a diverged attempt (Abaqus/Standard's D_f)
  double min_fraction = 1e-5;        // smallest sub-increment, of the program increment
  bool symmetric_tangent = false;    // Newton on DDSDDR's symmetric part (Abaqus/Standard without UNSYMM)
};

inline constexpr int kMaxRecordedIterations = 64;  // bound of ImplicitOptions::max_iterations

// How an attempt of one (sub)increment ended.
enum class AttemptOutcome { converged, cut_by_routine, diverged, not_converged, cycling };
const char* outcome_name(AttemptOutcome o);

// The residual sequence of one attempt: r_k after the k-th equilibrium
// iteration (k = 1 is the predictor), in MPa.
struct ResidualSequence {
  int step = 0;             // program step, 1-based
  long increment = 0;       // increment within the step, 1-based
  int sub_increment = 1;    // attempt within the program increment, 1-based
  double start = 0, size = 1;  // the attempt's span, as fractions of the program increment
  AttemptOutcome outcome = AttemptOutcome::converged;
  double pnewdt = 1;        // the routine's request when outcome == cut_by_routine
  int count = 0;            // iterations recorded
  std::array<double, kMaxRecordedIterations> residual{};
};

class ImplicitPointSolver {
 public:
  ImplicitPointSolver(const UinterSetup& setup, const ImplicitOptions& options);

  // Solves one program increment from `from` (the targets at its start) to
  // `to` (at its end), cutting it back as the routine or Newton asks, and
  // commits it. `time` is the program increment's; `on_attempt` (optional)
  // sees every attempt's residual sequence. Throws RunFailure.
  void advance(const PointTargets& from, const PointTargets& to, const CallTime& time, int step, long increment,
               const std::function<void(const ResidualSequence&)>& on_attempt);

  // The committed point (law signs) after the last program increment:
  // `increment` and `start_traction` span the program increment, `iterations`
  // and `dissipation_increment` sum its sub-increments.
  const PointResult& result() const { return result_; }
  // Trapezoidal external work of the last program increment, summed over its
  // sub-increments [N/mm].
  double work_increment() const { return work_increment_; }
  const double* state() const { return caller_.state(0); }
  long calls() const { return calls_; }
  // Attempts that ended in each outcome, all program increments so far.
  long attempts(AttemptOutcome o) const { return outcomes_[static_cast<size_t>(o)]; }
  int sub_increments() const { return sub_increments_; }  // of the last program increment

 private:
  using Vec3 = Eigen::Vector3d;
  using Mat3 = Eigen::Matrix3d;

  PointTargets targets_at(const PointTargets& from, const PointTargets& to, double end) const;
  AttemptOutcome attempt(const PointTargets& targets, CallTime time, ResidualSequence& record);
  Vec3 prescribed(const PointTargets& t) const;
  bool predict(const PointTargets& t, CallTime& time, Vec3& x, ResidualSequence& record);
  bool abandoned(ResidualSequence& record) const;
  bool hopeless(ResidualSequence& record) const;
  void call(const Vec3& rdisp, CallTime& time);
  void read_call();
  bool cut_requested() const;
  Vec3 residual(const PointTargets& t) const;
  Vec3 newton_step(const PointTargets& t, const Vec3& rhs) const;
  void commit(const Vec3& rdisp, const ResidualSequence& record);
  [[noreturn]] void give_up(const ResidualSequence& last, int cuts) const;
  [[noreturn]] void fail(const std::string& why) const;

  ImplicitOptions options_;
  UinterCaller caller_;
  int n_dir_;
  long calls_ = 0;
  std::array<long, 5> outcomes_{};
  int sub_increments_ = 0;
  long solved_in_step_ = 0;  // converged (sub)increments of the current step: KINC - 1
  int step_ = 0;         // program step and increment being solved, for messages
  long increment_ = 0;

  // RDISP at the start of the increment, and the last call's STRESS and
  // DDSDDR: Abaqus's variables of the Newton iteration (the caller's law
  // variables converted exactly, factors of +-1).
  Vec3 committed_rdisp_ = Vec3::Zero();
  Vec3 stress_ = Vec3::Zero();
  Mat3 ddsddr_ = Mat3::Zero();
  PointResult result_;
  double work_increment_ = 0;
};

}  // namespace mortar::harness
