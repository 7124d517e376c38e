// Parameter files, loading programs and the input-deck block: what is read
// is what was written, and the compact cycle notation expands as documented.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "harness_test_support.hpp"
#include "inp.hpp"
#include "input_error.hpp"

using namespace mortar;
using namespace mortar::harness;
using namespace mortar::harness::testing;

TEST_CASE("A parameter file gives the 14 values of Table 1 and where each was written", "[inputs]") {
  // Act
  const ParameterSet set = read_parameter_file(std::string(MJ_CALIBRATION_DATA_DIR) + "/almeida_tension/params_M34.toml");
  // Assert
  const double table1[kParameterCount] = {750.5, 312.7, 0.91, 1.37, 0.00293, 0.02925, 40,
                                          32,    2944.5, 8,   0,    4923.8,  10,      3};
  for (int i = 0; i < kParameterCount; ++i) {
    CAPTURE(kParameterInfo[i].name);
    CHECK(parameter_at(set.values, i) == table1[i]);
    CHECK(set.line[i] == i + 4);  // three comment lines, then one parameter per line
  }
}

TEST_CASE("Bare numbers are read in the documented units; integers count as numbers", "[inputs]") {
  // Arrange
  const auto dir = fresh_directory("bare_numbers");
  const std::string file = write_file(dir / "p.toml",
                                      "kn = 209.9\nks = 87.4\nft0 = 0.62\nc0 = 0.88\nGIC = 0.00458\nGIIC = 0.058\n"
                                      "phi0 = 40.97\nphir = 36.87\nm = 1217.7\npsi0 = 27.7\npsir = 0\nn = 1828.3\n"
                                      "bn = 10\nbs = 3\n");
  // Act
  const ParameterSet set = read_parameter_file(file);
  // Assert
  CHECK(set.values.psir == 0.0);
  CHECK(set.values.bn == 10.0);
  CHECK(set.values.m == 1217.7);
}

TEST_CASE("A non-finite parameter is an error, not a clamp", "[inputs]") {
  const auto dir = fresh_directory("nan_param");
  const std::string file = write_file(dir / "p.toml",
                                      "kn = nan\nks = 87.4\nft0 = 0.62\nc0 = 0.88\nGIC = 0.00458\nGIIC = 0.058\n"
                                      "phi0 = 40.97\nphir = 36.87\nm = 1217.7\npsi0 = 27.7\npsir = 0\nn = 1828.3\n"
                                      "bn = 10\nbs = 3\n");
  CHECK_THROWS_WITH(read_parameter_file(file), Catch::Contains("p.toml:1: parameter 'kn' must be a finite number"));
}

TEST_CASE("Unspecified components hold what they did; the first step starts bonded at zero", "[inputs]") {
  // Act
  const Protocol p = read_protocol_file(data_file("short_shear.toml"));
  // Assert
  REQUIRE(p.steps.size() == 2);
  CHECK(p.directions == 3);
  CHECK(p.total_increments() == 320);
  const ProgramStep& load = p.steps[0];
  CHECK(load.component[0].kind == Control::traction);
  CHECK(load.component[0].target == -0.5);
  CHECK(load.component[1].kind == Control::displacement);  // not given: bonded at zero slip
  CHECK(load.component[1].target == 0.0);
  const ProgramStep& shear = p.steps[1];
  CHECK(shear.component[0].kind == Control::traction);  // held from step 1
  CHECK(shear.component[0].target == -0.5);
  CHECK(shear.component[1].kind == Control::displacement);
  CHECK(shear.component[1].target == 0.03);
  CHECK(shear.component[2].kind == Control::displacement);
  CHECK(shear.component[2].target == 0.0);
}

TEST_CASE("Cycles expand into legs: to +a, to -a per repeat, then back", "[inputs]") {
  // Act: amplitudes 0.01 and 0.02 mm, twice each, 10 increments per quarter
  const Protocol p = read_protocol_file(data_file("cycles_2d.toml"));
  // Assert
  CHECK(p.directions == 2);
  const std::vector<double> targets = {0.01, -0.01, 0.01, -0.01, 0.02, -0.02, 0.02, -0.02, 0.0};
  // Leg length / amplitude * 10: the first leg and the last are quarters.
  const std::vector<long> increments = {10, 20, 20, 20, 15, 20, 20, 20, 10};
  REQUIRE(p.steps.size() == 1 + targets.size());
  for (size_t i = 0; i < targets.size(); ++i) {
    const ProgramStep& leg = p.steps[i + 1];
    CAPTURE(i, leg.name);
    CHECK(leg.component[1].kind == Control::displacement);
    CHECK(leg.component[1].target == Approx(targets[i]).margin(1e-15));
    CHECK(leg.increments == increments[i]);
    CHECK(leg.component[0].kind == Control::traction);  // the normal traction is held throughout
    CHECK(leg.component[0].target == -0.2);
  }
}

TEST_CASE("Cycles sized by max_increment use whole increments no larger than it", "[inputs]") {
  const auto dir = fresh_directory("cycles_max_increment");
  const std::string file = write_file(dir / "c.toml",
                                      "[[step]]\nincrements = 2\nn = { traction = -0.1 }\n"
                                      "[[step]]\ns1 = { cycles = [0.5], about = 0.1 }\nmax_increment = 0.1\n");
  const Protocol p = read_protocol_file(file);
  REQUIRE(p.steps.size() == 4);
  CHECK(p.steps[1].component[1].target == Approx(0.6));  // from 0 to about + a
  CHECK(p.steps[1].increments == 6);
  CHECK(p.steps[2].component[1].target == Approx(-0.4));
  CHECK(p.steps[2].increments == 10);
  CHECK(p.steps[3].component[1].target == Approx(0.1));  // back to about
  CHECK(p.steps[3].increments == 5);
}

TEST_CASE("Cycles of a traction-controlled component are refused with the reason", "[inputs]") {
  const auto dir = fresh_directory("cycles_after_traction");
  const std::string file = write_file(dir / "c.toml",
                                      "[[step]]\nincrements = 2\ns1 = { traction = 0.1 }\n"
                                      "[[step]]\ns1 = { cycles = [0.5] }\nmax_increment = 0.1\n");
  CHECK_THROWS_WITH(read_protocol_file(file), Catch::Contains("c.toml:5: step 2 cycles s1, which is traction-controlled"));
}

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
}

TEST_CASE("Numbers in the input deck read back exactly", "[inputs]") {
  for (double x : {0.1, 1.0 / 3.0, 209.9, 1e-300, 6.02214076e23, 0.0}) {
    const std::string s = exact_decimal(x);
    CAPTURE(s);
    CHECK(std::strtod(s.c_str(), nullptr) == x);
  }
}
