// The returns to the surface at fixed separation
// (src/mortar/integration/relaxation.hpp, drift_correction.hpp;
// docs/model.md 6 closure jump, 7.1 drift correction).
#include <catch2/catch.hpp>

#include <cmath>

#include "mortar/integration/drift_correction.hpp"
#include "mortar/integration/relaxation.hpp"
#include "paper_sets.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {
// A closed joint under pressure, slipped by `slip` (elastically: the traction
// may lie outside the surface by any amount).
Point slipped(const Model& M, double slip, const Vec3& works = Vec3::Zero()) {
  Point P;
  P.y.separation = Vec3(-1e-3, slip, 0);
  P.y.wI = works[0];
  P.y.wII = works[1];
  P.y.wIII = works[2];
  P.sigma = traction_of(M, P.y);
  return P;
}
}  // namespace

TEST_CASE("Return at fixed separation: ends on the surface, separation fixed, works not lower", "[relaxation]") {
  const Model M = make_model_checked(van_der_pluijm(-0.5));
  for (double factor : {1.01, 1.5, 5.0, 50.0}) {
    // The slip at which the elastic traction reaches the surface, times factor.
    Point P = slipped(M, 0);
    const Surface S = surface_of(M, P.y);
    const double tau_max = std::sqrt(std::pow(S.beta - P.sigma[0] * S.tan_phi, 2) - S.alpha * S.alpha);
    P = slipped(M, factor * tau_max / M.p.ks, Vec3(0, 0.1 * M.p.GIIC, 0));
    REQUIRE(yield_of(M, P) > yield_tolerance(M, P.sigma));
    const Point start = P;
    IntegrationStatus st;
    REQUIRE(relax(M, P, st, false));
    CHECK(std::abs(yield_of(M, P)) <= yield_tolerance(M, P.sigma));
    CHECK(P.y.separation == start.y.separation);
    CHECK(P.y.wII >= start.y.wII);
    CHECK(P.y.plastic[1] > 0);
    CHECK(P.sigma == traction_of(M, P.y));
    CHECK(st.relaxations == 1);
    CHECK(st.plastic);
  }
}

TEST_CASE("Drift correction: a point just outside returns within FTOL and one inside is left alone", "[relaxation]") {
  const Model M = make_model_checked(atkinson());
  Point P = slipped(M, 0);
  const Surface S = surface_of(M, P.y);
  const double tau_max = std::sqrt(std::pow(S.beta - P.sigma[0] * S.tan_phi, 2) - S.alpha * S.alpha);
  Point outside = slipped(M, 1.0005 * tau_max / M.p.ks);
  REQUIRE(yield_of(M, outside) > yield_tolerance(M, outside.sigma));
  const Point before = outside;
  correct_drift(M, outside);
  CHECK(yield_of(M, outside) <= yield_tolerance(M, outside.sigma));
  CHECK(outside.y.separation == before.y.separation);
  CHECK(outside.y.dissipation_plastic >= before.y.dissipation_plastic);
  Point inside = slipped(M, 0.5 * tau_max / M.p.ks);
  const Point untouched = inside;
  correct_drift(M, inside);
  CHECK(inside.sigma == untouched.sigma);
  CHECK(inside.y.plastic == untouched.y.plastic);
}
