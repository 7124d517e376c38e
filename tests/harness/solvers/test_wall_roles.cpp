// The wall scene's interfaces by role, the units' elasticity in series, the
// held beam and force control (issue 36, items 1 and 2): each against a value
// computed without the scene solver.
#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <vector>

#include "input/input_error.hpp"
#include "input/scene_file.hpp"
#include "output/wall_deck.hpp"
#include "scenes/wall.hpp"
#include "solvers/block_solver.hpp"
#include "wall_statics.hpp"

using namespace mortar;
using namespace mortar::harness;
using namespace mortar::harness::test;

namespace {

std::string data(const char* name) { return std::string(MJ_TEST_DATA_DIR) + "/" + name; }

std::vector<WallSample> history(const SceneSpec& spec, int every = 1) {
  const WallModel model = build_wall(spec.wall);
  BlockSolver solver(spec, model, {});
  std::vector<WallSample> out;
  solver.run(every, [&](const WallSample& s) { out.push_back(s); }, nullptr, nullptr);
  return out;
}

// The last sample of a stage.
WallSample end_of_stage(const std::vector<WallSample>& h, int stage) {
  WallSample last;
  for (const WallSample& s : h)
    if (s.stage == stage) last = s;
  return last;
}

double area_of(const WallModel& m, InterfaceRole r, bool bed) {
  double a = 0;
  for (const ContactPoint& p : m.points)
    if (p.role == r && p.bed == bed) a += p.area;
  return a;
}

}  // namespace

TEST_CASE("wall: split units: two halves per unit joined at its middle, the points grouped by role", "[wall]") {
  const SceneSpec split = read_scene_file(data("wall_split_units.toml"));
  SceneSpec whole = split;
  whole.wall.split_units = false;
  const WallModel ms = build_wall(split.wall), mw = build_wall(whole.wall);
  CHECK(ms.blocks() == 2 * mw.blocks());
  // Bed and head joints keep their areas; a unit crack per unit, one unit high.
  CHECK(area_of(ms, InterfaceRole::bed, true) == Approx(area_of(mw, InterfaceRole::bed, true)));
  CHECK(area_of(ms, InterfaceRole::head, false) == Approx(area_of(mw, InterfaceRole::head, false)));
  const double bh = split.wall.unit_height + split.wall.joint;
  CHECK(area_of(ms, InterfaceRole::unit_crack, false) == Approx(mw.blocks() * bh * split.wall.unit_depth));
  // Each crack lies at the middle of the unit it splits.
  std::set<int> cracked;
  for (const ContactPoint& p : ms.points) {
    if (p.role != InterfaceRole::unit_crack) continue;
    const Body &a = ms.bodies[p.a], &b = ms.bodies[p.b];
    CHECK(a.corners[2] == Approx(p.x));  // a's right edge
    CHECK(b.corners[0] == Approx(p.x));  // b's left edge
    CHECK(a.corners[2] - a.corners[0] == Approx(b.corners[2] - b.corners[0]));
    cracked.insert(p.a);
  }
  CHECK(static_cast<int>(cracked.size()) == mw.blocks());
  // Roles in runs: bed joints, head joints, unit cracks (one interaction each).
  for (size_t i = 1; i < ms.points.size(); ++i) CHECK(ms.points[i - 1].role <= ms.points[i].role);
}

TEST_CASE("wall: kn and ks in series with the units: 1/k' = 1/k + l/E (normal), l/G (shear)", "[wall]") {
  Parameters p;
  p.kn = 80, p.ks = 30;
  const UnitElasticity rigid{}, unit{16000, 0.25};
  CHECK(in_series_with_units(p, rigid, 52).kn == 80);
  const Parameters s = in_series_with_units(p, unit, 52);
  CHECK(s.kn == Approx(1 / (1.0 / 80 + 52 / 16000.0)));
  CHECK(s.ks == Approx(1 / (1.0 / 30 + 52 / (16000 / 2.5))));
  WallGeometry g;
  g.unit_length = 210, g.unit_height = 52;
  CHECK(lumped_unit_length(g, InterfaceRole::bed) == 52);
  CHECK(lumped_unit_length(g, InterfaceRole::head) == 210);
  g.split_units = true;
  CHECK(lumped_unit_length(g, InterfaceRole::head) == 105);
  CHECK(lumped_unit_length(g, InterfaceRole::unit_crack) == 105);
}

TEST_CASE("wall: a column under precompression shortens by its joints and its units", "[wall]") {
  const SceneSpec spec = read_scene_file(data("wall_column_units.toml"));
  const std::vector<WallSample> h = history(spec);
  // Three bed joints (the clamped courses count as units): each p/kn + p·h/E.
  const double p = spec.loading.precompression, kn = spec.interface[0].values.kn;
  const double expected = -3 * (p / kn + p * spec.wall.unit_height / spec.units.young);
  const WallSample held = end_of_stage(h, 2);
  INFO("top uy " << held.top_uy << " mm, closed form " << expected << " mm");
  CHECK(held.top_uy == Approx(expected).epsilon(1e-3));
  CHECK(std::fabs(p / kn * 3 - std::fabs(expected)) > 0.3 * std::fabs(expected));  // the units' share shows
}

TEST_CASE("wall: a beam held after the precompression: its height stays, a dilatant joint gains compression",
          "[wall]") {
  const SceneSpec held = read_scene_file(data("wall_one_block_held.toml"));
  SceneSpec free = held;
  free.wall.beam_held = false;
  const std::vector<WallSample> h = history(held), f = history(free);
  WallSample start;  // the first sample of the push: the beam is held from then on
  for (const WallSample& s : h)
    if (s.stage >= 3 && start.stage < 3) start = s;
  for (const WallSample& s : h)
    if (s.stage >= 3) REQUIRE(s.top_uy == start.top_uy);
  INFO("top joint normal force: " << start.top_normal << " N after the hold, " << h.back().top_normal
                                  << " N at the end; the free beam rose " << f.back().top_uy - start.top_uy << " mm");
  CHECK(h.back().top_normal < 1.2 * start.top_normal);  // compression negative: 20 % more
  CHECK(f.back().top_uy > start.top_uy + 1e-3);          // free, the same joint lifts the beam
  CHECK(std::fabs(f.back().top_normal - start.top_normal) < 0.02 * std::fabs(start.top_normal));
  // The books still close with the hold's reaction.
  const WallEnergies& e = h.back().energy;
  CHECK(std::fabs(e.balance()) < 1e-3 * e.external);
}

TEST_CASE("wall: a force at the panel's top rocks it past the threshold of statics, not below", "[wall]") {
  SceneSpec spec = read_scene_file(data("wall_rocking_force.toml"));
  const WallModel m = build_wall(spec.wall);
  const double N = base_load(spec);
  const double threshold = N * 0.5 * m.length / spec.loading.action_height;  // moment about the toe
  for (const double factor : {0.9, 1.1}) {
    CAPTURE(factor);
    spec.loading.force = {factor * threshold};
    spec.loading.force_rate = threshold / 0.05;
    const std::vector<WallSample> h = history(spec, 10);
    INFO("threshold " << threshold << " N, end rotation " << h.back().top_rotation << ", actuator "
                      << h.back().actuator << " N");
    CHECK(h.back().actuator == Approx(factor * threshold));
    if (factor < 1)  // the joint's compliance as its contact shrinks: a tenth of the rocking's
      CHECK(std::fabs(h.back().top_rotation) < 3e-4);
    else
      CHECK(h.back().top_rotation < -1e-3);  // it rocks clockwise on its toe
  }
}

TEST_CASE("inp --scene writes a held beam and force control, refuses a displacement at a height on a turning beam",
          "[wall][decks]") {
  std::ostringstream out;
  for (const char* file : {"wall_one_block_held.toml", "wall_rocking_force.toml"}) {
    const SceneSpec s = read_scene_file(data(file));
    CHECK_NOTHROW(write_wall_deck(out, s, build_wall(s.wall), 1e-5));
  }
  SceneSpec rocking = read_scene_file(data("wall_rocking.toml"));
  const WallModel m = build_wall(rocking.wall);
  // The slender panel's alpha·I does not fit dashpots at its box corners: an input error naming it.
  CHECK_THROWS_AS(write_wall_deck(out, rocking, m, 1e-5), InputError);
  CHECK_THROWS_WITH(write_wall_deck(out, rocking, m, 1e-5), Catch::Contains("mass_damping = 50"));
  rocking.solver.mass_damping = 0;
  rocking.loading.action_height = m.bodies[m.beam()].cy;  // at the centroid: the reference node's U1
  CHECK_NOTHROW(write_wall_deck(out, rocking, m, 1e-5));
  rocking.loading.action_height = 900.0;
  CHECK_THROWS_WITH(write_wall_deck(out, rocking, m, 1e-5), Catch::Contains("action_height = 900"));
  rocking.wall.beam_rotation = BeamRotation::fixed;  // the rotation fixed: U1 is the point's at any height
  CHECK_NOTHROW(write_wall_deck(out, rocking, build_wall(rocking.wall), 1e-5));
}

TEST_CASE("scene files: extends takes the base's keys, the file's own replace them", "[wall][inputs]") {
  const SceneSpec base = read_scene_file(data("wall_one_block.toml"));
  const SceneSpec held = read_scene_file(data("wall_one_block_held.toml"));
  CHECK(held.wall.beam_held);
  CHECK_FALSE(base.wall.beam_held);
  CHECK(held.loading.precompression == base.loading.precompression);
  CHECK(held.joint.file == base.joint.file);  // the base's path, relative to the base
  CHECK(held.wall.beam_rotation == base.wall.beam_rotation);
}

TEST_CASE("wall: a displacement at the panel's top, the beam free to turn: rocking at the threshold of statics",
          "[wall]") {
  SceneSpec spec = read_scene_file(data("wall_rocking.toml"));
  const WallModel m = build_wall(spec.wall);
  const double N = base_load(spec);
  for (const double height : {m.bodies[m.beam()].cy, 600.0, 900.0}) {
    CAPTURE(height);
    spec.loading.action_height = height;
    const std::vector<WallSample> h = history(spec, 10);
    // The force on the rocking panel's plateau (the start of rocking rings
    // at the panel's frequency, lightly damped).
    const double plateau = h.back().actuator, threshold = N * 0.5 * m.length / height;
    INFO("actuator force at the end " << plateau << " N, statics " << threshold << " N, end rotation "
                                      << h.back().top_rotation);
    CHECK(std::fabs(plateau - threshold) < 0.01 * threshold);
    CHECK(h.back().top_ux == Approx(spec.loading.displacement.back()));  // the action point followed the history
    CHECK(h.back().top_rotation < -1e-3);
    const WallEnergies& e = h.back().energy;
    CHECK(std::fabs(e.balance()) < 1e-3 * e.external);
  }
}

TEST_CASE("scene files: [output] experiment is read with the scene, its rows as in the file", "[wall][inputs]") {
  const SceneSpec s = read_scene_file(std::string(MJ_CALIBRATION_DATA_DIR) + "/../examples/tu_eindhoven_wall/wall_j4d.toml");
  REQUIRE(s.output.experiment_curve.size() == 10);
  CHECK(s.output.experiment_curve[4] == std::vector<double>{1.0, 57.0});
  CHECK_THAT(s.output.experiment_label, Catch::Contains("J4D"));
  CHECK_THROWS_WITH(read_scene_file(data("bad/scene_experiment_columns.toml")),
                    Catch::Contains("experiment_no_shear.csv: has no column 'base_shear_kN'"));
}

TEST_CASE("wall: a cyclic push: the base shear turns with the displacement, the residual both ways N·tan(phir)",
          "[wall]") {
  SceneSpec spec = read_scene_file(data("wall_one_block.toml"));
  spec.loading.displacement = {1.5, -1.5, 1.5};
  const std::vector<WallSample> h = history(spec, 10);
  const double residual = base_load(spec) * std::tan(spec.joint.values.phir * 3.14159265358979323846 / 180);
  // The first sample of each leg's last tenth: sliding on the residual surface.
  double lowest = 0, highest = 0;
  for (const WallSample& s : h) {
    if (s.stage == 4 && s.top_ux < -1.4) lowest = std::min(lowest, s.base_shear);
    if (s.stage == 5 && s.top_ux > 1.4) highest = std::max(highest, s.base_shear);
  }
  INFO("N tan(phir) " << residual << " N; reversed " << lowest << " N, again forward " << highest << " N");
  CHECK(lowest == Approx(-residual).epsilon(0.02));
  CHECK(highest == Approx(residual).epsilon(0.02));
  CHECK(h.back().top_ux == Approx(1.5));
  const WallEnergies& e = h.back().energy;
  CHECK(std::fabs(e.balance()) < 1e-3 * e.external);
}
