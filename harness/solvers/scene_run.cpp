#include "solvers/scene_run.hpp"

#include <algorithm>
#include <chrono>
#include <vector>

#include "mortar/state_layout.hpp"

namespace mortar::harness {

namespace {

class SceneRun {
 public:
  SceneRun(Scene& scene, MockSolver& solver, const SampleSink& sink)
      : scene_(scene), solver_(solver), sink_(sink), work_(static_cast<size_t>(scene.points()), 0.0),
        dissipation_(work_) {}

  RunStatistics execute(const ProgressSink& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int g = 0; g < solver_.groups(); ++g) {
      solver_.start(g);
      emit(g, -1, 0, IncrementClock{});
    }
    const long total = scene_.total_increments();
    long increment = 0;
    for (int s = 0; s < scene_.steps(); ++s) {
      for (int k = 0; k < scene_.points(); ++k)
        scene_.begin_step(s, k, solver_.result(k).separation, solver_.result(k).traction);
      for (long i = 1; i <= scene_.increments(s); ++i) {
        ++increment;
        const IncrementClock clock = clock_of(scene_, s, i);
        for (int g = 0; g < solver_.groups(); ++g) {
          advance(g, s, i, clock);
          emit(g, s, i, clock, increment);
        }
        if (progress) progress(increment, total);
      }
    }
    stats_.increments = increment;
    stats_.calls = solver_.calls();
    stats_.blocks = solver_.groups();
    stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return stats_;
  }

 private:
  // One increment of one group; a failure names where the step comes from.
  void advance(int g, int step, long i, const IncrementClock& clock) {
    try {
      solver_.advance(g, scene_, step, i, clock);
    } catch (const RunFailure& e) {
      throw RunFailure(std::string(e.what()) + scene_.origin(step));
    }
  }

  // Hands the group's committed points to the sink. Row 0 (step -1) is the
  // start, whose targets are all zero displacements.
  void emit(int g, int step, long i, const IncrementClock& clock, long increment = 0) {
    const int first = solver_.first_point(g);
    for (int point = first; point < first + solver_.group_size(g); ++point) {
      const PointResult& r = solver_.result(point);
      Sample s;
      s.increment = increment;
      s.step = step + 1;
      s.time = clock.total_time;
      s.separation = r.separation;
      s.traction = r.traction;
      std::copy_n(solver_.state(point), kStateCount, s.state.begin());
      s.integration_flags = load_integration_flags(solver_.state(point));
      s.elastic_energy = r.elastic_energy;
      s.dissipation_increment = r.dissipation_increment;
      if (increment > 0) {
        dissipation_[point] += r.dissipation_increment;
        work_[point] += solver_.work_increment(point);
        const PointTargets t = scene_.targets(step, i, point);
        for (int j = 0; j < 3; ++j) {
          s.traction_controlled[j] = t.kind[j] == Control::traction;
          s.target[j] = t.value[j];
        }
      }
      s.dissipation = dissipation_[point];
      s.external_work = work_[point];
      s.iterations = r.iterations;
      s.traction_residual = r.traction_residual;
      stats_.max_traction_residual = std::max(stats_.max_traction_residual, r.traction_residual);
      stats_.max_iterations = std::max(stats_.max_iterations, r.iterations);
      sink_(point, s);
    }
  }

  Scene& scene_;
  MockSolver& solver_;
  const SampleSink& sink_;
  std::vector<double> work_, dissipation_;
  RunStatistics stats_;
};

}  // namespace

RunStatistics run_scene(Scene& scene, MockSolver& solver, const SampleSink& sink, const ProgressSink& progress) {
  SceneRun run(scene, solver, sink);
  return run.execute(progress);
}

}  // namespace mortar::harness
