// `masonry-joint run`: a loading program through either mock solver
// (--solver explicit: solvers/explicit_run.hpp; --solver implicit:
// solvers/implicit_run.hpp), and the rules that tie the run options to the
// solver.
#pragma once

#include <iosfwd>
#include <map>
#include <string>

#include "mortar/parameters.hpp"
#include "solvers/implicit_run.hpp"

namespace mortar::harness {

inline constexpr const char* kSolverNames[] = {"explicit", "implicit"};

// Which run options were given, with their values, for the solver rules.
struct SolverOptionUse {
  std::string solver = "explicit";
  bool points_given = false, block_given = false, max_cuts_given = false, print_residuals = false;
  int points = 1, block = 512, max_cuts = 5;
  bool symmetric_tangent = false;
};

// InputError (exit 2) when an option does not belong to the chosen solver:
// --points and --block are the explicit solver's (blocks of points through
// vuinteraction_), --max-cuts and --print-residuals the implicit one's.
void check_solver_options(const SolverOptionUse& use);

// The options of `masonry-joint run`.
struct RunArgs {
  std::string params, protocol, out, scheme;  // scheme: empty = the solver's default
  std::string solver = "explicit";
  double stol = 0, traction_tol = 1e-9;
  int points = 1, block = 512, max_cuts = 5;
  bool quiet = false, print_residuals = false, symmetric_tangent = false;
  bool wide = false;  // the summary on stderr unwrapped (else within 100 columns)
  bool points_given = false, block_given = false, max_cuts_given = false;
};

// The schemes by their command-line names (props(15)).
const std::map<std::string, Scheme>& scheme_names();

// InputError unless 0 < STOL < 1 or STOL = 0 (the routine's default).
void check_stol(double stol);

// Runs the program with the chosen solver, writes the run CSV
// (harness/README.md), prints the summary on `err`. Returns the exit status
// (0, or 1 when the run could not be completed or identical points differ);
// throws InputError for bad files and options.
int run_command(const RunArgs& args, std::ostream& err);

// "r1 r2 ... [MPa]" of an attempt, 3 significant digits.
std::string format_residuals(const ResidualSequence& r);

}  // namespace mortar::harness
