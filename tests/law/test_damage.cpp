// Damage and the unilateral regime (src/mortar/physics/damage.hpp,
// docs/model.md 6): the secant damage rule of settle(), its energy booking,
// the branch tests and disintegration.
#include <catch2/catch.hpp>

#include <cmath>

#include "mortar/physics/damage.hpp"
#include "mortar/physics/elasticity.hpp"
#include "mortar/physics/yield_surface.hpp"
#include "paper_sets.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {
// An open joint with elastic separation e (plastic part p) and damage d.
State open_joint(const Vec3& e, double dn, double ds) {
  State y;
  y.open = true;
  y.plastic = Vec3(1e-3, 2e-3, 0);
  y.separation = y.plastic + e;
  y.dn = dn;
  y.ds = ds;
  return y;
}
}  // namespace

TEST_CASE("Damage: settle() puts the secant through the traction and books the released energy", "[damage]") {
  const Model M = make_model_checked(almeida_m15());
  const Vec3 e(2e-3, 3e-3, 0), e_start(1.5e-3, 2.5e-3, 0);
  State y = open_joint(e, 0.1, 0.2);
  // A traction below the current secant in both parts: the damage grows.
  Vec3 sigma(0.5 * M.p.kn * e[0], 0.4 * M.p.ks * e[1], 0);
  const Vec3 sigma_in = sigma;
  settle(M, y, sigma, e_start);
  CHECK(y.dn == Approx(0.5).epsilon(1e-14));
  CHECK(y.ds == Approx(0.6).epsilon(1e-14));
  CHECK((sigma - sigma_in).norm() <= 1e-14 * sigma_in.norm());  // Eq. 1 gives the traction back
  // 1/2 kbar (delta_e)^2 dd, trapezoidal in delta_e over the step.
  const double expected = 0.25 * M.p.kn * 0.4 * (e_start[0] * e_start[0] + e[0] * e[0]) +
                          0.25 * M.p.ks * 0.4 * (e_start[1] * e_start[1] + e[1] * e[1]);
  CHECK(y.dissipation_damage == Approx(expected).epsilon(1e-14));
}

TEST_CASE("Damage: settle() never lowers the damage and the traction follows the kept secant", "[damage]") {
  const Model M = make_model_checked(almeida_m15());
  const Vec3 e(2e-3, 3e-3, 0);
  State y = open_joint(e, 0.3, 0.3);
  Vec3 sigma(0.9 * M.p.kn * e[0], 0.9 * M.p.ks * e[1], 0);  // above the secant: would be d = 0.1
  settle(M, y, sigma, e);
  CHECK(y.dn == 0.3);
  CHECK(y.ds == 0.3);
  CHECK(y.dissipation_damage == 0);
  CHECK(sigma == traction_of(M, y));
  CHECK(sigma[0] == Approx(0.7 * M.p.kn * e[0]));
}

TEST_CASE("Damage: a closed joint keeps its damage and carries the full stiffness", "[damage]") {
  const Model M = make_model_checked(van_der_pluijm(-0.5));
  State y = open_joint(Vec3(-1e-3, 1e-3, 0), 0.5, 0.5);
  y.open = false;
  Vec3 sigma(0, 0, 0);
  settle(M, y, sigma, y.elastic_separation());
  CHECK(y.dn == 0.5);
  CHECK(sigma[0] == Approx(-M.p.kn * 1e-3));
  CHECK(sigma[1] == Approx(M.p.ks * 1e-3));
}

TEST_CASE("Damage: an open joint with no strength left disintegrates", "[damage]") {
  const Model M = make_model_checked(almeida_m34());
  State y = open_joint(Vec3(1e-3, 2e-3, 0), 0.2, 0.4);
  y.wI = M.p.GIC;  // s = 0
  REQUIRE(surface_of(M, y).s == 0);
  const double energy = elastic_energy(M, y);
  disintegrate_if_no_strength(M, y);
  CHECK(y.dn == 1);
  CHECK(y.ds == 1);
  CHECK(y.dissipation_damage == Approx(energy).epsilon(1e-14));
  CHECK(traction_of(M, y).norm() == 0);
  // With strength left, or closed, nothing happens.
  State strong = open_joint(Vec3(1e-3, 2e-3, 0), 0.2, 0.4);
  disintegrate_if_no_strength(M, strong);
  CHECK(strong.dn == 0.2);
  State closed = y;
  closed.open = false;
  closed.dn = closed.ds = 0.2;
  disintegrate_if_no_strength(M, closed);
  CHECK(closed.dn == 0.2);
}

TEST_CASE("Damage: the growing branch holds while the secant damage would not decrease", "[damage]") {
  const Model M = make_model_checked(almeida_m15());  // bn = 10, bs = 3
  const State y = open_joint(Vec3(2e-3, 2e-3, 0), 0.5, 0.5);
  // d (dd - dp) <= b dp along the elastic separation.
  CHECK(damage_grows_normal(M, y, Vec3(1e-4, 0, 0), Vec3(1e-5, 0, 0)));       // 0.5*9e-5 <= 1e-4
  CHECK_FALSE(damage_grows_normal(M, y, Vec3(1e-4, 0, 0), Vec3(1e-6, 0, 0)));  // 0.5*9.9e-5 > 1e-5
  CHECK(damage_grows_shear(M, y, Vec3(0, 1e-4, 0), Vec3(0, 2e-5, 0)));        // 0.5*8e-5 <= 6e-5
  CHECK_FALSE(damage_grows_shear(M, y, Vec3(0, 1e-4, 0), Vec3(0, 1e-6, 0)));
  // Unloading towards the closed side (e_n <= 0) or without elastic slip: no test to fail.
  State shut = y;
  shut.separation[0] = shut.plastic[0];
  CHECK(damage_grows_normal(M, shut, Vec3(1e-4, 0, 0), Vec3::Zero()));
  CHECK(crosses(true, -1e-9));
  CHECK_FALSE(crosses(true, 1e-9));
  CHECK(crosses(false, 1e-9));
}
