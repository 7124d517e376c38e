// The substepper (src/mortar/integration/substepper.*, docs/model.md 6-7):
// what one run() leaves for the next.
#include <catch2/catch.hpp>


#include "mortar/integration/substepper.hpp"
#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"
#include "paper_sets.hpp"
#include "formatted.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {

// A point on the surface after `calls` increments d from the bonded state.
Point after(const Model& M, const Vec3& d, int calls) {
  State s;
  for (int i = 0; i < calls; ++i) integrate_increment(M, s, d);
  return Point{s, traction_of(M, s)};
}

}  // namespace

TEST_CASE("Substepper: a run starts with no bracket of an earlier run, the normal completion's included",
          "[substepper]") {
  // Every run() of a segment's substepper is a run of its own: its brackets
  // (regime crossing, complete separation, complete normal damage) start
  // closed. A run that stops inside the normal-completion bracket (here on
  // its budget, after the first trial went past the threshold) must not hand
  // that bracket to the next run: there it would cut substeps that cross
  // nothing, towards sizes of another point. In the law a run stops inside a
  // bracket only on a failure, which ends the increment's substepper; the
  // test runs the substepper again to show what such a run leaves.
  // The points are made by the default scheme; the runs take forward-Euler
  // substeps (the whole rest at once), so that every cut shows in the count.
  Model M = model_with(almeida_m15(), Scheme::modified_euler);
  // A worn joint, opened while sliding to dn = 1 - 1.5e-6: one forward-Euler
  // step over the next increment takes sigma_n past the completion threshold.
  State near;
  for (int i = 1; i <= 5; ++i) integrate_increment(M, near, Vec3(0.01 * i, 0.01 * i, 0));
  REQUIRE(near.open);
  REQUIRE(near.dn > 1 - 1e-5);
  REQUIRE(near.dn < 1);
  const Point P1{near, traction_of(M, near)};
  const Vec3 d1(0.015, 0.015, 0);
  // An open joint far from complete damage, loading on.
  const Point P2 = after(M, Vec3(2e-3, 2e-3, 0), 2);
  REQUIRE(P2.y.open);
  REQUIRE(P2.y.dn < 0.95);
  const Vec3 d2(2e-4, 2e-4, 0);

  // The second run on a fresh substepper.
  Point fresh = P2;
  IntegrationStatus st_fresh;
  TangentTracker none;
  ForwardEuler scheme_fresh;
  Substepper first(M, fresh, st_fresh, none, scheme_fresh);
  const double done_fresh = first.run(d2, surface_at(M, fresh));
  REQUIRE(st_fresh.ok());

  // The same run on a substepper whose run before stopped in the bracket.
  Point P = P1;
  IntegrationStatus st;
  ForwardEuler scheme;
  Substepper reused(M, P, st, none, scheme);
  M.controls.max_substeps = 1;  // the run stops on its budget after four trials
  reused.run(d1, surface_at(M, P));
  REQUIRE(st.failure == Failure::too_many_substeps);
  REQUIRE(st.substeps_accepted == 0);  // every trial was cut by a bracket
  M.controls.max_substeps = Controls{}.max_substeps;
  st = IntegrationStatus{};
  P = P2;
  const double done = reused.run(d2, surface_at(M, P));
  REQUIRE(st.ok());

  INFO(mj_test::formatted(
      "[substepper] second run: fresh %d substeps, sigma (%.17g, %.17g), dn %.17g; after a run stopped in "
      "the bracket %d substeps, sigma (%.17g, %.17g), dn %.17g",
      st_fresh.substeps_accepted, fresh.sigma[0], fresh.sigma[1], fresh.y.dn, st.substeps_accepted, P.sigma[0],
      P.sigma[1], P.y.dn));
  CHECK(done == done_fresh);
  CHECK(st.substeps_accepted == st_fresh.substeps_accepted);
  CHECK(st.substeps_rejected == st_fresh.substeps_rejected);
  CHECK(P.sigma == fresh.sigma);
  CHECK(P.y.plastic == fresh.y.plastic);
  CHECK(P.y.dn == fresh.y.dn);
  CHECK(P.y.ds == fresh.y.ds);
}
