#include "runner.hpp"

#include <algorithm>
#include <chrono>
#include <memory>

namespace mortar::harness {

std::vector<double> props_for(const Parameters& p, Scheme scheme, double stol) {
  std::vector<double> props(kParameterCount + 2);
  for (int i = 0; i < kParameterCount; ++i) props[i] = parameter_at(p, i);
  props[kParameterCount] = static_cast<double>(static_cast<int>(scheme));
  props[kParameterCount + 1] = stol;
  return props;
}

namespace {

// Where a point was when the current step began: targets ramp from there.
struct StepStart {
  Eigen::Vector3d separation = Eigen::Vector3d::Zero();
  Eigen::Vector3d traction = Eigen::Vector3d::Zero();
};

class Run {
 public:
  Run(const Parameters& parameters, const Protocol& protocol, const RunSettings& settings, const SampleSink& sink)
      : protocol_(protocol), sink_(sink) {
    AbiSetup setup;
    setup.n_dir = protocol.directions;
    setup.n_states = kStateCount;
    setup.props = props_for(parameters, settings.scheme, settings.stol);
    setup.stiffness_default = parameters.kn;
    for (int first = 0; first < settings.points; first += settings.block) {
      const int count = std::min(settings.block, settings.points - first);
      blocks_.push_back(std::make_unique<BlockSolver>(setup, first, count, settings.mixed));
    }
    const size_t n = static_cast<size_t>(settings.points);
    scale_.assign(n, 1.0);
    if (settings.target_scale)
      for (int k = 0; k < settings.points; ++k) scale_[k] = settings.target_scale(k);
    start_.assign(n, StepStart{});
    work_.assign(n, 0.0);
    dissipation_.assign(n, 0.0);
    targets_.assign(static_cast<size_t>(std::min(settings.block, settings.points)), PointTargets{});
  }

  RunStatistics execute(const ProgressSink& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    RunStatistics stats;
    stats.blocks = static_cast<int>(blocks_.size());
    CallInfo info;
    for (auto& b : blocks_) {
      b->reference_call(info);
      emit(*b, info, 0);
    }
    const long total = protocol_.total_increments();
    long increment = 0;
    for (size_t s = 0; s < protocol_.steps.size(); ++s) {
      const ProgramStep& step = protocol_.steps[s];
      const ProgramStep* before = s > 0 ? &protocol_.steps[s - 1] : nullptr;
      remember_step_start();
      for (long i = 1; i <= step.increments; ++i) {
        ++increment;
        info.step = static_cast<int>(s) + 1;
        info.increment = static_cast<int>(i);
        info.time_increment = 1.0 / double(step.increments);
        info.step_time = double(i) / double(step.increments);
        info.total_time = double(s) + info.step_time;
        for (auto& b : blocks_) {
          for (int k = 0; k < b->size(); ++k) targets_[k] = targets_for(b->first_point() + k, step, before, i);
          advance(*b, step, info);
          emit(*b, info, increment);
        }
        if (progress) progress(increment, total);
      }
    }
    stats.increments = increment;
    for (auto& b : blocks_) stats.calls += b->calls();
    stats.max_traction_residual = max_residual_;
    stats.max_iterations = max_iterations_;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return stats;
  }

 private:
  // One increment of one block; a failure names the program step as well.
  void advance(BlockSolver& b, const ProgramStep& step, const CallInfo& info) {
    try {
      b.advance(targets_.data(), info);
    } catch (const RunFailure& e) {
      const std::string number = std::to_string(info.step);
      const std::string name = step.name == "step " + number ? "" : " ('" + step.name + "')";
      throw RunFailure(std::string(e.what()) + "; step " + number + name + " is defined at " + protocol_.file + ":" +
                       std::to_string(step.line));
    }
  }

  void remember_step_start() {
    for (auto& b : blocks_)
      for (int k = 0; k < b->size(); ++k) {
        const PointResult& r = b->result(k);
        start_[b->first_point() + k] = StepStart{r.separation, r.traction};
      }
  }

  // Targets of increment i of `step` for `point`: linear from the start of the
  // step to the step's end value. A traction that was already controlled in
  // the step before ramps from that step's target (so a held traction is held
  // exactly), otherwise from the traction the point carried.
  PointTargets targets_for(int point, const ProgramStep& step, const ProgramStep* before, long i) const {
    PointTargets t;
    const double f = double(i) / double(step.increments), scale = scale_[point];
    const StepStart& s = start_[point];
    for (int j = 0; j < 3; ++j) {
      const ComponentProgram& c = step.component[j];
      const double end = scale * c.target;
      double from = c.kind == Control::displacement ? s.separation[j] : s.traction[j];
      if (c.kind == Control::traction && before && before->component[j].kind == Control::traction)
        from = scale * before->component[j].target;
      t.kind[j] = c.kind;
      t.value[j] = i == step.increments ? end : from + (end - from) * f;
    }
    return t;
  }

  // Hands the block's committed results to the sink. `increment` 0 is the
  // reference call, whose targets are all zero displacements.
  void emit(const BlockSolver& b, const CallInfo& info, long increment) {
    for (int k = 0; k < b.size(); ++k) {
      const int point = b.first_point() + k;
      const PointResult& r = b.result(k);
      Sample s;
      s.increment = increment;
      s.step = increment == 0 ? 0 : info.step;
      s.time = info.total_time;
      s.separation = r.separation;
      s.traction = r.traction;
      std::copy_n(b.state(k), kStateCount, s.state.begin());
      s.elastic_energy = r.elastic_energy;
      s.dissipation_increment = r.dissipation_increment;
      if (increment > 0) {
        dissipation_[point] += r.dissipation_increment;
        work_[point] += 0.5 * (r.start_traction + r.traction).dot(r.increment);
        for (int j = 0; j < 3; ++j) {
          s.traction_controlled[j] = targets_[k].kind[j] == Control::traction;
          s.target[j] = targets_[k].value[j];
        }
      }
      s.dissipation = dissipation_[point];
      s.external_work = work_[point];
      s.iterations = r.iterations;
      s.traction_residual = r.traction_residual;
      max_residual_ = std::max(max_residual_, r.traction_residual);
      max_iterations_ = std::max(max_iterations_, r.iterations);
      sink_(point, s);
    }
  }

  const Protocol& protocol_;
  const SampleSink& sink_;
  std::vector<std::unique_ptr<BlockSolver>> blocks_;
  std::vector<double> scale_;
  std::vector<StepStart> start_;
  std::vector<double> work_, dissipation_;
  std::vector<PointTargets> targets_;
  double max_residual_ = 0;
  int max_iterations_ = 0;
};

}  // namespace

RunStatistics run_protocol(const Parameters& parameters, const Protocol& protocol, const RunSettings& settings,
                           const SampleSink& sink, const ProgressSink& progress) {
  Run run(parameters, protocol, settings, sink);
  return run.execute(progress);
}

}  // namespace mortar::harness
