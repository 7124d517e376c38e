#include "commands/validate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>

#include "input/input_error.hpp"
#include "input/parameter_file.hpp"
#include "input/protocol.hpp"
#include "output/flag_tally.hpp"
#include "output/output_paths.hpp"
#include "output/plots.hpp"
#include "output/progress.hpp"
#include "output/terminal_text.hpp"
#include "solvers/explicit_run.hpp"
#include "validation/calibration_data.hpp"
#include "validation/checks.hpp"

namespace fs = std::filesystem;

namespace mortar::harness {

namespace {

using Verdict = CheckRow::Verdict;

struct CaseOutcome {
  std::string name;
  std::vector<CheckRow> rows;
  bool ran = false;
  std::string csv;  // file name inside the output folder
  double seconds = 0;
};

bool passed(const CaseOutcome& c) {
  return std::none_of(c.rows.begin(), c.rows.end(), [](const CheckRow& r) { return r.verdict == Verdict::fail; });
}

class Validation {
 public:
  Validation(const ValidateOptions& o, std::ostream& err) : o_(o), err_(err) {}

  CaseOutcome run_case(const SeriesSpec& series, const CaseSpec& spec) {
    CaseOutcome outcome;
    outcome.name = spec.name;
    const ParameterSet params = read_parameter_file(spec.params_file);
    const Protocol protocol = read_protocol_file(spec.protocol_file);
    RunSettings settings;
    settings.scheme = series.scheme;
    settings.stol = series.stol;
    settings.mixed.traction_tolerance = o_.traction_tolerance;
    std::vector<Sample> curve;
    curve.reserve(static_cast<size_t>(protocol.total_increments()) + 1);
    Progress progress("validate: " + spec.name, o_.quiet);
    const auto t0 = std::chrono::steady_clock::now();
    try {
      run_protocol(params.values, protocol, settings, [&](int, const Sample& s) { curve.push_back(s); },
                   [&](long done, long total) { progress.update(done, total); });
    } catch (const RunFailure& e) {
      progress.finish();
      outcome.rows.push_back({"run through vuinteraction_", "failed", "", e.what(), "", Verdict::fail});
      return outcome;
    }
    progress.finish();
    outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    outcome.ran = true;
    outcome.csv = spec.name + ".csv";
    write_curve(o_.out_dir + "/" + outcome.csv, curve);
    outcome.rows = check_case(series.kind, curve, params.values, spec.independent, o_.traction_tolerance);
    outcome.rows.push_back(regression_row(spec, curve, passed(outcome)));
    if (fs::exists(spec.experimental_file))
      outcome.rows.push_back(compare_with_experiment(series.kind, curve, read_csv(spec.experimental_file)));
    if (!o_.quiet) {
      FlagTally flags;
      for (const Sample& s : curve) flags.add(0, s.integration_flags);
      err_ << "validate: " << spec.name << ": " << curve.size() - 1 << " increments in "
           << format_number(outcome.seconds, 3) << " s; " << flags.summary() << "\n";
    }
    return outcome;
  }

 private:
  static void write_curve(const std::string& path, const std::vector<Sample>& curve) {
    std::ofstream out(path);
    if (!out) throw InputError(cannot_write(path));
    write_run_header(out);
    for (const Sample& s : curve) write_run_row(out, s);
  }

  CheckRow regression_row(const CaseSpec& spec, const std::vector<Sample>& curve, bool checks_passed) const {
    if (o_.write_references) {
      if (!checks_passed)
        return {"reference curve", "not written", "", "a check failed: baselines only from passing runs", "",
                Verdict::fail};
      fs::create_directories(fs::path(spec.reference_file).parent_path());
      write_reference(spec.reference_file, curve);
      return {"reference curve", "written", "reference/" + spec.name + ".csv", "", "", Verdict::info};
    }
    if (!fs::exists(spec.reference_file))
      return {"reference curve", "missing", "reference/" + spec.name + ".csv", "see --write-references", "",
              Verdict::fail};
    return compare_with_reference(curve, read_csv(spec.reference_file));
  }

  const ValidateOptions& o_;
  std::ostream& err_;
};

// The table: one block of rows per case, columns sized to their content.
void print_table(std::ostream& out, const std::vector<CaseOutcome>& cases) {
  const std::vector<std::string> head = {"case", "check", "value", "expected", "error", "limit", "result"};
  std::vector<std::vector<std::string>> lines;
  for (const CaseOutcome& c : cases)
    for (size_t i = 0; i < c.rows.size(); ++i) {
      const CheckRow& r = c.rows[i];
      const char* verdict = r.verdict == Verdict::pass ? "pass" : r.verdict == Verdict::fail ? "FAIL" : "info";
      lines.push_back({i == 0 ? c.name : "", r.quantity, r.value, r.expected, r.error, r.limit, verdict});
    }
  std::vector<size_t> width(head.size());
  for (size_t j = 0; j < head.size(); ++j) {
    width[j] = head[j].size();
    for (const auto& l : lines) width[j] = std::max(width[j], l[j].size());
  }
  auto row = [&](const std::vector<std::string>& cells) {
    std::string s;
    for (size_t j = 0; j < cells.size(); ++j) {
      s += cells[j];
      if (j + 1 < cells.size()) s += std::string(width[j] - cells[j].size() + 2, ' ');
    }
    out << s << "\n";
  };
  size_t total = 0;
  for (size_t w : width) total += w + 2;
  const std::string rule(total - 2, '-');
  row(head);
  for (size_t i = 0; i < lines.size(); ++i) {
    if (!lines[i][0].empty()) out << rule << "\n";
    row(lines[i]);
  }
  out << rule << "\n";
}

// The table within 100 columns: the case on its rule line, then per check
// its value, result and error, and on a second line what it was held to
// (and an error too long for its column).
void print_narrow_table(std::ostream& out, const std::vector<CaseOutcome>& cases) {
  size_t check = 5, value = 5;
  for (const CaseOutcome& c : cases)
    for (const CheckRow& r : c.rows) check = std::max(check, r.quantity.size()), value = std::max(value, r.value.size());
  auto cell = [](const std::string& s, size_t w) { return s + std::string(w - std::min(w, s.size()) + 2, ' '); };
  const size_t error = kTerminalColumns - std::min(kTerminalColumns - 8, check + value + 12);
  out << cell("check", check) << cell("value", value) << "result  error\n"
      << "    expected, limit (and an error too long for its column)\n";
  for (const CaseOutcome& c : cases) {
    out << "-- " << c.name << " " << std::string(kTerminalColumns - std::min(kTerminalColumns - 8, c.name.size() + 4), '-')
        << "\n";
    for (const CheckRow& r : c.rows) {
      const char* verdict = r.verdict == Verdict::pass ? "pass" : r.verdict == Verdict::fail ? "FAIL" : "info";
      const bool error_fits = r.error.size() <= error;
      std::string line = cell(r.quantity, check) + cell(r.value, value) + verdict + "    " + (error_fits ? r.error : "");
      out << line.substr(0, line.find_last_not_of(' ') + 1) << "\n";
      std::string second;
      for (const auto& [label, text] : {std::pair<const char*, std::string>{"expected ", r.expected},
                                        {"limit ", r.limit}, {"error ", error_fits ? "" : r.error}})
        if (!text.empty()) second += (second.empty() ? "" : "; ") + (label + text);
      if (!second.empty()) out << "    " << second << "\n";
    }
  }
  out << std::string(kTerminalColumns, '-') << "\n";
}

}  // namespace

int run_validation(const ValidateOptions& o, std::ostream& out, std::ostream& err) {
  if (!(o.traction_tolerance > 0) || !std::isfinite(o.traction_tolerance))
    throw InputError("--traction-tol " + input_number(o.traction_tolerance) +
                     " violates the rule: a finite tolerance > 0 [MPa]");
  const std::vector<SeriesSpec> series = read_calibration_data(o.data_dir, o.series);
  prepare_output_folder(o.out_dir, "--out");
  Validation validation(o, err);
  std::vector<CaseOutcome> outcomes;
  std::vector<std::string> charts;
  const bool can_plot = o.plots && gnuplot_available();
  if (o.plots && !can_plot) err << "validate: warning: gnuplot not found on the PATH; no charts drawn\n";
  for (const SeriesSpec& s : series) {
    std::vector<PlotCase> plot_cases;
    for (const CaseSpec& c : s.cases) {
      outcomes.push_back(validation.run_case(s, c));
      if (outcomes.back().ran)
        plot_cases.push_back({c.label, outcomes.back().csv,
                              fs::exists(c.experimental_file) ? fs::absolute(c.experimental_file).string() : "",
                              c.independent});
    }
    if (!o.plots || plot_cases.empty()) continue;
    const std::string script = write_plot_script(o.out_dir, s, plot_cases);
    std::string message;
    if (!can_plot) continue;
    if (run_gnuplot(o.out_dir, script, message)) {
      charts.push_back(s.id + ".png");
      charts.push_back(s.id + ".svg");
    } else {
      err << "validate: warning: gnuplot failed on " << script << ":\n" << message;
    }
  }
  std::ostringstream table;
  print_table(table, outcomes);
  size_t checks = 0, failures = 0;
  for (const CaseOutcome& c : outcomes)
    for (const CheckRow& r : c.rows) {
      checks += r.verdict != Verdict::info;
      failures += r.verdict == Verdict::fail;
    }
  const std::string verdict = std::to_string(outcomes.size()) + " cases, " + std::to_string(checks) + " checks: " +
                              std::to_string(checks - failures) + " passed, " + std::to_string(failures) + " failed\n";
  table << verdict;
  if (o.wide) {
    out << table.str();
  } else {
    print_narrow_table(out, outcomes);
    out << verdict;
  }
  std::ofstream(o.out_dir + "/validation.txt") << table.str();
  if (!o.quiet) {
    std::string wrote = "validate: CSVs, table (validation.txt)" + std::string(charts.empty() ? "" : " and charts") +
                        " in " + o.out_dir + "/";
    for (const std::string& c : charts) wrote += " " + c;
    err << terminal_text(wrote + "\n", o.wide);
  }
  return failures == 0 ? 0 : 1;
}

}  // namespace mortar::harness
