#include "commands/calibrate.hpp"

#include <filesystem>
#include <ostream>
#include <sstream>
#include <system_error>

#include "calibration/cap_rules.hpp"
#include "calibration/curve_checks.hpp"
#include "calibration/pipeline.hpp"
#include "calibration/report.hpp"
#include "input/input_error.hpp"
#include "input/parameter_file.hpp"
#include "output/csv.hpp"
#include "solvers/explicit_run.hpp"
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
               const Verdict& v, const CompressionCap& cap = CompressionCap{}) {
  const std::string ready = out_dir + "/" + stem + ".toml", rejected = out_dir + "/" + stem + ".rejected.toml";
  std::error_code ec;
  fs::remove(v.accepted() ? rejected : ready, ec);
  if (!v.accepted()) {
    header.insert(header.begin(), "REJECTED: NOT a calibrated set; do not use it for an analysis. The reasons:");
    for (size_t k = 0; k < v.reasons.size(); ++k) header.insert(header.begin() + long(k) + 1, "  - " + v.reasons[k]);
  }
  write_parameter_file(v.accepted() ? ready : rejected, p, header, cap);
}

void write_per_level_files(const std::string& out_dir, const std::vector<TestCurve>& curves, const CalibrationRun& r,
                           const CompressionCap& cap) {
  for (const auto& [sigma_n, p] : per_level_sets(curves, r))
    write_set(out_dir, "params_sn" + level_tag(sigma_n), p,
              {"Calibrated by masonry-joint calibrate: m and n for sigma_n = " + level_tag(-sigma_n) + " MPa (report.md)"},
              r.per_level_verdict, cap);
}

// The report's section on the cap (only when compression curves were given).
std::string cap_section(const CapEstimate& e) {
  std::ostringstream md;
  md << "\n## Compression cap (docs/model.md 12)\n\n| parameter | value | how |\n|---|---|---|\n"
     << "| fc | " << number_text(e.cap.fc) << " MPa | direct rule |\n"
     << "| Gfc | " << number_text(e.cap.Gfc) << " N/mm | direct rule |\n"
     << "| kappa_p | " << number_text(e.cap.kappa_p) << " mm | direct rule |\n"
     << "| Cs | " << number_text(e.cap.Cs) << " | " << (e.Cs_held ? "held (default)" : "direct rule") << " |\n\n";
  for (const std::string& n : e.notes) md << "- " << n << "\n";
  return md.str();
}

// fit_<curve>.csv of each compression curve, as write_fit_curves.
void write_cap_fit_curves(const std::string& out_dir, const std::vector<TestCurve>& curves, const Parameters& p,
                          const CompressionCap& cap, const SimulationSettings& settings) {
  for (const TestCurve& c : curves) {
    SimulatedCurve sim;
    try {
      sim = simulate(p, c, settings, cap);
    } catch (const RunFailure&) {
      continue;  // as write_fit_curves: no fit curve for a run that fails
    }
    std::vector<std::vector<double>> rows;
    for (size_t i = 0; i < c.x.size(); ++i) rows.push_back({c.x[i], c.y[i], sim.y[i], sim.y[i] - c.y[i]});
    write_csv(out_dir + "/fit_" + c.name + ".csv", {"x_mm", "data_MPa", "fit_MPa", "residual_MPa"}, rows);
  }
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
  // Compression curves give the cap only; the other kinds, the paper's law.
  std::vector<TestCurve> curves, compression;
  for (TestCurve& c : read_test_curves(o.data_dir)) (c.compression() ? compression : curves).push_back(std::move(c));
  if (curves.empty())
    throw InputError("--data " + o.data_dir + ": holds only compression curves; the joint's other parameters need "
                     "tension and shear curves");
  prepare_output_folder(o.out_dir, "--out");
  CalibrationSettings settings;
  settings.fit.simulation.increments = o.increments;
  settings.per_sigma_n = o.per_sigma_n;
  // One line a stage (within 100 columns unless --wide), not one a simulation.
  if (!o.quiet)
    settings.stage_done = [&err, &o](const std::string& line) { err << terminal_text("calibrate: " + line, o.wide) << "\n"; };
  const CalibrationRun run = calibrate_curves(curves, settings);
  CapEstimate cap;  // off (fc = 0) without compression curves: no cap written
  if (!compression.empty()) {
    cap = estimate_cap(compression, run.final.values());
    if (!o.quiet) err << "calibrate: the cap from " << compression.size() << " compression curve(s): fc, Gfc, kappa_p; Cs held\n";
  }
  CalibrationReport report{&curves, &run.direct, run.final, &run.one_set, &run.one_set_uncertainty};
  report.verdict = &run.one_set_verdict;
  report.outliers = &run.outliers;
  if (cap.cap.fc > 0) report.cap_section = cap_section(cap);
  if (run.per_level_fitted) {
    report.per_level = &run.per_level, report.per_level_uncertainty = &run.per_level_uncertainty;
    report.per_level_verdict = &run.per_level_verdict;
    write_per_level_files(o.out_dir, curves, run, cap.cap);
  }
  write_set(o.out_dir, "params", report.final.values(),
            {"Calibrated by masonry-joint calibrate from " + o.data_dir,
             "Values, standard errors and how each was set: report.md"},
            run.one_set_verdict, cap.cap);
  write_fit_curves(o.out_dir, curves, run.one_set, run.start.values(), settings.fit.simulation);
  if (cap.cap.fc > 0) write_cap_fit_curves(o.out_dir, compression, run.final.values(), cap.cap, settings.fit.simulation);
  std::ostringstream md;
  write_report(md, o.out_dir, report);
  out << terminal_text(md.str(), o.wide);
  if (o.plots) {
    std::vector<TestCurve> drawn = curves;  // the compression curves in their own panels
    drawn.insert(drawn.end(), compression.begin(), compression.end());
    draw(o.out_dir, drawn, report, err);
  }
  for (const std::string& line : run.outliers) err << terminal_text("calibrate: warning: " + line, o.wide) << "\n";
  // The one set decides, unless the sets per sigma_n were asked for and pass.
  const bool handed = run.one_set_verdict.accepted() || (run.per_level_fitted && run.per_level_verdict.accepted());
  for (const auto* v : {&run.one_set_verdict, run.per_level_fitted ? &run.per_level_verdict : nullptr}) {
    if (!v || v->accepted()) continue;
    err << "calibrate: " << (v == &run.one_set_verdict ? "the one set" : "the sets per sigma_n")
        << " is REJECTED (written as *.rejected.toml, not for use):\n";
    for (const std::string& reason : v->reasons) err << terminal_text("calibrate:   - " + reason, o.wide) << "\n";
  }
  if (!o.quiet || !handed)
    err << terminal_text(std::string("calibrate: ") + (run.one_set_verdict.accepted() ? "params.toml" : "params.rejected.toml") +
                             ", report.md, fit_*.csv and charts in " + o.out_dir + "/",
                         o.wide)
        << "\n";
  return handed ? 0 : kCalibrationRejected;
}

}  // namespace mortar::harness
