// `masonry-joint calibrate`: the 14 parameters from a user's test curves
// (calibration/test_curve.hpp): direct rules, then the whole-curve fit, with
// standard errors; writes params.toml, report.md, the fitted curves and the
// charts (harness/README.md, "calibrate").
#pragma once

#include <iosfwd>
#include <string>

namespace mortar::harness {

struct CalibrateOptions {
  std::string data_dir;             // the test curves (*.csv, any depth)
  std::string out_dir = "calibration";
  bool per_sigma_n = false;         // also fit m and n per normal stress
  int increments = 100;             // simulation increments per curve
  bool plots = true;
  bool quiet = false;
  bool wide = false;  // the report on stdout as report.md has it, not fitted to 100 columns
};

// Exit status of a calibration whose set is rejected (calibration/acceptance.hpp):
// params.rejected.toml with the reasons, no params.toml.
inline constexpr int kCalibrationRejected = 3;

// Returns the exit status: 0, or kCalibrationRejected. InputError for bad
// data or options.
int calibrate_command(const CalibrateOptions& o, std::ostream& out, std::ostream& err);

}  // namespace mortar::harness
