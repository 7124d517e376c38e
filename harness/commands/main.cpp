// masonry-joint: the mock-solver harness of the mortar-joint law. Drives
// interface points only through the ABI entry points, vuinteraction_
// (Abaqus/Explicit) and uinter_ (Abaqus/Standard), as Abaqus would. This file
// declares the command line; each subcommand is its own file in commands/:
// run, validate, inp, bench, scene, calibrate (harness/README.md).
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "commands/bench.hpp"
#include "commands/calibrate.hpp"
#include "commands/command_line.hpp"
#include "commands/inp.hpp"
#include "commands/run.hpp"
#include "commands/scene.hpp"
#include "commands/validate.hpp"
#include "input/input_error.hpp"

#ifndef MJ_CALIBRATION_DATA_DIR
#define MJ_CALIBRATION_DATA_DIR "calibration_data"
#endif

using namespace mortar;
using namespace mortar::harness;

namespace {

constexpr int kExitChecksFailed = 1;  // a check failed or a run could not be completed
constexpr int kExitBadInput = 2;      // bad arguments or input files
constexpr const char* kWideHelp = "Tables in full on stdout, wider than 100 columns (the files always have them so)";

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"masonry-joint: mock Abaqus/Explicit (VUINTERACTION) and Abaqus/Standard (UINTER) solver for the mortar joint"};
  app.require_subcommand(1);
  app.set_version_flag("--version", version_text());
  std::vector<std::string> scheme_names;
  for (const auto& s : mortar::harness::scheme_names()) scheme_names.push_back(s.first);

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
  run_cmd->add_flag("--symmetric-tangent", run.symmetric_tangent,
                    "--solver implicit: Newton on DDSDDR's symmetric part (no UNSYMM)");
  run_cmd->add_option("--stol", run.stol, "Substep error tolerance STOL, props(16); 0 keeps the default 1e-5");
  run_cmd->add_option("--points", run.points, "Identical interface points")->check(CLI::Range(1, 10000000))
      ->capture_default_str();
  run_cmd->add_option("--block", run.block, "Points per call (nBlock), at most")->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  run_cmd->add_option("--traction-tol", run.traction_tol, "Tolerance of controlled tractions [MPa]")
      ->capture_default_str();
  run_cmd->add_option("--out", run.out, "Output CSV")->required();
  run_cmd->add_flag("--quiet,-q", run.quiet, "No progress or summary on stderr");
  run_cmd->add_flag("--wide", run.wide, "The summary on stderr in full lines, wider than 100 columns");

  ValidateOptions val;
  const std::string data_dir = default_data_dir(MJ_CALIBRATION_DATA_DIR);
  val.data_dir = data_dir;
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
  val_cmd->add_flag("--wide", val.wide, kWideHelp);

  InpArgs inp;
  CLI::App* inp_cmd = app.add_subcommand(
      "inp", "Print the *SURFACE INTERACTION block for a parameter file, or a complete Abaqus job (--scene, --two-blocks)");
  inp_cmd->add_option("--params", inp.params, "Parameter file (TOML)");
  inp_cmd->add_option("--scene", inp.scene, "Scene file (TOML): its wall as a complete Abaqus/Explicit job");
  inp_cmd->add_option("--two-blocks", inp.two_blocks,
                      "The two-block job for this solver (with --params): explicit (VUINTERACTION), standard (UINTER)")
      ->check(CLI::IsMember({"explicit", "standard"}));
  inp_cmd->add_option("--scheme", inp.scheme, "Also write props(15) (and props(16))")
      ->check(CLI::IsMember(scheme_names));
  inp_cmd->add_option("--stol", inp.stol, "Also write props(16) = STOL (and props(15))");
  inp_cmd->add_option("--name", inp.name, "NAME of the surface interaction")->capture_default_str();

  BenchOptions bench;
  bench.data_dir = data_dir;
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
  bench_cmd->add_flag("--wide", bench.wide, kWideHelp);
  bool throughput = false;
  ThroughputOptions throughput_options;
  bench_cmd->add_flag("--throughput", throughput,
                      "Instead of the study: ns per point-update (copy pass, elastic, softening, sliding), both "
                      "precisions, in and out of cache, 1 and 2 threads, and their ratios");
  bench_cmd->add_option("--repeats", throughput_options.repeats, "--throughput: timed repeats per case (median)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();

  SceneArgs scene;
  CLI::App* scene_cmd = app.add_subcommand("scene", "A wall of rigid blocks through vuinteraction_ (explicit dynamics)");
  scene_cmd->add_option("file", scene.file, "Scene file (TOML)")->required();
  scene_cmd->add_option("--out", scene.out, "Folder for the history, snapshots, charts and summary")
      ->capture_default_str();
  scene_cmd->add_option("--threads", scene.threads, "Threads calling vuinteraction_ (blocks are independent)")
      ->capture_default_str();
  scene_cmd->add_option("--block", scene.block, "Points per call (nBlock), at most 136")->capture_default_str();
  bool scene_no_plots = false;
  scene_cmd->add_flag("--no-plots", scene_no_plots, "Skip the charts");
  scene_cmd->add_flag("--quiet,-q", scene.quiet, "No progress on stderr");

  CalibrateOptions cal;
  bool cal_no_plots = false;
  CLI::App* cal_cmd = app.add_subcommand("calibrate", "The 14 parameters from test curves: direct rules, then a whole-curve fit");
  cal_cmd->add_option("--data", cal.data_dir, "Folder of test curves (*.csv with '# kind:' lines)")->required();
  cal_cmd->add_option("--out", cal.out_dir, "Folder for params.toml, report.md, fitted curves and charts")
      ->capture_default_str();
  cal_cmd->add_flag("--per-sigma-n", cal.per_sigma_n, "Also fit m and n per normal stress (Table 1's practice)");
  cal_cmd->add_option("--increments", cal.increments, "Simulation increments per curve")->capture_default_str();
  cal_cmd->add_flag("--no-plots", cal_no_plots, "Skip the charts");
  cal_cmd->add_flag("--quiet,-q", cal.quiet, "No progress on stderr");
  cal_cmd->add_flag("--wide", cal.wide, kWideHelp);

  std::vector<std::string> subcommands;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    subcommands.push_back(sub->get_name());
  if (const std::string unknown = unknown_subcommand(argc, argv, subcommands); !unknown.empty()) {
    std::cerr << "masonry-joint: " << unknown << "\n";
    return kExitBadInput;
  }
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
      return run_command(run, std::cerr);
    }
    scene.plots = !scene_no_plots;
    if (*scene_cmd) return scene_command(scene, std::cout, std::cerr);
    if (*inp_cmd) return inp_command(inp, std::cout);
    if (*cal_cmd) {
      cal.plots = !cal_no_plots;
      return calibrate_command(cal, std::cout, std::cerr);
    }
    if (*bench_cmd && throughput) {
      for (const char* ignored : {"--out", "--path", "--budget", "--no-plots"})
        if (bench_cmd->count(ignored) > 0)
          throw InputError(std::string(ignored) +
                           " is an option of the work-precision study, not of bench --throughput (which prints "
                           "its table and writes no file); --throughput takes --repeats, --quick, --data, --quiet");
      throughput_options.data_dir = bench.data_dir;
      throughput_options.quick = bench.quick;
      throughput_options.quiet = bench.quiet;
      throughput_options.wide = bench.wide;
      return run_throughput_command(throughput_options, std::cout, std::cerr);
    }
    if (*bench_cmd) {
      if (bench_cmd->count("--repeats") > 0)
        throw InputError("--repeats is an option of bench --throughput only");
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
