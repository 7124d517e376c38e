// Decisions of docs/model.md that the invariant tests do not pin on their
// own: regime switches inside an increment (docs/model.md 6), closure with a
// continuous traction, snap-back, disintegration, the regularised potential (docs/model.md 5).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "mortar/integration/rate_statement.hpp"
#include "mortar/physics/elasticity.hpp"
#include "mortar/physics/yield_surface.hpp"
#include "paper_sets.hpp"
#include "paths.hpp"
#include "schemes.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {
Vec3 kbar_of(const Model& M) { return Vec3(M.p.kn, M.p.ks, M.p.ks); }

double plastic_potential(const Vec3& sigma, const Surface& S) {
  return std::hypot(S.alpha, shear_norm(sigma)) + sigma[0] * S.tan_psi;
}

// A damaged, open joint: opened and slid in small increments.
State damaged_open_joint(const Model& M) {
  DisplacementDriver d(M);
  d.ramp(Vec3(0.003, 0.002, 0), 300);
  d.ramp(Vec3(0.0, 0.01, 0), 300);
  REQUIRE(d.state().open);
  REQUIRE(d.state().ds > 0.3);
  return d.state();
}
}  // namespace

TEST_CASE("Decision: the flow direction is dG/dsigma of the regularised potential under compression",
          "[decision][surface]") {
  const Model M = make_model_checked(van_der_pluijm(-0.5));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const Surface S = surface_of(M, 1e-3 * std::abs(u(rng)), 1e-2 * std::abs(u(rng)), 1e-4 * std::abs(u(rng)));
    const Vec3 sigma(-std::abs(u(rng)), u(rng), u(rng));
    const Vec3 m = flow_of(M, sigma, S, kbar_of(M)).m;
    for (int i = 0; i < 3; ++i) {
      Vec3 a = sigma, b = sigma;
      a[i] += 1e-6;
      b[i] -= 1e-6;
      CHECK(m[i] == Approx((plastic_potential(a, S) - plastic_potential(b, S)) / 2e-6).margin(1e-7));
    }
  }
}

TEST_CASE("Decision: a regime switch inside an increment is resolved where it happens", "[decision][regime]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  CAPTURE(S.name);
  const Model M = model_with(almeida_m15(), S.scheme);
  // Damaged by pure opening, so that closing with a small slip stays elastic.
  DisplacementDriver drive(M);
  drive.ramp(Vec3(0.004, 0, 0), 400);
  const State start = drive.state();
  REQUIRE(start.open);
  REQUIRE(start.dn > 0.5);
  const double e = start.elastic_separation()[0];
  // One increment that closes the joint and compresses it, against the same
  // path split exactly at delta_e_n = 0.
  const Vec3 d(-2 * e, 1e-5, 0);
  State one = start, two = start;
  const IncrementResult r1 = integrate_increment(M, one, d);
  integrate_increment(M, two, 0.5 * d);
  const IncrementResult r2 = integrate_increment(M, two, 0.5 * d);
  REQUIRE(r1.status.ok());
  CHECK(r1.status.regime_switches == 1);
  CHECK_FALSE(r1.status.plastic);
  CHECK_FALSE(one.open);
  for (int i = 0; i < 3; ++i) CHECK(r1.traction[i] == Approx(r2.traction[i]).margin(1e-12));
  // Closed: the full kn and ks act on the elastic separation (Eq. 13, h = 0).
  CHECK(r1.traction[0] == Approx(-M.p.kn * e).epsilon(1e-12));
  CHECK(r1.traction[1] == Approx(M.p.ks * 1e-5).epsilon(1e-9));
}

TEST_CASE("Decision: a joint closes with its traction continuous and creates no energy",
          "[decision][regime][closure]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  CAPTURE(S.name);
  const Model M = model_with(almeida_m15(), S.scheme);
  State s = damaged_open_joint(M);
  const State start = s;
  const Vec3 e = s.elastic_separation();
  const Vec3 tau0 = traction_of(M, s);
  // Read literally, Eq. 13 gives the shear its full ks back at fixed
  // separation: tau would jump to ks |delta_e_s|, far above the secant's.
  REQUIRE(M.p.ks * std::hypot(e[1], e[2]) > 1.5 * shear_norm(tau0));
  // Close just past delta_e_n = 0 in one increment. (Landing exactly on 0
  // keeps the joint open: a point on the boundary stays in its regime.)
  const IncrementResult r = integrate_increment(M, s, Vec3(-e[0] - 1e-12, 0, 0));
  REQUIRE(r.status.ok());
  CHECK(r.status.regime_switches == 1);
  CHECK_FALSE(s.open);
  CHECK(s.energy_unilateral >= start.energy_unilateral);
  // Forward Euler has no drift correction: its open joint may start outside
  // the surface, and then returns to it after the switch (docs/model.md 6).
  if (yield_function(tau0, surface_of(M, start)) > yield_tolerance(M, tau0)) {
    CHECK_FALSE(S.ends_on_surface);
    return;
  }
  CHECK(r.status.relaxations == 0);
  // The shear traction is the secant's, unchanged (docs/model.md 6).
  CHECK(r.traction[1] == Approx(tau0[1]).epsilon(1e-12));
  CHECK(r.traction[2] == Approx(tau0[2]).epsilon(1e-12));
  // The share ds delta_e_s became plastic, taken from the crack slip.
  CHECK(s.plastic[1] == Approx(start.plastic[1] + start.ds * e[1]).epsilon(1e-12));
  CHECK((s.plastic + s.crack - start.plastic - start.crack).norm() < 1e-15);
  // The elastic energy fell by 1/2 ks ds (1 - ds) delta_e_s^2 (+ the normal's
  // share of what is left of delta_e_n), booked as unilateral energy.
  const double lost = 0.5 * M.p.ks * start.ds * (1 - start.ds) * (e[1] * e[1] + e[2] * e[2]);
  CHECK(s.energy_unilateral - start.energy_unilateral == Approx(lost).epsilon(1e-6));
  CHECK(s.energy_unilateral >= 0);
  // Pressed further, the closed joint has the full stiffnesses (Eq. 13).
  const State closed = s;
  const IncrementResult p = integrate_increment(M, s, Vec3(-1e-5, 1e-7, 0));
  REQUIRE(p.status.ok());
  CHECK(p.traction[0] - r.traction[0] == Approx(-M.p.kn * (1e-5 - 1e-12)).epsilon(1e-6));
  CHECK(p.traction[1] - r.traction[1] == Approx(M.p.ks * 1e-7).epsilon(1e-6));
  CHECK(s.energy_unilateral == closed.energy_unilateral);
}

TEST_CASE("Decision: unilateral energy never decreases on open-slide-close cycles", "[decision][regime][closure]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  CAPTURE(S.name);
  for (const Parameters& p : {almeida_m15(), almeida_m34(), atkinson(), van_der_pluijm(-0.5)}) {
    const Model M = model_with(p, S.scheme);
    DisplacementDriver drive(M);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int closings = 0;
    const double u0 = p.GIC / p.ft0;  // the softening length of mode I
    for (int cycle = 0; cycle < 12; ++cycle) {
      drive.ramp(Vec3(u0 * (0.5 + std::abs(u(rng))), 0, 0), 20);  // open
      drive.ramp(Vec3(0, 5 * u0 * u(rng), 5 * u0 * u(rng)), 20);  // slide while open
      drive.ramp(Vec3(-drive.state().elastic_separation()[0] - u0 * std::abs(u(rng)), 0, 0), 7);  // close
      if (!drive.state().open) ++closings;
      drive.ramp(Vec3(0, u0 * u(rng), 0), 10);  // slide shut
    }
    // Every switch books what the elastic energy loses: never negative.
    double last = 0;
    for (const Sample& x : drive.curve().samples) {
      CAPTURE(x.separation, x.state.energy_unilateral, last);
      CHECK(x.state.energy_unilateral >= last);
      last = x.state.energy_unilateral;
    }
    CHECK(closings > 0);
    CHECK(drive.curve().all_ok);
  }
}

TEST_CASE("Decision: a snap-back drops at fixed separation to a stable point on the surface",
          "[decision][snapback]") {
  // ft0^2 / GIC = 1.0 / 0.0005 = 2000 > kn = 500: no strain-driven softening.
  Parameters p = almeida_m15();
  p.kn = 500;
  p.ft0 = 1.0;
  p.c0 = 2.0;
  p.GIC = 0.0005;
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  CAPTURE(S.name);
  const Model M = model_with(p, S.scheme);
  DisplacementDriver d(M);
  // 1e-7 mm increments: the drop happens inside one increment, so the
  // trapezoidal external work is accurate to about 1e-4.
  d.ramp(Vec3(0.004, 0, 0), 40000);
  REQUIRE(d.curve().all_ok);
  // Tallied over the 40000 increments, asserted once.
  bool dropped = false;
  int non_finite = 0, above_strength = 0, damage_decreased = 0;
  for (size_t i = 1; i < d.curve().samples.size(); ++i) {
    const Sample& a = d.curve().samples[i - 1];
    const Sample& b = d.curve().samples[i];
    if (b.result.status.relaxations > 0) dropped = true;
    if (!b.traction.allFinite()) ++non_finite;
    if (!(b.traction[0] <= p.ft0 * (1 + 1e-9))) ++above_strength;
    if (!(b.state.dn >= a.state.dn)) ++damage_decreased;
  }
  CHECK(non_finite == 0);
  CHECK(above_strength == 0);
  CHECK(damage_decreased == 0);
  CHECK(dropped);
  // The work done is all dissipated or stored.
  const double W = d.curve().external_work();
  CHECK(d.curve().stored_plus_dissipated(M) == Approx(W).epsilon(1e-3));
  // The drop ends where softening is stable again: kn = ft0 sigma_n / GIC.
  CHECK(d.curve().samples.back().traction[0] < p.kn * p.GIC / p.ft0);
}

TEST_CASE("Decision: an open joint with no strength left disintegrates", "[decision][disintegration]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  CAPTURE(S.name);
  const Model M = model_with(almeida_m34(), S.scheme);
  State s;
  s.wI = 2 * M.p.GIC;  // s = 0
  s.separation = Vec3(1e-3, 0, 0);
  IncrementResult r = integrate_increment(M, s, Vec3(1e-4, 0, 0));
  REQUIRE(r.status.ok());
  CHECK(s.open);
  CHECK(s.dn == 1);
  CHECK(s.ds == 1);
  CHECK(r.traction.norm() == 0);
  CHECK(s.dissipation_damage > 0);  // the elastic energy it had is dissipated, not lost
  // Sliding while open: still nothing.
  State sliding = s;
  CHECK(integrate_increment(M, sliding, Vec3(0, 5e-3, 0)).traction.norm() == 0);
  // Pressed shut it has the full kn and is a pure friction joint: tan(phir)
  // once worn (Eq. 6), at most tan(phi0) before.
  r = integrate_increment(M, s, Vec3(-s.elastic_separation()[0] - 1e-4, 0, 0));
  CHECK(r.traction[0] == Approx(-M.p.kn * 1e-4).epsilon(1e-9));
  for (int i = 0; i < 200; ++i) r = integrate_increment(M, s, Vec3(0, 1e-4, 0));
  REQUIRE(r.status.ok());
  CHECK(shear_norm(r.traction) <= M.tan_phi0 * std::abs(r.traction[0]) * (1 + 1e-6));
  CHECK(shear_norm(r.traction) >= M.tan_phir * std::abs(r.traction[0]) * (1 - 1e-6));
}

// docs/model.md 6, Decision - slip across the elastic slip: the rate
// statement of an open joint on its growing shear branch turns the traction
// as the secant relation (Eq. 1, tau parallel to the elastic slip) does
// after settle(). With the full ks across the elastic slip the stage turned
// tau by ks ds times more than settle() then kept, so the Heun pair's error
// estimate saw a swing that no substep size removed (a worn open joint took
// 10^4 substeps per call at the floor, and its answer depended on the cuts).
TEST_CASE("Decision: slip across the elastic slip of an open joint turns the traction on the shear secant",
          "[decision][damage]") {
  const Model M = make_model_checked(almeida_m15());
  Point P{damaged_open_joint(M), Vec3::Zero()};
  P.sigma = traction_of(M, P.y);
  REQUIRE(yield_of(M, P) > -1e-6 * M.p.ft0);  // on the surface: the slip loads it
  const double ds = P.y.ds;
  for (double angle_deg : {30.0, 60.0, 90.0, 120.0}) {
    const double a = angle_deg * M_PI / 180, h = 1e-7;
    const Vec3 dd(0, h * std::cos(a), h * std::sin(a));
    const Rates r = stage(M, P, dd);
    Point Q = P;
    add(Q, r, 1.0);
    Q.y.separation += dd;
    const Vec3 rate_end = Q.sigma;
    settle(M, Q, P.y.elastic_separation(), r.grow);
    INFO("slip at " << angle_deg << " degrees to the elastic slip, ds = " << ds);
    // The part across the elastic slip: the secant ks (1 - ds), not ks.
    CHECK(std::abs(r.dsigma[2] - M.p.ks * (1 - ds) * dd[2]) <= 1e-9 * M.p.ks * h);
    // The stage's end agrees with settle()'s to first order in the step.
    CHECK((Q.sigma - rate_end).norm() <= 1e-3 * r.dsigma.norm() + 1e-12);
  }
}
