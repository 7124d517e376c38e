// The scene deck's loading beyond a pushed beam, read back: a beam held from
// the end of the hold on (a second step), and force control (a CLOAD and its
// moment at the action's height), against the scene's stage ends and values.
#include <catch2/catch.hpp>

#include <string>

#include "input/scene_file.hpp"
#include "output/deck_checks.hpp"
#include "output/inp_reader.hpp"
#include "support.hpp"

using namespace mortar;
using namespace mortar::harness;
using namespace mortar::harness::test;

TEST_CASE("inp --scene: a held beam's U2 is held from the end of the hold on, in a second step", "[inputs][decks]") {
  for (const std::string& file :
       {kData + "/wall_one_block_held.toml", kExamples + "/tu_eindhoven_wall/wall_j4d.toml"}) {
    INFO(file);
    const SceneSpec s = read_scene_file(file);
    REQUIRE(s.wall.beam_held);
    const InpModel m(wall_deck_text(s));
    const std::vector<double> ends = s.stage_ends();
    // Two explicit steps, LOAD to the end of the hold, HELD to the end.
    const auto steps = m.all("STEP");
    REQUIRE(steps.size() == 2);
    CHECK(steps[0]->at("NAME") == "LOAD");
    CHECK(steps[1]->at("NAME") == "HELD");
    const auto dynamic = m.all("DYNAMIC");
    REQUIRE(dynamic.size() == 2);
    CHECK(inp_number(dynamic[0]->data[0][1]) == Approx(ends[2]));
    CHECK(inp_number(dynamic[1]->data[0][1]) == Approx(ends.back() - ends[2]));
    // The hold: a zero velocity on the beam's U2 in the second step only.
    const auto held = load_line(m, "BOUNDARY", "BEAM-REF", 2, 2);
    REQUIRE(held.size() == 5);
    CHECK(inp_number(held[2]) == 2);
    CHECK(inp_number(held[3]) == 0.0);
    CHECK(load_line(m, "BOUNDARY", "BEAM-REF", 2, 1).empty());
    for (const InpCard* c : m.all("BOUNDARY"))
      if (c->step == 2) CHECK(c->at("TYPE") == "VELOCITY");
    // The histories on total time, so that they run on through the second step.
    for (const InpCard* c : m.all("AMPLITUDE")) CHECK(c->at("TIME") == "TOTAL TIME");
    const auto top = numbers(amplitude(m, "TOP-DISPLACEMENT"));
    REQUIRE(top.size() == 2 * (2 + s.loading.corners().size()));
    CHECK(top[2] == Approx(ends[2]));
    for (size_t k = 0; k < s.loading.corners().size(); ++k) {
      CHECK(top[4 + 2 * k] == Approx(ends[3 + k]));
      CHECK(top[5 + 2 * k] == Approx(s.loading.corners()[k]));
    }
    // The precompression stays on (in the first step, carried over).
    const WallModel wm = build_wall(s.wall);
    CHECK(inp_number(load_line(m, "CLOAD", "BEAM-REF", 2, 1)[2]) ==
          Approx(-s.loading.precompression * wm.length * s.wall.unit_depth));
  }
}

TEST_CASE("inp --scene: force control is a CLOAD through the force corners, its moment at the action's height",
          "[inputs][decks]") {
  const SceneSpec s = read_scene_file(kData + "/wall_rocking_force.toml");
  REQUIRE(s.loading.force_control);
  const WallModel wm = build_wall(s.wall);
  const InpModel m(wall_deck_text(s));
  const std::vector<double> ends = s.stage_ends();
  REQUIRE(m.all("STEP").size() == 1);
  // No displacement on the beam's U1; the force along 1 and -F·arm about 3.
  CHECK(load_line(m, "BOUNDARY", "BEAM-REF", 1).empty());
  const auto fx = load_line(m, "CLOAD", "BEAM-REF", 1);
  REQUIRE(fx.size() == 4);
  CHECK(inp_number(fx[2]) == 1.0);
  CHECK(fx[3] == "TOP-FORCE");
  const double arm = s.loading.action_height - wm.bodies.back().cy;
  REQUIRE(arm != 0);
  const auto mz = load_line(m, "CLOAD", "BEAM-REF", 6);
  REQUIRE(mz.size() == 4);
  CHECK(inp_number(mz[2]) == Approx(-arm));
  CHECK(mz[3] == "TOP-FORCE");
  CHECK(load_line(m, "BOUNDARY", "BEAM-REF", 6).empty());  // the beam free to turn
  // The force's corners at the ends of the scene's stages.
  const auto top = numbers(amplitude(m, "TOP-FORCE"));
  REQUIRE(top.size() == 2 * (2 + s.loading.force.size()));
  CHECK(top[2] == Approx(ends[2]));
  CHECK(top[3] == 0.0);
  for (size_t k = 0; k < s.loading.force.size(); ++k) {
    CHECK(top[4 + 2 * k] == Approx(ends[3 + k]));
    CHECK(top[5 + 2 * k] == Approx(s.loading.force[k]));
  }
  // The beam's ux is free, so it is damped like the units' (alpha·m along x).
  bool beam_x = false;
  for (const auto& [name, e] : m.elsets) beam_x = beam_x || name == "DAMP-BEAM-X";
  CHECK(beam_x);
}
