// The crack-to-plastic ratios bn and bs from unloading branches (docs/model.md
// 6, "Damage"): an open joint unloads along the secant through its plastic
// separation, and on a monotonic path delta_p = delta_in/(1 + b) (Eq. 17)
// with delta_in = delta - t/k the inelastic separation where the branch
// starts. So each branch gives b = delta_in/delta_p - 1, delta_p being where
// the line fitted to the branch's open points (t > 0) crosses t = 0.
//  - bn: the unloading branches of cyclic_tension curves (k = kn);
//  - bs: those of cyclic_shear curves at constant tension (k = ks); under
//    compression the joint is closed, unloads with ks through delta_p alone
//    and shows no crack slip, so bs stays a combination (GIIC/(1 + bs)).
// The values start the fit (calibration/fit.hpp), which refines them on the
// whole curves.
#pragma once

#include <string>
#include <vector>

#include "calibration/calibration.hpp"
#include "calibration/test_curve.hpp"

namespace mortar::harness {

// What one unloading branch gives.
struct UnloadingBranch {
  std::string curve;
  int first_row = 0;     // data row (1-based) where the branch starts
  int points = 0;        // open points the line was fitted to
  double delta_in = 0;   // inelastic separation at the start [mm]
  double delta_p = 0;    // where the branch's line reaches zero traction [mm]
  double ratio = NAN;    // delta_in/delta_p - 1; NaN when the branch gives none
  std::string why_not;   // why it gives none
};

// The branches of one curve: runs of points below the abscissa already
// reached, each with the envelope point before it. `k` is kn or ks.
std::vector<UnloadingBranch> unloading_branches(const TestCurve& c, double k);

// Sets the starting values of bn and bs where unloading branches give them,
// and notes what each branch gave.
void unloading_rules(const std::vector<TestCurve>& curves, Calibration& cal);

}  // namespace mortar::harness
