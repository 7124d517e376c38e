// docs/model.md 10, invariant 1: below the surface the response is linear
// elastic and reversible, with zero dissipation, in every scheme.
#include <catch2/catch.hpp>

#include <random>

#include "paper_sets.hpp"
#include "paths.hpp"
#include "schemes.hpp"

using namespace mortar;
using namespace mortar::testing;

TEST_CASE("Invariant 1: elastic inside the surface, reversible, no dissipation", "[invariant1]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  CAPTURE(S.name);
  for (const Parameters& p : {van_der_pluijm(-0.5), atkinson(), almeida_m15()}) {
    const Model M = model_with(p, S.scheme);
    std::mt19937 rng(3);
    // Random points well inside the surface: |tau| < c0/3, -c0 < sigma_n < ft0/3.
    std::uniform_real_distribution<double> un(-p.c0 / p.kn, p.ft0 / (3 * p.kn));
    std::uniform_real_distribution<double> us(-p.c0 / (3 * p.ks * 1.5), p.c0 / (3 * p.ks * 1.5));
    DisplacementDriver drive(M);
    for (int k = 0; k < 200; ++k) {
      const Vec3 target(un(rng), us(rng), us(rng));
      drive.step(target - drive.state().separation);
      const Sample& s = drive.curve().samples.back();
      CHECK_FALSE(s.result.status.plastic);
      CHECK(s.result.status.newton_iterations == 0);  // no local solve for an elastic increment
      for (int i = 0; i < 3; ++i)
        CHECK(s.traction[i] == Approx((i == 0 ? p.kn : p.ks) * target[i]).epsilon(1e-12).margin(1e-15));
    }
    drive.step(-drive.state().separation);
    const State& s = drive.state();
    CHECK(drive.curve().samples.back().traction.norm() < 1e-14);
    CHECK(s.plastic.norm() == 0);
    CHECK(s.dn == 0);
    CHECK(s.ds == 0);
    CHECK(s.dissipation_plastic + s.dissipation_damage + s.energy_unilateral == 0);
    // Closed path: the external work is (up to the trapezoid) zero.
    CHECK(std::abs(drive.curve().external_work()) < 1e-12);
  }
}
