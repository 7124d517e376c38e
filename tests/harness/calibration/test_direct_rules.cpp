// The direct rules against the parameters that made the curves: noise-free
// synthetic curves of van der Pluijm's set (the digitised peak lies within
// 0.4 % of the true one, so the strengths are held to 1 %); 1 % and 3 % noise
// over several seeds on Table 1's sets and random valid ones; tension curves
// that snap back.
#include <catch2/catch.hpp>

#include <random>

#include "calibration/direct_rules.hpp"
#include "calibration/synthetic.hpp"
#include "input/input_error.hpp"
#include "paper_sets.hpp"
#include "random_parameters.hpp"
#include "test_scale.hpp"

using namespace mortar;
using namespace mortar::harness;

namespace {
std::vector<TestCurve> curves_of(const Parameters& p, double noise, std::uint32_t seed = 40) {
  std::vector<TestCurve> out;
  for (const SyntheticTest& t : standard_programme(p, 30)) out.push_back(synthetic_curve(p, t, noise, seed++, "c"));
  return out;
}
double relative(const Calibration& c, const Parameters& p, const char* name) {
  const double truth = parameter_at(p, parameter_index(name));
  return std::abs(c[name].value - truth) / truth;
}
// ft0^2/(GIC kn): above 1 the tension softening snaps back (docs/model.md 6).
double snap_ratio(const Parameters& p) { return p.ft0 * p.ft0 / (p.GIC * p.kn); }
}  // namespace

TEST_CASE("direct rules recover van der Pluijm's stiffnesses, strengths and GIC", "[calibration]") {
  const Parameters p = testing::van_der_pluijm(-0.5);
  const Calibration c = apply_direct_rules(curves_of(p, 0.0)).calibration;
  for (const char* name : {"kn", "ks", "ft0", "GIC"}) {
    INFO(name);
    CHECK(relative(c, p, name) < 1e-3);
    CHECK(c[name].stage == Stage::direct);
  }
  for (const char* name : {"c0", "phi0", "phir"}) {
    INFO(name);
    CHECK(relative(c, p, name) < 0.01);
  }
  // With the uplift measured psir is the fit's (from 0, its placeholder).
  CHECK(c["psir"].stage == Stage::fit);
  CHECK(c["psir"].value == 0);
}

// kn, ks, ft0 and GIC over seeds, on Table 1's three series and two random
// valid sets whose tension softening does not snap back. At 1 % noise each
// within 2 %. At 3 % noise 2 % for every draw is beyond what 30 points per
// curve hold: kn's standard error from one tension curve is about 1.6 % there,
// the least squares' own bound (`calibration_study direct`, 20 seeds: RMS
// errors 1.6 % kn, 1.0 % ks, 1.5-2.0 % ft0, 1.5 % GIC). So at 3 % each value
// must lie within 3 of its own standard errors, those be below 3 %, the
// errors be the size the standard errors say (RMS of error / standard error
// below 1.5 over the seeds and sets), and ks, ft0 and GIC within 2 % in RMS
// (kn: 2.1 % over the 30 draws here). The former rules (the weighted log of
// the softening, the largest sample) gave GIC 3.5 % RMS and up to 8.6 % off
// at 3 %, and failed on seeds where the peaks' scatter made the hyperbola's
// curvature negative.
TEST_CASE("direct rules hold kn, ks, ft0 and GIC at 1 % and 3 % noise", "[calibration]") {
  std::vector<Parameters> sets = {testing::van_der_pluijm(-0.5), testing::atkinson(), testing::almeida_m15()};
  std::mt19937 rng(5);
  while (sets.size() < 5) {
    const Parameters p = mj_test::random_parameters(rng);
    if (snap_ratio(p) < 1) sets.push_back(p);
  }
  const int seeds = mj_test::scaled(6);
  const char* names[] = {"kn", "ks", "ft0", "GIC"};
  double squares[4] = {}, z_squares[4] = {};  // of the relative errors and the errors / standard errors at 3 %
  int draws = 0;
  for (size_t k = 0; k < sets.size(); ++k)
    for (double noise : {0.01, 0.03})
      for (int s = 1; s <= seeds; ++s) {
        INFO("set " << k << ", noise " << noise << ", seed " << 1000 * s);
        const Calibration c = apply_direct_rules(curves_of(sets[k], noise, std::uint32_t(1000 * s))).calibration;
        draws += noise > 0.02;
        for (int i = 0; i < 4; ++i) {
          const char* name = names[i];
          const double truth = parameter_at(sets[k], parameter_index(name));
          INFO(name << " = " << c[name].value << " +- " << c[name].std_error << ", true " << truth);
          if (noise < 0.02) {
            CHECK(relative(c, sets[k], name) < 0.02);
          } else {
            CHECK(c[name].std_error < 0.03 * truth);
            CHECK(std::abs(c[name].value - truth) < 3 * c[name].std_error);
            squares[i] += std::pow(relative(c, sets[k], name), 2);
            z_squares[i] += std::pow((c[name].value - truth) / c[name].std_error, 2);
          }
        }
      }
  for (int i = 0; i < 4; ++i) {
    INFO(names[i] << ": RMS relative error at 3 % noise over " << draws << " curve sets");
    if (i > 0) CHECK(std::sqrt(squares[i] / draws) < 0.02);  // kn: its bound is 1.6 %, above
    CHECK(std::sqrt(z_squares[i] / draws) < 1.5);  // the standard errors are the errors' size
  }
}

// Snap-back (docs/model.md 6): between ft0^2/(GIC kn) = 1 and 2 the tension
// curve drops at the peak to a stable point and then decays on the surface,
// whose rate gives GIC; from 2 on, the elastic energy at the peak covers GIC
// and the curve drops to zero: GIC is not determined, set to that bound and
// said so.
TEST_CASE("direct rules on tension curves that snap back", "[calibration]") {
  Parameters p = testing::van_der_pluijm(-0.5);
  p.GIC = p.ft0 * p.ft0 / (1.5 * p.kn);
  Calibration c = apply_direct_rules(curves_of(p, 0.01)).calibration;
  for (const char* name : {"kn", "ft0"}) {
    INFO(name << " = " << c[name].value);
    CHECK(relative(c, p, name) < 0.02);
  }
  INFO("GIC = " << c["GIC"].value << " +- " << c["GIC"].std_error);
  CHECK(c["GIC"].stage == Stage::direct);
  CHECK(std::abs(c["GIC"].value - p.GIC) < 3 * c["GIC"].std_error);
  REQUIRE(!c.notes.empty());
  CHECK_THAT(c.notes[0], Catch::Contains("snaps back") && Catch::Contains("points after the drop"));

  p.GIC = p.ft0 * p.ft0 / (3 * p.kn);
  c = apply_direct_rules(curves_of(p, 0.01)).calibration;
  CHECK(relative(c, p, "kn") < 0.02);
  CHECK(relative(c, p, "ft0") < 0.02);
  CHECK(c["GIC"].stage == Stage::not_determined);
  CHECK(c["GIC"].value == Approx(c["ft0"].value * c["ft0"].value / (2 * c["kn"].value)));
  REQUIRE(!c.notes.empty());
  CHECK_THAT(c.notes[0], Catch::Contains("GIC is not determined: the tension softening snaps back") &&
                             Catch::Contains("point(s) after the peak above 3 times the noise"));
}

TEST_CASE("direct rules need enough normal stresses", "[calibration]") {
  const Parameters p = testing::van_der_pluijm(-0.5);
  std::vector<TestCurve> curves = curves_of(p, 0.0);
  curves.resize(2);  // tension and one shear curve
  CHECK_THROWS_WITH(apply_direct_rules(curves), Catch::Contains("shear curves at 1 compressive normal stress(es)"));
}
