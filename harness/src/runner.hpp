// Runs a loading program on N identical interface points, in blocks, through
// vuinteraction_ (the mock solver's main loop): the reference call, then per
// increment and per block the mixed-control solve of block_solver.hpp.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "block_solver.hpp"
#include "mortar/parameters.hpp"
#include "mortar/state.hpp"
#include "protocol.hpp"

namespace mortar::harness {

struct RunSettings {
  Scheme scheme = Scheme::modified_euler;  // props(15)
  double stol = 0;                         // props(16); 0 keeps the routine's default
  int points = 1;
  int block = 512;  // at most this many points per call, as Abaqus's nBlock
  MixedControlOptions mixed;
  // Optional: point k's targets (displacements and tractions) multiplied by
  // target_scale(k). Lets tests give every point a different history.
  std::function<double(int)> target_scale;
};

// One point at the end of one increment; increment 0 is the reference call.
struct Sample {
  long increment = 0;
  int step = 0;  // 1-based program step (0 for the reference call)
  double time = 0;
  Eigen::Vector3d separation = Eigen::Vector3d::Zero();  // law signs [mm]
  Eigen::Vector3d traction = Eigen::Vector3d::Zero();    // law signs [MPa]
  std::array<double, kStateCount> state{};               // SDV1..SDV23
  double elastic_energy = 0;          // sed [N/mm]
  double dissipation_increment = 0;   // spd [N/mm]
  double dissipation = 0;             // sum of spd [N/mm]
  double external_work = 0;           // sum 1/2 (sigma_old + sigma_new) . d(delta) [N/mm]
  int iterations = 0;                 // Newton updates of this increment
  double traction_residual = 0;       // max |sigma_j - target_j| over traction-controlled j [MPa]
  std::array<bool, 3> traction_controlled{};
  std::array<double, 3> target{};     // the increment's targets (separation or traction)
};

struct RunStatistics {
  long increments = 0;
  long calls = 0;  // calls of vuinteraction_, all blocks
  int blocks = 0;
  double seconds = 0;
  double max_traction_residual = 0;
  int max_iterations = 0;
};

using SampleSink = std::function<void(int point, const Sample& sample)>;
using ProgressSink = std::function<void(long done, long total)>;

// props(1..16): the 14 parameters, the scheme and STOL.
std::vector<double> props_for(const Parameters& p, Scheme scheme, double stol);

// Runs `protocol` and hands every point's sample of every increment to
// `sink` (points in order within an increment). Throws RunFailure.
RunStatistics run_protocol(const Parameters& parameters, const Protocol& protocol, const RunSettings& settings,
                           const SampleSink& sink, const ProgressSink& progress = {});

}  // namespace mortar::harness
