// The calibration's recovery study and the shipped synthetic example; a
// program, not a ctest test (it runs for minutes). Every curve it makes is
// synthetic: the law's own curve for a stated parameter set, resampled like a
// digitised figure, with stated noise (calibration/synthetic.hpp).
//
//   calibration_study example DIR   writes calibration_data/synthetic_example/'s curves
//   calibration_study recovery      the recovery table (true, fitted, standard error)
//   calibration_study per-sigma-n   van der Pluijm's per-sigma_n m and n: one set against per-level misfit
#include <cstdio>
#include <cstring>
#include <exception>
#include <random>
#include <string>

#include "calibration/direct_rules.hpp"
#include "calibration/fit.hpp"
#include "calibration/synthetic.hpp"
#include "calibration/uncertainty.hpp"
#include "paper_sets.hpp"
#include "random_parameters.hpp"

using namespace mortar;
using namespace mortar::harness;

namespace {

std::vector<TestCurve> curves_of(const std::vector<Parameters>& per_test, double noise, int points, std::uint32_t seed) {
  std::vector<TestCurve> out;
  const std::vector<SyntheticTest> plan = standard_programme(per_test[0], points);
  const char* names[] = {"tension", "shear_sn0.1", "shear_sn0.5", "shear_sn1.0"};
  for (size_t k = 0; k < plan.size(); ++k)
    out.push_back(synthetic_curve(per_test[k], plan[k], noise, seed + std::uint32_t(k), names[k]));
  return out;
}

void recovery(const char* title, const Parameters& truth, double noise, std::uint32_t seed) try {
  const std::vector<TestCurve> curves = curves_of({truth, truth, truth, truth}, noise, 30, seed);
  const DirectResult d = apply_direct_rules(curves);
  const FitResult fit = fit_softening(curves, d.calibration, FitOptions{});
  const Uncertainty u = uncertainty_from(fit.jacobian, fit.residuals);
  Calibration cal = d.calibration;
  apply_fit(cal, fit, u);
  fill_placeholders(true, cal);
  std::printf("\n### %s, noise %.0f %% (seed %u): RMS misfit %.4f, %ld simulations\n\n", title, 100 * noise, seed,
              fit.rms, fit.evaluations);
  std::printf("| parameter | true | fitted | error %% | standard error | stage |\n|---|---|---|---|---|---|\n");
  for (int i = 0; i < kParameterCount; ++i) {
    const CalibratedParameter& e = cal.entries[size_t(i)];
    const double t = parameter_at(truth, i);
    std::printf("| %s | %.5g | %.5g | %s | %s | %s |\n", kParameterInfo[size_t(i)].name, t, e.value,
                t != 0 ? std::to_string(std::lround(1000 * (e.value - t) / t) / 10.0).substr(0, 5).c_str() : "–",
                e.stage == Stage::not_determined ? "not determined" : std::to_string(e.std_error).c_str(),
                stage_name(e.stage));
  }
} catch (const std::exception& e) {
  std::printf("\n### %s, noise %.0f %% (seed %u): calibration failed: %s\n", title, 100 * noise, seed, e.what());
}

void per_sigma_n() {
  const std::vector<Parameters> sets = {testing::van_der_pluijm(-0.5), testing::van_der_pluijm(-0.1),
                                        testing::van_der_pluijm(-0.5), testing::van_der_pluijm(-1.0)};
  const std::vector<TestCurve> curves = curves_of(sets, 0.01, 30, 7);
  const DirectResult d = apply_direct_rules(curves);
  const FitResult one = fit_softening(curves, d.calibration, FitOptions{});
  Calibration cal = d.calibration;
  apply_fit(cal, one, uncertainty_from(one.jacobian, one.residuals));
  FitOptions per;
  per.per_sigma_n = true;
  const FitResult levels = fit_softening(curves, cal, per);
  std::printf("van der Pluijm with Table 1's m, n per sigma_n, 1 %% noise: RMS misfit one set %.4f, per sigma_n %.4f\n",
              one.rms, levels.rms);
  for (size_t k = 0; k < levels.unknowns.size(); ++k)
    std::printf("  %s = %.5g\n", levels.unknowns[k].label().c_str(), levels.value[long(k)]);
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IONBF, 0);
  if (argc == 3 && !std::strcmp(argv[1], "example")) {
    const Parameters p = testing::van_der_pluijm(-0.5);
    for (const TestCurve& c : curves_of({p, p, p, p}, 0.02, 30, 2024))
      write_test_curve(std::string(argv[2]) + "/" + c.name + ".csv", c,
                       {"SYNTHETIC, not experimental: made by calibration_study example from the law with",
                        "van der Pluijm's Table 1 set (m, n of sigma_n = -0.5 MPa), resampled at 30 points",
                        "equally spaced in arc length on the chart's scaled axes, plus Gaussian noise of 2 %",
                        "of the curve's largest value (seed 2024). See README.md here."});
    return 0;
  }
  if (argc == 2 && !std::strcmp(argv[1], "recovery")) {
    recovery("van der Pluijm (m, n of -0.5 MPa)", testing::van_der_pluijm(-0.5), 0.01, 11);
    recovery("Almeida M15", testing::almeida_m15(), 0.01, 12);
    std::mt19937 rng(5);
    const Parameters random = mj_test::random_parameters(rng);
    std::printf("\nrandom set (seed 5): ");
    for (int i = 0; i < kParameterCount; ++i) std::printf("%s %.5g ", kParameterInfo[size_t(i)].name, parameter_at(random, i));
    recovery("random valid set (seed 5)", random, 0.01, 13);
    recovery("Atkinson", testing::atkinson(), 0.01, 15);
    recovery("van der Pluijm (m, n of -0.5 MPa)", testing::van_der_pluijm(-0.5), 0.03, 14);
    return 0;
  }
  if (argc == 2 && !std::strcmp(argv[1], "per-sigma-n")) {
    per_sigma_n();
    return 0;
  }
  std::fprintf(stderr, "usage: calibration_study example DIR | recovery | per-sigma-n\n");
  return 2;
}
