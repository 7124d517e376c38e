// The run command's option rules: each solver's options belong to it, and
// STOL is checked before anything runs.
#include <catch2/catch.hpp>

#include "commands/run.hpp"
#include "input/input_error.hpp"

using namespace mortar;
using namespace mortar::harness;

TEST_CASE("Solver options are checked against the solver", "[implicit][inputs]") {
  SolverOptionUse use;
  use.solver = "implicit";
  use.points_given = true;
  use.points = 4;
  CHECK_THROWS_WITH(check_solver_options(use), Catch::Contains("--points 4 is an option of --solver explicit only"));
  use.points = 1;  // the default, spelled out: harmless
  CHECK_NOTHROW(check_solver_options(use));
  use.block_given = true;
  CHECK_THROWS_WITH(check_solver_options(use), Catch::Contains("--block 512 is an option of --solver explicit"));
  SolverOptionUse explicit_use;
  explicit_use.max_cuts_given = true;
  explicit_use.max_cuts = 3;
  CHECK_THROWS_WITH(check_solver_options(explicit_use),
                    Catch::Contains("--max-cuts 3 is an option of --solver implicit only"));
  explicit_use.max_cuts_given = false;
  explicit_use.print_residuals = true;
  CHECK_THROWS_WITH(check_solver_options(explicit_use), Catch::Contains("--print-residuals is an option of --solver implicit"));
}

TEST_CASE("STOL is 0 (the default) or in (0, 1)", "[inputs]") {
  CHECK_NOTHROW(check_stol(0));
  CHECK_NOTHROW(check_stol(1e-7));
  CHECK_THROWS_WITH(check_stol(1), Catch::Contains("--stol 1 violates the rule 0 < STOL < 1"));
  CHECK_THROWS_AS(check_stol(-1e-5), InputError);
}

TEST_CASE("Every scheme has its command-line name", "[inputs]") {
  CHECK(scheme_names().at("modified-euler") == Scheme::modified_euler);
  CHECK(scheme_names().at("forward-euler") == Scheme::forward_euler);
  CHECK(scheme_names().at("implicit") == Scheme::implicit);
  CHECK(scheme_names().size() == 3);
}
