// The state value type and its named layout over the solver's flat array
// (src/mortar/state.hpp, docs/model.md 3): SDV positions 1-14 are a
// user-facing contract, the mapping round-trips in both precisions, garbage
// in the count and status slots reads as 0, and check_state names the first
// rule an incoming state breaks.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"

using namespace mortar;

namespace {
// A state with a distinct value in every slot the law owns.
State distinct_state() {
  State s;
  s.plastic = Vec3(1.25, -2.5, 3.75);
  s.crack = Vec3(0.5, -0.25, 0.125);
  s.wI = 7;
  s.wII = 8;
  s.wIII = 9;
  s.dn = 0.625;
  s.ds = 0.375;
  s.separation = Vec3(12, -13, 14);
  s.open = true;
  s.dissipation_plastic = 16;
  s.dissipation_damage = 17;
  s.energy_unilateral = -18;
  s.substeps_accepted = 19;
  s.substeps_rejected = 20;
  s.status = 7;
  return s;
}
}  // namespace

TEST_CASE("State: SDV 1-14 hold delta_p, delta_cr, w_I..w_III, d_n, d_s, delta in the documented order", "[state]") {
  double a[kStateCount] = {};
  store_state(distinct_state(), a);
  const double expected[] = {1.25, -2.5, 3.75, 0.5, -0.25, 0.125, 7, 8, 9, 0.625, 0.375, 12, -13, 14,
                             1,    16,   17,   -18, 19,   20,    7};
  for (int i = 0; i < kLawStateCount; ++i) {
    CAPTURE(i + 1, kStateNames[i]);
    CHECK(a[i] == expected[i]);
  }
  CHECK(kStateCount == 23);
  CHECK(kLawStateCount == 21);
}

TEST_CASE("State: store then load gives the state back, in double and in single precision", "[state]") {
  const State s = distinct_state();  // every value exact in float
  double d[kStateCount] = {};
  float f[kStateCount] = {};
  store_state(s, d);
  store_state(s, f);
  for (const State& back : {[&] { State t; load_state(d, t); return t; }(),
                            [&] { State t; load_state(f, t); return t; }()}) {
    CHECK(back.plastic == s.plastic);
    CHECK(back.crack == s.crack);
    CHECK(back.separation == s.separation);
    CHECK((back.wI == s.wI && back.wII == s.wII && back.wIII == s.wIII));
    CHECK((back.dn == s.dn && back.ds == s.ds));
    CHECK(back.open == s.open);
    CHECK((back.dissipation_plastic == s.dissipation_plastic && back.dissipation_damage == s.dissipation_damage &&
           back.energy_unilateral == s.energy_unilateral));
    CHECK((back.substeps_accepted == 19 && back.substeps_rejected == 20 && back.status == 7));
  }
}

TEST_CASE("State: a count or status slot holding NaN, infinity or a value beyond int reads as 0", "[state]") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (double garbage : {nan, inf, -inf, 1e300, -3e9, 2147483648.0}) {
    CAPTURE(garbage);
    CHECK(int_slot(garbage) == 0);
    CHECK(int_slot(float(garbage)) == 0);
  }
  CHECK(int_slot(2147483647.0) == 2147483647);
  CHECK(int_slot(-2147483648.0) == -2147483647 - 1);
  CHECK(int_slot(7.0f) == 7);
}

TEST_CASE("State: check_state names the first rule an incoming state breaks", "[state]") {
  CHECK(check_state(State{}) == nullptr);
  CHECK(check_state(distinct_state()) == nullptr);  // a negative unilateral energy is legal
  struct Case {
    void (*corrupt)(State&);
    const char* fragment;
  };
  const Case cases[] = {
      {[](State& s) { s.separation[1] = std::numeric_limits<double>::quiet_NaN(); }, "finite"},
      {[](State& s) { s.dissipation_plastic = std::numeric_limits<double>::infinity(); }, "finite"},
      {[](State& s) { s.dn = 1.5; }, "d_n (SDV 10)"},
      {[](State& s) { s.ds = -0.1; }, "d_s (SDV 11)"},
      {[](State& s) { s.wI = -1; }, "w_I (SDV 7)"},
      {[](State& s) { s.wII = -1; }, "w_II (SDV 8)"},
      {[](State& s) { s.wIII = -1; }, "w_III (SDV 9)"},
      {[](State& s) { s.dissipation_damage = -1; }, "(SDV 17)"},
  };
  for (const Case& c : cases) {
    State s;
    c.corrupt(s);
    const char* rule = check_state(s);
    REQUIRE(rule != nullptr);
    CAPTURE(rule);
    CHECK(std::string(rule).find(c.fragment) != std::string::npos);
  }
}
