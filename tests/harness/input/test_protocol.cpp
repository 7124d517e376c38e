// Loading programs: components that are not given hold what they did, and
// the compact cycle notation expands into legs as documented.
#include <catch2/catch.hpp>

#include "support.hpp"

using namespace mortar;
using namespace mortar::harness;
using namespace mortar::harness::testing;

TEST_CASE("Unspecified components hold what they did and the first step starts bonded at zero", "[inputs]") {
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
