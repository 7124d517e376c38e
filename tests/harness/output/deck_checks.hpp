// What the deck read-back tests share: a scene's deck as text, an amplitude
// by name, a card's numbers, a load or boundary line by node set and dof.
#pragma once

#include <catch2/catch.hpp>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "input/scene_file.hpp"
#include "output/inp_reader.hpp"
#include "output/wall_deck.hpp"
#include "solvers/block_solver.hpp"

namespace mortar::harness::test {

inline const std::string kData = MJ_TEST_DATA_DIR;
inline const std::string kExamples = std::string(MJ_CALIBRATION_DATA_DIR) + "/../examples";

inline std::string wall_deck_text(const SceneSpec& s) {
  const WallModel m = build_wall(s.wall);
  std::ostringstream out;
  write_wall_deck(out, s, m, BlockSolver(s, m, BlockSolverOptions{}).time_increment());
  return out.str();
}

inline const InpCard& amplitude(const InpModel& m, const std::string& name) {
  for (const InpCard* c : m.all("AMPLITUDE"))
    if (c->at("NAME") == name) return *c;
  FAIL("no amplitude " << name);
  throw;
}

inline std::vector<double> numbers(const InpCard& c) {
  std::vector<double> out;
  for (const auto& d : c.data)
    for (const auto& f : d) out.push_back(inp_number(f));
  return out;
}

// The data line of a *BOUNDARY or *CLOAD (in `step`) on `node_set` and `dof`.
inline std::vector<std::string> load_line(const InpModel& m, const std::string& keyword,
                                          const std::string& node_set, int dof, int step = -1) {
  std::vector<std::string> found;
  for (const InpCard* c : m.all(keyword))
    for (const auto& d : c->data)
      if (d[0] == node_set && std::atoi(d[1].c_str()) == dof && (step < 0 || c->step == step)) {
        found = d;
        found.push_back(c->at("AMPLITUDE"));
      }
  return found;
}

}  // namespace mortar::harness::test
