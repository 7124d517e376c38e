// Runs a scene with a mock solver: the start, then step by step and
// increment by increment every group of points solved and committed, and
// every point's sample handed out (points in order within an increment).
// Both `masonry-joint run` solvers run through here.
#pragma once

#include "scenes/scene.hpp"
#include "solvers/mock_solver.hpp"
#include "solvers/sample.hpp"

namespace mortar::harness {

struct RunStatistics {
  long increments = 0;
  long calls = 0;  // calls of the ABI entry point, all groups
  int blocks = 0;  // groups of points solved together
  double seconds = 0;
  double max_traction_residual = 0;  // over every committed increment [MPa]
  int max_iterations = 0;            // Newton updates of one increment, at most
};

// Throws RunFailure, its message ending with where the failing step comes from.
RunStatistics run_scene(Scene& scene, MockSolver& solver, const SampleSink& sink,
                        const ProgressSink& progress = {});

}  // namespace mortar::harness
