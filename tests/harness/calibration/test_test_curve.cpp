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
      {"bad_kind", "# kind: torsion\nslip_mm,tau_MPa\n", ":1: kind 'torsion' is not one of tension, cyclic_tension, shear, cyclic_shear"},
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

// Values that break no rule of the format but cannot be a joint test's
// (calibration/curve_checks.hpp): each names the file, the row and the rule.
TEST_CASE("implausible test curves are errors naming the file and the rule", "[calibration]") {
  const std::string shear = "# kind: shear\n# sigma_n: -0.5 MPa\nslip_mm,tau_MPa\n";
  const std::string tension = "# kind: tension\nopening_mm,sigma_MPa\n";
  struct Bad {
    const char *name, *text, *message;
  } bad[] = {
      {"zero", "0,0\n0.01,0\n0.02,0\n0.03,0\n", "zero.csv: every tau is zero"},
      {"huge", "0,0\n0.01,0.5\n0.02,1e30\n0.03,0.4\n", "huge.csv: data row 3: tau = 1e+30 MPa is outside the plausible range"},
      {"negative", "0,0\n0.01,-0.5\n0.02,-0.6\n0.03,-0.4\n", "tau is negative (largest |tau| = -0.6 MPa at data row 3)"},
      {"backwards_slip", "0,0\n-0.01,0.5\n-0.02,0.6\n-0.03,0.4\n", "slip ends negative (-0.03 mm)"},
      {"no_peak", "0,0\n0.01,0.5\n0.02,0.6\n0.03,0.7\n", "the shear curve ends at its largest value (0.7 MPa at data row 4 of 4)"},
  };
  for (const Bad& b : bad) {
    INFO(b.name);
    CHECK_THROWS_WITH(read_test_curve(file_with(b.name, shear + b.text)), Catch::Contains(b.message));
  }
  // A tension curve cut just after its peak is not read as a snap-back.
  CHECK_THROWS_WITH(read_test_curve(file_with("cut", tension + "0,0\n0.001,0.3\n0.002,0.6\n0.0025,0.58\n")),
                    Catch::Contains("cut.csv: the tension curve ends within 10 % of its largest value"));
  CHECK_NOTHROW(read_test_curve(file_with("snap", tension + "0,0\n0.001,0.3\n0.002,0.6\n0.0021,0.01\n")));
}
