// Splitting invariance along random paths with jumps (docs/robustness.md,
// Splitting invariance; the controls and bounds of test_splitting.cpp):
// seeded random waypoints in (opening, slip 1, slip 2), scaled by the set's
// elastic limits and softening lengths, with reversals and jumps of 2-5
// elastic limits taken as one increment (splitting_paths.hpp, random_jumps).
//
// Every cut of every cell is checked: the decisions on slip across the
// elastic slip and on complete normal damage (docs/model.md 6) brought the
// worn open joint of rnd2 from 1.1e-1 of peak to 1.8e-9 (tight) and the jumps
// taken as one call (vdP -0.1, -0.5, M34, Atk) from 2.6e-6 ... 3.7e-4 below
// 1e-6, with the tight controls' smallest substep at 1e-6 of the call
// (splitting_paths.hpp).
#include <algorithm>

#include "splitting_check.hpp"

using namespace mj_test::splitting;

TEST_CASE("Splitting: random paths with jumps, h = 1e-3 mm", "[splitting]") {
  // M15 first: under the sanitizers only the first cell runs
  // (splitting_check.hpp).
  std::vector<Cell> cells = all_cells(1e-3);
  std::rotate(cells.begin(), std::find_if(cells.begin(), cells.end(), [](const Cell& c) { return c.set == "M15"; }),
              cells.end());
  check_cells("random-jumps", cells);
}

TEST_CASE("Splitting: random paths with jumps, h = 1e-4 and 1e-5 mm", "[splitting]") {
  check_cells("random-jumps", fine_cells("random-jumps", 1e-4));
  check_cells("random-jumps", fine_cells("random-jumps", 1e-5));
}
