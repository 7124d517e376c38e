// Scene files (`masonry-joint scene FILE.toml`): a wall of rigid blocks, its
// joint law, supports, loading stages and solver controls, in TOML (the
// format: harness/README.md, "scene"). Every key is checked: unknown keys,
// wrong types and values that break a rule are InputError naming the file,
// the line, the key, the value and the rule.
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "input/parameter_file.hpp"
#include "mortar/parameters.hpp"
#include "scenes/wall.hpp"

namespace mortar::harness {

// The loading stages, in this order: self-weight ramped in, precompression
// on the top beam ramped in, a hold, then the top beam's horizontal
// displacement through `displacement` (corner values from 0). Every ramp
// and every leg follows a half cosine (zero velocity at its ends) so that
// no stage starts with a jolt.
struct LoadingSpec {
  double gravity = 9810.0;          // [mm/s²]
  double self_weight_time = 0;      // [s]
  double precompression = 0;        // on the wall's top face, length × depth [MPa]
  double precompression_time = 0;   // [s]
  double hold_time = 0;             // [s]
  std::vector<double> displacement; // corners of the top beam's ux history [mm]
  double velocity = 0;              // mean speed of a leg [mm/s]
  // Force control (a cantilever push): the beam's ux is free and a
  // horizontal force follows the corners `force` [N] at `force_rate` [N/s].
  bool force_control = false;
  std::vector<double> force;
  double force_rate = 0;
  // Height of the horizontal action above the base [mm]; NaN: the top
  // beam's centroid. It matters with the beam's rotation free.
  double action_height = std::numeric_limits<double>::quiet_NaN();
  // The corners of the controlled quantity and the mean rate of a leg.
  const std::vector<double>& corners() const { return force_control ? force : displacement; }
  double rate() const { return force_control ? force_rate : velocity; }
};

struct SolverSpec {
  double safety_factor = 0.8;  // on the stable increment (Gershgorin bound, solvers/block_solver.hpp)
  double mass_scaling = 1.0;   // factor on every inertia (not on weights)
  double mass_damping = 0.0;   // alpha of C = alpha·M [1/s]
  long max_increments = 20000000;  // a scene that plans more is rejected (solvers/scene_plan.hpp)
};

// What colours the joint points in the wall pictures: the dissipated energy
// per unit area (SDV 16 + 17 + 18), the opening, or max(d_n, d_s).
enum class JointColour { dissipation, opening, damage };

struct SceneOutputSpec {
  int every = 0;                      // a history row every `every` increments (0: about 2000 rows)
  std::vector<double> snapshot_times; // pictures of the wall at these times [s] (the peak and the end always)
  double magnification = 0;           // of displacements in pictures (0: automatic)
  JointColour joint_colour = JointColour::dissipation;
  // A measured curve drawn beside the base shear: its file (columns
  // top_displacement_mm, base_shear_kN; '#' lines state its source), its
  // rows as read, and its label in the chart.
  std::string experiment;
  std::vector<std::vector<double>> experiment_curve;
  std::string experiment_label;
  long max_rows = 1000000;            // history rows, at most (solvers/scene_plan.hpp)
};

// The units' elasticity, lumped into the interfaces in series where the
// units are rigid: per unit area kn' = 1 / (1/kn + l/E), ks' = 1 / (1/ks + l/G),
// G = E / (2 (1 + nu)), l the unit length across the interface
// (lumped_unit_length, scenes/wall.hpp). E = 0: rigid units, kn and ks as read.
struct UnitElasticity {
  double young = 0;    // [MPa]
  double poisson = 0;  // [-]
};

// kn, ks of `p` in series with the units over the length l [mm].
Parameters in_series_with_units(const Parameters& p, const UnitElasticity& u, double l);

struct SceneSpec {
  std::string file;      // the scene file
  ParameterSet joint;    // the joint law (a parameter file, path relative to the scene file)
  // Each interface role's law as read ([interfaces], `joint` where absent),
  // and with the units' elasticity in series: what its points get.
  std::array<ParameterSet, kInterfaceRoles> interface;
  std::array<Parameters, kInterfaceRoles> interface_law;
  UnitElasticity units;
  Scheme scheme = Scheme::modified_euler;
  double stol = 0;       // props(16); 0 keeps the routine's default
  WallGeometry wall;
  LoadingSpec loading;
  SolverSpec solver;
  SceneOutputSpec output;
  // The end of each stage [s]: self-weight, precompression, hold, each leg.
  std::vector<double> stage_ends() const;
  double end_time() const { return stage_ends().back(); }
};

SceneSpec read_scene_file(const std::string& path);

// The horizontal action's height above the top beam's centroid [mm]: 0 when
// the scene gives no action_height (the action at the centroid).
double action_arm(const SceneSpec& s, const WallModel& m);

}  // namespace mortar::harness
