#include "implicit_command.hpp"

#include <cstdio>
#include <fstream>
#include <ostream>

#include "checks.hpp"
#include "csv.hpp"
#include "input_error.hpp"
#include "parameter_file.hpp"
#include "progress.hpp"
#include "protocol.hpp"

namespace mortar::harness {

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

void summary(const ImplicitRunRequest& a, const ImplicitStatistics& st, std::ostream& err) {
  err << "run (implicit, UINTER): " << st.increments << " increments, " << st.attempts << " attempts ("
      << st.cuts_by_routine << " cut back on PNEWDT, " << st.diverged << " diverged, " << st.not_converged
      << " not converged, " << st.cycling << " cycling): " << st.calls << " calls of uinter_ in " << st.seconds
      << " s\n"
      << "run: equilibrium iterations per attempt at most " << st.max_iterations
      << "; largest controlled-traction residual " << st.max_traction_residual << " MPa (tolerance "
      << a.settings.options.traction_tolerance << " MPa)\n";
  if (st.has_worst) err << "run: most iterations: " << describe(st.worst) << "\n";
  err << "run: wrote " << a.out << "\n";
}

}  // namespace

int run_implicit_command(const ImplicitRunRequest& a, std::ostream& err) {
  const ParameterSet params = read_parameter_file(a.params);
  const Protocol protocol = read_protocol_file(a.protocol);
  std::ofstream out(a.out);
  if (!out) throw InputError(a.out + ": cannot open the file for writing");
  write_run_header(out);
  Progress progress("run", a.quiet);
  ResidualSink residuals;
  if (a.print_residuals) residuals = [&](const ResidualSequence& r) { err << "residuals: " << describe(r) << "\n"; };
  ImplicitStatistics stats;
  try {
    stats = run_protocol_implicit(
        params.values, protocol, a.settings, [&](int, const Sample& s) { write_run_row(out, s); },
        [&](long done, long total) { progress.update(done, total); }, residuals);
  } catch (const RunFailure& e) {
    progress.finish();
    err << "masonry-joint run: " << e.what() << "\n"
        << "masonry-joint run: " << a.out << " holds the increments up to the failure\n";
    return 1;
  }
  progress.finish();
  out.close();
  if (!out) throw InputError(a.out + ": write failed");
  if (!a.quiet) summary(a, stats, err);
  return 0;
}

}  // namespace mortar::harness
