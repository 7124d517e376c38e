// A scene checked and set up before anything is written: the loading's
// magnitudes, the wall built (every free body with a mass), the solver's
// stable increment, and the run's size within the scene's bounds ([solver]
// max_increments, [output] max_rows, the snapshots). A broken rule is an
// InputError naming the scene file, the key, the value and the rule.
#pragma once

#include "input/scene_file.hpp"
#include "scenes/wall.hpp"
#include "solvers/block_solver.hpp"

namespace mortar::harness {

constexpr int kMaxSnapshots = 100;  // [output] snapshots: times, at most
// --threads N runs at most one thread per this many contact points: on
// fewer, a thread's share of an increment is too small to pay for the
// exchange of data between cores (docs/bench/throughput.md).
constexpr int kPointsPerThread = 200;

class ScenePlan {
 public:
  ScenePlan(const SceneSpec& spec, const BlockSolverOptions& options);
  ScenePlan(const ScenePlan&) = delete;
  ScenePlan& operator=(const ScenePlan&) = delete;

  const WallModel& model() const { return model_; }
  BlockSolver& solver() { return solver_; }
  long increments() const { return increments_; }
  int every() const { return every_; }  // a history row every `every` increments
  long rows() const { return history_rows(increments_, every_); }
  int threads() const { return threads_; }  // what the solver runs on

  // Rows of a run of n increments sampled every `every` (and at the last).
  static long history_rows(long n, int every) { return n / every + 1 + (n % every != 0 ? 1 : 0); }

 private:
  WallModel model_;  // before solver_, which holds a reference to it
  BlockSolver solver_;
  long increments_ = 0;
  int every_ = 1, threads_ = 1;
};

// The rules on the loading's magnitudes (finite is the reader's rule).
void check_loading_magnitudes(const SceneSpec& spec);

// build_wall, with the rules that need the wall (a mass on every body the
// solver moves) as InputError naming the file and the keys.
WallModel build_scene_wall(const SceneSpec& spec);

}  // namespace mortar::harness
