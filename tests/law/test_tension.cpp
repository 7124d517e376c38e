// docs/model.md 10, invariants 2, 3 and 4: mode I opening, unloading on the
// secant, stiffness recovery on closure, in every scheme.
#include <catch2/catch.hpp>


#include "paper_sets.hpp"
#include "paths.hpp"
#include "schemes.hpp"
#include "formatted.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {
// Opening to where the softening factor is below 1e-6: s decays like
// exp(-ft0 delta_in / GIC) in pure mode I, so about 14 GIC/ft0 of inelastic
// opening beyond the peak.
double full_separation(const Parameters& p) { return p.ft0 / p.kn + 15.0 * p.GIC / p.ft0; }

// Invariant 4 from a damaged open joint: close past delta_p into compression
// in one increment that crosses the regime boundary, then a little further;
// compression acts with the undamaged stiffness, measured from delta_p.
void check_closure_restores_kn(DisplacementDriver& drive, const Parameters& p) {
  const double dp = drive.state().plastic[0];
  drive.step(Vec3(dp - drive.state().separation[0] - 1e-4, 0, 0));
  const double s1 = drive.curve().samples.back().traction[0];
  drive.step(Vec3(-1e-4, 0, 0));
  const double s2 = drive.curve().samples.back().traction[0];
  CHECK(s1 == Approx(-p.kn * 1e-4).epsilon(1e-9));
  CHECK((s1 - s2) / 1e-4 == Approx(p.kn).epsilon(1e-9));
  CHECK_FALSE(drive.state().open);
}
}  // namespace

TEST_CASE("Invariant 2: pure opening peaks at ft0, dissipates GIC and ends separated", "[invariant2]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  const Parameters p = GENERATE(almeida_m15(), almeida_m34(), van_der_pluijm(-0.5), atkinson());
  CAPTURE(S.name, p.kn, p.ft0, p.GIC);
  // Arrange
  const Model M = model_with(p, S.scheme);
  DisplacementDriver drive(M);
  // Act: 1e-5 mm increments (explicit-typical), 1e-8 mm around the peak so
  // that the sampled maximum resolves it.
  const double elastic_limit = p.ft0 / p.kn, end = full_separation(p);
  drive.ramp_to(Vec3(0.99 * elastic_limit, 0, 0), 100);
  drive.ramp_to(Vec3(1.01 * elastic_limit, 0, 0), static_cast<int>(0.02 * elastic_limit / 1e-8));
  drive.ramp_to(Vec3(end, 0, 0), static_cast<int>(end / 1e-5));
  const Curve& c = drive.curve();
  // Assert
  REQUIRE(c.all_ok);
  CHECK(c.max_traction(0) == Approx(p.ft0).epsilon(1e-3));
  // Area under sigma_n - delta_n by the trapezoidal rule on the returned curve.
  const double area = c.external_work();
  INFO(mj_test::formatted("[invariant 2] %s: GIC area rel. error %.2e (ft0 %.3g)", S.name, (area - p.GIC) / p.GIC,
                          p.ft0));
  CHECK(area == Approx(p.GIC).epsilon(5e-3));
  CHECK(std::abs(c.samples.back().traction[0]) < 1e-5 * p.ft0);
  CHECK(drive.state().dn == Approx(1.0).margin(1e-5));
}

TEST_CASE("Invariant 2: the area converges to GIC as the increment shrinks", "[invariant2]") {
  const Parameters p = almeida_m15();
  const Model M = model_with(p, Scheme::modified_euler, 1e-8);
  const double end = full_separation(p);
  double previous_error = 1;
  for (double inc : {1e-4, 1e-5}) {
    DisplacementDriver drive(M);
    drive.ramp(Vec3(end, 0, 0), static_cast<int>(end / inc));
    // What is left at the end is the elastic energy still stored (tiny).
    const double error = std::abs(drive.curve().external_work() - p.GIC) / p.GIC;
    CAPTURE(inc, error);
    CHECK(error < previous_error);
    previous_error = error;
  }
  CHECK(previous_error < 1e-4);
}

TEST_CASE("Invariants 3 and 4: unloading from the softening branch follows the secant to delta_p, "
          "pressing shut restores the full kn", "[invariant3][invariant4]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  CAPTURE(S.name);
  const Parameters p = almeida_m15();
  const Model M = model_with(p, S.scheme);
  DisplacementDriver drive(M);
  // Arrange: into the softening branch, about half the strength left.
  drive.ramp(Vec3(0.004, 0, 0), 400);
  const State loaded = drive.state();
  const double sigma0 = drive.curve().samples.back().traction[0];
  REQUIRE(sigma0 < 0.9 * p.ft0);
  REQUIRE(sigma0 > 0.2 * p.ft0);
  // Act: unload part of the way, in small increments.
  const double back = 0.5 * (loaded.separation[0] - loaded.plastic[0]);
  drive.ramp(Vec3(-back, 0, 0), 50);
  const State& s = drive.state();
  const double sigma1 = drive.curve().samples.back().traction[0];
  // Assert: linear on the secant kn (1 - dn), nothing dissipated.
  const double slope = (sigma0 - sigma1) / back;
  CHECK(slope == Approx(p.kn * (1 - loaded.dn)).epsilon(1e-10));
  CHECK(s.dn == loaded.dn);
  CHECK(s.plastic == loaded.plastic);
  CHECK(s.dissipation_plastic == loaded.dissipation_plastic);
  // The secant passes through zero traction at delta_p (extrapolated).
  CHECK(loaded.separation[0] - sigma0 / slope == Approx(loaded.plastic[0]).epsilon(1e-10));
  // delta_p_n = delta_in_n / (1 + bn): the crack part is bn times the plastic part (Eq. 14, 17).
  const double delta_in = loaded.plastic[0] + loaded.crack[0];
  CHECK(loaded.plastic[0] == Approx(delta_in / (1 + p.bn)).epsilon(1e-12));
  // Eq. 15 on a monotonic path: d_n = b_n delta_p / (delta - delta_p).
  CHECK(loaded.dn == Approx(p.bn * loaded.plastic[0] / (loaded.separation[0] - loaded.plastic[0])).epsilon(1e-6));
  // Invariant 4 from the unloaded joint.
  check_closure_restores_kn(drive, p);
}

TEST_CASE("Invariant 4: pressing a heavily damaged joint shut restores the full kn, reopening the secant",
          "[invariant4]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  CAPTURE(S.name);
  const Parameters p = almeida_m34();
  const Model M = model_with(p, S.scheme);
  DisplacementDriver drive(M);
  // Arrange: heavily damaged by opening (d_n > 0.9).
  drive.ramp(Vec3(0.01, 0, 0), 1000);
  REQUIRE(drive.state().dn > 0.9);
  check_closure_restores_kn(drive, p);
  // Re-opening finds the damaged secant again.
  drive.step(Vec3(2e-4 + 1e-4, 0, 0));
  CHECK(drive.curve().samples.back().traction[0] ==
        Approx(p.kn * (1 - drive.state().dn) * 1e-4).epsilon(1e-9));
}
