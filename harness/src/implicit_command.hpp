// `masonry-joint run --solver implicit`: the command-line side of the
// implicit mock solver (implicit_runner.hpp), and the rules that tie the run
// options to the solver. Kept out of main.cpp so that the CLI file only
// declares options.
#pragma once

#include <iosfwd>
#include <string>

#include "implicit_runner.hpp"

namespace mortar::harness {

inline constexpr const char* kSolverNames[] = {"explicit", "implicit"};

// Which run options were given, with their values, for the solver rules.
struct SolverOptionUse {
  std::string solver = "explicit";
  bool points_given = false, block_given = false, max_cuts_given = false, print_residuals = false;
  int points = 1, block = 512, max_cuts = 5;
};

// InputError (exit 2) when an option does not belong to the chosen solver:
// --points and --block are the explicit solver's (blocks of points through
// vuinteraction_), --max-cuts and --print-residuals the implicit one's.
void check_solver_options(const SolverOptionUse& use);

struct ImplicitRunRequest {
  std::string params, protocol, out;
  ImplicitSettings settings;
  bool print_residuals = false;  // every attempt's residual sequence on stderr
  bool quiet = false;
};

// Runs the program, writes the run CSV (harness/README.md), prints the
// summary with the residual sequence of the worst increment on `err`.
// Returns the exit status (0, or 1 when the run could not be completed);
// throws InputError for bad files.
int run_implicit_command(const ImplicitRunRequest& request, std::ostream& err);

// "r1 r2 ... [MPa]" of an attempt, 3 significant digits.
std::string format_residuals(const ResidualSequence& r);

}  // namespace mortar::harness
