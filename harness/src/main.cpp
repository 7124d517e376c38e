// masonry-joint: the mock-solver harness of the mortar-joint law. Drives
// interface points only through the Abaqus/Explicit entry point
// vuinteraction_, as Abaqus would. Subcommands: run, validate, inp (see
// harness/README.md).
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench.hpp"
#include "checks.hpp"
#include "csv.hpp"
#include "implicit_command.hpp"
#include "inp.hpp"
#include "input_error.hpp"
#include "parameter_file.hpp"
#include "progress.hpp"
#include "protocol.hpp"
#include "runner.hpp"
#include "validate.hpp"

#ifndef MJ_CALIBRATION_DATA_DIR
#define MJ_CALIBRATION_DATA_DIR "calibration_data"
#endif

using namespace mortar;
using namespace mortar::harness;

namespace {

constexpr int kExitChecksFailed = 1;  // a check failed or a run could not be completed
constexpr int kExitBadInput = 2;      // bad arguments or input files

const std::map<std::string, Scheme> kSchemes = {{"modified-euler", Scheme::modified_euler},
                                                {"forward-euler", Scheme::forward_euler},
                                                {"implicit", Scheme::implicit}};

struct RunArgs {
  std::string params, protocol, out, scheme;  // scheme: empty = the solver's default
  std::string solver = "explicit";
  double stol = 0, traction_tol = 1e-9;
  int points = 1, block = 512, max_cuts = 5;
  bool quiet = false, print_residuals = false;
  bool points_given = false, block_given = false, max_cuts_given = false;
};

void check_stol(double stol) {
  if (stol != 0 && !(stol > 0 && stol < 1))
    throw InputError("--stol " + format_number(stol, 9) + " violates the rule 0 < STOL < 1 (0 keeps the default)");
}

// Largest difference of one sample from another (same increment).
double difference(const Sample& a, const Sample& b) {
  double d = std::max((a.traction - b.traction).cwiseAbs().maxCoeff(),
                      (a.separation - b.separation).cwiseAbs().maxCoeff());
  for (int i = 0; i < kStateCount; ++i) d = std::max(d, std::abs(a.state[i] - b.state[i]));
  d = std::max(d, std::abs(a.elastic_energy - b.elastic_energy));
  return std::max(d, std::abs(a.dissipation_increment - b.dissipation_increment));
}

// --solver implicit: one point through UINTER (implicit_command.hpp).
int run_implicit(const RunArgs& a) {
  ImplicitRunRequest r{a.params, a.protocol, a.out, {}, a.print_residuals, a.quiet};
  r.settings.scheme = kSchemes.at(a.scheme.empty() ? "implicit" : a.scheme);
  r.settings.stol = a.stol;
  r.settings.options.traction_tolerance = a.traction_tol;
  r.settings.options.max_cuts = a.max_cuts;
  return run_implicit_command(r, std::cerr);
}

int run_command(const RunArgs& a) {
  check_stol(a.stol);
  if (!(a.traction_tol > 0)) throw InputError("--traction-tol must be > 0 [MPa]");
  check_solver_options({a.solver, a.points_given, a.block_given, a.max_cuts_given, a.print_residuals, a.points,
                        a.block, a.max_cuts});
  if (a.solver == "implicit") return run_implicit(a);
  const ParameterSet params = read_parameter_file(a.params);
  const Protocol protocol = read_protocol_file(a.protocol);
  RunSettings settings;
  settings.scheme = kSchemes.at(a.scheme.empty() ? "modified-euler" : a.scheme);
  settings.stol = a.stol;
  settings.points = a.points;
  settings.block = a.block;
  settings.mixed.traction_tolerance = a.traction_tol;

  std::ofstream out(a.out);
  if (!out) throw InputError(a.out + ": cannot open the file for writing");
  write_run_header(out);
  // Point 1 is written; every other point must reproduce it exactly, since
  // all points are identical and blocks must not matter.
  Sample first;
  double worst = 0;
  Progress progress("run", a.quiet);
  RunStatistics stats;
  try {
    stats = run_protocol(
        params.values, protocol, settings,
        [&](int point, const Sample& s) {
          if (point == 0) {
            first = s;
            write_run_row(out, s);
          } else {
            worst = std::max(worst, difference(s, first));
          }
        },
        [&](long done, long total) { progress.update(done, total); });
  } catch (const RunFailure& e) {
    progress.finish();
    std::cerr << "masonry-joint run: " << e.what() << "\n"
              << "masonry-joint run: " << a.out << " holds the increments up to the failure\n";
    return kExitChecksFailed;
  }
  progress.finish();
  out.close();
  if (!out) throw InputError(a.out + ": write failed");
  if (!a.quiet) {
    std::cerr << "run: " << stats.increments << " increments x " << a.points << " point(s) in " << stats.blocks
              << " block(s): " << stats.calls << " calls of vuinteraction_ in " << stats.seconds << " s\n"
              << "run: Newton updates per increment at most " << stats.max_iterations
              << "; largest controlled-traction residual " << stats.max_traction_residual << " MPa (tolerance "
              << a.traction_tol << " MPa)\n";
    if (a.points > 1) std::cerr << "run: largest difference of any point from point 1: " << worst << "\n";
    std::cerr << "run: wrote " << a.out << "\n";
  }
  if (worst != 0) {
    std::cerr << "masonry-joint run: identical points gave different results (largest difference " << worst
              << "): the result depends on the blocking\n";
    return kExitChecksFailed;
  }
  return 0;
}

struct InpArgs {
  std::string params, scheme, name = "MORTAR";
  double stol = 0;
};

int inp_command(const InpArgs& a) {
  check_stol(a.stol);
  const ParameterSet params = read_parameter_file(a.params);
  InpOptions o;
  o.name = a.name;
  o.depvar = kStateCount;
  for (int i = 0; i < kParameterCount; ++i) o.props.push_back(parameter_at(params.values, i));
  // Controls only when asked for: absent props mean the routine's defaults.
  if (!a.scheme.empty() || a.stol != 0) {
    o.props.push_back(a.scheme.empty() ? 0.0 : static_cast<double>(static_cast<int>(kSchemes.at(a.scheme))));
    o.props.push_back(a.stol);
  }
  write_surface_interaction(std::cout, o);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"masonry-joint: mock Abaqus/Explicit (VUINTERACTION) and Abaqus/Standard (UINTER) solver for the mortar joint"};
  app.require_subcommand(1);
  std::vector<std::string> scheme_names;
  for (const auto& s : kSchemes) scheme_names.push_back(s.first);

  RunArgs run;
  CLI::App* run_cmd = app.add_subcommand("run", "Run a loading program; one CSV row per increment");
  run_cmd->add_option("--params", run.params, "Parameter file (TOML)")->required();
  run_cmd->add_option("--protocol", run.protocol, "Loading program (TOML)")->required();
  run_cmd->add_option("--scheme", run.scheme,
                      "Integration scheme, props(15); default modified-euler (--solver explicit), implicit "
                      "(--solver implicit)")
      ->check(CLI::IsMember(scheme_names));
  run_cmd->add_option("--solver", run.solver, "Mock solver: explicit (vuinteraction_), implicit (uinter_)")
      ->check(CLI::IsMember(std::vector<std::string>(std::begin(kSolverNames), std::end(kSolverNames))))
      ->capture_default_str();
  run_cmd->add_option("--max-cuts", run.max_cuts, "--solver implicit: cut-backs allowed per increment")
      ->check(CLI::Range(0, 20))
      ->capture_default_str();
  run_cmd->add_flag("--print-residuals", run.print_residuals,
                    "--solver implicit: every attempt's residual sequence on stderr");
  run_cmd->add_option("--stol", run.stol, "Substep error tolerance STOL, props(16); 0 keeps the default 1e-5");
  run_cmd->add_option("--points", run.points, "Identical interface points")->check(CLI::Range(1, 10000000))
      ->capture_default_str();
  run_cmd->add_option("--block", run.block, "Points per call (nBlock), at most")->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  run_cmd->add_option("--traction-tol", run.traction_tol, "Tolerance of controlled tractions [MPa]")
      ->capture_default_str();
  run_cmd->add_option("--out", run.out, "Output CSV")->required();
  run_cmd->add_flag("--quiet,-q", run.quiet, "No progress or summary on stderr");

  ValidateOptions val;
  val.data_dir = MJ_CALIBRATION_DATA_DIR;
  bool no_plots = false;
  CLI::App* val_cmd = app.add_subcommand("validate", "Run and check the three test series of calibration_data/");
  val_cmd->add_option("--out", val.out_dir, "Folder for CSVs, charts and the table")->capture_default_str();
  val_cmd->add_option("--data", val.data_dir, "The calibration data folder")->capture_default_str();
  val_cmd->add_option("--series", val.series, "Only this series (folder name); repeatable");
  val_cmd->add_option("--traction-tol", val.traction_tolerance, "Tolerance of controlled tractions [MPa]")
      ->capture_default_str();
  val_cmd->add_flag("--no-plots", no_plots, "Skip the charts");
  val_cmd->add_flag("--write-references", val.write_references,
                    "Store the fresh curves as regression baselines (only for cases whose checks all pass)");
  val_cmd->add_flag("--quiet,-q", val.quiet, "No progress on stderr");

  InpArgs inp;
  CLI::App* inp_cmd = app.add_subcommand("inp", "Print the *SURFACE INTERACTION block for a parameter file");
  inp_cmd->add_option("--params", inp.params, "Parameter file (TOML)")->required();
  inp_cmd->add_option("--scheme", inp.scheme, "Also write props(15) (and props(16))")
      ->check(CLI::IsMember(scheme_names));
  inp_cmd->add_option("--stol", inp.stol, "Also write props(16) = STOL (and props(15))");
  inp_cmd->add_option("--name", inp.name, "NAME of the surface interaction")->capture_default_str();

  BenchOptions bench;
  bench.data_dir = MJ_CALIBRATION_DATA_DIR;
  bool bench_no_plots = false;
  CLI::App* bench_cmd = app.add_subcommand("bench", "Work-precision study and stability map of the schemes");
  bench_cmd->add_flag("--quick", bench.quick, "Fewer increment sizes, tolerances and paths (for CI)");
  bench_cmd->add_option("--out", bench.out_dir, "Folder for CSVs, charts and the stability list")
      ->capture_default_str();
  bench_cmd->add_option("--data", bench.data_dir, "The calibration data folder")->capture_default_str();
  bench_cmd->add_option("--path", bench.paths, "Only this bench path (id); repeatable");
  bench_cmd->add_option("--budget", bench.budget_seconds, "Wall time allowed per run of one point [s]")
      ->capture_default_str();
  bench_cmd->add_flag("--no-plots", bench_no_plots, "Skip the charts");
  bench_cmd->add_flag("--quiet,-q", bench.quiet, "No progress on stderr");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kExitBadInput;
  }
  try {
    if (*run_cmd) {
      run.points_given = run_cmd->count("--points") > 0;
      run.block_given = run_cmd->count("--block") > 0;
      run.max_cuts_given = run_cmd->count("--max-cuts") > 0;
      return run_command(run);
    }
    if (*inp_cmd) return inp_command(inp);
    if (*bench_cmd) {
      bench.plots = !bench_no_plots;
      return run_bench_command(bench, std::cout, std::cerr);
    }
    val.plots = !no_plots;
    return run_validation(val, std::cout, std::cerr);
  } catch (const InputError& e) {
    std::cerr << "masonry-joint: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "masonry-joint: " << e.what() << "\n";
    return kExitChecksFailed;
  }
}
