// Whether a calibrated set may be handed over as ready. `calibrate` writes
// params.toml only for an accepted set; a rejected one goes to
// params.rejected.toml with the reasons in its header, exit status 3
// (harness/README.md, calibrate). The rules:
//  - the least squares converged (not stopped by its budget or by machine
//    precision);
//  - the misfit is near the noise: the RMS of the scaled residuals (each
//    curve's residuals over its largest |value|) at most kMaxMisfit over the
//    data set and kMaxCurveMisfit on every curve;
//  - no fitted value on a bound of the fit (fit.hpp, on_bound);
//  - every value finite, every fitted standard error a number, every curve
//    simulated, and the set valid for the law (validate).
#pragma once

#include <string>
#include <vector>

#include "calibration/calibration.hpp"
#include "calibration/fit.hpp"
#include "calibration/test_curve.hpp"

namespace mortar::harness {

// Synthetic curves with 1-3 % noise end at 0.01-0.03 (README, recovery);
// 5 % is beyond any noise a digitised curve of a joint test carries.
inline constexpr double kMaxMisfit = 0.05;
inline constexpr double kMaxCurveMisfit = 0.10;

struct Verdict {
  std::vector<std::string> reasons;  // empty: accepted
  bool accepted() const { return reasons.empty(); }
};

// The rules above for a fit and the parameter sets it produced (`sets`: the
// one set, or one per normal stress, each with a label for the message).
Verdict judge(const FitResult& fit, const std::vector<std::pair<std::string, Parameters>>& sets);

// Adds the rules on a calibration's own entries (non-finite values, a fitted
// parameter whose standard error is not a number).
void judge_entries(const Calibration& cal, Verdict& v);

// Outliers, by a stated rule: a point whose scaled residual at the fit
// exceeds kOutlierFactor times the data set's robust scatter (1.4826 x the
// median |scaled residual|, the standard deviation of Gaussian noise), and
// kMaxCurveMisfit. One line each: file, data row, quantity, value, residual.
inline constexpr double kOutlierFactor = 5;
std::vector<std::string> outliers(const FitResult& fit, const std::vector<TestCurve>& curves);

}  // namespace mortar::harness
