// The integration schemes behind the substepper
// (src/mortar/integration/scheme.hpp, docs/model.md 7.1, 7.2, 7.5): what an
// attempt returns and how each sizes its next substep.
#include <catch2/catch.hpp>

#include <cmath>

#include "mortar/integration/scheme.hpp"
#include "paper_sets.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {
Model model_for(Scheme s, double stol = 1e-5) {
  Controls c;
  c.scheme = s;
  c.stol = stol;
  return make_model_checked(van_der_pluijm(-0.5), c);
}
// A closed joint under pressure with its shear traction on the surface.
Point on_surface(const Model& M) {
  Point P;
  P.y.separation = Vec3(-1e-3, 0, 0);
  P.sigma = traction_of(M, P.y);
  const Surface S = surface_of(M, P.y);
  const double tau = std::sqrt(std::pow(S.beta - P.sigma[0] * S.tan_phi, 2) - S.alpha * S.alpha);
  P.y.separation[1] = tau / M.p.ks;
  P.sigma = traction_of(M, P.y);
  return P;
}
}  // namespace

TEST_CASE("Scheme: forward Euler ends at the first stage and takes the whole rest next", "[scheme]") {
  const Model M = model_for(Scheme::forward_euler);
  const Point P = on_surface(M);
  const Vec3 dd(0, 1e-4, 0);
  const Rates r1 = stage(M, P, dd);
  REQUIRE(r1.dwII > 0);  // plastic
  ForwardEuler fe;
  const Attempt a = fe.attempt(P, dd, 0.25, r1);
  REQUIRE(a.kind == Attempt::step);
  CHECK(a.end->sigma == P.sigma + r1.dsigma);
  CHECK(a.end->y.separation == P.y.separation + dd);
  CHECK(fe.next_size(0.25) == 1);
  CHECK_FALSE(fe.traits.consistent_tangent);
}

TEST_CASE("Scheme: modified Euler grows by at most 1.1, and not right after a rejection", "[scheme]") {
  const Model M = model_for(Scheme::modified_euler, 1e-6);
  IntegrationStatus st;
  ModifiedEuler me(M, st);
  // A tiny step: the two stages agree far below STOL (q = 0.9 sqrt(STOL/err) > 1.1).
  Point inside = on_surface(M);
  inside.y.separation[1] *= 0.5;
  inside.sigma = traction_of(M, inside.y);
  const Vec3 small(0, 1e-6, 0);
  Attempt a = me.attempt(inside, small, 0.5, stage(M, inside, small));
  REQUIRE(a.kind == Attempt::step);
  CHECK(me.next_size(0.5) == Approx(0.55));
  // A large plastic step at a tight STOL: rejected, the retry shrinks by at
  // most a factor 10 and stays above the smallest substep.
  const Point P = on_surface(M);
  const Vec3 big(0, 5e-3, 0);
  a = me.attempt(P, big, 1.0, stage(M, P, big));
  REQUIRE(a.kind == Attempt::retry);
  CHECK(a.size < 1.0);
  CHECK(a.size >= 0.1);
  CHECK(st.substeps_rejected == 0);  // the substepper counts, not the scheme
  // The next accepted substep after the rejection does not grow.
  a = me.attempt(inside, small, 0.3, stage(M, inside, small));
  REQUIRE(a.kind == Attempt::step);
  CHECK(me.next_size(0.3) == Approx(0.3));
  // Never below the smallest substep.
  CHECK(me.next_size(0.5 * M.controls.min_substep) >= M.controls.min_substep);
}

TEST_CASE("Scheme: backward Euler halves a failed step and stops on its Newton budget", "[scheme]") {
  const Model M = model_for(Scheme::implicit);
  IntegrationStatus st;
  TangentTracker tracker;
  BackwardEuler be(M, st, tracker);
  CHECK(be.traits.consistent_tangent);
  CHECK(be.next_size(0.25) == 0.5);
  CHECK(be.budget_spent(st) == Failure::none);
  st.newton_iterations = 200001;
  CHECK(be.budget_spent(st) == Failure::local_solve_failed);
  // A plastic step that converges: the end point is on the surface.
  st.newton_iterations = 0;
  const Point P = on_surface(M);
  const Vec3 dd(0, 1e-4, 0);
  const Attempt a = be.attempt(P, dd, 1.0, stage(M, P, dd));
  REQUIRE(a.kind == Attempt::step);
  CHECK(std::abs(yield_of(M, *a.end)) <= yield_tolerance(M, a.end->sigma));
  CHECK(st.newton_iterations > 0);
}
