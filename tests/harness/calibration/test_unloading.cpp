// bn and bs from unloading branches (calibration/unloading_rules.hpp).
// The reading is checked against the law's own secant rule on noise-free
// curves, and the whole calibration against the set that made noisy ones.
#include <catch2/catch.hpp>

#include <fstream>

#include "calibration/pipeline.hpp"
#include "calibration/synthetic.hpp"
#include "calibration/unloading_rules.hpp"
#include "input/input_error.hpp"
#include "paper_sets.hpp"
#include "support.hpp"

using namespace mortar;
using namespace mortar::harness;

namespace {

// van der Pluijm's set with bn and bs away from Table 1's 10 and 3, so that
// no starting value is the answer.
Parameters truth() {
  Parameters p = mortar::testing::van_der_pluijm(-0.5);
  p.bn = 6;
  p.bs = 2;
  return p;
}

// Shear at -0.1, -0.5, -1.0 MPa (the standard programme), the tension
// unloaded three times and the shear at constant tension unloaded three times.
std::vector<TestCurve> curves_with_unloading(const Parameters& p, double noise, std::uint32_t seed, int points) {
  std::vector<SyntheticTest> plan = standard_programme(p, 30);
  plan.erase(plan.begin());  // the monotonic tension: the cyclic one replaces it
  for (SyntheticTest& t : unloading_programme(p, points)) plan.push_back(t);
  std::vector<TestCurve> curves;
  for (const SyntheticTest& t : plan) curves.push_back(synthetic_curve(p, t, noise, seed, "u" + std::to_string(seed))), ++seed;
  return curves;
}

}  // namespace

TEST_CASE("unloading branches of noise-free curves give the law's bn and bs", "[calibration]") {
  const Parameters p = truth();
  const std::vector<SyntheticTest> plan = unloading_programme(p, 60);
  REQUIRE(plan.size() == 2);
  const TestCurve tension = synthetic_curve(p, plan[0], 0, 1, "tension");
  const TestCurve shear = synthetic_curve(p, plan[1], 0, 2, "shear");
  REQUIRE(tension.kind == TestKind::cyclic_tension);
  REQUIRE(shear.sigma_n > 0);
  for (auto [curve, k, b] : {std::tuple{&tension, p.kn, p.bn}, std::tuple{&shear, p.ks, p.bs}}) {
    const std::vector<UnloadingBranch> branches = unloading_branches(*curve, k);
    CHECK(branches.size() == 3);
    for (const UnloadingBranch& br : branches) {
      INFO(curve->name << " from row " << br.first_row << ": " << br.why_not << " delta_in " << br.delta_in
                       << " delta_p " << br.delta_p);
      CHECK(br.points >= 3);
      // The secant reaches zero traction at delta_in/(1 + b) (docs/model.md 6).
      CHECK(br.ratio == Approx(b).epsilon(0.01));
    }
  }
}

// Four draws at 1 % noise with 120 points on each unloading curve. What the
// data give is limited by the plastic opening's smallness (delta_p =
// delta_in/(1 + bn)): over ten draws (calibration_study unloading) bn is
// within 5 % in 7, bs in 9, RMS errors 4.5 % and 3.1 %. Each draw here within
// 10 % and 3.5 of its standard errors, which include the direct values'.
TEST_CASE("calibration recovers bn and bs from curves with unloading branches", "[calibration][full-size]") {
  const Parameters p = truth();
  double sum2_bn = 0, sum2_bs = 0;
  for (std::uint32_t seed : {9000u, 9010u, 9020u, 9030u}) {
    const CalibrationRun r = calibrate_curves(curves_with_unloading(p, 0.01, seed, 120), CalibrationSettings{});
    std::string why;
    for (const std::string& s : r.one_set_verdict.reasons) why += s + "; ";
    for (const std::string& s : r.one_set.held) why += "held " + s + "; ";
    const Calibration& c = r.final;
    INFO("seed " << seed << ": " << (why.empty() ? "accepted" : why) << " bn = " << c["bn"].value << " +- "
                 << c["bn"].std_error << ", bs = " << c["bs"].value << " +- " << c["bs"].std_error
                 << ", GIIC = " << c["GIIC"].value << ", RMS " << r.one_set.rms);
    REQUIRE(r.one_set_verdict.accepted());
    for (auto [name, t] : {std::pair{"bn", p.bn}, std::pair{"bs", p.bs}}) {
      CHECK(c[name].stage == Stage::fit);
      CHECK(std::abs(c[name].value - t) < 0.10 * t);
      CHECK(std::abs(c[name].value - t) < 3.5 * c[name].std_error);
    }
    CHECK(std::abs(c["GIIC"].value - p.GIIC) < 0.05 * p.GIIC);
    CHECK(r.one_set.rms < 0.02);
    sum2_bn += std::pow(c["bn"].value / p.bn - 1, 2), sum2_bs += std::pow(c["bs"].value / p.bs - 1, 2);
  }
  INFO("RMS relative error over the draws: bn " << std::sqrt(sum2_bn / 4) << ", bs " << std::sqrt(sum2_bs / 4));
  CHECK(std::sqrt(sum2_bs / 4) < 0.05);
}

// Issue 39's claim: bn and bs within 5 % from curves with unloading
// branches. At 1 % noise (above) the plastic opening's smallness allows 10 %
// per draw; at 0.5 % noise with 120 points on each unloading curve every
// draw must give both within 5 %.
TEST_CASE("calibration recovers bn and bs within 5 % at 0.5 % noise", "[calibration][full-size]") {
  const Parameters p = truth();
  for (std::uint32_t seed : {9100u, 9110u, 9120u}) {
    const CalibrationRun r = calibrate_curves(curves_with_unloading(p, 0.005, seed, 120), CalibrationSettings{});
    const Calibration& c = r.final;
    INFO("seed " << seed << ": bn = " << c["bn"].value << " +- " << c["bn"].std_error << ", bs = " << c["bs"].value
                 << " +- " << c["bs"].std_error << ", RMS " << r.one_set.rms);
    REQUIRE(r.one_set_verdict.accepted());
    for (auto [name, t] : {std::pair{"bn", p.bn}, std::pair{"bs", p.bs}}) {
      CHECK(c[name].stage == Stage::fit);
      CHECK(std::abs(c[name].value - t) < 0.05 * t);
    }
  }
}

TEST_CASE("unloading under compression leaves bs undetermined and says why", "[calibration]") {
  const Parameters p = truth();
  SyntheticTest closed;
  closed.kind = TestKind::cyclic_shear;
  closed.sigma_n = -0.5;
  closed.uplift = false;
  closed.path = {0.05, 0.03, 0.1, 0.06, 0.15};
  closed.travel = 0.15;
  std::vector<TestCurve> curves;
  std::uint32_t seed = 800;
  for (const SyntheticTest& t : standard_programme(p, 30)) curves.push_back(synthetic_curve(p, t, 0.01, seed++, "s"));
  curves.push_back(synthetic_curve(p, closed, 0.01, seed, "closed"));
  const DirectResult d = apply_direct_rules(curves);
  bool said = false;
  for (const std::string& n : d.calibration.notes) said = said || n.find("bs: the shear curves' unloading branches are under compression") != std::string::npos;
  CHECK(said);
  CHECK(d.calibration["bs"].value == 3);  // Table 1's starting value: nothing replaced it
}

TEST_CASE("a cyclic shear curve may be at constant tension, a monotonic one not", "[calibration]") {
  const auto dir = mortar::harness::testing::fresh_directory("test_unloading_reader");
  const std::string rows = "slip_mm,tau_MPa\n0,0\n0.01,0.5\n0.005,0.2\n0.02,0.4\n";
  auto file = [&](const char* name, const std::string& text) {
    const std::string path = (dir / name).string();
    std::ofstream(path) << text;
    return path;
  };
  CHECK(read_test_curve(file("open.csv", "# kind: cyclic_shear\n# sigma_n: 0.05 MPa\n" + rows)).sigma_n == 0.05);
  CHECK_THROWS_WITH(read_test_curve(file("zero.csv", "# kind: cyclic_shear\n# sigma_n: 0 MPa\n" + rows)),
                    Catch::Contains("sigma_n = 0 MPa violates the rule: a cyclic shear test at constant compression"));
  CHECK_THROWS_WITH(read_test_curve(file("mono.csv", "# kind: shear\n# sigma_n: 0.05 MPa\n" + rows)),
                    Catch::Contains("a test at constant tension with unloading branches is kind cyclic_shear"));
  const TestCurve t = read_test_curve(file("cyc.csv", "# kind: cyclic_tension\nopening_mm,sigma_MPa\n0,0\n0.002,0.6\n"
                                                      "0.004,0.3\n0.003,0.2\n0.005,0.25\n0.006,0.1\n"));
  CHECK(t.cycles());
  CHECK_FALSE(t.shear());
}
