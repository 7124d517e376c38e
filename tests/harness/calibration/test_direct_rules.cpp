// The direct rules against the parameters that made the curves: noise-free
// synthetic curves of van der Pluijm's set (the digitised peak lies within
// 0.4 % of the true one, so the strengths are held to 1 %), and 1 % noise.
#include <catch2/catch.hpp>

#include "calibration/direct_rules.hpp"
#include "calibration/synthetic.hpp"
#include "input/input_error.hpp"
#include "paper_sets.hpp"

using namespace mortar;
using namespace mortar::harness;

namespace {
std::vector<TestCurve> curves_of(const Parameters& p, double noise) {
  std::vector<TestCurve> out;
  std::uint32_t seed = 40;
  for (const SyntheticTest& t : standard_programme(p, 30)) out.push_back(synthetic_curve(p, t, noise, seed++, "c"));
  return out;
}
double relative(const Calibration& c, const Parameters& p, const char* name) {
  const double truth = parameter_at(p, parameter_index(name));
  return std::abs(c[name].value - truth) / truth;
}
}  // namespace

TEST_CASE("direct rules recover van der Pluijm's stiffnesses, strengths and GIC", "[calibration]") {
  const Parameters p = testing::van_der_pluijm(-0.5);
  const std::vector<TestCurve> curves = curves_of(p, 0.0);
  const Calibration c = apply_direct_rules(curves).calibration;
  for (const char* name : {"kn", "ks", "ft0", "GIC"}) {
    INFO(name);
    CHECK(relative(c, p, name) < 1e-3);
    CHECK(c[name].stage == Stage::direct);
  }
  for (const char* name : {"c0", "phi0", "phir"}) {
    INFO(name);
    CHECK(relative(c, p, name) < 0.01);
  }
  CHECK(c["psir"].stage == Stage::not_determined);
  // 1 % noise: the regressions stay within 2 %, and say how far they may be off.
  const Calibration noisy = apply_direct_rules(curves_of(p, 0.01)).calibration;
  for (const char* name : {"kn", "ks", "ft0", "GIC"}) {
    INFO(name);
    CHECK(relative(noisy, p, name) < 0.02);
    CHECK(noisy[name].std_error > 0);
    CHECK(std::abs(noisy[name].value - parameter_at(p, parameter_index(name))) < 3 * noisy[name].std_error);
  }
}

TEST_CASE("direct rules need enough normal stresses", "[calibration]") {
  const Parameters p = testing::van_der_pluijm(-0.5);
  std::vector<TestCurve> curves = curves_of(p, 0.0);
  curves.resize(2);  // tension and one shear curve
  CHECK_THROWS_WITH(apply_direct_rules(curves), Catch::Contains("shear curves at 1 normal stress(es)"));
}
