#include "solvers/implicit_run.hpp"

#include <algorithm>

#include "abi/props.hpp"
#include "mortar/state_layout.hpp"
#include "scenes/joint_test.hpp"
#include "solvers/scene_run.hpp"

namespace mortar::harness {

namespace {

// Point 0 of the scene through UINTER; every attempt's residual sequence
// goes to `observe`. Row 0 is the point before the first increment (all
// state variables zero): Abaqus/Standard makes no reference call.
class ImplicitSolver : public MockSolver {
 public:
  // props(1..19): the 14 parameters and the controls, the substep budget
  // only when set.
  ImplicitSolver(const Parameters& parameters, const Scene& scene, const ImplicitSettings& settings,
                 std::function<void(const ResidualSequence&)> observe)
      : solver_(UinterSetup{scene.directions(), state_count_for(settings.cap),
                            props_for(parameters, settings.scheme, settings.stol, settings.max_substeps,
                                      settings.cap)},
                settings.options),
        observe_(std::move(observe)) {}

  int groups() const override { return 1; }
  int first_point(int) const override { return 0; }
  int group_size(int) const override { return 1; }
  void start(int) override {}

  // One program increment, from the targets at its start to those at its end.
  void advance(int, const Scene& scene, int step, long i, const IncrementClock& clock) override {
    CallTime time;
    time.step = step + 1;
    time.time_increment = clock.time_increment;
    time.step_time = clock.step_time;
    time.total_time = clock.total_time;
    solver_.advance(scene.targets(step, i - 1, 0), scene.targets(step, i, 0), time, time.step, i, observe_);
  }

  const PointResult& result(int) const override { return solver_.result(); }
  const double* state(int) const override { return solver_.state(); }
  double work_increment(int) const override { return solver_.work_increment(); }
  long calls() const override { return solver_.calls(); }
  long attempts(AttemptOutcome o) const { return solver_.attempts(o); }

 private:
  ImplicitPointSolver solver_;
  std::function<void(const ResidualSequence&)> observe_;
};

// The statistics of every attempt, and the worst converged one.
void observe(ImplicitStatistics& stats, const ResidualSink& residuals, const ResidualSequence& r) {
  ++stats.attempts;
  if (residuals) residuals(r);
  if (r.outcome != AttemptOutcome::converged) return;
  stats.max_traction_residual = std::max(stats.max_traction_residual, r.residual[r.count - 1]);
  if (!stats.has_worst || r.count > stats.worst.count) {
    stats.has_worst = true;
    stats.worst = r;
  }
  stats.max_iterations = std::max(stats.max_iterations, r.count);
}

}  // namespace

ImplicitStatistics run_scene_implicit(const Parameters& parameters, Scene& scene, const ImplicitSettings& settings,
                                      const SampleSink& sink, const ProgressSink& progress,
                                      const ResidualSink& residuals) {
  ImplicitStatistics stats;
  ImplicitSolver solver(parameters, scene, settings,
                        [&](const ResidualSequence& r) { observe(stats, residuals, r); });
  const RunStatistics run = run_scene(scene, solver, sink, progress);
  stats.increments = run.increments;
  stats.calls = run.calls;
  stats.cuts_by_routine = solver.attempts(AttemptOutcome::cut_by_routine);
  stats.diverged = solver.attempts(AttemptOutcome::diverged);
  stats.not_converged = solver.attempts(AttemptOutcome::not_converged);
  stats.cycling = solver.attempts(AttemptOutcome::cycling);
  stats.seconds = run.seconds;
  return stats;
}

ImplicitStatistics run_protocol_implicit(const Parameters& parameters, const Protocol& protocol,
                                         const ImplicitSettings& settings, const SampleSink& sink,
                                         const ProgressSink& progress, const ResidualSink& residuals) {
  JointTest scene(protocol, 1);
  return run_scene_implicit(parameters, scene, settings, sink, progress, residuals);
}

}  // namespace mortar::harness
