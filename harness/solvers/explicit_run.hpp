// The explicit mock solver: a scene's points in blocks of at most `block`,
// each block one call of vuinteraction_ per trial, the way Abaqus/Explicit
// calls it (solvers/mixed_control_solver.hpp), run by solvers/scene_run.hpp.
#pragma once

#include <functional>

#include "input/protocol.hpp"
#include "mortar/parameters.hpp"
#include "scenes/scene.hpp"
#include "solvers/mixed_control_solver.hpp"
#include "solvers/sample.hpp"
#include "solvers/scene_run.hpp"

namespace mortar::harness {

struct RunSettings {
  Scheme scheme = Scheme::modified_euler;  // props(15)
  double stol = 0;                         // props(16); 0 keeps the routine's default
  CompressionCap cap;                      // props(21..24); off by default
  int points = 1;   // run_protocol's joint test: identical points
  int block = 512;  // at most this many points per call, as Abaqus's nBlock
  MixedControlOptions mixed;
  // Optional, run_protocol's joint test: point k's targets (displacements
  // and tractions) multiplied by target_scale(k) (scenes/joint_test.hpp).
  std::function<double(int)> target_scale;
};

// Runs every point of `scene` (settings.points and target_scale are the
// scene's business here) and hands every point's sample of every increment
// to `sink` (points in order within an increment). Throws RunFailure.
RunStatistics run_scene(const Parameters& parameters, Scene& scene, const RunSettings& settings,
                        const SampleSink& sink, const ProgressSink& progress = {});

// The joint test (scenes/joint_test.hpp) of `protocol` on settings.points points.
RunStatistics run_protocol(const Parameters& parameters, const Protocol& protocol, const RunSettings& settings,
                           const SampleSink& sink, const ProgressSink& progress = {});

}  // namespace mortar::harness
