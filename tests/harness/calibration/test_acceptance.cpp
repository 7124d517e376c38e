// The acceptance rules of a calibrated set (calibration/acceptance.hpp) on
// made-up fit results, one rule at a time, and a parameter file never
// holding a non-finite value (issue 39: c0 = -nan was written as ready).
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "calibration/acceptance.hpp"
#include "input/parameter_file.hpp"
#include "paper_sets.hpp"
#include "support.hpp"

using namespace mortar;
using namespace mortar::harness;

namespace {

// A converged fit of GIIC at 0.058 with a misfit at the noise.
FitResult good_fit() {
  FitResult f;
  f.unknowns = {{parameter_index("GIIC"), NAN, 1e-4, 10}};
  f.value = Eigen::VectorXd::Constant(1, 0.058);
  f.converged = true, f.status = "converged";
  f.rms = 0.01;
  f.misfit = {{"shear", 0.01, NAN, 0.01, false}};
  return f;
}

std::string reasons(const Verdict& v) {
  std::string s;
  for (const std::string& r : v.reasons) s += r + "\n";
  return s;
}

}  // namespace

TEST_CASE("a calibrated set is accepted only when the fit converged near the noise, off its bounds, finite",
          "[calibration]") {
  const Parameters p = mortar::testing::van_der_pluijm(-0.5);
  CHECK(judge(good_fit(), {{"", p}}).accepted());
  struct Case {
    const char* message;
    void (*spoil)(FitResult&, Parameters&);
  } cases[] = {
      {"did not converge", [](FitResult& f, Parameters&) { f.converged = false; }},
      {"RMS misfit 0.375 of the curves' scale is above 0.05", [](FitResult& f, Parameters&) { f.rms = 0.375; }},
      {"shear: RMS misfit 0.2 of its scale is above 0.1", [](FitResult& f, Parameters&) { f.misfit[0].rms_scaled = 0.2; }},
      {"GIIC = 9.99 is on a bound of the fit", [](FitResult& f, Parameters&) { f.value[0] = 9.99; }},
      {"c0 is not finite", [](FitResult&, Parameters& q) { q.c0 = NAN; }},
      {"breaks a rule of the law", [](FitResult&, Parameters& q) { q.phir = q.phi0 + 1; }},
  };
  for (const Case& c : cases) {
    FitResult f = good_fit();
    Parameters q = p;
    c.spoil(f, q);
    const Verdict v = judge(f, {{"", q}});
    INFO(reasons(v));
    CHECK_THAT(reasons(v), Catch::Contains(c.message));
  }
  // psir's lower bound, 0, is the law's own value: not a bound that stopped the fit.
  FitResult f = good_fit();
  f.unknowns = {{parameter_index("psir"), NAN, 0, 45, true}};
  f.value[0] = 0;
  CHECK(judge(f, {{"", p}}).accepted());
}

TEST_CASE("a parameter file never holds a non-finite value", "[calibration]") {
  Parameters p = mortar::testing::van_der_pluijm(-0.5);
  p.c0 = NAN, p.psi0 = -NAN;
  const std::string path = (mortar::harness::testing::fresh_directory("nonfinite") / "params.toml").string();
  write_parameter_file(path, p, {"test"});
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  CHECK_THAT(text.str(), Catch::Contains("# c0 = not finite"));
  CHECK_THAT(text.str(), !Catch::Contains("c0   = {"));
  CHECK_THROWS(read_parameter_file(path));
}

// Issue 39 asked for outliers to be reported: a point far off the fit is
// named by file, data row, quantity and value; the others are not.
TEST_CASE("a point far off the fit is reported as an outlier, by file and row", "[calibration]") {
  TestCurve c;
  c.file = "shear_sn0.5.csv";
  c.kind = TestKind::shear;
  c.sigma_n = -0.5;
  for (int i = 0; i < 20; ++i) c.x.push_back(0.001 * i), c.y.push_back(0.05 * i), c.uplift.push_back(0);
  c.y[7] = 30;
  FitResult f = good_fit();
  f.residuals = Eigen::VectorXd::Zero(40);
  for (long i = 0; i < 40; ++i) f.residuals[i] = (i % 3 - 1) * 0.01;
  f.residuals[14] = 2.5;  // row 8's tau (traction then uplift per point)
  const std::vector<std::string> found = outliers(f, {c});
  REQUIRE(found.size() == 1);
  CHECK_THAT(found[0], Catch::StartsWith("shear_sn0.5.csv: data row 8: tau 30 MPa is an outlier: scaled residual 2.5"));
  f.residuals[14] = 0.01;
  CHECK(outliers(f, {c}).empty());
}
