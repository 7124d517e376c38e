#include "commands/calibrate.hpp"

#include <filesystem>
#include <ostream>
#include <set>

#include "calibration/pipeline.hpp"
#include "calibration/report.hpp"
#include "input/input_error.hpp"
#include "input/parameter_file.hpp"
#include "output/output_paths.hpp"
#include "output/plots.hpp"

namespace fs = std::filesystem;

namespace mortar::harness {

namespace {

// Progress of one fit on stderr: iteration, simulations, RMS misfit.
std::function<void(const FitProgress&)> progress_line(std::ostream& err, const std::string& label, bool quiet) {
  if (quiet) return {};
  return [&err, label](const FitProgress& p) {
    err << "calibrate: " << label << ": iteration " << p.iteration << ", " << p.evaluations
        << " simulations, RMS misfit " << p.rms << "\n";
  };
}

std::string level_tag(double sigma_n) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", -sigma_n);
  return buf;
}

void write_per_level_files(const std::string& out_dir, const std::vector<TestCurve>& curves, const FitResult& fit,
                           const Parameters& base) {
  std::set<double> done;
  for (const TestCurve& c : curves) {
    if (!c.shear() || !done.insert(c.sigma_n).second) continue;
    write_parameter_file(out_dir + "/params_sn" + level_tag(c.sigma_n) + ".toml",
                         parameters_for(c, base, fit.unknowns, fit.value),
                         {"Calibrated by masonry-joint calibrate: m and n for sigma_n = " + level_tag(-c.sigma_n) +
                          " MPa (report.md)"});
  }
}

void draw(const std::string& out_dir, const std::vector<TestCurve>& curves, std::ostream& err) {
  const std::string script = write_calibration_plots(out_dir, curves);
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
  settings.fit.progress = progress_line(err, "one set", o.quiet);
  settings.per_sigma_n = o.per_sigma_n;
  settings.per_level_progress = progress_line(err, "m and n per sigma_n", o.quiet);
  const CalibrationRun run = calibrate_curves(curves, settings);
  CalibrationReport report{&curves, &run.direct, run.final, &run.one_set, &run.one_set_uncertainty};
  if (run.per_level_fitted) {
    report.per_level = &run.per_level, report.per_level_uncertainty = &run.per_level_uncertainty;
    write_per_level_files(o.out_dir, curves, run.per_level, run.per_level_base);
  }
  write_parameter_file(o.out_dir + "/params.toml", report.final.values(),
                       {"Calibrated by masonry-joint calibrate from " + o.data_dir,
                        "Values, standard errors and how each was set: report.md"});
  write_fit_curves(o.out_dir, curves, run.one_set, run.direct.calibration.values(), settings.fit.simulation);
  write_report(out, o.out_dir, report);
  if (o.plots) draw(o.out_dir, curves, err);
  if (!o.quiet) err << "calibrate: params.toml, report.md, fit_*.csv and charts in " << o.out_dir << "/\n";
  return 0;
}

}  // namespace mortar::harness
