// The explicit solver of a wall of rigid blocks: central
// differences in time, as Abaqus/Explicit integrates, with the joints'
// tractions from vuinteraction_ (solvers/joint_calls.hpp).
//
//   v(n+1/2) = [(1 - α·dt/2)·v(n-1/2) + dt·M⁻¹·(F_ext(n) + F_joint(n))] / (1 + α·dt/2)
//   q(n+1)   = q(n) + dt·v(n+1/2)
//
// M is the block masses and rotary inertias times the mass-scaling factor,
// α the mass-proportional damping. The base is fixed; the top beam's ux
// follows the loading history (0 before the displacement stage) or is free
// under a horizontal force (force control), its rotation is held at 0 or
// free, its uy is free under its weight and the precompression, or held at
// its height from the end of the hold on.
//
// The stable increment is 2/ω_max with ω_max² bounded by Gershgorin's
// theorem on M^-1/2·K·M^-1/2, K the undamaged joint stiffness (kn, ks times
// each point's area; damage only lowers it, compression keeps kn), over the
// free degrees of freedom; the increment used is the safety factor times it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "abi/vuinteraction_call.hpp"
#include "input/scene_file.hpp"
#include "scenes/wall.hpp"

namespace mortar::harness {

struct BlockSolverOptions {
  int block = 136;  // points per call of vuinteraction_ (nBlock), at most
  int threads = 1;
  // Stop after this many increments (0: run to the end); for tests.
  long max_increments = 0;
};

// The energies at one instant [N·mm].
struct WallEnergies {
  double external = 0;     // work of weights, precompression and the actuator
  double elastic = 0;      // Σ sed·area
  double dissipated = 0;   // Σ (spd + sfd)·area, accumulated
  double plastic = 0, damage = 0, unilateral = 0;  // the law's split (SDV 16, 17, 18 × area)
  double kinetic = 0;
  double damping = 0;      // work of the mass-proportional damping
  double internal() const { return elastic + dissipated; }
  // Everything the external work went into, and the external work minus it.
  double accounted() const { return elastic + dissipated + kinetic + damping; }
  double balance() const { return external - accounted(); }
};

struct WallSample {
  long increment = 0;
  double time = 0;
  int stage = 0;  // 0 self-weight, 1 precompression, 2 hold, 3 + leg: the displacement legs
  double top_ux = 0, top_uy = 0, top_rotation = 0;  // the top beam [mm, rad]
  double base_shear = 0;   // Σ τ·area over the base joint [N] (positive: the wall pushes the base along +x)
  double base_normal = 0;  // Σ σ·area over the base joint [N] (compression negative)
  double top_normal = 0;   // Σ σ·area over the joint under the top beam [N] (compression negative)
  double actuator = 0;     // horizontal force of the actuator on the top beam [N]
  WallEnergies energy;
};

// The wall at one instant, for pictures.
struct WallSnapshot {
  double time = 0;
  std::string label;
  std::vector<double> q;  // 3 per body
  // Per point: opening and slip [mm], d_n, d_s, the dissipated energy per
  // unit area, SDV 16 + 17 + 18 [N/mm], and the cap's kappa_c [mm] (0 without).
  std::vector<double> opening, slip, damage_n, damage_s, dissipation, kappa_c;
};

class JointCalls;
// The wall under q with the joints' state after their last call.
WallSnapshot wall_snapshot(const JointCalls& joints, const std::vector<double>& q, double t, const std::string& label);

struct WallRunSummary {
  double stable_increment = 0, time_increment = 0;
  long increments = 0;
  int points = 0, blocks = 0, calls_per_increment = 0;
  double seconds = 0, seconds_in_routine = 0;
  double peak_shear = 0, peak_displacement = 0, peak_time = 0;  // largest |base shear| in the displacement stage
  double max_kinetic_ratio = 0;  // largest kinetic / internal energy in the displacement stage
  double max_balance_error = 0;  // largest |balance| / max(external work so far), displacement stage
  std::string integration_flags;  // the points' SDV 35 at the end (output/flag_tally.hpp)
  std::string unpaired_warning;   // "" or the points the routine took as unpaired (flag_tally.hpp)
  double point_updates_per_second() const { return seconds > 0 ? points * double(increments) / seconds : 0; }
};

class BlockSolver {
 public:
  BlockSolver(const SceneSpec& scene, const WallModel& model, const BlockSolverOptions& options);

  double stable_increment() const { return stable_dt_; }
  double time_increment() const { return dt_; }
  long total_increments() const;

  // Runs every stage. `sample` is called every `every` increments (and at
  // the last); `progress(done, total)` now and then. Snapshots are taken at
  // the scene's snapshot times, the peak and the end.
  WallRunSummary run(int every, const std::function<void(const WallSample&)>& sample,
                     const std::function<void(long, long)>& progress, std::vector<WallSnapshot>* snapshots);

 private:
  double stable_increment_bound() const;

  const SceneSpec& scene_;
  const WallModel& model_;
  BlockSolverOptions options_;
  std::vector<double> mass_;  // scaled, 3 per body
  std::vector<char> free_;    // 3 per body
  double action_arm_ = 0;     // height of the horizontal action above the beam's centroid [mm]
  double stable_dt_ = 0, dt_ = 0;
};

// The arguments of each interface role's interaction (InterfaceRole order):
// its law with the units in series, the scene's scheme and stol, its cap.
std::vector<AbiSetup> interface_setups(const SceneSpec& scene);

// The horizontal action at time t (0 before the legs): the top beam's
// displacement [mm], or its force [N] under force control; and the factors
// (0..1) of the self-weight and precompression.
double horizontal_action_at(const SceneSpec& s, const std::vector<double>& stage_ends, double t);
double gravity_factor_at(const SceneSpec& s, double t);
double precompression_factor_at(const SceneSpec& s, double t);

}  // namespace mortar::harness
