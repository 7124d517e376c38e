// The result of a calibration: each of the 14 parameters with its value, the
// stage that set it, how, and its standard error where the data determine it.
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "mortar/parameters.hpp"

namespace mortar::harness {

enum class Stage {
  direct,          // a rule on the data (initial slope, peak, area, residual)
  refined,         // a direct rule's value, refined by the fit
  fit,             // least squares on whole curves (calibration/fit.hpp)
  not_determined,  // the data cannot determine it: a stated placeholder
};
const char* stage_name(Stage s);

struct CalibratedParameter {
  double value = 0;
  Stage stage = Stage::not_determined;
  std::string how;          // the rule, or why it is not determined
  double std_error = NAN;   // standard error [parameter unit]; NaN when not determined
};

struct Calibration {
  std::array<CalibratedParameter, kParameterCount> entries;
  std::vector<std::string> notes;  // cross-checks and warnings for the report
  // Correlations between direct values fitted together (Table 1 positions i < j):
  // the fit carries them with the standard errors (calibration/uncertainty.hpp).
  struct Correlation {
    int i = 0, j = 0;
    double value = 0;
  };
  std::vector<Correlation> correlations;

  CalibratedParameter& operator[](const char* name) { return entries.at(static_cast<size_t>(parameter_index(name))); }
  const CalibratedParameter& operator[](const char* name) const {
    return entries.at(static_cast<size_t>(parameter_index(name)));
  }
  Parameters values() const;
};

inline constexpr double kDegree = M_PI / 180;

}  // namespace mortar::harness
