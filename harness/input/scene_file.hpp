// Scene files (`masonry-joint scene FILE.toml`): a wall of rigid blocks, its
// joint law, supports, loading stages and solver controls, in TOML (the
// format: harness/README.md, "scene"). Every key is checked: unknown keys,
// wrong types and values that break a rule are InputError naming the file,
// the line, the key, the value and the rule.
#pragma once

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
};

struct SolverSpec {
  double safety_factor = 0.8;  // on the stable increment (Gershgorin bound, solvers/block_solver.hpp)
  double mass_scaling = 1.0;   // factor on every inertia (not on weights)
  double mass_damping = 0.0;   // alpha of C = alpha·M [1/s]
  long max_increments = 20000000;  // a scene that plans more is rejected (solvers/scene_plan.hpp)
};

struct SceneOutputSpec {
  int every = 0;                      // a history row every `every` increments (0: about 2000 rows)
  std::vector<double> snapshot_times; // pictures of the wall at these times [s] (the peak and the end always)
  double magnification = 0;           // of displacements in pictures (0: automatic)
  long max_rows = 1000000;            // history rows, at most (solvers/scene_plan.hpp)
};

struct SceneSpec {
  std::string file;      // the scene file
  ParameterSet joint;    // the joint law (a parameter file, path relative to the scene file)
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

}  // namespace mortar::harness
