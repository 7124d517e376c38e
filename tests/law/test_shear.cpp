// docs/model.md 10, invariants 5 and 6: shear at constant normal compression
// (peak, residual, dilatancy) and isotropy in the joint plane, in every scheme.
#include <catch2/catch.hpp>

#include <algorithm>

#include "mortar/physics/elasticity.hpp"
#include "mortar/physics/yield_surface.hpp"
#include "paper_sets.hpp"
#include "paths.hpp"
#include "schemes.hpp"
#include "formatted.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {
// Closed form of docs/model.md 4 (Eq. 3's alpha and beta): peak shear strength at sigma_n < 0, before softening.
double peak_formula(const Parameters& p, double sigma_n) {
  const double t = std::tan(p.phi0 * M_PI / 180);
  const double beta = 0.5 * (p.c0 * p.c0 / (p.ft0 * t) + p.ft0 * t);
  const double alpha = 0.5 * (p.c0 * p.c0 / (p.ft0 * t) - p.ft0 * t);
  return std::sqrt(std::pow(beta - sigma_n * t, 2) - alpha * alpha);
}
double max_abs_shear(const Curve& c) {
  double m = 0;
  for (const Sample& s : c.samples) m = std::max(m, shear_norm(s.traction));
  return m;
}
}  // namespace

TEST_CASE("Invariant 5: shear peak at constant compression matches docs/model.md 4", "[invariant5]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  const double sigma_n = GENERATE(-0.1, -0.5, -1.0);
  const Parameters p = van_der_pluijm(sigma_n);
  const Model M = model_with(p, S.scheme);
  CAPTURE(S.name, sigma_n);
  // Slip to just past the elastic limit in 2e-7 mm increments resolves the peak.
  const double limit = peak_formula(p, sigma_n) / p.ks;
  const Curve c = shear_at_constant_normal(M, sigma_n, 1.02 * limit, 5000);
  REQUIRE(c.all_ok);
  CHECK(max_abs_shear(c) == Approx(peak_formula(p, sigma_n)).epsilon(1e-3));
}

TEST_CASE("Invariant 5: shear softens to the residual friction tan(phir) |sigma_n|", "[invariant5]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  const double sigma_n = GENERATE(-0.1, -0.5, -1.0);
  const Parameters p = van_der_pluijm(sigma_n);
  const Model M = model_with(p, S.scheme);
  const Curve c = shear_at_constant_normal(M, sigma_n, 2.0, 4000);
  REQUIRE(c.all_ok);
  const double residual = std::tan(p.phir * M_PI / 180) * std::abs(sigma_n);
  CAPTURE(S.name, sigma_n, c.samples.back().state.wIII);
  CHECK(shear_norm(c.samples.back().traction) == Approx(residual).epsilon(S.residual_friction));
  // Softened: practically no cohesion left (s decays asymptotically).
  CHECK(surface_of(M, c.samples.back().state).s < 1e-6);
}

TEST_CASE("Invariant 5: plastic dilatancy ratio is tan(psi) R/|tau| of the regularised G", "[invariant5]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  CAPTURE(S.name);
  const Parameters p = van_der_pluijm(-0.5);
  const Model M = model_with(p, S.scheme, 1e-8);
  const Curve c = shear_at_constant_normal(M, -0.5, 0.1, 20000);
  REQUIRE(c.all_ok);
  // Expected ratio at the middle of the increment (first-order accurate in
  // the increment); the worst relative deviation over the plastic increments.
  auto ratio_at = [&](const State& s) {
    const Surface surface = surface_of(M, s);
    const double tau = shear_norm(traction_of(M, s));
    return surface.tan_psi * std::hypot(surface.alpha, tau) / tau;
  };
  int checked = 0;
  double worst = 0;
  for (size_t i = 2; i < c.samples.size(); ++i) {
    const State& a = c.samples[i - 1].state;
    const State& b = c.samples[i].state;
    const double dps = std::hypot(b.plastic[1] - a.plastic[1], b.plastic[2] - a.plastic[2]);
    if (dps < 1e-7) continue;  // elastic increments
    const double expected = 0.5 * (ratio_at(a) + ratio_at(b));
    worst = std::max(worst, std::abs((b.plastic[0] - a.plastic[0]) / dps - expected) / std::abs(expected));
    ++checked;
  }
  INFO(mj_test::formatted("[invariant 5] %s: dilatancy ratio, worst rel. deviation %.2e over %d plastic increments",
                          S.name, worst, checked));
  CHECK(checked > 10000);
  CHECK(worst <= S.dilatancy_ratio);
}

TEST_CASE("Invariant 6: shearing in any direction of the joint plane gives the same |tau| history", "[invariant6]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  const Parameters p = van_der_pluijm(-0.5);
  const Model M = model_with(p, S.scheme);
  const Curve ref = shear_at_constant_normal(M, -0.5, 0.1, 500, 0.0);
  for (double angle_deg : {30.0, 90.0, 135.0, 250.0}) {
    const Curve c = shear_at_constant_normal(M, -0.5, 0.1, 500, angle_deg * M_PI / 180);
    REQUIRE(c.samples.size() == ref.samples.size());
    double worst = 0;
    for (size_t i = 0; i < c.samples.size(); ++i)
      worst = std::max(worst, std::abs(shear_norm(c.samples[i].traction) - shear_norm(ref.samples[i].traction)));
    CAPTURE(S.name, angle_deg);
    CHECK(worst < 1e-9);
  }
}

TEST_CASE("Paths: a step at prescribed normal traction reaches it and keeps the imposed slip", "[paths]") {
  // The mixed control every shear test above relies on (tests/support/paths.hpp).
  const Parameters p = van_der_pluijm(-0.5);
  const Model M = model_with(p, Scheme::modified_euler);
  State s;
  IncrementResult r;
  // Elastic: the normal separation is sigma_n / kn, whatever the slip.
  REQUIRE(step_at_normal_traction(M, s, -0.5, 1e-4, -2e-4, r));
  CHECK(std::abs(r.traction[0] + 0.5) <= 1e-12);
  CHECK(s.separation[0] == Approx(-0.5 / p.kn).epsilon(1e-10));
  CHECK(s.separation[1] == 1e-4);
  CHECK(s.separation[2] == -2e-4);
  // Plastic, with dilatancy: still on the target, the slip still imposed.
  const Vec3 before = s.separation;
  REQUIRE(step_at_normal_traction(M, s, -0.5, 0.02, 0, r));
  CHECK(r.status.plastic);
  CHECK(std::abs(r.traction[0] + 0.5) <= 1e-12);
  CHECK(s.separation[1] == before[1] + 0.02);
  // A tension beyond the strength cannot be reached: false, state unchanged.
  const State kept = s;
  CHECK_FALSE(step_at_normal_traction(M, s, 10 * p.ft0, 0, 0, r));
  CHECK(s.separation == kept.separation);
}
