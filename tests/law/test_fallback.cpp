// docs/model.md 9: when the chosen scheme fails on an integrable point, the
// increment is integrated again from its unchanged start state by the
// fallback chain, and the result says so. The first attempt is forced to
// fail here by a substep budget (Controls::max_substeps) too small for it.
#include <catch2/catch.hpp>

#include <cmath>

#include "mortar/integrator.hpp"
#include "paper_sets.hpp"
#include "schemes.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {

// Compressed, then a large slip increment: softening with dilatancy, many
// substeps in one increment.
State pressed(const Model& M) {
  State s;
  integrate_increment(M, s, Vec3(-0.5 / M.p.kn, 0, 0));
  return s;
}
const Vec3 kSlip(0, 0.05, 0.02);

// The same increment cut into 2000 equal pieces, modified Euler at STOL 1e-8.
Vec3 reference_traction(const Parameters& p, State s) {
  const Model R = model_with(p, Scheme::modified_euler, 1e-8);
  IncrementResult r;
  for (int i = 0; i < 2000; ++i) r = integrate_increment(R, s, kSlip / 2000);
  REQUIRE(r.status.ok());
  return r.traction;
}

}  // namespace

TEST_CASE("Fallback: an increment beyond the substep budget is integrated by the fallback chain, flagged",
          "[fallback]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  const Parameters p = almeida_m15();
  // The substeps the chosen scheme needs with the default budget; half of
  // that budget makes it fail.
  State s = pressed(model_with(p, S.scheme));
  const State start = s;
  const IncrementResult free_run = integrate_increment(model_with(p, S.scheme), s, kSlip);
  REQUIRE(free_run.status.ok());
  REQUIRE_FALSE(free_run.status.fell_back());
  const int needed = free_run.status.substeps_accepted + free_run.status.substeps_rejected;
  CAPTURE(S.name, needed);
  if (needed < 2) return;  // forward Euler: one substep, nothing to take away

  Model tight = model_with(p, S.scheme);
  tight.controls.max_substeps = needed / 2;
  s = start;
  Mat3 T;
  const IncrementResult r = integrate_increment(tight, s, kSlip, &T);
  CHECK(r.status.ok());
  CHECK(r.status.fell_back());
  CHECK(r.status.first_failure == Failure::too_many_substeps);
  CHECK(r.status.fallback_pieces >= 8);
  CHECK(r.status.tangent_approximate);
  CHECK(T.allFinite());
  CHECK(s.status == 0);
  CHECK(check_state(s) == nullptr);
  CHECK(s.separation == start.separation + kSlip);
  // The fallback's answer is the law's: within the rung's accuracy of the
  // finely cut reference (modified Euler at STOL 1e-5 over 8 pieces, or
  // forward Euler over 1024).
  const Vec3 ref = reference_traction(p, start);
  CAPTURE(r.traction.transpose(), ref.transpose());
  CHECK((r.traction - ref).norm() <= 1e-3 * ref.norm());
  CHECK(r.elastic_energy > 0);
  CHECK(std::isfinite(r.d_dissipation_plastic + r.d_dissipation_damage + r.d_energy_unilateral));
}

TEST_CASE("Fallback: bad input is refused as it came, without a fallback", "[fallback]") {
  const Model M = model_with(almeida_m15(), Scheme::modified_euler);
  State s;
  s.dn = 2;  // breaks a rule
  const IncrementResult r = integrate_increment(M, s, Vec3(1e-3, 0, 0));
  CHECK(r.status.failure == Failure::invalid_state);
  CHECK_FALSE(r.status.fell_back());
  State t;
  const IncrementResult q = integrate_increment(M, t, Vec3(std::nan(""), 0, 0));
  CHECK(q.status.failure == Failure::non_finite_increment);
  CHECK_FALSE(q.status.fell_back());
}

TEST_CASE("Fallback: an increment the chosen scheme integrates is not touched by it", "[fallback]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  const Model M = model_with(almeida_m15(), S.scheme);
  State s = pressed(M);
  const IncrementResult r = integrate_increment(M, s, kSlip);
  CHECK(r.status.ok());
  CHECK_FALSE(r.status.fell_back());
  CHECK(r.status.fallback_pieces == 0);
  CHECK(r.status.first_failure == Failure::none);
}
