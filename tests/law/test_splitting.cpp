// Splitting invariance (docs/model.md 6, Decision - complete separation at
// s_sep; 7.1, Decisions - s relative, loading from the surface): the traction
// after an increment does not depend on how the solver cuts it into calls.
// Each path (tests/support/splitting_paths.hpp) is cut into increments of
// size h; each increment is handed to integrate_increment as N equal calls,
// and the traction after every increment is compared with the tight
// reference (STOL 1e-9, FTOL 1e-12, 100 calls per increment), relative to the
// path's peak traction (splitting_check.hpp):
//   (a) tight controls, 1 and 20 calls: within 1e-6;
//   (b) default controls (STOL 1e-5, FTOL 1e-8), 1 call: within 1e-3.
// h = 1e-3 mm on Table 1's six sets and three random valid ones; 1e-4 and
// 1e-5 mm on a subset (splitting_cells.hpp) along shorter paths. Random paths
// with jumps: test_splitting_jumps.cpp. The table of every cell:
// tests/law/splitting_table.cpp, docs/robustness.md.
#include "splitting_check.hpp"

using namespace mj_test::splitting;

// Proves that complete separation at s_sep (model.md 6) and regaining
// contact at delta_n = delta_p_n (the largest opening over 1 + bn) land in
// the same place however the increments are cut.
TEST_CASE("Splitting: repeated separation and reclosing, shear of both signs between, h = 1e-3 mm",
          "[splitting]") {
  check_cells("separation", all_cells(1e-3));
}
TEST_CASE("Splitting: repeated separation and reclosing, h = 1e-4 and 1e-5 mm", "[splitting]") {
  check_cells("separation", fine_cells("separation", 1e-4));
  // rnd0 included: the round-off of the summed works, amplified by 1/s_sep,
  // still moves the place of separation, but no longer where contact is
  // regained (model.md 6, Decision - opening past complete normal damage).
  check_cells("separation", fine_cells("separation", 1e-5));
}

// Proves the open-regime branches (model.md 6, Decision - open-regime
// branches; unloading slip on the shear secant) do not depend on the cuts
// while the joint opens and softens on the tension cap with the slip
// reversing.
TEST_CASE("Splitting: slip reversals while opening and softening on the tension cap, h = 1e-3 mm", "[splitting]") {
  check_cells("cap", all_cells(1e-3));
}
TEST_CASE("Splitting: slip reversals on the tension cap, h = 1e-4 and 1e-5 mm", "[splitting]") {
  check_cells("cap", fine_cells("cap", 1e-4));
  check_cells("cap", fine_cells("cap", 1e-5));
}

// Proves the regime switches (model.md 6, Regime switches) and the closure
// return at fixed separation are found at the same place for any cut.
TEST_CASE("Splitting: open, shear, close, h = 1e-3 mm", "[splitting]") {
  check_cells("open-shear-close", all_cells(1e-3));
}
TEST_CASE("Splitting: open, shear, close, h = 1e-4 and 1e-5 mm", "[splitting]") {
  check_cells("open-shear-close", fine_cells("open-shear-close", 1e-4));
  check_cells("open-shear-close", fine_cells("open-shear-close", 1e-5));
}

// Proves the closed-regime flow with wear and dilatancy (model.md 5) is
// cut-independent when the slip turns by 90 degrees and reverses.
TEST_CASE("Splitting: 3D slip under compression with direction changes, h = 1e-3 mm", "[splitting]") {
  check_cells("slip3d", all_cells(1e-3));
}
TEST_CASE("Splitting: 3D slip with direction changes, h = 1e-4 and 1e-5 mm", "[splitting]") {
  check_cells("slip3d", fine_cells("slip3d", 1e-4));
  check_cells("slip3d", fine_cells("slip3d", 1e-5));
}

// Proves the compression cap (model.md 12) is cut-independent: the yield on
// the cap, its hardening and softening, the corner with the hyperbola (Koiter,
// two multipliers), a slip reversal on the cap, opening and reloading onto the
// softened cap.
TEST_CASE("Splitting: crushing on the compression cap, through the corner, h = 1e-3 mm", "[splitting][cap]") {
  check_cells("crush", all_cells(1e-3));
}
TEST_CASE("Splitting: crushing on the compression cap, h = 1e-4 and 1e-5 mm", "[splitting][cap]") {
  check_cells("crush", fine_cells("crush", 1e-4));
  check_cells("crush", fine_cells("crush", 1e-5));
}
