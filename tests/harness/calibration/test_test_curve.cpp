// Reading test curves: the metadata lines, the columns with their units, and
// every rule of the format, each with its message.
#include <catch2/catch.hpp>

#include <fstream>

#include "calibration/test_curve.hpp"
#include "input/input_error.hpp"
#include "support.hpp"

using namespace mortar::harness;

namespace {
std::string file_with(const std::string& name, const std::string& text) {
  const auto dir = testing::fresh_directory("test_curve_" + name);
  const std::string path = (dir / (name + ".csv")).string();
  std::ofstream(path) << text;
  return path;
}
}  // namespace

TEST_CASE("a shear curve with uplift is read with its kind and normal stress", "[calibration]") {
  const TestCurve c = read_test_curve(file_with("good", "# digitised from a figure\n# kind: shear\n# sigma_n: -0.5 MPa\n"
                                                        "slip_mm,tau_MPa,uplift_mm\n0,0,0\n0.01,0.8,0\n0.02,1.1,0.001\n0.1,0.5,0.003\n"));
  CHECK(c.kind == TestKind::shear);
  CHECK(c.sigma_n == -0.5);
  CHECK(c.name == "good");
  REQUIRE(c.x.size() == 4);
  CHECK(c.y[2] == 1.1);
  CHECK(c.uplift[3] == 0.003);
}

TEST_CASE("bad test curves are errors naming the rule", "[calibration]") {
  const std::string rows = "0,0\n0.01,0.5\n0.02,0.6\n0.03,0.4\n";
  struct Bad {
    const char *name, *text, *message;
  } bad[] = {
      {"no_kind", "slip_mm,tau_MPa\n", "states no kind of test"},
      {"bad_kind", "# kind: torsion\nslip_mm,tau_MPa\n", ":1: kind 'torsion' is not one of tension, shear, cyclic_shear"},
      {"no_sigma", "# kind: shear\nslip_mm,tau_MPa\n", "needs its constant normal stress"},
      {"sigma_unit", "# kind: shear\n# sigma_n: -0.5 kPa\nslip_mm,tau_MPa\n", "must state its unit as MPa"},
      {"sigma_sign", "# kind: shear\n# sigma_n: 0.5 MPa\nslip_mm,tau_MPa\n", "sigma_n = 0.5 MPa violates the rule"},
      {"tension_sigma", "# kind: tension\n# sigma_n: -0.5 MPa\nopening_mm,sigma_MPa\n", "a tension curve has no constant normal stress"},
      {"column", "# kind: tension\nopening_mm,sigma_kPa\n", "column 'sigma_kPa' is not a column of a tension curve"},
  };
  for (const Bad& b : bad) {
    INFO(b.name);
    CHECK_THROWS_WITH(read_test_curve(file_with(b.name, std::string(b.text) + rows)), Catch::Contains(b.message));
  }
  CHECK_THROWS_WITH(read_test_curve(file_with("backwards", "# kind: shear\n# sigma_n: -0.5 MPa\nslip_mm,tau_MPa\n"
                                                           "0,0\n0.02,0.5\n0.01,0.6\n0.03,0.4\n")),
                    Catch::Contains("row 3: slip 0.010000 mm is below the row before"));
}
