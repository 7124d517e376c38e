#include "implicit_runner.hpp"

#include <algorithm>
#include <chrono>

#include "mortar/state.hpp"

namespace mortar::harness {

namespace {

// Where the point was when the current step began: targets ramp from there.
struct StepStart {
  Eigen::Vector3d separation = Eigen::Vector3d::Zero();
  Eigen::Vector3d traction = Eigen::Vector3d::Zero();
};

// Targets after increment i (0..increments) of `step`, as the explicit
// runner computes them (runner.cpp): linear from the start of the step to its
// end value, the end exactly; a traction already controlled in the step
// before ramps from that step's target, otherwise from the traction carried.
PointTargets targets_after(const ProgramStep& step, const ProgramStep* before, const StepStart& s, long i) {
  PointTargets t;
  const double f = double(i) / double(step.increments);
  for (int j = 0; j < 3; ++j) {
    const ComponentProgram& c = step.component[j];
    double from = c.kind == Control::displacement ? s.separation[j] : s.traction[j];
    if (c.kind == Control::traction && before && before->component[j].kind == Control::traction)
      from = before->component[j].target;
    t.kind[j] = c.kind;
    t.value[j] = i == step.increments ? c.target : from + (c.target - from) * f;
  }
  return t;
}

// props(1..16) as the explicit runner passes them; props(17..18) (FTOL
// default, max substeps) only when a substep budget is set.
std::vector<double> props_of(const Parameters& parameters, const ImplicitSettings& settings) {
  std::vector<double> props = props_for(parameters, settings.scheme, settings.stol);
  if (settings.max_substeps > 0) {
    props.resize(kParameterCount + 4, 0.0);
    props[kParameterCount + 3] = settings.max_substeps;
  }
  return props;
}

class ImplicitRun {
 public:
  ImplicitRun(const Parameters& parameters, const Protocol& protocol, const ImplicitSettings& settings,
              const SampleSink& sink, const ResidualSink& residuals)
      : protocol_(protocol), sink_(sink), residuals_(residuals),
        solver_(UinterSetup{protocol.directions, kStateCount, props_of(parameters, settings)}, settings.options) {}

  ImplicitStatistics execute(const ProgressSink& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    emit_start();
    const long total = protocol_.total_increments();
    long done = 0;
    for (size_t s = 0; s < protocol_.steps.size(); ++s) {
      const ProgramStep& step = protocol_.steps[s];
      const ProgramStep* before = s > 0 ? &protocol_.steps[s - 1] : nullptr;
      const StepStart start{solver_.result().separation, solver_.result().traction};
      for (long i = 1; i <= step.increments; ++i) {
        UinterTime time;
        time.step = static_cast<int>(s) + 1;
        time.time_increment = 1.0 / double(step.increments);
        time.step_time = double(i) / double(step.increments);
        time.total_time = double(s) + time.step_time;
        const PointTargets from = targets_after(step, before, start, i - 1);
        const PointTargets to = targets_after(step, before, start, i);
        advance(step, from, to, time, i);
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
  // One program increment; a failure names the program step as well.
  void advance(const ProgramStep& step, const PointTargets& from, const PointTargets& to, const UinterTime& time,
               long i) {
    try {
      solver_.advance(from, to, time, time.step, i, on_attempt_);
    } catch (const RunFailure& e) {
      const std::string number = std::to_string(time.step);
      const std::string name = step.name == "step " + number ? "" : " ('" + step.name + "')";
      throw RunFailure(std::string(e.what()) + "; step " + number + name + " is defined at " + protocol_.file + ":" +
                       std::to_string(step.line));
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

  const Protocol& protocol_;
  const SampleSink& sink_;
  const ResidualSink& residuals_;
  ImplicitPointSolver solver_;
  std::function<void(const ResidualSequence&)> on_attempt_ = [this](const ResidualSequence& r) { observe(r); };
  ImplicitStatistics stats_;
  double dissipation_ = 0, work_ = 0;
};

}  // namespace

ImplicitStatistics run_protocol_implicit(const Parameters& parameters, const Protocol& protocol,
                                         const ImplicitSettings& settings, const SampleSink& sink,
                                         const ProgressSink& progress, const ResidualSink& residuals) {
  ImplicitRun run(parameters, protocol, settings, sink, residuals);
  return run.execute(progress);
}

}  // namespace mortar::harness
