// The files behind the wall pictures (output/scene_csv.hpp): the dissipation
// written per point against the points' states, the pictures' magnification
// against rigid motions, and the history's energy columns against the
// balance they must close.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "abi/props.hpp"
#include "input/scene_file.hpp"
#include "mortar/state_layout.hpp"
#include "output/scene_csv.hpp"
#include "solvers/block_solver.hpp"
#include "solvers/joint_calls.hpp"
#include "support.hpp"

using namespace mortar;
using namespace mortar::harness;
using namespace mortar::harness::testing;

namespace {

// A CSV with a header: its columns by name.
std::map<std::string, std::vector<double>> read_csv(const std::string& path) {
  std::ifstream in(path);
  std::string line, cell;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::istringstream h(line); std::getline(h, cell, ',');) names.push_back(cell);
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::istringstream r(line);
    for (const std::string& name : names) {
      std::getline(r, cell, ',');
      columns[name].push_back(std::stod(cell));
    }
  }
  return columns;
}

bool agree(double a, double b, double scale) { return std::fabs(a - b) <= 1e-9 * std::max(1.0, scale); }

}  // namespace

TEST_CASE("scene output: the dissipation per point is SDV 16 + 17 + 18 of the point", "[scene_output]") {
  // Arrange: the small wall's joints driven through vuinteraction_ by the top
  // beam alone (every block held): the top joint opened a little and slipped
  // past its peak (plastic and damage dissipation), closed with its slip held
  // (the closure releases energy, SDV 18), slipped further and lifted.
  const SceneSpec spec = read_scene_file(data_file("wall_small.toml"));
  const WallModel model = build_wall(spec.wall);
  JointCalls joints(model, interface_setups(spec), 16, 1);
  CallTime time;
  joints.reference(time);
  std::vector<double> q(3 * model.bodies.size(), 0.0);
  const int beam = 3 * model.beam();
  // The beam's ux, uy at the end of each leg [mm].
  const double path[][2] = {{0, 0.002}, {0.05, 0.002}, {0.05, -0.002}, {0.3, -0.002}, {0.3, 0.05}};
  double ux = 0, uy = 0;
  for (const auto& leg : path)
    for (int k = 1; k <= 50; ++k) {
      q[beam] = ux + (leg[0] - ux) * k / 50, q[beam + 1] = uy + (leg[1] - uy) * k / 50;
      ++time.increment;
      joints.update(q, time);
      if (k == 50) ux = leg[0], uy = leg[1];
    }
  // Act
  const WallSnapshot snap = wall_snapshot(joints, q, 1.0, "end");
  const std::filesystem::path dir = fresh_directory("scene_dissipation");
  write_snapshot_csv(dir.string(), 0, model, snap, 10.0);
  auto csv = read_csv((dir / "snapshot_0_joints.csv").string());
  // Assert: every part of the sum occurs, so a part left out shows.
  REQUIRE(csv["dissipation_N_per_mm"].size() == model.points.size());
  double largest[3] = {0, 0, 0};
  for (int i = 0; i < joints.points(); ++i) {
    const double parts[3] = {joints.state(i, slot::dissipation_plastic), joints.state(i, slot::dissipation_damage),
                             joints.state(i, slot::energy_unilateral)};
    for (int j = 0; j < 3; ++j) largest[j] = std::max(largest[j], parts[j]);
    const double sum = parts[0] + parts[1] + parts[2];
    CAPTURE(i, sum, csv["dissipation_N_per_mm"][i]);
    CHECK(std::fabs(csv["dissipation_N_per_mm"][i] - sum) <= 1e-9 * sum);
    CHECK(csv["d_n"][i] == Approx(joints.state(i, slot::damage_n)).margin(1e-12));
    CHECK(csv["d_s"][i] == Approx(joints.state(i, slot::damage_s)).margin(1e-12));
    CHECK(csv["opening_mm"][i] == Approx(joints.opening(i)).margin(1e-12));
    CHECK(csv["slip_mm"][i] == Approx(joints.slip(i)).margin(1e-12));
    CHECK(csv["role"][i] == static_cast<int>(model.points[static_cast<size_t>(i)].role));
    CHECK(csv["kappa_c_mm"][i] == 0.0);  // no cap in this wall's law
  }
  INFO("largest SDV 16, 17, 18: " << largest[0] << ", " << largest[1] << ", " << largest[2] << " N/mm");
  CHECK(largest[0] > 0);
  CHECK(largest[1] > 0);
  CHECK(largest[2] > 0);
}

TEST_CASE("scene output: the magnification follows the joints' relative motion, not a rigid motion",
          "[scene_output]") {
  // Arrange: the small wall part-way through its push (the beam's slip and
  // the blocks' rocking), then the same with every body moved rigidly.
  const SceneSpec spec = read_scene_file(data_file("wall_small.toml"));
  const WallModel model = build_wall(spec.wall);
  BlockSolverOptions options;
  options.max_increments = 2500;
  std::vector<WallSnapshot> snaps;
  BlockSolver(spec, model, options).run(0, nullptr, nullptr, &snaps);
  const WallSnapshot& s = snaps.back();
  WallSnapshot moved = s;
  const double tx = 3.0, ty = -1.5, theta = 0.01, x0 = 100, y0 = 50;  // a rigid motion about (x0, y0)
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    moved.q[3 * b] += tx - theta * (model.bodies[b].cy - y0);
    moved.q[3 * b + 1] += ty + theta * (model.bodies[b].cx - x0);
    moved.q[3 * b + 2] += theta;
  }
  // Act
  const Magnification m = picture_magnification(spec.output, model, s);
  const Magnification m_moved = picture_magnification(spec.output, model, moved);
  // Assert: the largest relative displacement is the largest |opening, slip|
  // that the joints computed for themselves, and the rigid motion (far larger)
  // changes neither it nor the factor.
  double largest = 0;
  for (size_t i = 0; i < s.opening.size(); ++i) largest = std::max(largest, std::hypot(s.opening[i], s.slip[i]));
  CAPTURE(largest, m.largest_relative, m_moved.largest_relative, m.factor, m_moved.factor);
  REQUIRE(largest > 1e-4);
  CHECK(m.largest_relative == Approx(largest).epsilon(1e-9));
  CHECK(m.automatic);
  CHECK(m.factor == Approx(0.05 * model.height / largest).epsilon(1e-9));
  CHECK(m_moved.largest_relative == Approx(m.largest_relative).epsilon(1e-9));
  CHECK(m_moved.factor == Approx(m.factor).epsilon(1e-9));
  // The scene file's factor wins.
  SceneOutputSpec given = spec.output;
  given.magnification = 50;
  const Magnification g = picture_magnification(given, model, moved);
  CHECK(g.factor == 50);
  CHECK_FALSE(g.automatic);
}

TEST_CASE("scene output: the history's energy columns add up to its balance", "[scene_output]") {
  // Arrange: the small wall pushed until it cracks, every 50th increment written.
  const SceneSpec spec = read_scene_file(data_file("wall_small.toml"));
  const WallModel model = build_wall(spec.wall);
  const std::filesystem::path dir = fresh_directory("scene_energy");
  {
    HistoryCsv history((dir / "history.csv").string());
    BlockSolver(spec, model, {}).run(50, [&](const WallSample& s) { history.row(s); }, nullptr, nullptr);
  }
  // Act
  auto h = read_csv((dir / "history.csv").string());
  // Assert: in every row, the sum of the parts is the accounted energy, the
  // external work minus it the balance error; the three dissipation parts
  // add up to the dissipation.
  const size_t rows = h["time"].size();
  REQUIRE(rows > 10);
  for (size_t r = 0; r < rows; ++r) {
    const double external = h["external_work"][r], dissipation = h["dissipation"][r];
    const double parts = h["elastic_energy"][r] + dissipation + h["kinetic_energy"][r] + h["damping_work"][r];
    const double split = h["plastic_dissipation"][r] + h["damage_dissipation"][r] + h["unilateral_energy"][r];
    CAPTURE(r, external, parts, h["energy_accounted"][r], h["balance_error"][r], dissipation, split);
    CHECK(agree(h["energy_accounted"][r], parts, external));
    CHECK(agree(h["balance_error"][r], external - h["energy_accounted"][r], external));
    CHECK(std::fabs(split - dissipation) <= 1e-6 * std::max(1.0, dissipation));
  }
  // The books close: the balance error is small against the external work.
  CHECK(h["dissipation"].back() > 0.2 * h["external_work"].back());
  CHECK(std::fabs(h["balance_error"].back()) < 1e-3 * h["external_work"].back());
}
