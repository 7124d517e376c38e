// What `calibrate` writes: the report (the parameter table with value, unit,
// standard error, stage and rule; the misfit of one set, and of m and n per
// normal stress when asked; the correlations of the fit; the notes), one CSV
// per curve with the data, the fitted curve and the residuals, and the charts
// drawn by gnuplot from them (output/plots.hpp's helpers).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "calibration/acceptance.hpp"
#include "calibration/calibration.hpp"
#include "calibration/direct_rules.hpp"
#include "calibration/fit.hpp"
#include "calibration/uncertainty.hpp"

namespace mortar::harness {

struct CalibrationReport {
  const std::vector<TestCurve>* curves = nullptr;
  const DirectResult* direct = nullptr;
  Calibration final;                 // the one set, with errors and stages
  const FitResult* one_set = nullptr;
  const Uncertainty* uncertainty = nullptr;
  const FitResult* per_level = nullptr;  // m and n per sigma_n, or null
  const Uncertainty* per_level_uncertainty = nullptr;
  const Verdict* verdict = nullptr;            // of the one set (calibration/acceptance.hpp)
  const Verdict* per_level_verdict = nullptr;  // of the sets per sigma_n
  const std::vector<std::string>* outliers = nullptr;
  std::string cap_section{};  // Markdown on the compression cap, "" without compression curves
};

// The report as Markdown: printed and written to <out_dir>/report.md.
void write_report(std::ostream& out, const std::string& out_dir, const CalibrationReport& r);

// <out_dir>/fit_<curve>.csv for each curve: x, data, fit, residual (and the
// uplift's), the fit simulated at `p` with the curve's own program.
void write_fit_curves(const std::string& out_dir, const std::vector<TestCurve>& curves, const FitResult& fit,
                      const Parameters& base, const SimulationSettings& settings);

// <out_dir>/calibration.gp, and with gnuplot calibration.png and .svg: data
// against the fitted curves (shear and dilatancy on a log slip axis, where
// the peaks show; tension), each curve labelled by its sigma_n and misfit,
// and below each the residuals of that quantity alone; the RMS misfit, the
// verdict and the parameter values in the title. Returns the script's name.
std::string write_calibration_plots(const std::string& out_dir, const std::vector<TestCurve>& curves,
                                    const CalibrationReport& r);

}  // namespace mortar::harness
