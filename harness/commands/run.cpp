#include "commands/run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <sstream>

#include "input/input_error.hpp"
#include "input/parameter_file.hpp"
#include "input/protocol.hpp"
#include "abi/vuinteraction_signs.hpp"
#include "output/csv.hpp"
#include "output/flag_tally.hpp"
#include "output/output_paths.hpp"
#include "output/progress.hpp"
#include "output/terminal_text.hpp"
#include "scenes/joint_test.hpp"
#include "solvers/explicit_run.hpp"
#include "validation/checks.hpp"

namespace mortar::harness {

const std::map<std::string, Scheme>& scheme_names() {
  static const std::map<std::string, Scheme> names = {{"modified-euler", Scheme::modified_euler},
                                                      {"forward-euler", Scheme::forward_euler},
                                                      {"implicit", Scheme::implicit}};
  return names;
}

void check_stol(double stol) {
  if (stol != 0 && !(stol > 0 && stol < 1))
    throw InputError("--stol " + input_number(stol) + " violates the rule 0 < STOL < 1 (0 keeps the default)");
}

void check_solver_options(const SolverOptionUse& u) {
  if (u.solver == "implicit") {
    const char* why =
        " is an option of --solver explicit only: Abaqus/Standard calls UINTER once per contact point, and "
        "--solver implicit drives one point";
    if (u.points_given && u.points != 1) throw InputError("--points " + std::to_string(u.points) + why);
    if (u.block_given) throw InputError("--block " + std::to_string(u.block) + why);
    return;
  }
  const char* why = " is an option of --solver implicit only: the explicit solver never cuts an increment back";
  if (u.max_cuts_given) throw InputError("--max-cuts " + std::to_string(u.max_cuts) + why);
  if (u.symmetric_tangent)
    throw InputError(std::string("--symmetric-tangent is an option of --solver implicit only: the explicit "
                                 "solver does not use the routine's tangent"));
  if (u.print_residuals)
    throw InputError(std::string("--print-residuals is an option of --solver implicit only: the explicit solver's "
                                 "Newton uses a finite-difference Jacobian, whose residuals show nothing about "
                                 "the routine's tangent"));
}

std::string format_residuals(const ResidualSequence& r) {
  std::string s;
  char number[32];
  for (int k = 0; k < r.count; ++k) {
    std::snprintf(number, sizeof number, "%s%.3e", k ? " " : "", r.residual[static_cast<size_t>(k)]);
    s += number;
  }
  return s + " MPa";
}

namespace {

std::string describe(const ResidualSequence& r) {
  char where[160];
  std::snprintf(where, sizeof where, "step %d, increment %ld, sub-increment %d (%.6g..%.6g of the increment)",
                r.step, r.increment, r.sub_increment, r.start, r.start + r.size);
  std::string s = std::string(where) + ": ";
  s += r.outcome == AttemptOutcome::converged ? "converged" : std::string("cut back on ") + outcome_name(r.outcome);
  if (r.outcome == AttemptOutcome::cut_by_routine) s += " (PNEWDT = " + format_number(r.pnewdt) + ")";
  return s + ", " + std::to_string(r.count) + " iteration(s): " + format_residuals(r);
}

void summary(const RunArgs& a, const ImplicitStatistics& st, const FlagTally& flags, std::ostream& out) {
  std::ostringstream err;
  err << "run (implicit, UINTER): " << st.increments << " increments, " << st.attempts << " attempts ("
      << st.cuts_by_routine << " cut back on PNEWDT, " << st.diverged << " diverged, " << st.not_converged
      << " not converged, " << st.cycling << " cycling): " << st.calls << " calls of uinter_ in " << st.seconds
      << " s\n"
      << "run: equilibrium iterations per attempt at most " << st.max_iterations
      << "; largest controlled-traction residual " << st.max_traction_residual << " MPa (tolerance "
      << a.traction_tol << " MPa)\n";
  if (st.has_worst) err << "run: most iterations: " << describe(st.worst) << "\n";
  err << "run: " << flags.summary() << "\n";
  err << "run: wrote " << a.out << "\n";
  out << terminal_text(err.str(), a.wide);
}

// The run CSV (point 1's rows) and the progress line around one solver run.
class RunOutput {
 public:
  explicit RunOutput(const RunArgs& a) : file_(a.out), csv_(a.out), progress_("run", a.quiet) {
    if (!csv_) throw InputError(cannot_write(file_));
    write_run_header(csv_);
  }
  void write(const Sample& s) { write_run_row(csv_, s); }
  ProgressSink progress() {
    return [this](long done, long total) { progress_.update(done, total); };
  }
  // Runs `solve`; false (and the reason on `err`) when it throws RunFailure.
  template <class Solve>
  bool complete(const Solve& solve, std::ostream& err) {
    try {
      solve();
    } catch (const RunFailure& e) {
      progress_.finish();
      err << "masonry-joint run: " << e.what() << "\n"
          << "masonry-joint run: " << file_ << " holds the increments up to the failure\n";
      return false;
    }
    progress_.finish();
    csv_.close();
    if (!csv_) throw InputError(file_ + ": write failed");
    return true;
  }

 private:
  std::string file_;
  std::ofstream csv_;
  Progress progress_;
};

// --solver implicit: one point through UINTER.
int run_implicit(const RunArgs& a, std::ostream& err) {
  ImplicitSettings settings;
  settings.scheme = scheme_names().at(a.scheme.empty() ? "implicit" : a.scheme);
  settings.stol = a.stol;
  settings.options.traction_tolerance = a.traction_tol;
  settings.options.max_cuts = a.max_cuts;
  settings.options.symmetric_tangent = a.symmetric_tangent;
  const ParameterSet params = read_parameter_file(a.params);
  settings.cap = params.cap;
  const Protocol protocol = read_protocol_file(a.protocol);
  JointTest scene(protocol, 1);
  RunOutput output(a);
  ResidualSink residuals;
  if (a.print_residuals) residuals = [&](const ResidualSequence& r) { err << "residuals: " << describe(r) << "\n"; };
  ImplicitStatistics stats;
  FlagTally flags;
  const bool completed = output.complete(
      [&] {
        stats = run_scene_implicit(
            params.values, scene, settings,
            [&](int point, const Sample& s) {
              flags.add(point, s.integration_flags);
              if (abi_signs::unpaired(s.separation[0])) flags.add_unpaired(point);
              output.write(s);
            },
            output.progress(), residuals);
      },
      err);
  if (!completed) return 1;
  if (!a.quiet) summary(a, stats, flags, err);
  if (const std::string w = flags.unpaired_warning(); !w.empty()) err << "run: " << w << "\n";
  return 0;
}

// Largest difference of one sample from another (same increment).
double difference(const Sample& a, const Sample& b) {
  double d = std::max((a.traction - b.traction).cwiseAbs().maxCoeff(),
                      (a.separation - b.separation).cwiseAbs().maxCoeff());
  for (int i = 0; i < kStateCount; ++i) d = std::max(d, std::abs(a.state[i] - b.state[i]));
  d = std::max(d, std::abs(a.elastic_energy - b.elastic_energy));
  return std::max(d, std::abs(a.dissipation_increment - b.dissipation_increment));
}

// --solver explicit: N identical points in blocks through vuinteraction_.
int run_explicit(const RunArgs& a, std::ostream& err) {
  const ParameterSet params = read_parameter_file(a.params);
  const Protocol protocol = read_protocol_file(a.protocol);
  RunSettings settings;
  settings.scheme = scheme_names().at(a.scheme.empty() ? "modified-euler" : a.scheme);
  settings.stol = a.stol;
  settings.cap = params.cap;
  settings.block = a.block;
  settings.mixed.traction_tolerance = a.traction_tol;
  JointTest scene(protocol, a.points);
  RunOutput output(a);
  // Point 1 is written; every other point must reproduce it exactly, since
  // all points are identical and blocks must not matter.
  Sample first;
  double worst = 0;
  RunStatistics stats;
  FlagTally flags;
  const bool completed = output.complete(
      [&] {
        stats = run_scene(
            params.values, scene, settings,
            [&](int point, const Sample& s) {
              flags.add(point, s.integration_flags);
              if (abi_signs::unpaired(s.separation[0])) flags.add_unpaired(point);
              if (point == 0) {
                first = s;
                output.write(s);
              } else {
                worst = std::max(worst, difference(s, first));
              }
            },
            output.progress());
      },
      err);
  if (!completed) return 1;
  if (!a.quiet) {
    std::ostringstream text;
    text << "run: " << stats.increments << " increments x " << a.points << " point(s) in " << stats.blocks
        << " block(s): " << stats.calls << " calls of vuinteraction_ in " << stats.seconds << " s\n"
        << "run: Newton updates per increment at most " << stats.max_iterations
        << "; largest controlled-traction residual " << stats.max_traction_residual << " MPa (tolerance "
        << a.traction_tol << " MPa)\n";
    if (a.points > 1) text << "run: largest difference of any point from point 1: " << worst << "\n";
    text << "run: " << flags.summary() << "\n";
    text << "run: wrote " << a.out << "\n";
    err << terminal_text(text.str(), a.wide);
  }
  if (const std::string w = flags.unpaired_warning(); !w.empty()) err << "run: " << w << "\n";
  if (worst != 0) {
    err << "masonry-joint run: identical points gave different results (largest difference " << worst
        << "): the result depends on the blocking\n";
    return 1;
  }
  return 0;
}

}  // namespace

int run_command(const RunArgs& a, std::ostream& err) {
  check_stol(a.stol);
  if (!(a.traction_tol > 0) || !std::isfinite(a.traction_tol))
    throw InputError("--traction-tol " + input_number(a.traction_tol) +
                     " violates the rule: a finite tolerance > 0 [MPa]");
  check_output_file(a.out, "--out");
  check_solver_options({a.solver, a.points_given, a.block_given, a.max_cuts_given, a.print_residuals, a.points,
                        a.block, a.max_cuts, a.symmetric_tangent});
  return a.solver == "implicit" ? run_implicit(a, err) : run_explicit(a, err);
}

}  // namespace mortar::harness
