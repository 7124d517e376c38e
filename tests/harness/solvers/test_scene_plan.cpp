// A scene checked before it runs (solvers/scene_plan.hpp): a top beam of no
// height, the planned rows against the rows a run writes, the bounds as
// input errors that name the key.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "input/input_error.hpp"
#include "input/scene_file.hpp"
#include "solvers/scene_plan.hpp"

using namespace mortar;
using namespace mortar::harness;

namespace {

std::string data(const char* name) { return std::string(MJ_TEST_DATA_DIR) + "/" + name; }

// The message of the InputError that building a plan of `spec` throws.
std::string plan_error(const SceneSpec& spec) {
  try {
    ScenePlan plan(spec, {});
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("scene plan: a top beam of no height is its mass along the top of the wall", "[wall]") {
  SceneSpec spec = read_scene_file(data("wall_small.toml"));
  spec.wall.beam_height = 0;
  const ScenePlan plan(spec, {});
  const WallModel& m = plan.model();
  const Body& beam = m.bodies[m.beam()];
  const double mass = spec.wall.beam_mass, L = m.length;
  CHECK(beam.mass == mass);
  CHECK(beam.cx == Approx(0.5 * L));
  CHECK(beam.cy == m.height);
  CHECK(beam.inertia == Approx(mass * L * L / 12).epsilon(1e-12));
  // With a height h the inertia is m (L² + h²) / 12 about the beam's middle.
  SceneSpec tall = spec;
  tall.wall.beam_height = 100;
  const WallModel t = build_scene_wall(tall);
  CHECK(t.bodies[t.beam()].inertia == Approx(mass * (L * L + 100.0 * 100.0) / 12).epsilon(1e-12));
  CHECK(t.bodies[t.beam()].cy == Approx(m.height + 50));
}

TEST_CASE("scene plan: a run writes the rows the plan counts", "[wall]") {
  SceneSpec spec = read_scene_file(data("wall_small.toml"));
  for (int every : {1, 7, 2342, 5000}) {
    spec.output.every = every;
    ScenePlan plan(spec, {});
    long rows = 0;
    plan.solver().run(plan.every(), [&](const WallSample&) { ++rows; }, nullptr, nullptr);
    INFO("every " << every << ", " << plan.increments() << " increments");
    CHECK(rows == plan.rows());
  }
}

TEST_CASE("scene plan: the bounds are input errors naming the key, the value and the rule", "[wall]") {
  const SceneSpec good = read_scene_file(data("wall_small.toml"));
  const ScenePlan plan(good, {});
  REQUIRE(plan.increments() == 2342);

  SceneSpec s = good;
  s.solver.max_increments = 2341;
  CHECK_THAT(plan_error(s), Catch::Contains("the run plans 2342 increments") &&
                                Catch::Contains("at most [solver] max_increments = 2341"));
  s.solver.max_increments = 2342;
  CHECK(plan_error(s) == "no error");

  s = good;
  s.output.every = 1;
  s.output.max_rows = 2342;
  CHECK_THAT(plan_error(s), Catch::Contains("[output] every = 1 gives 2343 history rows") &&
                                Catch::Contains("at most [output] max_rows = 2342"));
  s.output.max_rows = 2343;
  CHECK(plan_error(s) == "no error");

  s = good;
  s.output.snapshot_times.assign(kMaxSnapshots + 1, 0.01);
  CHECK_THAT(plan_error(s), Catch::Contains("[output] snapshots has 101 times"));
  s.output.snapshot_times = {0.1};
  CHECK_THAT(plan_error(s), Catch::Contains("[output] snapshots time 0.1 s violates the rule"));

  s = good;
  s.loading.precompression = 2e3;
  CHECK_THAT(plan_error(s), Catch::Contains("[loading] precompression = 2000 MPa violates the rule: <= 1000 MPa"));
  s = good;
  s.loading.velocity = 1e7;
  CHECK_THAT(plan_error(s), Catch::Contains("[loading] velocity = 10000000 mm/s violates the rule"));

  s = good;
  s.wall.density = 0;
  CHECK_THAT(plan_error(s), Catch::Contains("[wall] density = 0 kg/m^3 leaves the blocks without mass"));
  s.wall.tie_top_course = true;
  s.wall.beam_mass = 0;
  CHECK_THAT(plan_error(s), Catch::Contains("the top beam has no mass"));
}

TEST_CASE("scene plan: at most one thread per kPointsPerThread contact points", "[wall]") {
  const SceneSpec small = read_scene_file(data("wall_small.toml"));  // 69 points
  const SceneSpec j4d = read_scene_file(std::string(MJ_CALIBRATION_DATA_DIR) + "/../examples/tu_eindhoven_wall/wall_j4d.toml");
  BlockSolverOptions o;
  o.threads = 2;
  CHECK(ScenePlan(small, o).threads() == 1);
  const ScenePlan plan(j4d, o);
  const int most = static_cast<int>(plan.model().points.size()) / kPointsPerThread;
  REQUIRE(most >= 2);
  CHECK(plan.threads() == 2);
  o.threads = most + 5;
  CHECK(ScenePlan(j4d, o).threads() == most);
}
