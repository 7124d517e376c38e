// The compression cap's parameters from compression curves (docs/model.md
// 12): direct rules on the strength sigma_c(kappa_c), read against the
// plastic closure kappa = closure - |sigma|/kn (uniaxial: the cap's flow is
// normal only).
//  - fc: the largest |sigma|, refined by least squares of the curve's shape;
//  - kappa_p: the pre-peak parabola reaches sigma_i + 0.75 (fc - sigma_i) at
//    x = kappa/kappa_p = 1/2 (a level where its slope is not zero);
//  - Gfc: the post-peak parabola ends at fc/2 at kappa_m, and
//    Gfc = 481 fc (kappa_m - kappa_p)/588;
//  - Cs: from shear curves whose peak lies on the cap (under compression
//    below fc, more than 5 % below the hyperbola of Eqs. 2-3 with p):
//    tau_p^2 = (fc^2 - sigma_n^2)/Cs, the mean; else held at Lourenco's 9.
// The set ends on validate(cap, p) or InputError naming the rule.
#pragma once

#include <string>
#include <vector>

#include "calibration/test_curve.hpp"
#include "mortar/parameters.hpp"

namespace mortar::harness {

inline constexpr double kDefaultCs = 9;  // Lourenco & Rots 1997

struct CapEstimate {
  CompressionCap cap;
  bool Cs_held = true;              // Cs at kDefaultCs: no shear curve's peak on the cap
  std::vector<std::string> notes;   // how each value was set, for the report
};

// Averages the estimates of every compression curve among `curves` (Cs from
// its shear curves); kn, c0, phi0, ft0 from p.
// InputError when there is none, or the set breaks validate(cap, p).
CapEstimate estimate_cap(const std::vector<TestCurve>& curves, const Parameters& p);

}  // namespace mortar::harness
