// The whole calibration of a set of test curves, as `calibrate` runs it and
// the tests and the recovery study check it: the direct rules, the one-set
// fit with its uncertainty (from the rules' start, or from a raised phi0
// where that fit stalls), the final parameter set, and on request the fit
// of m and n per normal stress.
#pragma once

#include <functional>
#include <vector>

#include "calibration/acceptance.hpp"
#include "calibration/direct_rules.hpp"
#include "calibration/fit.hpp"
#include "calibration/uncertainty.hpp"

namespace mortar::harness {

struct CalibrationRun {
  DirectResult direct;
  Calibration start;  // where the one set's fit started: the rules' values or a raised start
  FitResult one_set;
  Uncertainty one_set_uncertainty;
  Calibration final;  // the one set, with errors and stages
  bool per_level_fitted = false;
  FitResult per_level;  // m and n per sigma_n (when per_level_fitted)
  Parameters per_level_base;  // its start: the values of what it did not fit
  Uncertainty per_level_uncertainty;
  Verdict one_set_verdict;    // calibration/acceptance.hpp: may `final` be handed over?
  Verdict per_level_verdict;  // and the sets per sigma_n
  std::vector<std::string> outliers;  // points far off the one set's fit (acceptance.hpp)
};

// The parameter set of each normal stress of a per-level fit: (sigma_n, set).
std::vector<std::pair<double, Parameters>> per_level_sets(const std::vector<TestCurve>& curves, const CalibrationRun& r);

struct CalibrationSettings {
  FitOptions fit;            // of the one set (its per_sigma_n is ignored)
  bool per_sigma_n = false;  // also fit m and n per normal stress
  std::function<void(const std::string&)> stage_done;  // one line per finished stage (progress)
};

CalibrationRun calibrate_curves(const std::vector<TestCurve>& curves, const CalibrationSettings& s);

}  // namespace mortar::harness
