// docs/model.md 9: when the chosen scheme fails on an integrable point, the
// increment is integrated again from its unchanged start state by the
// fallback chain, and the result says so. The first attempt is forced to
// fail by a substep budget (Controls::max_substeps) too small for it, and
// met where backward Euler's local solve fails.
#include <catch2/catch.hpp>

#include <cmath>

#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"
#include "paper_sets.hpp"
#include "schemes.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {

// Compressed, then a large slip increment: softening with dilatancy, many
// substeps in one increment.
State pressed(const Model& M) {
  State s;
  integrate_increment(M, s, Vec3(-0.5 / M.p.kn, 0, 0));
  return s;
}
const Vec3 kSlip(0, 0.05, 0.02);

// The increment d from s cut into `pieces` equal calls of R, the reference a
// fallback is measured against; s ends where the last call leaves it.
IncrementResult cut_into(const Model& R, State& s, const Vec3& d, int pieces) {
  IncrementResult r;
  for (int i = 0; i < pieces; ++i) r = integrate_increment(R, s, d / pieces);
  REQUIRE(r.status.ok());
  return r;
}

// The slip increment cut into 2000 equal pieces, modified Euler at STOL 1e-8.
Vec3 reference_traction(const Parameters& p, State s) {
  return cut_into(model_with(p, Scheme::modified_euler, 1e-8), s, kSlip, 2000).traction;
}

}  // namespace

// Modified Euler, whose substep count grows with the increment (forward and
// backward Euler take one substep for this plastic part).
TEST_CASE("Fallback: an increment beyond the substep budget is integrated by the fallback chain, flagged",
          "[fallback]") {
  SchemeUnderTest S = modified_euler_under_test();
  const Parameters p = almeida_m15();
  // The substeps the chosen scheme needs with the default budget; half of
  // that budget makes it fail.
  State s = pressed(model_with(p, S.scheme));
  const State start = s;
  const IncrementResult free_run = integrate_increment(model_with(p, S.scheme), s, kSlip);
  REQUIRE(free_run.status.ok());
  REQUIRE_FALSE(free_run.status.fell_back());
  const int needed = free_run.status.substeps_accepted + free_run.status.substeps_rejected;
  CAPTURE(needed);
  REQUIRE(needed >= 16);

  Model tight = model_with(p, S.scheme);
  tight.controls.max_substeps = needed / 2;
  s = start;
  Mat3 T;
  const IncrementResult r = integrate_increment(tight, s, kSlip, &T);
  CHECK(r.status.ok());
  CHECK(r.status.fell_back());
  CHECK(r.status.first_failure == Failure::too_many_substeps);
  CHECK(r.status.fallback_pieces >= 8);
  CHECK(r.status.tangent_approximate);
  CHECK(T.allFinite());
  CHECK(s.status == 0);
  // Flagged beside SDV 21 (docs/model.md 9): the rung's bit, in the
  // increment's status and OR'd into the state.
  const int rung = r.status.fallback_pieces == 8    ? integration_flag::fallback_rung_1
                   : r.status.fallback_pieces == 64 ? integration_flag::fallback_rung_2
                                                    : integration_flag::fallback_rung_3;
  CHECK((r.status.flags & rung) != 0);
  CHECK((s.integration_flags & rung) != 0);
  CHECK((s.integration_flags & ~r.status.flags) == 0);
  CHECK(check_state(s) == nullptr);
  CHECK(s.separation == start.separation + kSlip);
  // The fallback's answer is the law's: within the rung's accuracy of the
  // finely cut reference (modified Euler at STOL 1e-5 over 8 pieces, or
  // forward Euler over 1024).
  const Vec3 ref = reference_traction(p, start);
  CAPTURE(r.traction.transpose(), ref.transpose());
  CHECK((r.traction - ref).norm() <= 1e-3 * ref.norm());
  CHECK(r.elastic_energy > 0);
  CHECK(std::isfinite(r.d_dissipation_plastic + r.d_dissipation_damage + r.d_energy_unilateral));
}

TEST_CASE("Fallback: an extreme increment on which backward Euler's local solve fails is integrated, flagged",
          "[fallback]") {
  // Invariant 10's first failure of the implicit scheme (a fully softened
  // joint, an increment of hundreds of elastic limits): the Newton solve
  // fails at the smallest substep.
  const double props[14] = {340.67201361795071, 135.85809961516628, 0.073897985419679693, 0.16798947691995109, 0.019287844983704474, 0.44459805200810676, 32.080103938003873, 23.943985213075255, 84.830862903058645, 29.700664327644393, 21.659485199208596, 425.50811537277986, 2.7990073298038483, 2.5364878655267362};
  const double state[21] = {2.2135690715098146, 0.23973654509557663, 9.3153385931521042e-05, 6.1957960561830676, 0.60808883755823406, 0.00023628243304803218, 0.0071643571024048612, 0.2794544526496483, 0.061197542065267369, 1, 0.99999999984584864, 8.0524814152214397, 4.8378386553152275, 0.00048277866360746515, 1, -2.0004161804551193, 1.4674835489632196, 0, 1, 0, 0};
  const Vec3 d(9.6337885879381907e-12, 1.8266813500998373, 1.632056986027571e-05);
  Parameters p;
  Controls c;
  REQUIRE(read_props(props, 14, p, c).ok());
  c.scheme = Scheme::implicit;
  const Model M = make_model(p, c);
  State start;
  load_state(state, start);
  State s = start;
  Mat3 T;
  const IncrementResult r = integrate_increment(M, s, d, &T);
  CHECK(r.status.ok());
  CHECK(r.status.fell_back());
  CHECK(r.status.first_failure == Failure::local_solve_failed);
  CHECK(r.status.tangent_approximate);
  CHECK(T.allFinite());
  CHECK(s.status == 0);
  CHECK(s.separation == start.separation + d);
  // Against the increment cut into 2000 pieces, modified Euler at STOL 1e-8.
  const Model R = model_with(p, Scheme::modified_euler, 1e-8);
  State fine = start;
  const IncrementResult q = cut_into(R, fine, d, 2000);
  CAPTURE(r.traction.transpose(), q.traction.transpose(), s.dn, fine.dn);
  CHECK((r.traction - q.traction).norm() <= 1e-3 * std::max(q.traction.norm(), p.ft0));
  CHECK(std::abs(s.dn - fine.dn) <= 1e-6);
}

TEST_CASE("Fallback: a worn open joint at d ~ 1 and s ~ 1e-4 is integrated and agrees with forward Euler over "
          "16384 pieces",
          "[fallback]") {
  // From the property tests' worn family. Modified Euler once ran out of
  // substeps here over the whole increment and over 8 and 64 pieces, and the
  // chain's last rung (forward Euler over 1024 pieces) integrated it; with the
  // branch choice of docs/model.md 6 the scheme integrates it itself. Either
  // way the answer must be the finely cut one.
  const double props[14] = {662.47704927347479, 436.85981980617862, 0.50485108664701195, 0.69842634155911254, 0.00091145538989339365, 0.0036644609965412744, 30.611840279452011, 20.78262651301112, 0, 12.445535119497462, 1.9837604589664393, 2415.3361234788631, 13.477914917002609, 2.887080119386972};
  const double state[21] = {0.00097067482063328749, 0.0025472912132265017, 0, 0.01308267264457035, 0.0073542338199952687, 0, 0.00010643607484104201, 0.0032324593502411898, 0.00060660229719922837, 0.99989360153755191, 0.9999999999992778, 0.0089466030476240445, 0.0027216152024154205, 0, 1, 0.0011630364690219507, 0.00010282332649628231, 0, 17, 2, 0};
  const Vec3 d(0.00026327096802570052, -0.012802235746458876, 0);
  Parameters p;
  Controls c;
  REQUIRE(read_props(props, 14, p, c).ok());
  State start;
  load_state(state, start);
  State s = start;
  const IncrementResult r = integrate_increment(make_model(p, c), s, d);
  CHECK(r.status.ok());
  CHECK(s.status == 0);
  CHECK(check_state(s) == nullptr);
  // Against forward Euler over 16 384 pieces (first order: its own error is
  // about 1/16 of the 1024-piece rung's).
  const Model R = model_with(p, Scheme::forward_euler);
  State fine = start;
  const IncrementResult q = cut_into(R, fine, d, 16384);
  CAPTURE(r.traction.transpose(), q.traction.transpose(), s.dn, fine.dn);
  CHECK((r.traction - q.traction).norm() <= 1e-2 * std::max(q.traction.norm(), p.ft0));
}

TEST_CASE("Fallback: bad input is refused as it came, without a fallback", "[fallback]") {
  const Model M = model_with(almeida_m15(), Scheme::modified_euler);
  State s;
  s.dn = 2;  // breaks a rule
  const IncrementResult r = integrate_increment(M, s, Vec3(1e-3, 0, 0));
  CHECK(r.status.failure == Failure::invalid_state);
  CHECK_FALSE(r.status.fell_back());
  State t;
  const IncrementResult q = integrate_increment(M, t, Vec3(std::nan(""), 0, 0));
  CHECK(q.status.failure == Failure::non_finite_increment);
  CHECK_FALSE(q.status.fell_back());
}

TEST_CASE("Fallback: an increment the chosen scheme integrates is not touched by it", "[fallback]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  const Model M = model_with(almeida_m15(), S.scheme);
  State s = pressed(M);
  const IncrementResult r = integrate_increment(M, s, kSlip);
  CHECK(r.status.ok());
  CHECK_FALSE(r.status.fell_back());
  CHECK(r.status.fallback_pieces == 0);
  CHECK(r.status.first_failure == Failure::none);
}
