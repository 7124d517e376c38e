// The direct rules of the tension curves: kn, ft0 and GIC from the law's
// closed form in pure mode I (docs/model.md 4). Up to the peak the joint is
// elastic, sigma = kn d; after it the traction stays on the surface,
//   sigma = ft0 exp(-(ft0/GIC) (d - sigma/kn)),
// whose area is GIC. Both branches together are fitted by least squares on
// the traction (the noise of a digitised curve is additive on it), so the
// peak, the slope and the area come from every point rather than from the
// largest sample, the points below 90 % of it, or the log of a noisy tail.
//
// Where the softening snaps back (ft0^2/(GIC kn) >= 1, docs/model.md 6) the
// joint drops at fixed separation: with ft0^2/(GIC kn) >= 2 the elastic energy
// at the peak, ft0^2/(2 kn), covers GIC and the joint separates completely;
// between 1 and 2 it drops to a stable point and then follows the surface,
// sigma = A exp(-(ft0/GIC) (d - sigma/kn)) with A < ft0. There kn is the
// initial slope, ft0 the elastic line at the peak, and GIC the tail's decay
// rate; without a tail above the noise GIC is not determined and is set to
// its bound, ft0^2/(2 kn).
#pragma once

#include <string>
#include <vector>

#include "calibration/calibration.hpp"
#include "calibration/test_curve.hpp"

namespace mortar::harness {

struct TensionRules {
  CalibratedParameter kn, ft0, GIC;
  double correlation[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // of kn, ft0, GIC where fitted together
  std::vector<std::string> notes;  // a snap-back and what it left determined
};

// Every tension curve's loading envelope (its virgin curve). InputError when fewer than 2 points lie
// on the elastic branch.
TensionRules tension_rules(const std::vector<TestCurve>& curves);

}  // namespace mortar::harness
