// The Abaqus jobs of `inp --scene` and `inp --two-blocks`, read back with a
// reader of the keyword rules (inp_reader.hpp) and compared with what they
// came from: the units' corners with the geometry computed here from the
// scene file's numbers, the props with the parameter file, the amplitudes'
// corners with the scene's stage durations, the loads and displacements
// with the loading programs of examples/two_blocks/.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "input/parameter_file.hpp"
#include "input/protocol.hpp"
#include "input/scene_file.hpp"
#include "output/inp_deck.hpp"
#include "output/deck_checks.hpp"
#include "output/inp_reader.hpp"
#include "output/two_block_deck.hpp"
#include "output/wall_deck.hpp"
#include "solvers/block_solver.hpp"
#include "support.hpp"

using namespace mortar;
using namespace mortar::harness;
using namespace mortar::harness::test;

namespace {


std::vector<double> table_order(const Parameters& p) {
  return {p.kn, p.ks, p.ft0, p.c0, p.GIC, p.GIIC, p.phi0, p.phir, p.m, p.psi0, p.psir, p.n, p.bn, p.bs};
}

// The units' rectangles [x0, y0, x1, y1] from the scene's numbers: blocks
// are units plus a joint; running bond starts every other course with a
// half block; tied courses belong to the base or the beam.
std::vector<std::array<double, 4>> expected_units(const SceneSpec& s) {
  const WallGeometry& g = s.wall;
  const double bl = g.unit_length + g.joint, bh = g.unit_height + g.joint, L = g.units_per_course * bl;
  std::vector<std::array<double, 4>> out;
  for (int c = 0; c < g.courses; ++c) {
    if ((c == 0 && g.tie_bottom_course) || (c == g.courses - 1 && g.tie_top_course)) continue;
    double x = (g.bond == Bond::running && c % 2 == 1) ? 0.5 * bl : 0.0;
    if (x > 0) out.push_back({0, c * bh, x, (c + 1) * bh});
    for (; x < L - 1e-9; x += bl) out.push_back({x, c * bh, std::min(x + bl, L), (c + 1) * bh});
  }
  if (g.split_units) {  // every unit two halves
    std::vector<std::array<double, 4>> halves;
    for (const auto& u : out) {
      const double xm = 0.5 * (u[0] + u[2]);
      halves.push_back({u[0], u[1], xm, u[3]});
      halves.push_back({xm, u[1], u[2], u[3]});
    }
    out = halves;
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("inp --scene: units, rigid bodies, joints by role, props, loading", "[inputs][decks]") {
  const SceneSpec s = read_scene_file(kData + "/wall_small.toml");
  const InpModel m(wall_deck_text(s));
  const WallGeometry& g = s.wall;
  const double bl = g.unit_length + g.joint, bh = g.unit_height + g.joint, L = g.units_per_course * bl;

  // Units: every UNIT-k element set spans one expected rectangle, over the depth.
  const auto expected = expected_units(s);
  std::vector<std::array<double, 4>> found;
  for (const auto& [name, elements] : m.elsets)
    if (name.rfind("UNIT-", 0) == 0) {
      const auto b = m.box_of(name);
      CHECK(b[0][2] == 0.0);
      CHECK(b[1][2] == Approx(g.unit_depth));
      found.push_back({b[0][0], b[0][1], b[1][0], b[1][1]});
    }
  std::sort(found.begin(), found.end());
  REQUIRE(found.size() == expected.size());
  for (size_t i = 0; i < found.size(); ++i)
    for (int k = 0; k < 4; ++k) CHECK(found[i][k] == Approx(expected[i][k]).margin(1e-9));

  // Each unit a rigid body whose reference node is its centre.
  int rigid_units = 0;
  for (const InpCard* c : m.all("RIGID BODY")) {
    const std::string set = c->at("ELSET");
    if (set.rfind("UNIT-", 0) != 0) continue;
    ++rigid_units;
    const auto b = m.box_of(set);
    const auto& ref = m.nodes.at(std::atoi(c->at("REF NODE").c_str()));
    CHECK(ref[0] == Approx(0.5 * (b[0][0] + b[1][0])));
    CHECK(ref[1] == Approx(0.5 * (b[0][1] + b[1][1])));
  }
  CHECK(rigid_units == static_cast<int>(expected.size()));

  // Joints by role: every face on its plane (bed joints at course heights,
  // the base at 0, the top at the wall's height, head joints inside).
  for (const auto& [name, faces] : m.surfaces) {
    CAPTURE(name);
    for (const auto& [e, f] : faces) {
      const auto pts = m.face_nodes(e, f);
      const bool bed = name.rfind("HEAD", 0) != 0;
      for (const auto& p : pts) {
        CHECK(p[bed ? 1 : 0] == Approx(pts[0][bed ? 1 : 0]));
        if (!bed) continue;
        const double course = p[1] / bh;
        CHECK(course == Approx(std::round(course)).margin(1e-9));
        if (name.rfind("BASE", 0) == 0) CHECK(p[1] == Approx(0).margin(1e-9));
        if (name.rfind("TOP", 0) == 0) CHECK(p[1] == Approx(g.courses * bh));
        if (name.rfind("BED", 0) == 0) CHECK((p[1] > 0.5 * bh && p[1] < (g.courses - 0.5) * bh));
      }
      if (!bed) CHECK((pts[0][0] > 0 && pts[0][0] < L));
    }
  }
  for (const char* role : {"BED-A", "BED-B", "HEAD-A", "HEAD-B", "BASE-A", "BASE-B", "TOP-A", "TOP-B"})
    CHECK(m.surfaces.count(role) == 1);

  // Props: the parameter file's values, as VUINTERACTION reads them.
  const std::vector<double> params = table_order(read_parameter_file(kData + "/vdp_sn0.5.toml").values);
  const auto interactions = m.all("SURFACE INTERACTION");
  CHECK(interactions.size() == 4);
  for (const InpCard* c : interactions) {
    CHECK(c->at("USER") == "INTERACTION");
    CHECK(c->at("DEPVAR") == "35");
    CHECK(m.props(*c) == params);
  }

  // Amplitudes: corners at the ends of the scene's stages.
  const double t_sw = 0.005, t_pc = 0.005 + 0.005, t_hold = t_pc + 0.002, t_end = t_hold + 0.6 / 40.0;
  CHECK(numbers(amplitude(m, "SELF-WEIGHT")) == std::vector<double>{0, 0, t_sw, 1});
  const auto pre = numbers(amplitude(m, "PRECOMPRESSION"));
  CHECK(pre.size() == 6);
  CHECK(pre[4] == Approx(t_pc));
  CHECK(pre[5] == 1.0);
  const auto top = numbers(amplitude(m, "TOP-DISPLACEMENT"));
  REQUIRE(top.size() == 6);
  CHECK(top[2] == Approx(t_hold));
  CHECK(top[4] == Approx(t_end));
  CHECK(top[5] == Approx(0.6));
  // Loads and supports.
  CHECK(inp_number(load_line(m, "CLOAD", "BEAM-REF", 2)[2]) == Approx(-0.3 * L * g.unit_depth));
  const auto push = load_line(m, "BOUNDARY", "BEAM-REF", 1);
  REQUIRE(push.size() == 5);
  CHECK(inp_number(push[3]) == 1.0);
  CHECK(push[4] == "TOP-DISPLACEMENT");
  CHECK(load_line(m, "BOUNDARY", "BEAM-REF", 6).size() == 4);  // rotation fixed
  const auto step = m.all("DYNAMIC");
  REQUIRE(step.size() == 1);
  CHECK(step[0]->has("DIRECT USER CONTROL"));
  CHECK(inp_number(step[0]->data[0][1]) == Approx(t_end));

  // Damping: Abaqus/Explicit has DASHPOTA only (DASHPOT1/DASHPOT2 and
  // torsional dashpots are Abaqus/Standard's), so every dashpot runs from a
  // node of a body along x or y to a fixed ground node; summed per rigid
  // body about its reference node they give the scene's C = alpha·f·M on
  // every free degree of freedom (u1, u2, ur3) and nothing on the others.
  std::map<int, std::pair<int, double>> dashpot;  // element -> (ground node, coefficient)
  std::map<std::string, double> coefficient;
  for (const InpCard* c : m.all("DASHPOT")) {
    REQUIRE(c->data.size() == 2);
    CHECK(c->data[0] == std::vector<std::string>{""});  // no degrees of freedom for DASHPOTA
    coefficient[c->at("ELSET")] = inp_number(c->data[1][0]);
  }
  REQUIRE(m.nsets.count("DAMP-GROUND") == 1);
  const auto& ground = m.nsets.at("DAMP-GROUND");
  const auto fixed = load_line(m, "BOUNDARY", "DAMP-GROUND", 1);
  REQUIRE(fixed.size() == 4);
  CHECK(std::atoi(fixed[2].c_str()) == 3);
  for (const InpCard* c : m.all("ELEMENT")) {
    const std::string type = inp_upper(c->at("TYPE"));
    CHECK((type == "C3D8R" || type == "DASHPOTA"));
    if (type != "DASHPOTA") continue;
    REQUIRE(coefficient.count(c->at("ELSET")) == 1);
    for (const auto& d : c->data) {
      REQUIRE(d.size() == 3);
      const int e = std::atoi(d[0].c_str()), to = std::atoi(d[2].c_str());
      CHECK(std::count(ground.begin(), ground.end(), to) == 1);
      dashpot[e] = {to, coefficient.at(c->at("ELSET"))};
    }
  }
  const WallModel wm = build_wall(g);
  const double af = s.solver.mass_damping * s.solver.mass_scaling;
  int damped = 0;
  for (const InpCard* c : m.all("RIGID BODY")) {
    const std::string set = c->at("ELSET");
    if (set == "BASE") continue;
    const int body = set == "BEAM" ? wm.beam() : std::atoi(set.substr(5).c_str());
    const auto& ref = m.nodes.at(std::atoi(c->at("REF NODE").c_str()));
    std::set<int> nodes = {std::atoi(c->at("REF NODE").c_str())};
    for (int e : m.elsets.at(set))
      for (int n : m.elements.at(e)) nodes.insert(n);
    double D[3][3] = {};
    for (const auto& [e, gc] : dashpot) {
      const int n = m.elements.at(e)[0];
      if (!nodes.count(n)) continue;
      const auto& p = m.nodes.at(n);
      const auto& q = m.nodes.at(gc.first);
      const double dx = q[0] - p[0], dy = q[1] - p[1], dz = q[2] - p[2], len = std::sqrt(dx * dx + dy * dy + dz * dz);
      CHECK(std::max(std::abs(dx), std::abs(dy)) / len == Approx(1.0).epsilon(1e-9));  // along x or y
      const double v[3] = {dx / len, dy / len, (p[0] - ref[0]) * dy / len - (p[1] - ref[1]) * dx / len};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) D[i][j] += gc.second * v[i] * v[j];
      ++damped;
    }
    const Body& b = wm.bodies[static_cast<size_t>(body)];
    const bool beam = body == wm.beam();
    const double expected[3] = {beam ? 0.0 : af * b.mass, af * b.mass, beam ? 0.0 : af * b.inertia};
    CAPTURE(set);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        CHECK(D[i][j] == Approx(i == j ? expected[i] : 0.0).margin(1e-9 * af * (b.mass + b.inertia)));
  }
  CHECK(damped == static_cast<int>(dashpot.size()));
}

TEST_CASE("inp --scene: the J4D wall's tied courses join the base and the beam", "[inputs][decks]") {
  const SceneSpec s = read_scene_file(kExamples + "/tu_eindhoven_wall/wall_j4d_free_beam.toml");
  const InpModel m(wall_deck_text(s));
  int units = 0;
  for (const auto& [name, e] : m.elsets) units += name.rfind("UNIT-", 0) == 0;
  CHECK(units == static_cast<int>(expected_units(s).size()));
  // The unit cracks: their own interaction, with their own law.
  REQUIRE(s.wall.split_units);
  const std::string text = wall_deck_text(s);
  const size_t at = text.find("*SURFACE INTERACTION, NAME=MORTAR-UNIT-CRACK,");
  REQUIRE(at != std::string::npos);
  const size_t line = text.find('\n', text.find("** props(1..8)", at)) + 1;  // props(1) = kn, the halves in series
  CHECK(inp_number(text.substr(line, text.find(',', line) - line)) ==
        Approx(s.interface_law[static_cast<int>(InterfaceRole::unit_crack)].kn));
  const double bh = s.wall.unit_height + s.wall.joint;
  CHECK(m.box_of("BASE")[1][1] == Approx(bh));                       // the bottom course in the base
  CHECK(m.box_of("BEAM")[0][1] == Approx((s.wall.courses - 1) * bh));  // the top course in the beam
}

TEST_CASE("inp --two-blocks: geometry, props and loading match the loading programs", "[inputs][decks]") {
  const Parameters p = read_parameter_file(std::string(MJ_CALIBRATION_DATA_DIR) + "/almeida_tension/params_M15.toml").values;
  const Protocol shear = read_protocol_file(kExamples + "/two_blocks/shear.toml");
  const Protocol tension = read_protocol_file(kExamples + "/two_blocks/tension.toml");
  for (const bool standard : {false, true}) {
    CAPTURE(standard);
    std::ostringstream out;
    write_two_block_deck(out, deck_props(p, false, false, Scheme::modified_euler, 0),
                         standard ? DeckSolver::standard_contact_pair : DeckSolver::explicit_general_contact);
    const InpModel m(out.str());
    // The joint faces: on y = 0, 100 x 100 mm; the lower block's 25 nodes on it.
    double area = 0;
    for (const char* surface : {"SHEAR-UPPER-BOTTOM", "SHEAR-LOWER-TOP"}) {
      double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
      for (const auto& [e, f] : m.surfaces.at(surface))
        for (const auto& n : m.face_nodes(e, f)) {
          CHECK(n[1] == 0.0);
          lo[0] = std::min(lo[0], n[0]), hi[0] = std::max(hi[0], n[0]), lo[1] = std::min(lo[1], n[2]), hi[1] = std::max(hi[1], n[2]);
        }
      area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
      CHECK(area == 1e4);
    }
    CHECK(m.surfaces.at("TENSION-LOWER-TOP").size() == 16);
    // Props and the interaction's form.
    const auto ia = m.all("SURFACE INTERACTION");
    REQUIRE(ia.size() == 1);
    CHECK(m.props(*ia[0]) == table_order(p));
    CHECK(ia[0]->at("USER") == (standard ? "" : "INTERACTION"));
    CHECK(ia[0]->at("DEPVAR") == (standard ? "23" : "35"));
    CHECK(ia[0]->has("UNSYMM") == standard);
    if (standard) CHECK(ia[0]->data[0] == std::vector<std::string>{""});
    // Step 1: the pressure of the SHEAR program on the joint's area.
    CHECK(inp_number(load_line(m, "CLOAD", "SHEAR-REF", 2, 1)[2]) == Approx(shear.steps[0].component[0].target * area));
    // Step 2: the programs' slip and opening.
    CHECK(inp_number(load_line(m, "BOUNDARY", "SHEAR-REF", 1, 2)[3]) == shear.steps[1].component[1].target);
    CHECK(inp_number(load_line(m, "BOUNDARY", "TENSION-REF", 2, 2)[3]) == tension.steps[1].component[0].target);
    if (standard) {
      const auto st = m.all("STATIC");
      REQUIRE(st.size() == 2);
      for (int k = 0; k < 2; ++k) {
        CHECK(inp_number(st[k]->data[0][0]) * shear.steps[k].increments == Approx(1.0));
        CHECK(inp_number(st[k]->data[0][3]) * tension.steps[k].increments == Approx(1.0));
      }
      const auto pair = m.all("CONTACT PAIR");
      REQUIRE(pair.size() == 1);
      CHECK(pair[0]->step == 0);  // model data in Abaqus/Standard
    } else {
      CHECK(m.all("CONTACT PROPERTY ASSIGNMENT").size() == 1);
    }
  }
}

TEST_CASE("The shipped two-block decks are what inp --two-blocks writes today", "[inputs][decks]") {
  const Parameters p = read_parameter_file(std::string(MJ_CALIBRATION_DATA_DIR) + "/almeida_tension/params_M15.toml").values;
  for (const bool standard : {false, true}) {
    const std::string file = kExamples + "/two_blocks/two_blocks_" + (standard ? "standard" : "explicit") + ".inp";
    CAPTURE(file);
    std::ifstream in(file);
    REQUIRE(in);
    std::stringstream shipped;
    shipped << in.rdbuf();
    std::ostringstream fresh;
    write_two_block_deck(fresh, deck_props(p, false, false, Scheme::modified_euler, 0),
                         standard ? DeckSolver::standard_contact_pair : DeckSolver::explicit_general_contact);
    CHECK(shipped.str() == fresh.str());
  }
}

TEST_CASE("inp --scene: a joint file with a compression cap gives props(21..24) and DEPVAR 37", "[inputs][decks][cap]") {
  // Arrange: the one-block scene with the capped van der Pluijm joint.
  const auto dir = testing::fresh_directory("scene_cap");
  std::filesystem::copy_file(kData + "/vdp_sn0.5_cap.toml", dir / "vdp_sn0.5_cap.toml");
  std::ifstream in(kData + "/wall_one_block.toml");
  std::string scene((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string plain = "joint = \"vdp_sn0.5.toml\"";
  REQUIRE(scene.find(plain) != std::string::npos);
  scene.replace(scene.find(plain), plain.size(), "joint = \"vdp_sn0.5_cap.toml\"");
  // Act
  const SceneSpec s = read_scene_file(testing::write_file(dir / "scene.toml", scene));
  const std::string text = wall_deck_text(s);
  // Assert
  REQUIRE(s.joint.cap.on());
  CHECK(s.joint.cap.fc == 10);
  CHECK_THAT(text, Catch::Contains("PROPERTIES=24, DEPVAR=37\n"));
  CHECK_THAT(text, Catch::Contains("fc Cs Gfc kappa_p\n0., 0., 0., 0., 10., 1., 2., 0.02\n"));
}
