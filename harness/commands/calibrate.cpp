#include "commands/calibrate.hpp"

#include <filesystem>
#include <ostream>
#include <sstream>
#include <system_error>

#include "calibration/pipeline.hpp"
#include "calibration/report.hpp"
#include "input/input_error.hpp"
#include "input/parameter_file.hpp"
#include "output/output_paths.hpp"
#include "output/plots.hpp"
#include "output/terminal_text.hpp"

namespace fs = std::filesystem;

namespace mortar::harness {

namespace {

std::string level_tag(double sigma_n) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", -sigma_n);
  return buf;
}

// A set is written as <stem>.toml when accepted, else as <stem>.rejected.toml
// with the reasons in its header; the other name is removed, so that no
// earlier run's ready file stays beside a rejected one.
void write_set(const std::string& out_dir, const std::string& stem, const Parameters& p, std::vector<std::string> header,
               const Verdict& v) {
  const std::string ready = out_dir + "/" + stem + ".toml", rejected = out_dir + "/" + stem + ".rejected.toml";
  std::error_code ec;
  fs::remove(v.accepted() ? rejected : ready, ec);
  if (!v.accepted()) {
    header.insert(header.begin(), "REJECTED: NOT a calibrated set; do not use it for an analysis. The reasons:");
    for (size_t k = 0; k < v.reasons.size(); ++k) header.insert(header.begin() + long(k) + 1, "  - " + v.reasons[k]);
  }
  write_parameter_file(v.accepted() ? ready : rejected, p, header);
}

void write_per_level_files(const std::string& out_dir, const std::vector<TestCurve>& curves, const CalibrationRun& r) {
  for (const auto& [sigma_n, p] : per_level_sets(curves, r))
    write_set(out_dir, "params_sn" + level_tag(sigma_n), p,
              {"Calibrated by masonry-joint calibrate: m and n for sigma_n = " + level_tag(-sigma_n) + " MPa (report.md)"},
              r.per_level_verdict);
}

void draw(const std::string& out_dir, const std::vector<TestCurve>& curves, const CalibrationReport& r,
          std::ostream& err) {
  const std::string script = write_calibration_plots(out_dir, curves, r);
  if (!gnuplot_available()) {
    err << "calibrate: warning: gnuplot not found on the PATH; " << script << " written, no charts drawn\n";
    return;
  }
  std::string message;
  if (!run_gnuplot(out_dir, script, message)) err << "calibrate: warning: gnuplot failed on " << script << ":\n" << message;
}

}  // namespace

int calibrate_command(const CalibrateOptions& o, std::ostream& out, std::ostream& err) {
  if (o.increments < 10 || o.increments > 100000)
    throw InputError("--increments " + std::to_string(o.increments) + " violates the rule: 10 <= increments <= 100000");
  const std::vector<TestCurve> curves = read_test_curves(o.data_dir);
  prepare_output_folder(o.out_dir, "--out");
  CalibrationSettings settings;
  settings.fit.simulation.increments = o.increments;
  settings.per_sigma_n = o.per_sigma_n;
  if (!o.quiet) settings.stage_done = [&err](const std::string& line) { err << "calibrate: " << line << "\n"; };
  const CalibrationRun run = calibrate_curves(curves, settings);
  CalibrationReport report{&curves, &run.direct, run.final, &run.one_set, &run.one_set_uncertainty};
  report.verdict = &run.one_set_verdict;
  report.outliers = &run.outliers;
  if (run.per_level_fitted) {
    report.per_level = &run.per_level, report.per_level_uncertainty = &run.per_level_uncertainty;
    report.per_level_verdict = &run.per_level_verdict;
    write_per_level_files(o.out_dir, curves, run);
  }
  write_set(o.out_dir, "params", report.final.values(),
            {"Calibrated by masonry-joint calibrate from " + o.data_dir,
             "Values, standard errors and how each was set: report.md"},
            run.one_set_verdict);
  write_fit_curves(o.out_dir, curves, run.one_set, run.start.values(), settings.fit.simulation);
  std::ostringstream md;
  write_report(md, o.out_dir, report);
  out << terminal_text(md.str(), o.wide);
  if (o.plots) draw(o.out_dir, curves, report, err);
  for (const std::string& line : run.outliers) err << "calibrate: warning: " << line << "\n";
  // The one set decides, unless the sets per sigma_n were asked for and pass.
  const bool handed = run.one_set_verdict.accepted() || (run.per_level_fitted && run.per_level_verdict.accepted());
  for (const auto* v : {&run.one_set_verdict, run.per_level_fitted ? &run.per_level_verdict : nullptr}) {
    if (!v || v->accepted()) continue;
    err << "calibrate: " << (v == &run.one_set_verdict ? "the one set" : "the sets per sigma_n")
        << " is REJECTED (written as *.rejected.toml, not for use):\n";
    for (const std::string& reason : v->reasons) err << "calibrate:   - " << reason << "\n";
  }
  if (!o.quiet || !handed)
    err << "calibrate: " << (run.one_set_verdict.accepted() ? "params.toml" : "params.rejected.toml")
        << ", report.md, fit_*.csv and charts in " << o.out_dir << "/\n";
  return handed ? 0 : kCalibrationRejected;
}

}  // namespace mortar::harness
