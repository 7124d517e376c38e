// docs/model.md 9: a point the law can integrate is never reported as
// failed. Over random valid parameter sets and random extreme paths, in every
// scheme, no increment fails: where the chosen scheme does, the fallback chain
// integrates it, and says so (IntegrationStatus::fell_back()). Law level
// (integrate_increment), so that the fallback's record can be read; the paths
// are the property tests' families (abi_block.hpp), increments of up to 1e5
// elastic limits, a fully softened joint, and worn open joints: almost no
// strength left (s from 1e-6 to 1e-2), where the consistency denominator of
// the blended normal flow is tiny and the modified-Euler substeps run out at
// the regime boundary.
//
// Size in the normal build: 1 189 730 point-increments in 6 test cases, run
// side by side by ctest (about 19 s of one core in all, most of it backward
// Euler's own Newton budget on the increments it fails on); 110 153 under the
// sanitizers (a tenth of the sets, test_scale.hpp). Measured: the chosen
// scheme fails on 59 of them (modified Euler 25, backward Euler 34), every
// one integrated by the fallback.
#include <catch2/catch.hpp>

#include <map>
#include <random>

#include "abi_block.hpp"
#include "worn_cases.hpp"
#include "formatted.hpp"

using namespace mj_property;
using mortar::Failure;
using mortar::IncrementResult;
using mortar::Scheme;
using mortar::State;
using mortar::Vec3;
using mj_test::kWornCases;
using mj_test::WornCase;

namespace {

constexpr int kIncrements = 60;  // per path
constexpr int kPathsPerSet = 10;  // 5 families + softened + 4 worn

struct Tally {
  long increments = 0, first_failures = 0, failures = 0;
  std::map<int, long> first_by_code;                 // Failure code of the chosen scheme
  std::map<std::pair<int, int>, long> rescued_by;    // (scheme, pieces) of the rung
  // Each of these must stay zero.
  long non_finite = 0, invalid = 0, damage_decreased = 0, not_flagged = 0, off_surface = 0;
  std::string notes;  // the first few failures
};

// One increment, checked and tallied.
void step(const mortar::Model& M, State& s, const Vec3& d, Tally& t) {
  const State before = s;
  mortar::Mat3 T;
  const IncrementResult r = mortar::integrate_increment(M, s, d, &T);
  ++t.increments;
  if (!r.status.ok()) {
    ++t.failures;
    if (t.failures <= 3)
      t.notes += mj_test::formatted("failed: %s, separation (%.17g, %.17g, %.17g), increment (%.17g, %.17g, %.17g); ",
                                    mortar::failure_name(r.status.failure), before.separation[0], before.separation[1],
                                    before.separation[2], d[0], d[1], d[2]);
  }
  if (r.status.fell_back()) {
    ++t.first_failures;
    ++t.first_by_code[static_cast<int>(r.status.first_failure)];
    ++t.rescued_by[{static_cast<int>(r.status.fallback_scheme), r.status.fallback_pieces}];
    if (!r.status.tangent_approximate || s.status != 0) ++t.not_flagged;
  }
  if (!(r.traction.allFinite() && T.allFinite() && std::isfinite(r.elastic_energy))) ++t.non_finite;
  if (mortar::check_state(s)) ++t.invalid;
  if (s.dn < before.dn || s.ds < before.ds) ++t.damage_decreased;
  if (M.controls.scheme != Scheme::forward_euler && r.status.ok() && !r.status.fell_back()) {
    if (mortar::yield_ratio(M, s, r.traction) > 10) ++t.off_surface;
  }
}

Vec3 law_increment(const Step& s) { return Vec3(-s.d_penetration, s.slip1, s.slip2); }

// A worn open joint: opened while sliding until the softening factor is
// below `target`, then increments of opening, sliding and closing of up to
// 20 elastic limits.
void worn_path(const mortar::Model& M, std::mt19937& rng, Tally& t) {
  const mortar::Parameters& p = M.p;
  const double un = p.ft0 / p.kn, us = p.c0 / p.ks;
  const double target = log_uniform(rng, 1e-6, 1e-2);
  const double angle = uniform(rng, 0, 2 * M_PI);
  State s;
  for (int i = 0; i < 400 && mortar::softening_factor(M, s) > target; ++i) {
    const double slip = uniform(rng, 0.2, 1.0) * us;
    step(M, s, Vec3(uniform(rng, 0.0, 0.1) * un, slip * std::cos(angle), slip * std::sin(angle)), t);
  }
  for (int k = 0; k < kIncrements; ++k) {
    const double n = log_uniform(rng, 1e-6, 20) * un * (uniform(rng, 0, 1) < 0.8 ? 1 : -1);
    const double s1 = log_uniform(rng, 1e-3, 30) * us * (uniform(rng, 0, 1) < 0.5 ? -1 : 1);
    const double s2 = uniform(rng, 0, 1) < 0.5 ? 0.0 : log_uniform(rng, 1e-3, 10) * us;
    step(M, s, Vec3(n, s1, s2), t);
  }
}

// From a worn case's state, increments around its own: each component
// scaled by a log-uniform factor in [1e-3, 10], either sign.
void worn_case_path(const WornCase& w, Scheme scheme, std::mt19937& rng, Tally& t) {
  mortar::Parameters p;
  mortar::Controls c;
  REQUIRE(mortar::read_props(w.props, 14, p, c).ok());
  c.scheme = scheme;
  const mortar::Model M = mortar::make_model(p, c);
  State s;
  mortar::load_state(w.state, s);
  const double size = std::max(std::abs(w.increment[0]), std::abs(w.increment[1]));
  for (int k = 0; k < kIncrements; ++k) {
    Vec3 d;
    for (int i = 0; i < 2; ++i) d[i] = size * log_uniform(rng, 1e-3, 10) * (uniform(rng, 0, 1) < 0.5 ? -1 : 1);
    d[2] = 0;
    step(M, s, d, t);
  }
}

void run_set(const mortar::Parameters& p, Scheme scheme, bool worn_cases, std::mt19937& rng, Tally& t) {
  mortar::Controls c;
  c.scheme = scheme;
  const mortar::Model M = mortar::make_model_checked(p, c);
  for (int family = 0; family < 5; ++family) {
    State s;
    for (int k = 0; k < kIncrements; ++k) step(M, s, law_increment(random_step(rng, p, family, false)), t);
  }
  // Fully softened (opened far beyond separation), then anything.
  State s;
  step(M, s, Vec3(2 * p.ft0 / p.kn + 200 * p.GIC / p.ft0, 0, 0), t);
  for (int k = 0; k < kIncrements; ++k) step(M, s, law_increment(random_step(rng, p, 4, false)), t);
  for (int w = 0; w < 4; ++w) worn_path(M, rng, t);
  if (worn_cases)
    for (const WornCase& w : kWornCases) worn_case_path(w, scheme, rng, t);
}

// What a tally measured, shown when a check fails.
std::string summary(const char* what, const Tally& t) {
  std::string text = mj_test::formatted("%s: %ld point-increments; the chosen scheme failed on %ld (by code:", what,
                                        t.increments, t.first_failures);
  for (const auto& [code, n] : t.first_by_code) text += mj_test::formatted(" %d x%ld", code, n);
  text += "), rescued by:";
  for (const auto& [rung, n] : t.rescued_by)
    text += mj_test::formatted(" %s x%d: %ld", mortar::scheme_name(static_cast<Scheme>(rung.first)), rung.second, n);
  return text + mj_test::formatted("; failures %ld; ", t.failures) + t.notes;
}

// `sets` random parameter sets (seed `seed`) of 10 paths each, in `scheme`.
void check_no_failure(const char* what, Scheme scheme, unsigned seed, int sets) {
  std::mt19937 rng(seed);
  Tally t;
  for (int set = 0; set < scaled(sets); ++set) run_set(random_parameters(rng), scheme, set % 2 == 0, rng, t);
  INFO(summary(what, t));
  CHECK(t.increments >= long(scaled(sets)) * kPathsPerSet * kIncrements);
  CHECK(t.failures == 0);
  CHECK(t.non_finite == 0);
  CHECK(t.invalid == 0);
  CHECK(t.damage_decreased == 0);
  CHECK(t.not_flagged == 0);
  CHECK(t.off_surface == 0);
}

}  // namespace

TEST_CASE("Fallback: no failure on random extreme paths (modified Euler part 1)", "[property][fallback]") {
  check_no_failure("modified Euler 1", Scheme::modified_euler, 20261301, 75);
}
TEST_CASE("Fallback: no failure on random extreme paths (modified Euler part 2)", "[property][fallback]") {
  check_no_failure("modified Euler 2", Scheme::modified_euler, 20261302, 75);
}
TEST_CASE("Fallback: no failure on random extreme paths (forward Euler part 1)", "[property][fallback]") {
  check_no_failure("forward Euler 1", Scheme::forward_euler, 20261303, 400);
}
TEST_CASE("Fallback: no failure on random extreme paths (forward Euler part 2)", "[property][fallback]") {
  check_no_failure("forward Euler 2", Scheme::forward_euler, 20261304, 400);
}
TEST_CASE("Fallback: no failure on random extreme paths (backward Euler part 1)", "[property][fallback]") {
  check_no_failure("backward Euler 1", Scheme::implicit, 20261305, 40);
}
TEST_CASE("Fallback: no failure on random extreme paths (backward Euler part 2)", "[property][fallback]") {
  check_no_failure("backward Euler 2", Scheme::implicit, 20261306, 40);
}
