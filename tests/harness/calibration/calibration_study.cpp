// The calibration's recovery study and the shipped synthetic example; a
// program, not a ctest test (it runs for minutes). Every curve it makes is
// synthetic: the law's own curve for a stated parameter set, resampled like a
// digitised figure, with stated noise (calibration/synthetic.hpp).
//
//   calibration_study example DIR   writes calibration_data/synthetic_example/'s curves
//   calibration_study recovery      the recovery table (true, fitted, standard error, stage;
//                                   misfit of one set and of m, n per sigma_n)
//   calibration_study direct        the direct rules' errors over 20 seeds, 1 % and 3 % noise
//   calibration_study coverage      the one set's standard errors against the spread of 20 noisy
//                                   draws, with and without each shear curve's peak sample
//   calibration_study compression DIR  the example's curves and a compression curve made with
//                                   a cap: calibration_data/synthetic_compression/
//   calibration_study unloading [DIR]  bn and bs from curves with unloading branches over 10
//                                   seeds; with DIR writes calibration_data/synthetic_unloading/
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <random>
#include <string>

#include "calibration/pipeline.hpp"
#include "calibration/synthetic.hpp"
#include "paper_sets.hpp"
#include "random_parameters.hpp"

using namespace mortar;
using namespace mortar::harness;

namespace {

// The standard programme's curves, each made with its own set (per_test[k]
// for the k-th test: tension, then sigma_n = -0.1, -0.5, -1.0 MPa).
std::vector<TestCurve> curves_of(const std::vector<Parameters>& per_test, double noise, int points, std::uint32_t seed) {
  std::vector<TestCurve> out;
  const std::vector<SyntheticTest> plan = standard_programme(per_test[0], points);
  const char* names[] = {"tension", "shear_sn0.1", "shear_sn0.5", "shear_sn1.0"};
  for (size_t k = 0; k < plan.size(); ++k)
    out.push_back(synthetic_curve(per_test[k], plan[k], noise, seed + std::uint32_t(k), names[k]));
  return out;
}

// van der Pluijm's set (m, n of -0.5 MPa) with bn = 6 and bs = 2, not Table
// 1's 10 and 3: the fit's placeholders are then not the answer.
Parameters unloading_truth() {
  Parameters p = testing::van_der_pluijm(-0.5);
  p.bn = 6, p.bs = 2;
  return p;
}

// The standard programme's shear curves and the unloading programme's
// tension and shear at constant tension (calibration/synthetic.hpp).
std::vector<TestCurve> unloading_curves(const Parameters& p, double noise, std::uint32_t seed, int points) {
  std::vector<SyntheticTest> plan = standard_programme(p, 30);
  plan.erase(plan.begin());
  for (const SyntheticTest& t : unloading_programme(p, points)) plan.push_back(t);
  const char* names[] = {"shear_sn0.1", "shear_sn0.5", "shear_sn1.0", "tension_cycles", "shear_open_cycles"};
  std::vector<TestCurve> out;
  for (size_t k = 0; k < plan.size(); ++k) out.push_back(synthetic_curve(p, plan[k], noise, seed + std::uint32_t(k), names[k]));
  return out;
}

std::string percent(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%+.1f %%", 100 * x);
  return buf;
}

// One row per parameter: true, fitted, error, standard error, stage; m and n
// per level below when the truth had them per level.
void recovery(const char* title, const std::vector<Parameters>& truth, double noise, std::uint32_t seed) try {
  CalibrationSettings s;
  s.per_sigma_n = true;
  const CalibrationRun r = calibrate_curves(curves_of(truth, noise, 30, seed), s);
  std::printf("\n### %s, noise %.0f %% (seed %u)\n\nRMS misfit: one set %.4f, m and n per sigma_n %.4f "
              "(%ld + %ld simulations of the data set)\n\n",
              title, 100 * noise, seed, r.one_set.rms, r.per_level.rms, r.one_set.evaluations, r.per_level.evaluations);
  std::printf("| parameter | true | fitted | error | standard error | stage |\n|---|---|---|---|---|---|\n");
  for (int i = 0; i < kParameterCount; ++i) {
    const CalibratedParameter& e = r.final.entries[size_t(i)];
    const double t = parameter_at(truth[2], i);
    std::printf("| %s | %.5g | %.5g | %s | %s | %s |\n", kParameterInfo[size_t(i)].name, t, e.value,
                t != 0 ? percent((e.value - t) / t).c_str() : "–",
                e.stage == Stage::not_determined ? "–" : (std::to_string(e.std_error).substr(0, 8) + " (" +
                                                          percent(e.std_error / e.value).substr(1) + ")").c_str(),
                stage_name(e.stage));
  }
  std::printf("\nm and n per sigma_n:\n\n| unknown | true | fitted | error | standard error |\n|---|---|---|---|---|\n");
  for (size_t k = 0; k < r.per_level.unknowns.size(); ++k) {
    const FitUnknown& u = r.per_level.unknowns[k];
    const size_t level = u.sigma_n == -0.1 ? 1 : u.sigma_n == -1.0 ? 3 : 2;
    const double t = parameter_at(truth[level], u.index), v = r.per_level.value[long(k)];
    std::printf("| %s | %.5g | %.5g | %s | %.3g |\n", u.label().c_str(), t, v, percent((v - t) / t).c_str(),
                r.per_level_uncertainty.std_error[long(k)]);
  }
  for (const std::string& n : r.final.notes) std::printf("- %s\n", n.c_str());
} catch (const std::exception& e) {
  std::printf("\n### %s, noise %.0f %% (seed %u): calibration failed: %s\n", title, 100 * noise, seed, e.what());
}

std::vector<Parameters> same(const Parameters& p) { return {p, p, p, p}; }

// The direct rules alone over 20 seeds: largest and RMS relative error of
// kn, ks, ft0 and GIC, and the largest |error|/standard error.
void direct_study() {
  std::mt19937 rng(5);
  std::vector<std::pair<std::string, Parameters>> sets = {
      {"van der Pluijm", testing::van_der_pluijm(-0.5)}, {"Atkinson", testing::atkinson()}, {"Almeida M15", testing::almeida_m15()}};
  for (int i = 0; i < 4; ++i) sets.push_back({"random " + std::to_string(i), mj_test::random_parameters(rng)});
  const char* names[] = {"kn", "ks", "ft0", "GIC"};
  std::printf("| set | ft0^2/(GIC kn) | noise | kn | ks | ft0 | GIC |\n|---|---|---|---|---|---|---|\n");
  for (auto& [name, p] : sets)
    for (double noise : {0.01, 0.03}) {
      double worst[4] = {}, sum2[4] = {}, z[4] = {};
      int n = 0;
      std::string failure;
      for (std::uint32_t seed = 1; seed <= 20; ++seed) try {
          const DirectResult d = apply_direct_rules(curves_of(same(p), noise, 30, 1000 * seed));
          for (int k = 0; k < 4; ++k) {
            const double t = parameter_at(p, parameter_index(names[k])), v = d.calibration[names[k]].value;
            worst[k] = std::max(worst[k], std::abs(v - t) / t), sum2[k] += std::pow((v - t) / t, 2);
            z[k] = std::max(z[k], std::abs(v - t) / d.calibration[names[k]].std_error);
          }
          ++n;
        } catch (const std::exception& e) {
          failure = e.what();
        }
      std::printf("| %s | %.3g | %.0f %% |", name.c_str(), p.ft0 * p.ft0 / (p.GIC * p.kn), 100 * noise);
      for (int k = 0; k < 4; ++k)
        std::printf(" %.2f / %.2f %% (%.1f) |", 100 * worst[k], 100 * std::sqrt(sum2[k] / n), z[k]);
      std::printf(n < 20 ? " %d failed: %s\n" : "\n", 20 - n, failure.c_str());
    }
  std::printf("\nper cell: largest / RMS relative error over 20 seeds (largest |error| / standard error); "
              "a GIC the data cannot determine has no standard error (nan)\n");
}

// Are the reported standard errors honest? Over 20 draws of 2 % noise: the
// spread of each estimate against the mean reported standard error, and how
// often the truth lies within 2 standard errors (95 % if they are honest).
void coverage_study() {
  const Parameters truth = testing::van_der_pluijm(-0.5);
  for (bool drop_peaks : {false, true}) {
    constexpr int kDraws = 20;
    std::vector<std::vector<double>> value(kParameterCount), error(kParameterCount);
    int failed = 0, stalled = 0;
    double rms_lo = INFINITY, rms_hi = 0, stalled_lo = INFINITY;
    for (std::uint32_t draw = 1; draw <= kDraws; ++draw) try {
        std::vector<TestCurve> curves = curves_of(same(truth), 0.02, 30, 5000 + 10 * draw);
        if (drop_peaks) curves = without_shear_peaks(curves);
        const CalibrationRun r = calibrate_curves(curves, CalibrationSettings{});
        rms_lo = std::min(rms_lo, r.one_set.rms), rms_hi = std::max(rms_hi, r.one_set.rms);
        if (r.one_set.rms > 0.05) ++stalled, stalled_lo = std::min(stalled_lo, r.one_set.rms);
        for (int i = 0; i < kParameterCount; ++i) {
          const CalibratedParameter& e = r.final.entries[size_t(i)];
          if (e.stage == Stage::not_determined || !std::isfinite(e.std_error)) continue;
          value[size_t(i)].push_back(e.value), error[size_t(i)].push_back(e.std_error);
        }
      } catch (const std::exception& e) {
        ++failed;
        std::printf("draw %u failed: %s\n", draw, e.what());
      }
    std::printf("\n### van der Pluijm (m, n of -0.5 MPa), 2 %% noise, %d draws, %s\n\n"
                "RMS misfit of the one set %.4f-%.4f; %d draw(s) above 0.05 (the lowest of them %.4f)\n\n"
                "| parameter | true | mean error | spread of the estimates | mean standard error | spread / "
                "standard error | truth within 2 standard errors |\n|---|---|---|---|---|---|---|\n",
                kDraws - failed, drop_peaks ? "each shear curve's peak sample removed" : "every sample", rms_lo, rms_hi,
                stalled, stalled ? stalled_lo : NAN);
    for (int i = 0; i < kParameterCount; ++i) {
      const std::vector<double>& v = value[size_t(i)];
      if (v.size() < 2) continue;
      const double t = parameter_at(truth, i);
      double mean = 0, se = 0, within = 0;
      for (size_t k = 0; k < v.size(); ++k) {
        mean += v[k] / double(v.size()), se += error[size_t(i)][k] / double(v.size());
        within += std::abs(v[k] - t) <= 2 * error[size_t(i)][k];
      }
      double var = 0;
      for (double x : v) var += (x - mean) * (x - mean) / double(v.size() - 1);
      std::printf("| %s | %.5g | %s | %.3g | %.3g | %.2f | %d of %zu |\n", kParameterInfo[size_t(i)].name, t,
                  percent((mean - t) / t).c_str(), std::sqrt(var), se, std::sqrt(var) / se, int(within), v.size());
    }
  }
}

// Each curve as DIR/<name>.csv with the comment lines first.
void write_curves(const std::string& dir, const std::vector<TestCurve>& curves, const std::vector<std::string>& comments) {
  for (const TestCurve& c : curves) write_test_curve(dir + "/" + c.name + ".csv", c, comments);
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IONBF, 0);
  if (argc == 3 && !std::strcmp(argv[1], "example")) {
    const Parameters p = testing::van_der_pluijm(-0.5);
    write_curves(argv[2], curves_of(same(p), 0.02, 30, 2024),
                 {"SYNTHETIC, not experimental: made by calibration_study example from the law with",
                  "van der Pluijm's Table 1 set (m, n of sigma_n = -0.5 MPa), resampled at 30 points",
                  "equally spaced in arc length on the chart's scaled axes, plus Gaussian noise of 2 %",
                  "of the curve's largest value (seed 2024). See README.md here."});
    return 0;
  }
  if (argc == 3 && !std::strcmp(argv[1], "compression")) {
    const Parameters p = testing::van_der_pluijm(-0.5);
    const CompressionCap cap{10, 9, 2, 0.05};
    std::vector<TestCurve> curves = curves_of(same(p), 0.02, 30, 2024);
    SyntheticTest crush;
    crush.kind = TestKind::compression;
    crush.travel = cap.fc / p.kn + cap.kappa_p + 4 * 588 * cap.Gfc / (481 * cap.fc);
    crush.points = 40;
    crush.uplift = false;
    curves.push_back(synthetic_curve(p, crush, 0.02, 2026, "compression", cap));
    write_curves(argv[2], curves,
                 {"SYNTHETIC, not experimental: made by calibration_study compression from the law with",
                  "van der Pluijm's Table 1 set (m, n of sigma_n = -0.5 MPa) and the cap fc = 10 MPa,",
                  "Cs = 9, Gfc = 2 N/mm, kappa_p = 0.05 mm, resampled in arc length on the chart's scaled",
                  "axes, plus Gaussian noise of 2 % of the curve's largest value (seeds 2024, 2026)."});
    return 0;
  }
  if (argc == 2 && !std::strcmp(argv[1], "recovery")) {
    using testing::van_der_pluijm;
    recovery("van der Pluijm, m and n of Table 1 per sigma_n",
             {van_der_pluijm(-0.5), van_der_pluijm(-0.1), van_der_pluijm(-0.5), van_der_pluijm(-1.0)}, 0.01, 7);
    recovery("van der Pluijm (m, n of -0.5 MPa)", same(van_der_pluijm(-0.5)), 0.01, 11);
    recovery("Almeida M15", same(testing::almeida_m15()), 0.01, 12);
    recovery("Atkinson", same(testing::atkinson()), 0.01, 15);
    std::mt19937 rng(5);
    const Parameters snap = mj_test::random_parameters(rng);
    recovery("random valid set (seed 5, draw 1: its tension softening snaps back)", same(snap), 0.01, 13);
    mj_test::random_parameters(rng), mj_test::random_parameters(rng);
    recovery("random valid set (seed 5, draw 4)", same(mj_test::random_parameters(rng)), 0.01, 16);
    recovery("van der Pluijm (m, n of -0.5 MPa)", same(van_der_pluijm(-0.5)), 0.03, 14);
    return 0;
  }
  if (argc == 2 && !std::strcmp(argv[1], "direct")) {
    direct_study();
    return 0;
  }
  if (argc == 2 && !std::strcmp(argv[1], "coverage")) {
    coverage_study();
    return 0;
  }
  if ((argc == 2 || argc == 3) && !std::strcmp(argv[1], "unloading")) {
    const Parameters p = unloading_truth();
    if (argc == 3) {
      write_curves(argv[2], unloading_curves(p, 0.02, 2025, 60),
                   {"SYNTHETIC, not experimental: made by calibration_study unloading from the law with",
                    "van der Pluijm's Table 1 set (m, n of sigma_n = -0.5 MPa) but bn = 6, bs = 2, resampled",
                    "in arc length on the chart's scaled axes with the reversals among the points, plus",
                    "Gaussian noise of 2 % of the curve's largest value (seed 2025). See README.md here."});
      return 0;
    }
    std::printf("| seed | noise | points | bn (6) | bs (2) | GIIC (0.058) | RMS | verdict |\n"
                "|---|---|---|---|---|---|---|---|\n");
    for (auto [noise, points] : {std::pair{0.01, 60}, std::pair{0.01, 120}, std::pair{0.02, 120}}) {
      double e2[2] = {0, 0};
      int within[2] = {0, 0};
      for (std::uint32_t seed = 9000; seed < 9100; seed += 10) {
        const CalibrationRun r = calibrate_curves(unloading_curves(p, noise, seed, points), CalibrationSettings{});
        auto cell = [&](const char* name, double truth, int k) {
          const CalibratedParameter& e = r.final[name];
          if (k >= 0) e2[k] += std::pow(e.value / truth - 1, 2), within[k] += std::abs(e.value / truth - 1) <= 0.05;
          char buf[96];
          std::snprintf(buf, sizeof buf, "%.4g ± %.2g (%s, %s)", e.value, e.std_error, percent(e.value / truth - 1).c_str(),
                        stage_name(e.stage));
          return std::string(buf);
        };
        const std::string bn = cell("bn", p.bn, 0), bs = cell("bs", p.bs, 1);
        std::printf("| %u | %.0f %% | %d | %s | %s | %s | %.4f | %s |\n", seed, 100 * noise, points, bn.c_str(), bs.c_str(),
                    cell("GIIC", p.GIIC, -1).c_str(), r.one_set.rms, r.one_set_verdict.accepted() ? "accepted" : "rejected");
      }
      std::printf("| RMS error | %.0f %% | %d | %.1f %% (%d of 10 within 5 %%) | %.1f %% (%d of 10 within 5 %%) | | | |\n",
                  100 * noise, points, 100 * std::sqrt(e2[0] / 10), within[0], 100 * std::sqrt(e2[1] / 10), within[1]);
    }
    return 0;
  }
  std::fprintf(stderr, "usage: calibration_study example DIR | compression DIR | recovery | direct | coverage | unloading [DIR]\n");
  return 2;
}
