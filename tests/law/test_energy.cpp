// MODEL.md section 8, invariant 7: energy closure. The external work is the
// trapezoidal sum over the returned curve; the law's books (elastic energy,
// plastic and damage dissipation, unilateral switch energy) must match it.
#include <catch2/catch.hpp>

#include "paper_sets.hpp"
#include "paths.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {
double closure_error(const Model& M, const Curve& c) {
  const double W = c.external_work();
  return std::abs(W - c.stored_plus_dissipated(M)) / std::max(std::abs(W), 1e-300);
}
}  // namespace

TEST_CASE("Invariant 7: energy closes on pure opening", "[invariant7]") {
  const Model M = model_with(almeida_m15(), Scheme::modified_euler, 1e-8);
  DisplacementDriver drive(M);
  drive.ramp(Vec3(0.006, 0, 0), 3000);   // into softening
  drive.ramp(Vec3(-0.004, 0, 0), 500);  // unload, close and compress
  drive.ramp(Vec3(0.02, 0, 0), 5000);   // reopen to near separation
  REQUIRE(drive.curve().all_ok);
  CHECK(closure_error(M, drive.curve()) < 1e-6);
}

TEST_CASE("Invariant 7: energy closes in shear at constant compression", "[invariant7]") {
  const Model M = model_with(van_der_pluijm(-0.5), Scheme::modified_euler, 1e-8);
  const Curve c = shear_at_constant_normal(M, -0.5, 0.1, 5000);
  REQUIRE(c.all_ok);
  CHECK(closure_error(M, c) < 1e-6);
}

TEST_CASE("Invariant 7: energy closes through opening, shear and closing", "[invariant7]") {
  const Model M = model_with(almeida_m34(), Scheme::modified_euler, 1e-8);
  DisplacementDriver drive(M);
  drive.ramp(Vec3(0.002, 0.004, 0), 2000);   // mixed-mode opening
  drive.ramp(Vec3(0.0, 0.01, 0.005), 2000);  // slide while open
  drive.ramp(Vec3(-0.004, 0, 0), 2000);      // close: shear stiffness comes back
  drive.ramp(Vec3(0, -0.03, 0), 3000);       // slide back under compression
  REQUIRE(drive.curve().all_ok);
  const State& s = drive.state();
  CAPTURE(s.energy_unilateral, s.dissipation_plastic, s.dissipation_damage);
  CHECK(closure_error(M, drive.curve()) < 1e-6);
}

TEST_CASE("Invariant 7: forward Euler closes energy to first order", "[invariant7]") {
  // Forward Euler has no error control; its closure error is that of the
  // scheme. Stated looser tolerance: 1e-3 at 1e-5 mm increments.
  const Model M = model_with(van_der_pluijm(-0.5), Scheme::forward_euler);
  const Curve c = shear_at_constant_normal(M, -0.5, 0.1, 10000);
  REQUIRE(c.all_ok);
  CHECK(closure_error(M, c) < 1e-3);
}
