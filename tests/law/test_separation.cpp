// Complete separation and the loading test of every scheme (docs/model.md 6,
// Decision - complete separation at s_sep; 7.1, Decision - loading from the
// surface, every scheme).
#include <catch2/catch.hpp>

#include "mortar/integration/point.hpp"
#include "paper_sets.hpp"
#include "paths.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {
// Opens the joint from the origin to delta_n in n calls.
State opened(const Model& M, double delta_n, int n) {
  State s;
  for (int i = 0; i < n; ++i) REQUIRE(integrate_increment(M, s, Vec3(delta_n / n, 0, 0)).status.ok());
  return s;
}
}  // namespace

TEST_CASE("Decision: an open joint separates completely at s_sep, and stays separated until contact at dp_n",
          "[decision][separation]") {
  const Scheme scheme = GENERATE(Scheme::modified_euler, Scheme::forward_euler, Scheme::implicit);
  CAPTURE(scheme_name(scheme));
  const Parameters p = almeida_m15();
  const Model M = model_with(p, scheme);
  const double u = p.GIC / p.ft0;
  // s ~ exp(-delta/u): 20 u is past s_sep (2e-9), 14 u short of it (8e-7).
  const State short_of = opened(M, 14 * u, 1400);
  CHECK(surface_of(M, short_of).s_raw > kSeparated);
  CHECK(short_of.dn < 1);
  State s = opened(M, 20 * u, 2000);
  CHECK(s.open);
  CHECK(s.dn == 1);
  CHECK(s.ds == 1);
  CHECK(separated(surface_of(M, s).s_raw));
  // Landed on s_sep, not past it (modified Euler brackets the substep; the
  // others land where their steps put them, within the same bracket).
  CHECK(surface_of(M, s).s_raw == Approx(kSeparated).epsilon(1e-6));
  CHECK(traction_of(M, s).norm() == 0);
  // Open: no traction and no work; sliding and closing change nothing but
  // the separation, opening past the inelastic opening moves it with the
  // opening, split as Eq. 17 splits it (6, Decision - opening past complete
  // normal damage).
  const State before = s;
  double reach = s.plastic[0] + s.crack[0];
  for (const Vec3& d : {Vec3(0.01, 0, 0), Vec3(0, 0.02, -0.01), Vec3(-0.005, -0.02, 0.01)}) {
    const Vec3 dp_shear(0, s.plastic[1], s.plastic[2]), dcr_shear(0, s.crack[1], s.crack[2]);
    const IncrementResult r = integrate_increment(M, s, d);
    REQUIRE(r.status.ok());
    reach = std::max(reach, s.separation[0]);
    CHECK(r.traction.norm() == 0);
    CHECK(s.plastic[0] + s.crack[0] == Approx(reach).epsilon(1e-14));
    CHECK(s.crack[0] == Approx(p.bn * s.plastic[0]).epsilon(1e-8));
    CHECK(Vec3(0, s.plastic[1], s.plastic[2]) == dp_shear);
    CHECK(Vec3(0, s.crack[1], s.crack[2]) == dcr_shear);
    CHECK(s.wI == before.wI);
    CHECK(s.wII == before.wII);
    CHECK(s.dissipation_plastic == before.dissipation_plastic);
    CHECK(s.dissipation_damage == before.dissipation_damage);
  }
  // Contact is regained where the normal separation reaches dp_n (no slip
  // left to jump back on closure, 6, Decision - closure jump).
  const double gap = s.separation[0] - s.plastic[0];
  REQUIRE(gap > 0);
  integrate_increment(M, s, Vec3(-0.999 * gap, 0, 0));
  CHECK(s.open);
  const double dp_n = s.plastic[0];
  const IncrementResult r = integrate_increment(M, s, Vec3(-0.002 * gap, 0, 0));
  REQUIRE(r.status.ok());
  CHECK_FALSE(s.open);
  CHECK(s.plastic[0] == dp_n);
  CHECK(r.traction[0] == Approx(p.kn * (s.separation[0] - dp_n)).epsilon(1e-9));
  CHECK(r.traction[0] < 0);
}

TEST_CASE("Decision: every scheme softens the same whether an opening increment is one call or 100",
          "[decision][separation]") {
  const Scheme scheme = GENERATE(Scheme::modified_euler, Scheme::forward_euler, Scheme::implicit);
  CAPTURE(scheme_name(scheme));
  const Parameters p = van_der_pluijm(-0.5);
  const Model M = model_with(p, scheme);
  const double u = p.GIC / p.ft0, h = 0.05 * u;
  // Late in mode-I softening (s ~ 1e-4): the secant trial of a 1/100 call
  // rises by less than FTOL (default, 1e-8), but the rate statement loads
  // the surface.
  State one = opened(M, 9 * u, 180), cut = one;
  for (int i = 0; i < 40; ++i) {
    REQUIRE(integrate_increment(M, one, Vec3(h, 0, 0)).status.ok());
    for (int k = 0; k < 100; ++k) REQUIRE(integrate_increment(M, cut, Vec3(h / 100, 0, 0)).status.ok());
    // Within the first-order schemes' own discretisation error.
    CHECK(std::abs(traction_of(M, cut)[0] - traction_of(M, one)[0]) <= 1e-5 * p.ft0);
  }
}
