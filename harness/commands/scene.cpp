#include "commands/scene.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>

#include "input/input_error.hpp"
#include "input/scene_file.hpp"
#include "output/csv.hpp"
#include "output/output_paths.hpp"
#include "output/plots.hpp"
#include "output/progress.hpp"
#include "output/scene_csv.hpp"
#include "output/scene_plots.hpp"
#include "output/terminal_text.hpp"
#include "scenes/wall.hpp"
#include "solvers/block_solver.hpp"
#include "solvers/scene_plan.hpp"

namespace mortar::harness {

namespace {

void check_args(const SceneArgs& a) {
  if (a.threads < 1 || a.threads > 256)
    throw InputError("--threads " + std::to_string(a.threads) + " violates the rule: 1 <= threads <= 256");
  if (a.block < 1 || a.block > 136)
    throw InputError("--block " + std::to_string(a.block) +
                     " violates the rule: 1 <= block <= 136 (Abaqus/Explicit's largest nBlock)");
}

}  // namespace

int scene_command(const SceneArgs& args, std::ostream& out, std::ostream& err) {
  check_args(args);
  const SceneSpec spec = read_scene_file(args.file);
  BlockSolverOptions options;
  options.block = args.block;
  options.threads = args.threads;
  // Everything checked before the folder is made: a bad scene writes nothing.
  ScenePlan plan(spec, options);
  const WallModel& model = plan.model();
  BlockSolver& solver = plan.solver();
  const long total = plan.increments();
  const int every = plan.every();
  prepare_output_folder(args.out, "--out");
  HistoryCsv history(args.out + "/history.csv");
  WallSample last;
  std::vector<WallSnapshot> snaps;
  Progress progress("scene: " + std::to_string(total) + " increments", args.quiet);
  const WallRunSummary r = solver.run(
      every,
      [&](const WallSample& s) {
        history.row(s);
        last = s;
      },
      [&](long done, long all) { progress.update(done, all); }, &snaps);
  progress.finish();
  std::vector<Magnification> mags;
  std::ostringstream factors;
  factors.precision(3);
  for (size_t k = 0; k < snaps.size(); ++k) {
    mags.push_back(picture_magnification(spec.output, model, snaps[k]));
    write_snapshot_csv(args.out, static_cast<int>(k), model, snaps[k], mags[k].factor);
    factors << (k ? ", " : "") << mags[k].factor;
  }
  if (!spec.output.experiment.empty())  // beside the pictures, with the scene's units
    write_csv(args.out + "/experiment.csv", {"top_displacement_mm", "base_shear_kN"}, spec.output.experiment_curve);
  const std::string summary = scene_summary(spec, model, r, last);
  {
    std::ofstream f(args.out + "/summary.txt");
    if (!f) throw InputError(cannot_write(args.out + "/summary.txt"));
    f << summary;
  }
  std::ostringstream wrote;
  wrote << "scene: wrote " << args.out << "/history.csv, summary.txt, snapshot_*_{blocks,joints}.csv (" << snaps.size()
        << " snapshots, displacements x " << factors.str()
        << (spec.output.magnification > 0 ? ", the scene file's"
                                          : ", each picture's largest joint opening or slip drawn as 5 % of the height")
        << ")\n";
  out << fit_to_width(summary + wrote.str());
  if (!args.plots) return 0;
  std::vector<std::string> labels;
  for (const WallSnapshot& s : snaps) labels.push_back(s.label);
  const std::string script =
      write_scene_plot_script(args.out, labels, mags, spec.output.joint_colour, spec.output.experiment_label);
  if (!gnuplot_available()) {
    err << "scene: gnuplot is not on the PATH: wrote " << script << " only\n";
    return 0;
  }
  std::string message;
  if (!run_gnuplot(args.out, script, message)) {
    err << "scene: gnuplot failed on " << script << ":\n" << message;
    return 1;
  }
  out << fit_to_width("scene: drew base_shear, energy and wall_0.." + std::to_string(snaps.size() - 1) +
                      " (.png, .svg) with " + script + "\n");
  return 0;
}

}  // namespace mortar::harness
