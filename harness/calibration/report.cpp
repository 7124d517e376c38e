#include "calibration/report.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <sstream>

#include "input/input_error.hpp"
#include "output/csv.hpp"
#include "output/output_paths.hpp"
#include "output/plots.hpp"
#include "solvers/mixed_control.hpp"

namespace mortar::harness {

namespace {

std::string number(double x, int digits = 4) {
  if (std::isnan(x)) return "–";
  if (std::isinf(x)) return "∞";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

void parameter_table(std::ostream& out, const Calibration& cal) {
  out << "| parameter | value | unit | standard error | stage | how |\n|---|---|---|---|---|---|\n";
  for (int i = 0; i < kParameterCount; ++i) {
    const CalibratedParameter& e = cal.entries[size_t(i)];
    const std::string se = e.stage == Stage::not_determined ? "not determined" : number(e.std_error, 2);
    out << "| " << kParameterInfo[size_t(i)].name << " | " << number(e.value, 5) << " | "
        << kParameterInfo[size_t(i)].unit << " | " << se << " | " << stage_name(e.stage) << " | " << e.how << " |\n";
  }
}

void misfit_table(std::ostream& out, const FitResult& fit, const char* title) {
  out << "\n**" << title << "**: RMS of the scaled residuals " << number(fit.rms, 4) << " (" << fit.unknowns.size()
      << " unknowns, " << fit.residuals.size() << " residuals; " << fit.iterations << " iterations, " << fit.evaluations
      << " simulations of the data set; " << fit.status << ")\n\n"
      << "| curve | RMS traction [MPa] | RMS uplift [mm] |\n|---|---|---|\n";
  for (const CurveMisfit& m : fit.misfit)
    out << "| " << m.curve << " | " << (m.failed ? "run failed" : number(m.rms_traction, 3)) << " | "
        << number(m.rms_uplift, 3) << " |\n";
}

void correlations(std::ostream& out, const FitResult& fit, const Uncertainty& u) {
  out << "\n**Correlations of the fitted parameters** (from the Jacobian at the optimum)\n\n|   |";
  for (const FitUnknown& k : fit.unknowns) out << " " << k.label() << " |";
  out << "\n|---|";
  for (size_t i = 0; i < fit.unknowns.size(); ++i) out << "---|";
  out << "\n";
  for (size_t i = 0; i < fit.unknowns.size(); ++i) {
    out << "| " << fit.unknowns[i].label() << " |";
    for (size_t j = 0; j < fit.unknowns.size(); ++j) out << " " << number(u.correlation(long(i), long(j)), 2) << " |";
    out << "\n";
  }
}

void per_level_values(std::ostream& out, const FitResult& fit, const Uncertainty& u) {
  out << "\n| parameter | value | standard error |\n|---|---|---|\n";
  for (size_t k = 0; k < fit.unknowns.size(); ++k)
    out << "| " << fit.unknowns[k].label() << " | " << number(fit.value[long(k)], 5) << " | "
        << number(u.std_error[long(k)], 2) << " |\n";
}

void verdict_section(std::ostream& md, const Verdict* v, const char* what, const char* ready) {
  if (!v) return;
  if (v->accepted()) {
    md << "**" << what << ": accepted** (" << ready << "): converged, RMS misfit within " << kMaxMisfit
       << " of the curves' scale (" << kMaxCurveMisfit << " per curve), no fitted value on a bound, all finite.\n\n";
    return;
  }
  md << "**" << what << ": REJECTED** (written as *.rejected.toml, not for use):\n\n";
  for (const std::string& reason : v->reasons) md << "- " << reason << "\n";
  md << "\n";
}

}  // namespace

void write_report(std::ostream& out, const std::string& out_dir, const CalibrationReport& r) {
  std::ostringstream md;
  md << "# Calibration\n\n";
  verdict_section(md, r.verdict, "One set", "params.toml");
  verdict_section(md, r.per_level_verdict, "m and n per normal stress", "params_sn*.toml");
  md << r.curves->size() << " curves:";
  for (const TestCurve& c : *r.curves)
    md << " " << c.name << " (" << test_kind_name(c.kind) << (c.shear() ? ", σn = " + number(c.sigma_n) + " MPa" : "")
       << (c.has_uplift() ? ", uplift" : "") << ")";
  md << "\n\n## Parameters (params.toml)\n\n";
  parameter_table(md, r.final);
  md << "\nStages: *direct* a rule on the data; *direct+fit* a rule's value refined by the whole-curve fit; *fit* "
        "least squares on the whole curves; *not determined* a stated placeholder the data cannot check.\n\n"
        "## Peaks and residual strengths read by the rules\n\n| curve | σn [MPa] | peak τ [MPa] | residual τ [MPa] |\n|---|---|---|---|\n";
  for (const ShearPeak& p : r.direct->peaks)
    md << "| " << p.curve << " | " << number(p.sigma_n) << " | " << number(p.peak) << " | " << number(p.residual) << " |\n";
  md << "\n## Misfit\n";
  misfit_table(md, *r.one_set, "One set across normal stresses");
  if (r.per_level) {
    misfit_table(md, *r.per_level, "m and n per normal stress (params_sn*.toml)");
    per_level_values(md, *r.per_level, *r.per_level_uncertainty);
  }
  correlations(md, *r.one_set, *r.uncertainty);
  if (r.outliers && !r.outliers->empty()) {
    md << "\n## Outliers\n\nPoints whose residual exceeds " << kOutlierFactor
       << " times the robust scatter of all points (calibration/acceptance.hpp); check them in the data:\n\n";
    for (const std::string& o : *r.outliers) md << "- " << o << "\n";
  }
  md << r.cap_section;
  md << "\n## Notes\n\n";
  for (const std::string& h : r.one_set->held) md << "- held: " << h << "\n";
  for (const std::string& n : r.final.notes) md << "- " << n << "\n";
  out << md.str();
  std::ofstream file(out_dir + "/report.md");
  if (!(file << md.str())) throw InputError(out_dir + "/report.md: cannot write the report");
}

void write_fit_curves(const std::string& out_dir, const std::vector<TestCurve>& curves, const FitResult& fit,
                      const Parameters& base, const SimulationSettings& settings) {
  for (const TestCurve& c : curves) {
    SimulatedCurve sim;
    try {
      sim = simulate(parameters_for(c, base, fit.unknowns, fit.value), c, settings);
    } catch (const RunFailure&) {
      continue;  // the misfit table says the run failed
    }
    std::vector<std::vector<double>> rows;
    for (size_t i = 0; i < c.x.size(); ++i) {
      std::vector<double> row = {c.x[i], c.y[i], sim.y[i], sim.y[i] - c.y[i]};
      if (c.has_uplift()) row.insert(row.end(), {c.uplift[i], sim.uplift[i], sim.uplift[i] - c.uplift[i]});
      rows.push_back(row);
    }
    std::vector<std::string> header = {"x_mm", "data_MPa", "fit_MPa", "residual_MPa"};
    if (c.has_uplift()) header.insert(header.end(), {"uplift_data_mm", "uplift_fit_mm", "uplift_residual_mm"});
    write_csv(out_dir + "/fit_" + c.name + ".csv", header, rows);
  }
}

}  // namespace mortar::harness
