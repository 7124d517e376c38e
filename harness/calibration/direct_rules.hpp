// The first stage of the calibration: parameters that standard tests give
// directly (the paper's "calibration methods ... using common test data and
// physical rules"), each by a regression on the data points with its standard
// error from that regression:
//  - ks: the slope through the origin of the shear curves' elastic branches
//    (Eq. 1: the law is elastic up to the peak);
//  - kn, ft0, GIC: the tension curve in closed form, elastic to the peak, then
//    sigma = ft0 exp(-ft0 d_in / GIC) with d_in = d - sigma/kn (docs/model.md
//    4), by least squares on all its points; snap-back included
//    (calibration/tension_rules.hpp);
//  - c0, phi0 (and ft0 without a tension test): the hyperbola of Eqs. 2-3
//    through the peak shear strengths, tau_p^2 = c0^2 - (c0^2/ft0 + ft0 tan^2 phi0)
//    sigma_n + tan^2 phi0 sigma_n^2, linear in its coefficients, with
//    phi0 >= phir (docs/model.md 2);
//  - phir: the residual strengths, tau_r = tan(phir) |sigma_n| (Eq. 6 worn out);
//  - psi0 (a starting value for the fit): the initial dilatancy after the
//    peak, d(uplift)/d(plastic slip) = tan(psi) sqrt(alpha^2 + tau^2)/|tau| (docs/model.md 5).
// Parameters the data leave open get a stated placeholder, marked not determined.
#pragma once

#include <vector>

#include "calibration/calibration.hpp"
#include "calibration/test_curve.hpp"

namespace mortar::harness {

// What the rules read off one shear curve (for the report and the fit).
struct ShearPeak {
  std::string curve;
  double sigma_n = 0;   // [MPa]
  double peak = 0;      // largest tau [MPa]
  double residual = 0;  // mean tau over the last quarter of the slip [MPa]
};

struct DirectResult {
  Calibration calibration;        // direct values; the fit's parameters hold starting values
  std::vector<ShearPeak> peaks;   // one per shear curve
};

// InputError when the data cannot give the direct parameters: no shear
// curve, fewer than two normal stresses, or fewer than three without a
// tension curve (ft0 then comes from the hyperbola alone).
DirectResult apply_direct_rules(const std::vector<TestCurve>& curves);

// Another start for the fit (calibration/pipeline.cpp): the rules' start
// with c0 kept, phi0 multiplied by `factor`, and m, n, psi0 recomputed from
// it by the same rules. Where the peaks are not sampled the hyperbola reads
// phi0 low, and the fit from the rules' start can stall far from the data.
Calibration raised_start(const std::vector<TestCurve>& curves, const Calibration& rules, double factor);

// The placeholders that follow other parameters (kn and GIC without a tension
// curve, psir): set by the rules, and again after the fit has moved GIIC.
void fill_placeholders(bool tension, Calibration& cal);

}  // namespace mortar::harness
