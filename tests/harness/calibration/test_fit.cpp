// The whole calibration on synthetic curves of van der Pluijm's set with 1 %
// noise, against the true parameters that made them: the strengths within
// 2 %, GIIC within 5 %, m, n and psi0 within three of their own standard
// errors (the fit's claim about itself), and bn, bs named as not determined
// (under compression only GIIC/(1 + bs) and m(1 + bs) act, Eqs. 8-9, 17; pure
// tension never sees bn).
#include <catch2/catch.hpp>

#include "calibration/direct_rules.hpp"
#include "calibration/fit.hpp"
#include "calibration/synthetic.hpp"
#include "calibration/uncertainty.hpp"
#include "paper_sets.hpp"
#include "test_scale.hpp"

using namespace mortar;
using namespace mortar::harness;

namespace {

// The whole calibration of the standard programme's curves of `truth` (30
// points each, 1 % noise, seeds from `seed`): direct rules, then the fit.
Calibration calibrate_synthetic(const Parameters& truth, std::uint32_t seed, FitResult& fit) {
  std::vector<TestCurve> curves;
  for (const SyntheticTest& t : standard_programme(truth, 30))
    curves.push_back(synthetic_curve(truth, t, 0.01, seed, "c" + std::to_string(seed))), ++seed;
  const DirectResult direct = apply_direct_rules(curves);
  fit = fit_softening(curves, direct.calibration, FitOptions{});
  Calibration c = direct.calibration;
  apply_fit(c, fit, uncertainty_from(fit.jacobian, fit.residuals));
  return c;
}

}  // namespace

TEST_CASE("calibration recovers the parameters that made the curves", "[calibration]") {
  const Parameters truth = testing::van_der_pluijm(-0.5);
  FitResult fit;
  const Calibration c = calibrate_synthetic(truth, 100, fit);
  auto error = [&](const char* name) {
    return std::abs(c[name].value - parameter_at(truth, parameter_index(name)));
  };
  for (const char* name : {"kn", "ks", "ft0", "GIC", "c0", "phi0", "phir"}) {
    INFO(name << " = " << c[name].value);
    CHECK(error(name) < 0.02 * parameter_at(truth, parameter_index(name)));
  }
  CHECK(error("GIIC") < 0.05 * truth.GIIC);
  for (const char* name : {"m", "n", "psi0"}) {
    INFO(name << " = " << c[name].value << " +- " << c[name].std_error);
    CHECK(c[name].stage == Stage::fit);
    CHECK(error(name) < 3 * c[name].std_error);
  }
  CHECK(c["bn"].stage == Stage::not_determined);
  CHECK(c["bs"].stage == Stage::not_determined);
  CHECK(fit.rms < 0.02);  // the noise is 1 % of each curve's scale
}

// Almeida M15's curves stop before the cohesion is gone, so the starting
// GIIC (the work beyond the residual) is 3.4 times too small; from there the
// softening alone slid to GIIC at its lower bound (RMS misfit 0.13, c0 15 %
// off). The fit's second start (fit.cpp, softening_alone) must find the
// true basin: GIIC within 5 % and a misfit at the noise level.
TEST_CASE("calibration of Almeida M15's curves does not stop where GIIC vanishes", "[calibration]") {
  // About 600 simulated tests: minutes under the sanitizers, where the test
  // above runs the same code (test_scale.hpp).
  if (mj_test::property_scale() < 1) {
    WARN("scaled run (MJ_PROPERTY_SCALE): the M15 calibration is left to the unscaled suite");
    return;
  }
  const Parameters truth = testing::almeida_m15();
  FitResult fit;
  const Calibration c = calibrate_synthetic(truth, 12, fit);
  INFO("GIIC = " << c["GIIC"].value << ", c0 = " << c["c0"].value << ", RMS misfit " << fit.rms);
  CHECK(std::abs(c["GIIC"].value - truth.GIIC) < 0.05 * truth.GIIC);
  CHECK(std::abs(c["c0"].value - truth.c0) < 0.02 * truth.c0);
  CHECK(fit.rms < 0.02);
}
