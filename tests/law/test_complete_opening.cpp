// Opening past complete normal damage (docs/model.md 6, Decision - opening
// past complete normal damage): the inelastic opening follows the opening
// as the growing branch does in its limit dn -> 1, so neither the completion
// threshold nor s_sep sets where contact is regained (the tolerance table of
// docs/model.md 6), and nothing is dissipated on the way.
#include <catch2/catch.hpp>

#include "mortar/physics/damage.hpp"
#include "paper_sets.hpp"
#include "paths.hpp"
#include "schemes.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {

// Drives s to `target` in increments of at most h, each as `calls` equal
// calls; the traction at the end.
Vec3 drive_to(const Model& M, State& s, const Vec3& target, double h, int calls = 1) {
  const Vec3 d = target - s.separation;
  const int n = std::max(1, int(std::ceil(d.norm() / h - 1e-9)));
  Vec3 t = Vec3::Zero();
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < calls; ++c) {
      const IncrementResult r = integrate_increment(M, s, d / n / calls);
      REQUIRE(r.status.ok());
      t = r.traction;
    }
  return t;
}

// O(threshold ft0 / kn): where the normal completes, delta_n - delta_in_n is
// the traction left over kn.
double completion_gap(const Parameters& p) { return 10 * kNormalComplete * p.ft0 / p.kn; }

}  // namespace

TEST_CASE("Decision: a mode-I opening past complete damage regains contact at delta_max / (1 + bn)",
          "[decision][separation]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  CAPTURE(S.name);
  const Parameters p = almeida_m15();  // completes near 0.109 mm (s = 1e-7)
  const Model M = model_with(p, S.scheme);
  double D_completed = -1, wI_completed = -1;
  for (const double reach : {0.12, 0.2, 0.5}) {
    CAPTURE(reach);
    State s;
    drive_to(M, s, Vec3(reach, 0, 0), 1e-4);
    REQUIRE(s.open);
    REQUIRE(s.dn == 1);
    // The inelastic opening is the opening, split as Eq. 17 splits it.
    CHECK(s.plastic[0] + s.crack[0] == Approx(s.separation[0]).epsilon(1e-14));
    CHECK(s.crack[0] == Approx(p.bn * s.plastic[0]).epsilon(1e-8));
    // Nothing dissipated past completion: the same works and dissipation
    // whatever the reach.
    const double D = s.dissipation_plastic + s.dissipation_damage;
    if (D_completed < 0) {
      D_completed = D;
      wI_completed = s.wI;
    }
    // The implicit scheme's dyadic substeps (docs/model.md 7.5) switch at
    // thresholds that the round-off of reach / n moves before completion:
    // 2e-12 between the reaches, measured.
    const double same = S.scheme == Scheme::implicit ? 1e-10 : 1e-12;
    CHECK(D == Approx(D_completed).epsilon(same));
    CHECK(s.wI == Approx(wI_completed).epsilon(same));
    // GIC (invariant 2; the first-order schemes within their own error at
    // this increment).
    if (S.scheme == Scheme::modified_euler) CHECK(D == Approx(p.GIC).epsilon(1e-4));
    // Contact at delta_n = delta_p_n = reach / (1 + bn), to O(threshold).
    const Vec3 at_zero = drive_to(M, s, Vec3(0, 0, 0), 1e-4);
    CHECK_FALSE(s.open);
    CHECK(std::abs(s.plastic[0] - reach / (1 + p.bn)) <= completion_gap(p));
    CHECK(at_zero[0] == Approx(-p.kn * s.plastic[0]).epsilon(1e-12));
  }
}

TEST_CASE("Decision: the contact point after complete damage is the same however the opening is cut or cycled",
          "[decision][separation][splitting]") {
  const Parameters p = almeida_m15();
  const Model M = model_with(p, Scheme::modified_euler);
  double first = -1;
  for (const int calls : {1, 20, 100}) {
    CAPTURE(calls);
    // Past completion, partly closed (the joint stays open), opened further,
    // closed into contact: the largest opening decides.
    State s;
    drive_to(M, s, Vec3(0.15, 0, 0), 1e-3, calls);
    drive_to(M, s, Vec3(0.05, 0, 0), 1e-2, calls);
    CHECK(s.open);
    drive_to(M, s, Vec3(0.25, 0, 0), 2e-2, calls);
    drive_to(M, s, Vec3(-1e-3, 0, 0), 1e-2, calls);
    CHECK_FALSE(s.open);
    CHECK(std::abs(s.plastic[0] - 0.25 / (1 + p.bn)) <= completion_gap(p));
    if (first < 0) first = s.plastic[0];
    CHECK(s.plastic[0] == Approx(first).epsilon(1e-12));
  }
}

TEST_CASE("Decision: a joint completed while sliding never lags behind its opening", "[decision][separation]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  CAPTURE(S.name);
  // The bench's cap_reversal path (bench/paths.cpp): the normal completes
  // while the slip zig-zags on the tension cap.
  const Parameters p = van_der_pluijm(-0.5);
  const Model M = model_with(p, S.scheme);
  const double u = p.GIC / p.ft0;
  State s;
  bool completed = false;
  for (int k = 1; k <= 8; ++k) {
    const double opening = 6.0 * u * k / 8;
    drive_to(M, s, Vec3(opening, (k % 2 ? 0.1 : -0.1) * opening, 0), 1e-4);
    if (s.dn < 1) continue;
    completed = true;
    CHECK(s.open);
    CHECK(s.separation[0] - s.plastic[0] - s.crack[0] <= completion_gap(p));
  }
  CHECK(completed);
  // The plastic opening it closes on is at least delta_max / (1 + bn).
  const double reach = s.separation[0];
  drive_to(M, s, Vec3(0, s.separation[1], 0), 1e-4);
  CHECK_FALSE(s.open);
  CHECK(s.plastic[0] >= reach / (1 + p.bn) - completion_gap(p));
}

TEST_CASE("Decision: the elastic shortcut leaves an opening past complete damage to the full path",
          "[decision][separation][elastic]") {
  const Parameters p = almeida_m15();
  const Model M = model_with(p, Scheme::modified_euler);
  State s;
  drive_to(M, s, Vec3(0.2, 0, 0), 1e-4);
  REQUIRE(s.dn == 1);
  IncrementResult r;
  State t = s;
  CHECK_FALSE(elastic_increment(M, t, Vec3(1e-5, 0, 0), r));  // would move delta_p_n
  CHECK(t.separation == s.separation);
  CHECK(elastic_increment(M, t, Vec3(-2e-5, 0, 0), r));  // closing: elastic, delta_p_n kept
  CHECK(t.plastic == s.plastic);
  // From there, reopening short of the largest opening is elastic again;
  // past it, not.
  CHECK(elastic_increment(M, t, Vec3(1e-5, 0, 0), r));
  CHECK_FALSE(elastic_increment(M, t, Vec3(2e-5, 0, 0), r));
}
