// The input-deck block: header, comments, eight exact props per line.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <sstream>

#include "output/inp_deck.hpp"

using namespace mortar::harness;

TEST_CASE("The input-deck block: header, comments, eight exact props per line", "[inputs]") {
  // Arrange
  InpOptions o;
  o.props = {209.9, 87.4, 0.62, 0.88, 0.00458, 0.058, 40.97, 36.87, 1217.7, 27.7, 0, 1828.3, 10, 3, 1, 1e-8};
  o.depvar = 23;
  std::ostringstream out;
  // Act
  write_surface_interaction(out, o);
  // Assert
  const std::string text = out.str();
  CHECK_THAT(text, Catch::Contains("*SURFACE INTERACTION, NAME=MORTAR, USER=INTERACTION, PROPERTIES=16, DEPVAR=23\n"));
  CHECK_THAT(text, Catch::Contains("\n209.9, 87.4, 0.62, 0.88, 0.00458, 0.058, 40.97, 36.87\n"));
  CHECK_THAT(text, Catch::Contains("** props(9..16): m psi0 psir n bn bs scheme STOL\n"
                                   "1217.7, 27.7, 0., 1828.3, 10., 3., 1., 1e-08\n"));
  // How to run it, as README and docs/abaqus.md say: the prebuilt libraries
  // from usub_lib_dir, no user= on the command line.
  CHECK_THAT(text, Catch::Contains("Run without user=: usub_lib_dir in abaqus_v6.env"));
  CHECK_THAT(text, !Catch::Contains("run with user="));
}

TEST_CASE("Numbers in the input deck read back exactly", "[inputs]") {
  for (double x : {0.1, 1.0 / 3.0, 209.9, 1e-300, 6.02214076e23, 0.0}) {
    const std::string s = exact_decimal(x);
    CAPTURE(s);
    CHECK(std::strtod(s.c_str(), nullptr) == x);
  }
}

TEST_CASE("A deck with a compression cap carries props(21..24) and DEPVAR 37 (UINTER: 36)", "[inputs][cap]") {
  // Arrange: van der Pluijm's set with a cap that keeps its rules.
  const mortar::Parameters p = {209.9, 87.4, 0.62, 0.88, 0.00458, 0.058, 40.97, 36.87, 1217.7, 27.7, 0, 1828.3, 10, 3};
  const mortar::CompressionCap cap = {10, 1, 2, 0.02};
  REQUIRE(mortar::validate(cap, p).ok());
  // Act
  InpOptions o;
  o.props = deck_props(p, false, false, mortar::Scheme::modified_euler, 0, cap);
  o.depvar = deck_depvar(o.props, false);
  std::ostringstream out;
  write_surface_interaction(out, o);
  // Assert
  const std::string text = out.str();
  CHECK_THAT(text, Catch::Contains("PROPERTIES=24, DEPVAR=37\n"));
  CHECK_THAT(text, Catch::Contains("** props(17..24): FTOL max substeps min substep shear sign fc Cs Gfc kappa_p\n"
                                   "0., 0., 0., 0., 10., 1., 2., 0.02\n"));
  CHECK(deck_depvar(o.props, true) == 36);
  // Without a cap (or fc = 0): today's props and DEPVAR.
  const std::vector<double> plain = deck_props(p, false, false, mortar::Scheme::modified_euler, 0);
  CHECK(plain.size() == 14);
  CHECK(deck_depvar(plain, false) == 35);
  CHECK(deck_depvar(plain, true) == 23);
  std::vector<double> off = o.props;
  off[20] = 0;
  CHECK(deck_depvar(off, false) == 35);
}

// Issue 39: `inp --name 'A B,C'` and `--name ''` wrote an invalid deck with
// exit 0. The rule behind the command's exit 2 (ctest drops an empty
// argument, so the empty name is checked here).
TEST_CASE("An interaction NAME Abaqus cannot read is named with its fault", "[inputs]") {
  CHECK(abaqus_name_problem("") == "is empty");
  CHECK(abaqus_name_problem("A B,C") == "holds a space");
  CHECK(abaqus_name_problem("AB,C") == "holds ','");
  CHECK(abaqus_name_problem("1JOINT") == "does not start with a letter");
  CHECK(abaqus_name_problem(std::string(81, 'A')) == "has 81 characters");
  CHECK(abaqus_name_problem(std::string(80, 'A')).empty());
  CHECK(abaqus_name_problem("MORTAR-M15_a").empty());
}
