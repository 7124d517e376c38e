// What a run hands out: one point at the end of one increment, as the run CSV
// (output/csv.hpp) and the validation checks read it.
#pragma once

#include <array>
#include <functional>

#include <Eigen/Core>

#include "mortar/state_layout.hpp"

namespace mortar::harness {

// Increment 0 is the start (the reference call of the explicit solver).
struct Sample {
  long increment = 0;
  int step = 0;  // 1-based program step (0 for the start)
  double time = 0;
  Eigen::Vector3d separation = Eigen::Vector3d::Zero();  // law signs [mm]
  Eigen::Vector3d traction = Eigen::Vector3d::Zero();    // law signs [MPa]
  std::array<double, kStateCount> state{};               // SDV1..SDV23
  int integration_flags = 0;                             // SDV35 (docs/model.md 9)
  double elastic_energy = 0;          // sed [N/mm]
  double dissipation_increment = 0;   // spd [N/mm]
  double dissipation = 0;             // sum of spd [N/mm]
  double external_work = 0;           // sum 1/2 (sigma_old + sigma_new) . d(delta) [N/mm]
  int iterations = 0;                 // Newton updates of this increment
  double traction_residual = 0;       // max |sigma_j - target_j| over traction-controlled j [MPa]
  std::array<bool, 3> traction_controlled{};
  std::array<double, 3> target{};     // the increment's targets (separation or traction)
};

using SampleSink = std::function<void(int point, const Sample& sample)>;
using ProgressSink = std::function<void(long done, long total)>;

}  // namespace mortar::harness
