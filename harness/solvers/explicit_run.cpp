#include "solvers/explicit_run.hpp"

#include <algorithm>
#include <memory>
#include <vector>

#include "abi/props.hpp"
#include "mortar/state_layout.hpp"
#include "scenes/joint_test.hpp"

namespace mortar::harness {

namespace {

// The scene's points in blocks of at most `block` (the last one shorter).
class ExplicitSolver : public MockSolver {
 public:
  ExplicitSolver(const Parameters& parameters, const Scene& scene, const RunSettings& settings)
      : block_(settings.block) {
    AbiSetup setup;
    setup.n_dir = scene.directions();
    // The double routine's layout with the integration flags (SDV 35) and,
    // with a cap, kappa_c (SDV 36); it leaves SDV 24-34, single precision's
    // pairs, as they are.
    setup.n_states = state_count_for(settings.cap);
    setup.props = props_for(parameters, settings.scheme, settings.stol, 0, settings.cap);
    setup.stiffness_default = parameters.kn;
    const int points = scene.points();
    for (int first = 0; first < points; first += block_) {
      const int count = std::min(block_, points - first);
      blocks_.push_back(std::make_unique<MixedControlSolver>(setup, first, count, settings.mixed));
    }
    targets_.assign(static_cast<size_t>(std::min(block_, points)), PointTargets{});
  }

  int groups() const override { return static_cast<int>(blocks_.size()); }
  int first_point(int g) const override { return blocks_[g]->first_point(); }
  int group_size(int g) const override { return blocks_[g]->size(); }

  // Abaqus's first sight of the points (solvers/mixed_control_solver.hpp), step 1, increment 0.
  void start(int g) override { blocks_[g]->reference_call(CallTime{}); }

  void advance(int g, const Scene& scene, int step, long i, const IncrementClock& clock) override {
    MixedControlSolver& b = *blocks_[g];
    for (int k = 0; k < b.size(); ++k) targets_[k] = scene.targets(step, i, b.first_point() + k);
    CallTime info;
    info.step = step + 1;
    info.increment = static_cast<int>(i);
    info.time_increment = clock.time_increment;
    info.step_time = clock.step_time;
    info.total_time = clock.total_time;
    b.advance(targets_.data(), info);
  }

  const PointResult& result(int point) const override { return block_of(point).result(point % block_); }
  const double* state(int point) const override { return block_of(point).state(point % block_); }
  // Trapezoidal: 1/2 (sigma_start + sigma_end) . d(delta).
  double work_increment(int point) const override {
    const PointResult& r = result(point);
    return 0.5 * (r.start_traction + r.traction).dot(r.increment);
  }
  long calls() const override {
    long n = 0;
    for (const auto& b : blocks_) n += b->calls();
    return n;
  }

 private:
  const MixedControlSolver& block_of(int point) const { return *blocks_[static_cast<size_t>(point / block_)]; }

  int block_;
  std::vector<std::unique_ptr<MixedControlSolver>> blocks_;
  std::vector<PointTargets> targets_;  // of the block being solved
};

}  // namespace

RunStatistics run_scene(const Parameters& parameters, Scene& scene, const RunSettings& settings,
                        const SampleSink& sink, const ProgressSink& progress) {
  ExplicitSolver solver(parameters, scene, settings);
  return run_scene(scene, solver, sink, progress);
}

RunStatistics run_protocol(const Parameters& parameters, const Protocol& protocol, const RunSettings& settings,
                           const SampleSink& sink, const ProgressSink& progress) {
  JointTest scene(protocol, settings.points, settings.target_scale);
  return run_scene(parameters, scene, settings, sink, progress);
}

}  // namespace mortar::harness
