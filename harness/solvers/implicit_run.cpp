#include "solvers/implicit_run.hpp"

#include <algorithm>
#include <chrono>

#include "abi/props.hpp"
#include "mortar/state.hpp"
#include "scenes/joint_test.hpp"

namespace mortar::harness {

namespace {

class ImplicitRun {
 public:
  // props(1..19): the 14 parameters and the controls, the substep budget
  // only when set.
  ImplicitRun(const Parameters& parameters, Scene& scene, const ImplicitSettings& settings, const SampleSink& sink,
              const ResidualSink& residuals)
      : scene_(scene), sink_(sink), residuals_(residuals),
        solver_(UinterSetup{scene.directions(), kStateCount,
                            props_for(parameters, settings.scheme, settings.stol, settings.max_substeps)},
                settings.options) {}

  ImplicitStatistics execute(const ProgressSink& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    emit_start();
    const long total = scene_.total_increments();
    long done = 0;
    for (int s = 0; s < scene_.steps(); ++s) {
      scene_.begin_step(s, 0, solver_.result().separation, solver_.result().traction);
      for (long i = 1; i <= scene_.increments(s); ++i) {
        const IncrementClock clock = clock_of(scene_, s, i);
        UinterTime time;
        time.step = s + 1;
        time.time_increment = clock.time_increment;
        time.step_time = clock.step_time;
        time.total_time = clock.total_time;
        const PointTargets to = scene_.targets(s, i, 0);
        advance(s, scene_.targets(s, i - 1, 0), to, time, i);
        emit(to, time, ++done, time.step);
        if (progress) progress(done, total);
      }
    }
    stats_.increments = done;
    stats_.calls = solver_.calls();
    stats_.cuts_by_routine = solver_.attempts(AttemptOutcome::cut_by_routine);
    stats_.diverged = solver_.attempts(AttemptOutcome::diverged);
    stats_.not_converged = solver_.attempts(AttemptOutcome::not_converged);
    stats_.cycling = solver_.attempts(AttemptOutcome::cycling);
    stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return stats_;
  }

 private:
  // One program increment; a failure names where the step comes from.
  void advance(int step, const PointTargets& from, const PointTargets& to, const UinterTime& time, long i) {
    try {
      solver_.advance(from, to, time, time.step, i, on_attempt_);
    } catch (const RunFailure& e) {
      throw RunFailure(std::string(e.what()) + scene_.origin(step));
    }
  }

  void observe(const ResidualSequence& r) {
    ++stats_.attempts;
    if (residuals_) residuals_(r);
    if (r.outcome != AttemptOutcome::converged) return;
    stats_.max_traction_residual = std::max(stats_.max_traction_residual, r.residual[r.count - 1]);
    if (!stats_.has_worst || r.count > stats_.worst.count) {
      stats_.has_worst = true;
      stats_.worst = r;
    }
    stats_.max_iterations = std::max(stats_.max_iterations, r.count);
  }

  // Row 0: the point before the first increment (all state variables zero).
  void emit_start() {
    Sample s;
    std::copy_n(solver_.state(), kStateCount, s.state.begin());
    sink_(0, s);
  }

  void emit(const PointTargets& targets, const UinterTime& time, long increment, int step) {
    const PointResult& r = solver_.result();
    dissipation_ += r.dissipation_increment;
    work_ += solver_.work_increment();
    Sample s;
    s.increment = increment;
    s.step = step;
    s.time = time.total_time;
    s.separation = r.separation;
    s.traction = r.traction;
    std::copy_n(solver_.state(), kStateCount, s.state.begin());
    s.elastic_energy = r.elastic_energy;
    s.dissipation_increment = r.dissipation_increment;
    s.dissipation = dissipation_;
    s.external_work = work_;
    s.iterations = r.iterations;
    s.traction_residual = r.traction_residual;
    for (int j = 0; j < 3; ++j) {
      s.traction_controlled[j] = targets.kind[j] == Control::traction;
      s.target[j] = targets.value[j];
    }
    sink_(0, s);
  }

  Scene& scene_;
  const SampleSink& sink_;
  const ResidualSink& residuals_;
  ImplicitPointSolver solver_;
  std::function<void(const ResidualSequence&)> on_attempt_ = [this](const ResidualSequence& r) { observe(r); };
  ImplicitStatistics stats_;
  double dissipation_ = 0, work_ = 0;
};

}  // namespace

ImplicitStatistics run_scene_implicit(const Parameters& parameters, Scene& scene, const ImplicitSettings& settings,
                                      const SampleSink& sink, const ProgressSink& progress,
                                      const ResidualSink& residuals) {
  ImplicitRun run(parameters, scene, settings, sink, residuals);
  return run.execute(progress);
}

ImplicitStatistics run_protocol_implicit(const Parameters& parameters, const Protocol& protocol,
                                         const ImplicitSettings& settings, const SampleSink& sink,
                                         const ProgressSink& progress, const ResidualSink& residuals) {
  JointTest scene(protocol, 1);
  return run_scene_implicit(parameters, scene, settings, sink, progress, residuals);
}

}  // namespace mortar::harness
