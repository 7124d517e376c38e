// docs/model.md 9, large increments and the integration flags: one increment
// that opens a joint far beyond separation dissipates GIC, as the opening
// cut fine does, whatever its size; what the integration had to do besides
// converging under error control (a fallback rung, a substep accepted at the
// floor above STOL) is flagged per increment and OR'd into the state.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"
#include "paper_sets.hpp"
#include "formatted.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {

struct PaperSet {
  const char* name;
  Parameters p;
};
const PaperSet kSets[] = {{"Almeida M15", almeida_m15()},
                          {"Almeida M34", almeida_m34()},
                          {"van der Pluijm (-0.5)", van_der_pluijm(-0.5)},
                          {"Atkinson", atkinson()}};

double dissipated(const State& s) { return s.dissipation_plastic + s.dissipation_damage + s.energy_unilateral; }

}  // namespace

// Before the floor was bounded by a material length (docs/model.md 9), at
// 10 / 100 / 1000 mm: M15 1.020 / 1.704 / 1.704, M34 1.090 / 1.574 / 1.574,
// vdP 1.016 / 1.459 / 1.459, Atkinson 1.005 / 1.403 / 41.3 x GIC; after,
// within 3.5e-5 of GIC.
TEST_CASE("Large increments: one increment opening a joint to 10, 100, 1000 mm dissipates GIC (default scheme)",
          "[large_increment]") {
  const double opening = GENERATE(10.0, 100.0, 1000.0);
  for (const PaperSet& set : kSets) {
    const Model M = model_with(set.p, Scheme::modified_euler);
    State s;
    const IncrementResult r = integrate_increment(M, s, Vec3(opening, 0, 0));
    const double ratio = dissipated(s) / set.p.GIC;
    INFO(mj_test::formatted(
        "[large increment] %s, 0 -> %g mm in one increment: dissipation / GIC = %.7f (%d substeps, %d "
        "rejected, flags %d)",
        set.name, opening, ratio, r.status.substeps_accepted, r.status.substeps_rejected, r.status.flags));
    CAPTURE(set.name, opening, s.dissipation_plastic, s.dissipation_damage, s.energy_unilateral);
    REQUIRE(r.status.ok());
    CHECK_FALSE(r.status.fell_back());
    CHECK(s.dn == 1);
    CHECK(r.traction.norm() == 0);
    CHECK(r.elastic_energy == 0);
    CHECK(std::abs(ratio - 1) < 1e-4);
    // The increment's books are the state's.
    CHECK(r.d_inelastic() == Approx(dissipated(s)).epsilon(1e-12));
  }
}

// The same opening to 20 mm in 2000 increments of 0.01 mm (Atkinson: +0.5 %
// of GIC before the damage booking's check, docs/model.md 7.1).
TEST_CASE("Large increments: the same opening cut into 0.01 mm increments dissipates GIC", "[large_increment]") {
  for (const PaperSet& set : kSets) {
    const Model M = model_with(set.p, Scheme::modified_euler);
    State s;
    for (int i = 0; i < 2000; ++i) REQUIRE(integrate_increment(M, s, Vec3(0.01, 0, 0)).status.ok());
    CAPTURE(set.name);
    CHECK(std::abs(dissipated(s) / set.p.GIC - 1) < 1e-4);
  }
}

// The damage booking's check (docs/model.md 7.1, step 4): Atkinson past its
// peak in one call to 5e-4 mm booked 1.5 times the damage dissipation of the
// path cut into 500 calls; now within 1 %.
TEST_CASE("Large increments: the damage dissipation of one call through the peak is the finely cut one",
          "[large_increment]") {
  const Model M = model_with(atkinson(), Scheme::modified_euler);
  State one, fine;
  REQUIRE(integrate_increment(M, one, Vec3(5e-4, 0, 0)).status.ok());
  for (int i = 0; i < 500; ++i) REQUIRE(integrate_increment(M, fine, Vec3(1e-6, 0, 0)).status.ok());
  CAPTURE(one.dissipation_damage, fine.dissipation_damage, one.dn, fine.dn);
  CHECK(one.dn == Approx(fine.dn).epsilon(1e-6));
  CHECK(one.dissipation_damage == Approx(fine.dissipation_damage).epsilon(1e-2));
}

TEST_CASE("Integration flags: a substep accepted at the floor is flagged and the flag stays with the point",
          "[large_increment][flags]") {
  // A coarse floor (min_substep 0.5) on a plastic increment: the error control
  // cannot meet STOL there.
  Controls c;
  c.min_substep = 0.5;
  const Model M = make_model_checked(almeida_m15(), c);
  State s;
  const IncrementResult r = integrate_increment(M, s, Vec3(0.004, 0, 0));
  REQUIRE(r.status.ok());
  CHECK(r.status.min_substep_hit);
  CHECK(r.status.flags == integration_flag::floor_above_stol);
  CHECK(s.integration_flags == integration_flag::floor_above_stol);
  CHECK(s.status == 0);
  // An elastic increment (unloading) raises nothing and clears nothing.
  const IncrementResult e = integrate_increment(M, s, Vec3(-1e-4, 0, 0));
  REQUIRE(e.status.ok());
  CHECK(e.status.flags == 0);
  CHECK(s.integration_flags == integration_flag::floor_above_stol);
  // The default controls: an error-controlled answer raises none.
  State t;
  const IncrementResult q = integrate_increment(model_with(almeida_m15(), Scheme::modified_euler), t,
                                                Vec3(0.004, 0, 0));
  REQUIRE(q.status.ok());
  CHECK(q.status.flags == 0);
  CHECK(t.integration_flags == 0);
}

TEST_CASE("Integration flags: the SDV 35 slot and the flag names", "[flags]") {
  STATIC_REQUIRE(flag_slot::integration_flags == 34);
  STATIC_REQUIRE(kFlaggedStateCount == 35);
  double a[kFlaggedStateCount] = {};
  store_integration_flags(integration_flag::fallback_rung_2 | integration_flag::floor_above_stol, a);
  CHECK(a[34] == 10);
  CHECK(load_integration_flags(a) == 10);
  float f[kFlaggedStateCount] = {};
  f[34] = std::nanf("");
  CHECK(load_integration_flags(f) == 0);  // garbage reads as none
  f[34] = -7.5f;
  CHECK(load_integration_flags(f) == 0);
  CHECK(std::string(integration_flag::kNames[3]) == "floor_above_stol");
}
