// docs/model.md 10, invariant 10: no NaN, infinity, crash or hang for any
// finite input, in every scheme — randomised valid parameter sets and load
// paths (fixed seeds): opening-closing, shear reversals, jumps across the
// apex, anything from tiny to huge, from a virgin and a fully softened joint.
//
// Every increment is tallied and the tallies are asserted once at the end
// (as tests/property does): about a million checks would otherwise be
// Catch2 assertions, which dominate the run time under the sanitizers.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "mortar/physics/elasticity.hpp"
#include "mortar/physics/yield_surface.hpp"
#include "paper_sets.hpp"
#include "paths.hpp"
#include "random_parameters.hpp"
#include "schemes.hpp"
#include "test_scale.hpp"
#include "formatted.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {
using mj_test::log_uniform;
using mj_test::uniform;

// A random increment of one of the path families, scaled to the joint.
Vec3 random_increment(std::mt19937& rng, const Parameters& p, int family) {
  const double un = p.ft0 / p.kn, us = p.c0 / p.ks;
  switch (family) {
    case 0:  // opening-closing
      return Vec3(uniform(rng, -3, 3.2) * un, uniform(rng, -0.1, 0.1) * us, 0);
    case 1:  // shear reversals under a normal wander
      return Vec3(uniform(rng, -0.2, 0.2) * un, uniform(rng, -4, 4) * us, uniform(rng, -1, 1) * us);
    case 2:  // jumps across the apex: large tension with shear, then back
      return Vec3(uniform(rng, -40, 40) * un, uniform(rng, -10, 10) * us, uniform(rng, -10, 10) * us);
    default:  // anything, from tiny to huge
      return Vec3(log_uniform(rng, 1e-12, 10) * (uniform(rng, 0, 1) < 0.5 ? -1 : 1),
                  log_uniform(rng, 1e-12, 10) * (uniform(rng, 0, 1) < 0.5 ? -1 : 1),
                  uniform(rng, 0, 1) < 0.5 ? 0.0 : log_uniform(rng, 1e-12, 1));
  }
}

struct Tally {
  long increments = 0, plastic = 0, newton = 0, rejected = 0;
  int max_newton = 0, approximate = 0;
  // Each of these must stay zero.
  int invalid_parameters = 0, not_softened = 0, non_finite = 0, invalid_state = 0, damage_decreased = 0,
      failure_not_exhausted = 0, failure_changed_state = 0, off_surface = 0;
  int failures = 0, failures_by_family[4] = {0, 0, 0, 0};
  int fallbacks = 0, not_flagged = 0;  // the chosen scheme failed and the fallback chain integrated the increment
  std::string notes;                   // the first few offences of each kind
};

// Counts one offence and describes the first few.
void offence(Tally& t, int& count, const char* what, int set, int family, int k) {
  if (++count <= 3) t.notes += mj_test::formatted("%s: set %d, family %d, increment %d; ", what, set, family, k);
}

void run_path(const SchemeUnderTest& S, const Model& M, std::mt19937& rng, int set, int family, State start,
              Tally& t) {
  State s = start;
  for (int k = 0; k < 60; ++k) {
    const State before = s;
    Mat3 T;
    const IncrementResult r = integrate_increment(M, s, random_increment(rng, M.p, family), &T);
    ++t.increments;
    if (r.status.plastic) ++t.plastic;
    t.newton += r.status.newton_iterations;
    t.max_newton = std::max(t.max_newton, r.status.newton_iterations);
    t.rejected += r.status.substeps_rejected;
    if (r.status.tangent_approximate) ++t.approximate;
    if (r.status.fell_back()) {
      ++t.fallbacks;
      if (!(r.status.ok() && r.status.tangent_approximate && s.status == 0))
        offence(t, t.not_flagged, "a fallback not flagged", set, family, k);
    }
    if (!r.status.ok()) {
      ++t.failures;
      ++t.failures_by_family[family];
      // None is expected (below); a failure would be reported and keep the
      // start state (the solver cuts back).
      const bool exhausted = r.status.failure == Failure::local_solve_failed ||
                             r.status.failure == Failure::too_many_substeps;
      if (!exhausted) offence(t, t.failure_not_exhausted, failure_name(r.status.failure), set, family, k);
      if (!(s.plastic == before.plastic && s.separation == before.separation))
        offence(t, t.failure_changed_state, "a failure changed the state", set, family, k);
    }
    if (!(r.traction.allFinite() && T.allFinite() && std::isfinite(r.elastic_energy)))
      offence(t, t.non_finite, "non-finite traction, tangent or energy", set, family, k);
    if (const char* rule = check_state(s)) offence(t, t.invalid_state, rule, set, family, k);
    if (!(s.dn >= before.dn && s.ds >= before.ds && s.wI >= before.wI))
      offence(t, t.damage_decreased, "damage or work decreased", set, family, k);
    if (S.ends_on_surface && r.status.ok()) {
      // On or inside the surface: FTOL, with the slack the drift correction leaves.
      const double F = yield_function(r.traction, surface_of(M, s));
      if (F > 10 * yield_tolerance(M, r.traction)) offence(t, t.off_surface, "off the surface", set, family, k);
    }
  }
}
}  // namespace

TEST_CASE("Invariant 10: random parameters and paths never give NaN, failure or hang", "[invariant10]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  // Under the sanitizers the first tenth of the sets (tests/support/test_scale.hpp).
  const int sets = mj_test::scaled(S.random_sets);
  std::mt19937 rng(S.random_seed);
  Tally t;
  for (int set = 0; set < sets; ++set) {
    const Parameters p = mj_test::random_parameters(rng);
    if (!validate(p).ok()) offence(t, t.invalid_parameters, "invalid parameter set", set, -1, -1);
    const Model M = model_with(p, S.scheme);
    for (int family = 0; family < 4; ++family) run_path(S, M, rng, set, family, State{}, t);
    // Fully softened joint: opened far beyond separation, then everything again.
    State softened;
    const Vec3 opening(2 * p.ft0 / p.kn + 200 * p.GIC / p.ft0, 0, 0);
    for (int i = 0; i < S.softening_increments; ++i) integrate_increment(M, softened, opening / S.softening_increments);
    if (!(std::abs(softened.dn - 1.0) <= 1e-6)) offence(t, t.not_softened, "not fully softened", set, -1, -1);
    for (int family = 0; family < 4; ++family) run_path(S, M, rng, set, family, softened, t);
  }
  INFO(mj_test::formatted(
      "[invariant 10] %s: %ld increments, %ld plastic, %d failures (by family %d %d %d %d), %d integrated by "
      "the fallback, %d off the surface, %d approximate tangents, %.1f Newton iterations per plastic increment "
      "(max %d), %ld halvings",
      S.name, t.increments, t.plastic, t.failures, t.failures_by_family[0], t.failures_by_family[1],
      t.failures_by_family[2], t.failures_by_family[3], t.fallbacks, t.off_surface, t.approximate,
      double(t.newton) / std::max(t.plastic, 1L), t.max_newton, t.rejected));
  CAPTURE(S.name, t.increments, t.failures, t.notes);
  CHECK(t.increments == 8L * 60 * sets);
  CHECK(t.invalid_parameters == 0);
  CHECK(t.not_softened == 0);
  CHECK(t.non_finite == 0);
  CHECK(t.invalid_state == 0);
  CHECK(t.damage_decreased == 0);
  CHECK(t.failure_not_exhausted == 0);
  CHECK(t.failure_changed_state == 0);
  if (S.ends_on_surface) CHECK(t.off_surface == 0);
  CHECK(t.not_flagged == 0);
  // No failure in any scheme (docs/model.md 9): where the chosen scheme
  // fails (backward Euler, on the extreme families: the local solve at the
  // smallest substep or its Newton budget), the fallback chain integrates
  // the increment.
  CHECK(t.failures == 0);
}
