#include "solvers/explicit_run.hpp"

#include <algorithm>
#include <chrono>
#include <memory>

#include "abi/props.hpp"
#include "scenes/joint_test.hpp"

namespace mortar::harness {

namespace {

class Run {
 public:
  Run(const Parameters& parameters, Scene& scene, const RunSettings& settings, const SampleSink& sink)
      : scene_(scene), sink_(sink) {
    AbiSetup setup;
    setup.n_dir = scene.directions();
    setup.n_states = kStateCount;
    setup.props = props_for(parameters, settings.scheme, settings.stol);
    setup.stiffness_default = parameters.kn;
    const int points = scene.points();
    for (int first = 0; first < points; first += settings.block) {
      const int count = std::min(settings.block, points - first);
      blocks_.push_back(std::make_unique<BlockSolver>(setup, first, count, settings.mixed));
    }
    work_.assign(static_cast<size_t>(points), 0.0);
    dissipation_.assign(static_cast<size_t>(points), 0.0);
    targets_.assign(static_cast<size_t>(std::min(settings.block, points)), PointTargets{});
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
    const long total = scene_.total_increments();
    long increment = 0;
    for (int s = 0; s < scene_.steps(); ++s) {
      begin_step(s);
      for (long i = 1; i <= scene_.increments(s); ++i) {
        ++increment;
        const IncrementClock clock = clock_of(scene_, s, i);
        info.step = s + 1;
        info.increment = static_cast<int>(i);
        info.time_increment = clock.time_increment;
        info.step_time = clock.step_time;
        info.total_time = clock.total_time;
        for (auto& b : blocks_) {
          for (int k = 0; k < b->size(); ++k) targets_[k] = scene_.targets(s, i, b->first_point() + k);
          advance(*b, s, info);
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
  // One increment of one block; a failure names where the step comes from.
  void advance(BlockSolver& b, int step, const CallInfo& info) {
    try {
      b.advance(targets_.data(), info);
    } catch (const RunFailure& e) {
      throw RunFailure(std::string(e.what()) + scene_.origin(step));
    }
  }

  void begin_step(int step) {
    for (auto& b : blocks_)
      for (int k = 0; k < b->size(); ++k) {
        const PointResult& r = b->result(k);
        scene_.begin_step(step, b->first_point() + k, r.separation, r.traction);
      }
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

  Scene& scene_;
  const SampleSink& sink_;
  std::vector<std::unique_ptr<BlockSolver>> blocks_;
  std::vector<double> work_, dissipation_;
  std::vector<PointTargets> targets_;
  double max_residual_ = 0;
  int max_iterations_ = 0;
};

}  // namespace

RunStatistics run_scene(const Parameters& parameters, Scene& scene, const RunSettings& settings,
                        const SampleSink& sink, const ProgressSink& progress) {
  Run run(parameters, scene, settings, sink);
  return run.execute(progress);
}

RunStatistics run_protocol(const Parameters& parameters, const Protocol& protocol, const RunSettings& settings,
                           const SampleSink& sink, const ProgressSink& progress) {
  JointTest scene(protocol, settings.points, settings.target_scale);
  return run_scene(parameters, scene, settings, sink, progress);
}

}  // namespace mortar::harness
