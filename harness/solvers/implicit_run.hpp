// Runs a one-point scene through UINTER, the way Abaqus/Standard would
// (solvers/implicit_solver.hpp): `masonry-joint run --solver implicit`. The
// targets come from the same scene as the explicit run's
// (scenes/joint_test.hpp), so the two solvers' curves can be compared
// increment by increment.
#pragma once

#include <functional>

#include "input/protocol.hpp"
#include "mortar/parameters.hpp"
#include "scenes/scene.hpp"
#include "solvers/implicit_solver.hpp"
#include "solvers/sample.hpp"

namespace mortar::harness {

struct ImplicitSettings {
  Scheme scheme = Scheme::implicit;  // props(15); the explicit schemes return their continuum tangent
  double stol = 0;                   // props(16); 0 keeps the routine's default
  int max_substeps = 0;              // props(18) when > 0 (else not passed: the routine's default)
  CompressionCap cap;                // props(21..24); off by default
  ImplicitOptions options;
};

struct ImplicitStatistics {
  long increments = 0;  // program increments
  long calls = 0;       // calls of uinter_
  long attempts = 0;    // (sub)increments tried
  long cuts_by_routine = 0, diverged = 0, not_converged = 0, cycling = 0;  // attempts cut back, by reason
  int max_iterations = 0;            // equilibrium iterations of one converged attempt, at most
  double max_traction_residual = 0;  // at convergence [MPa]
  double seconds = 0;
  // The converged attempt with the most iterations (the first of them).
  bool has_worst = false;
  ResidualSequence worst;
};

using ResidualSink = std::function<void(const ResidualSequence&)>;

// Runs point 0 of `scene` and hands every increment's sample to `sink` (row
// 0 is the state before the first increment: Abaqus/Standard makes no
// reference call, UINTER integrates the first increment). `residuals`, when
// given, sees every attempt. Throws RunFailure.
ImplicitStatistics run_scene_implicit(const Parameters& parameters, Scene& scene, const ImplicitSettings& settings,
                                      const SampleSink& sink, const ProgressSink& progress = {},
                                      const ResidualSink& residuals = {});

// The joint test (scenes/joint_test.hpp) of `protocol` on one point.
ImplicitStatistics run_protocol_implicit(const Parameters& parameters, const Protocol& protocol,
                                         const ImplicitSettings& settings, const SampleSink& sink,
                                         const ProgressSink& progress = {}, const ResidualSink& residuals = {});

}  // namespace mortar::harness
