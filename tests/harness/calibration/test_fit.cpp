// The whole calibration on synthetic curves of van der Pluijm's set with 1 %
// noise, against the true parameters that made them: the strengths within
// 2 %, GIIC within 5 %, m, n and psi0 within three of their own standard
// errors (the fit's claim about itself), and bn, bs named as not determined
// (under compression only GIIC/(1 + bs) and m(1 + bs) act, Eqs. 8-9, 17; pure
// tension never sees bn).
#include <catch2/catch.hpp>

#include "calibration/pipeline.hpp"
#include "calibration/synthetic.hpp"
#include "paper_sets.hpp"

using namespace mortar;
using namespace mortar::harness;

namespace {

// The standard programme's curves (30 points each, 1 % noise unless said,
// seeds from `seed`), the k-th test made with per_test[k] (tension, then
// sigma_n = -0.1, -0.5, -1.0 MPa).
std::vector<TestCurve> curves_of(const std::vector<Parameters>& per_test, std::uint32_t seed, double noise = 0.01) {
  std::vector<TestCurve> curves;
  const std::vector<SyntheticTest> plan = standard_programme(per_test[0], 30);
  for (size_t k = 0; k < plan.size(); ++k)
    curves.push_back(synthetic_curve(per_test[k], plan[k], noise, seed, "c" + std::to_string(seed))), ++seed;
  return curves;
}

// The whole calibration of curves made with `truth`: direct rules, then the fit.
Calibration calibrate_synthetic(const Parameters& truth, std::uint32_t seed, FitResult& fit) {
  const CalibrationRun r = calibrate_curves(curves_of({truth, truth, truth, truth}, seed), CalibrationSettings{});
  fit = r.one_set;
  return r.final;
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
// About 600 simulated tests: minutes under the sanitizers, which leave the
// [full-size] tests out (tests/harness/CMakeLists.txt); the test above runs
// the same code there.
TEST_CASE("calibration of Almeida M15's curves does not stop where GIIC vanishes", "[calibration][full-size]") {
  const Parameters truth = testing::almeida_m15();
  FitResult fit;
  const Calibration c = calibrate_synthetic(truth, 12, fit);
  INFO("GIIC = " << c["GIIC"].value << ", c0 = " << c["c0"].value << ", RMS misfit " << fit.rms);
  CHECK(std::abs(c["GIIC"].value - truth.GIIC) < 0.05 * truth.GIIC);
  CHECK(std::abs(c["c0"].value - truth.c0) < 0.02 * truth.c0);
  CHECK(fit.rms < 0.02);
}

// Table 1 gives van der Pluijm's m and n per normal stress (10 547 to 398 for
// m). Curves made so cannot be matched by one set (its misfit stays about 0.2
// of each curve's scale, m and n on their bounds, psi0 near 0); m and n per
// sigma_n must reach the noise. Started from the one set's optimum, where n
// has no effect and was held, the per-level fit stayed at the one set's 0.23
// (pipeline.cpp starts it from the rules).
// About 800 simulated tests: [full-size], as the test above.
TEST_CASE("m and n per normal stress fit curves made with Table 1's per-level m and n",
          "[calibration][full-size]") {
  using testing::van_der_pluijm;
  const std::vector<Parameters> truth = {van_der_pluijm(-0.5), van_der_pluijm(-0.1), van_der_pluijm(-0.5),
                                         van_der_pluijm(-1.0)};
  CalibrationSettings settings;
  settings.per_sigma_n = true;
  const CalibrationRun r = calibrate_curves(curves_of(truth, 7), settings);
  INFO("RMS misfit: one set " << r.one_set.rms << ", per sigma_n " << r.per_level.rms);
  REQUIRE(r.per_level_fitted);
  CHECK(r.per_level.rms < 0.02);  // the noise is 1 % of each curve's scale
  CHECK(r.one_set.rms > 5 * r.per_level.rms);
  const Parameters& mid = truth[2];
  for (size_t k = 0; k < r.per_level.unknowns.size(); ++k) {
    const FitUnknown& u = r.per_level.unknowns[k];
    const double value = r.per_level.value[long(k)], se = r.per_level_uncertainty.std_error[long(k)];
    const Parameters& at = std::isnan(u.sigma_n) ? mid : u.sigma_n == -0.1 ? truth[1] : u.sigma_n == -1.0 ? truth[3] : mid;
    const double t = parameter_at(at, u.index);
    INFO(u.label() << " = " << value << " +- " << se << ", true " << t);
    CHECK(std::abs(value - t) < 3 * se);
  }
  size_t per_level_m = 0;
  for (const FitUnknown& u : r.per_level.unknowns) per_level_m += u.label().rfind("m @", 0) == 0;
  CHECK(per_level_m == 3);
  // The one set cannot describe these curves (misfit about 0.2): it is
  // rejected (calibration/acceptance.hpp), the sets per sigma_n accepted.
  CHECK(!r.one_set_verdict.accepted());
  CHECK(r.per_level_verdict.accepted());
}

// Issue 39: curves made with psir = 2 deg, which the fit used to hold at 0:
// GIIC came out 26 times too large with bs on its bound (only GIIC/(1 + bs)
// was right), handed over as a ready set. psir is fitted where the uplift
// shows it, and what the data do not determine at the solution is held.
TEST_CASE("calibration recovers a set with residual dilatancy (psir > 0)", "[calibration]") {
  Parameters truth = testing::van_der_pluijm(-0.5);
  truth.psir = 2;
  const CalibrationRun r = calibrate_curves(curves_of({truth, truth, truth, truth}, 300), CalibrationSettings{});
  std::string why;
  for (const std::string& s : r.one_set_verdict.reasons) why += s + "; ";
  const Calibration& c = r.final;
  INFO("verdict: " << (why.empty() ? "accepted" : why) << " psir = " << c["psir"].value << " +- " << c["psir"].std_error
                   << ", GIIC = " << c["GIIC"].value << ", bs = " << c["bs"].value << ", RMS " << r.one_set.rms);
  REQUIRE(r.one_set_verdict.accepted());
  CHECK(c["psir"].stage == Stage::fit);
  CHECK(std::abs(c["psir"].value - truth.psir) < 3 * c["psir"].std_error);
  CHECK(std::abs(c["GIIC"].value - truth.GIIC) < 0.05 * truth.GIIC);
  CHECK(c["bs"].stage == Stage::not_determined);
  CHECK(r.one_set.rms < 0.02);
}

// Issue 39: curves whose peaks are not sampled (each shear curve's largest
// tau removed). The hyperbola through the remaining peaks reads phi0 low, and
// the fit from the rules' start alone stalled at an RMS misfit of 0.19 (GIIC
// a quarter of the truth, m 43 times it, neither with a standard error: 5 of
// these 9 checks failed). From the raised starts (pipeline.cpp) the fit must
// reach the noise (2 %), be accepted, and give every fitted strength and wear
// parameter within three of its standard errors. The curves are the coverage
// study's first draw (calibration_study coverage).
TEST_CASE("calibration without the peak samples reaches the noise", "[calibration][full-size]") {
  const Parameters truth = testing::van_der_pluijm(-0.5);
  const CalibrationRun r =
      calibrate_curves(without_shear_peaks(curves_of({truth, truth, truth, truth}, 5010, 0.02)), CalibrationSettings{});
  INFO("RMS misfit " << r.one_set.rms << ", start phi0 " << r.start["phi0"].value);
  CHECK(r.one_set.rms < 0.03);
  CHECK(r.one_set_verdict.accepted());
  for (const char* name : {"c0", "phi0", "phir", "GIIC", "m", "n", "psi0"}) {
    const CalibratedParameter& e = r.final[name];
    const double t = parameter_at(truth, parameter_index(name));
    INFO(name << " = " << e.value << " +- " << e.std_error << ", true " << t);
    CHECK(std::abs(e.value - t) < 3 * e.std_error);
  }
}
