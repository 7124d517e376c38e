// MODEL.md section 8, invariant 10: no NaN, infinity, crash or hang for any
// finite input — randomised valid parameter sets and load paths (fixed seeds):
// opening-closing, shear reversals, jumps across the apex, fully softened joints.
#include <catch2/catch.hpp>

#include <random>

#include "mortar/surface.hpp"
#include "paper_sets.hpp"
#include "paths.hpp"
#include "random_parameters.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {
using mj_test::log_uniform;
using mj_test::uniform;
Parameters random_parameters(std::mt19937& rng) {
  const Parameters p = mj_test::random_parameters(rng);
  REQUIRE(validate(p).ok());
  return p;
}

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
  int increments = 0, failures = 0, off_surface = 0;
};

void run_path(const Model& M, std::mt19937& rng, int family, State start, Tally& t) {
  State s = start;
  for (int k = 0; k < 60; ++k) {
    const State before = s;
    const IncrementResult r = integrate_increment(M, s, random_increment(rng, M.p, family));
    ++t.increments;
    if (!r.status.ok()) {
      ++t.failures;
      UNSCOPED_INFO("failure: " << failure_name(r.status.failure));
    }
    REQUIRE(r.traction.allFinite());
    REQUIRE(std::isfinite(r.elastic_energy));
    REQUIRE(check_state(s) == nullptr);
    CHECK(s.dn >= before.dn);
    CHECK(s.ds >= before.ds);
    CHECK(s.wI >= before.wI);
    if (M.controls.scheme == Scheme::modified_euler) {
      const double F = yield_function(r.traction, surface_of(M, s));
      // On or inside the surface: FTOL, with the slack the drift correction leaves.
      if (F > 10 * yield_tolerance(M, r.traction)) ++t.off_surface;
    }
  }
}
}  // namespace

TEST_CASE("Invariant 10: random parameters and paths never give NaN, failure or hang", "[invariant10]") {
  const Scheme scheme = GENERATE(Scheme::modified_euler, Scheme::forward_euler);
  std::mt19937 rng(20261122);
  Tally t;
  for (int set = 0; set < 200; ++set) {
    const Parameters p = random_parameters(rng);
    const Model M = model_with(p, scheme);
    CAPTURE(set, p.kn, p.ks, p.ft0, p.c0, p.GIC, p.GIIC, p.phi0, p.phir, p.m, p.psi0, p.psir, p.n, p.bn, p.bs);
    for (int family = 0; family < 4; ++family) run_path(M, rng, family, State{}, t);
    // Fully softened joint: opened far beyond separation, then everything again.
    State softened;
    integrate_increment(M, softened, Vec3(2 * p.ft0 / p.kn + 200 * p.GIC / p.ft0, 0, 0));
    REQUIRE(softened.dn == Approx(1.0).margin(1e-6));
    for (int family = 0; family < 4; ++family) run_path(M, rng, family, softened, t);
  }
  CAPTURE(scheme_name(scheme), t.increments, t.failures, t.off_surface);
  CHECK(t.failures == 0);
  CHECK(t.off_surface == 0);
}
