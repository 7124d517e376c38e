// Splitting invariance along random paths with jumps (docs/robustness.md,
// Splitting invariance; the controls and bounds of test_splitting.cpp):
// seeded random waypoints in (opening, slip 1, slip 2), scaled by the set's
// elastic limits and softening lengths, with reversals and jumps of 2-5
// elastic limits taken as one increment (splitting_paths.hpp, random_jumps).
//
// Left out, with the error measured (relative to the path's peak; 1 and 20
// calls tight against 100, default 1 call against the tight reference).
// Every one is a point that slides on the regime boundary (sigma_n = 0,
// delta_e_n = 0) or crosses it while sliding: where and whether the switch
// happens depends on the cut (docs/model.md 6, Regime switches).
//   vdP-0.1  1e-3: tight 5.7e-4 (1 call), 2.9e-4 (20), default 5.7e-4; and
//                  30-60 s to run
//   vdP-0.5  1e-3: tight 9.9e-6 (1 call); 20 calls and default (1.0e-4)
//                  are checked
//   M15      1e-3: tight 4.0e-6 (1), 2.8e-5 (20), default 1.5e-2 (closing
//                  while sliding: the switch to closed and the closure return)
//   M34      1e-3: tight 4.8e-6 (1 call); 20 calls and default (3.8e-4)
//                  are checked
//   Atk      1e-3: tight 7.4e-2 (1), 2.9e-3 (20), default 7.4e-2 (1 call
//                  stays open at sigma_n = 0 where the reference closes)
//   rnd2     1e-3: tight 1.1e-1 (1), 3.7e-3 (20), default 1.1e-1 (contact
//                  regained on the reference, not with 1 call)
//   vdP-1.0  1e-5: tight 1.1e-6 (1 call); 20 calls (8.2e-7) and default
//                  (4.9e-5) are checked
#include "splitting_check.hpp"

using namespace mj_test::splitting;

namespace {

std::vector<LeftOut> every_cut(const std::string& set, double h) {
  return {{set, h, Cut::tight_1}, {set, h, Cut::tight_20}, {set, h, Cut::default_1}};
}

std::vector<LeftOut> left_out_at_1e3() {
  std::vector<LeftOut> v = {{"vdP-0.5", 1e-3, Cut::tight_1}, {"M34", 1e-3, Cut::tight_1}};
  for (const char* s : {"vdP-0.1", "M15", "Atk", "rnd2"})
    for (const LeftOut& o : every_cut(s, 1e-3)) v.push_back(o);
  return v;
}

}  // namespace

TEST_CASE("Splitting: random paths with jumps, h = 1e-3 mm", "[splitting]") {
  check_cells("random-jumps", all_cells(1e-3), left_out_at_1e3());
}

TEST_CASE("Splitting: random paths with jumps, h = 1e-4 and 1e-5 mm", "[splitting]") {
  check_cells("random-jumps", fine_cells("random-jumps", 1e-4));
  check_cells("random-jumps", fine_cells("random-jumps", 1e-5), {{"vdP-1.0", 1e-5, Cut::tight_1}});
}
