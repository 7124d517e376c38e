#include "solvers/scene_plan.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "input/input_error.hpp"

namespace mortar::harness {

namespace {

// A count for a message: whole below 1e15, else as a number.
std::string count_text(double n) {
  if (n < 1e15) return std::to_string(static_cast<long long>(n));
  return input_number(n);
}

// A magnitude rule of [loading]: `x` <= `bound`.
void check_bound(const SceneSpec& s, const char* key, double x, double bound, const char* unit, const char* why) {
  if (std::fabs(x) <= bound) return;
  throw InputError(s.file + ": [loading] " + key + " " + input_number(x) + " " + unit + " violates the rule: " + why);
}

int threads_for(const WallModel& model, int threads) {
  const int most = std::max(1, static_cast<int>(model.points.size()) / kPointsPerThread);
  return std::max(1, std::min(threads, most));
}

BlockSolver checked_solver(const SceneSpec& spec, const WallModel& model, BlockSolverOptions options) {
  options.threads = threads_for(model, options.threads);
  try {
    return BlockSolver(spec, model, options);
  } catch (const std::invalid_argument& e) {
    throw InputError(spec.file + ": the scene cannot be solved: " + e.what());
  }
}

}  // namespace

void check_loading_magnitudes(const SceneSpec& s) {
  const LoadingSpec& l = s.loading;
  check_bound(s, "gravity =", l.gravity, 1e6, "mm/s^2", "<= 1e6 mm/s^2 (about 100 g)");
  check_bound(s, "precompression =", l.precompression, 1e3, "MPa", "<= 1000 MPa");
  check_bound(s, "velocity =", l.velocity, 1e6, "mm/s", "<= 1e6 mm/s");
  check_bound(s, "force_rate =", l.force_rate, 1e12, "N/s", "<= 1e12 N/s");
}

WallModel build_scene_wall(const SceneSpec& spec) {
  const WallGeometry& g = spec.wall;
  const std::string need = " (an explicit solver needs a mass on every free degree of freedom)";
  if (!(g.beam_mass > 0) && !(g.tie_top_course && g.density > 0))
    throw InputError(spec.file + ": [top_beam] mass = " + input_number(1e3 * g.beam_mass) + " kg, [wall] density = " +
                     input_number(1e12 * g.density) + " kg/m^3, tie_top_course = " + (g.tie_top_course ? "true" : "false") +
                     ": the top beam has no mass: violates the rule: [top_beam] mass > 0, or [wall] density > 0 with "
                     "tie_top_course" + need);
  WallModel m;
  try {
    m = build_wall(g);
  } catch (const std::invalid_argument& e) {
    throw InputError(spec.file + ": the wall cannot be built: " + e.what());
  }
  for (size_t b = 1; b < m.bodies.size(); ++b)
    if (!(m.bodies[b].mass > 0))
      throw InputError(spec.file + ": [wall] density = " + input_number(1e12 * g.density) +
                       " kg/m^3 leaves the blocks without mass: violates the rule: > 0" + need);
  return m;
}

ScenePlan::ScenePlan(const SceneSpec& spec, const BlockSolverOptions& options)
    : model_(build_scene_wall(spec)), solver_(checked_solver(spec, model_, options)) {
  check_loading_magnitudes(spec);
  const double end = spec.end_time(), dt = solver_.time_increment();
  const double planned = std::ceil(end / dt - 1e-9);
  if (!(planned <= static_cast<double>(spec.solver.max_increments))) {
    std::ostringstream m;
    m << spec.file << ": the run plans " << count_text(planned) << " increments of " << input_number(dt)
      << " s (safety_factor " << input_number(spec.solver.safety_factor) << " x the stable increment "
      << input_number(solver_.stable_increment()) << " s) over " << input_number(end)
      << " s: violates the rule: at most [solver] max_increments = " << spec.solver.max_increments
      << "; fewer with a shorter loading ([loading] self_weight_time, precompression_time, hold_time, "
         "displacement, velocity or force, force_rate), a larger [solver] safety_factor or mass_scaling, or a larger max_increments";
    throw InputError(m.str());
  }
  increments_ = solver_.total_increments();
  threads_ = threads_for(model_, options.threads);
  const int every = spec.output.every;
  every_ = every > 0 ? every : static_cast<int>(std::max(1L, increments_ / 2000));
  if (rows() > spec.output.max_rows)
    throw InputError(spec.file + ": [output] every = " + std::to_string(every) + (every == 0 ? " (about 2000 rows)" : "") +
                     " gives " + std::to_string(rows()) + " history rows over " + std::to_string(increments_) +
                     " increments: violates the rule: at most [output] max_rows = " +
                     std::to_string(spec.output.max_rows) + "; a larger every, or a larger max_rows");
  const std::vector<double>& snaps = spec.output.snapshot_times;
  if (snaps.size() > static_cast<size_t>(kMaxSnapshots))
    throw InputError(spec.file + ": [output] snapshots has " + std::to_string(snaps.size()) +
                     " times: violates the rule: at most " + std::to_string(kMaxSnapshots));
  for (double t : snaps)
    if (!(t >= 0 && t <= end))
      throw InputError(spec.file + ": [output] snapshots time " + input_number(t) +
                       " s violates the rule: 0 <= t <= the run's end, " + input_number(end) + " s");
}

}  // namespace mortar::harness
