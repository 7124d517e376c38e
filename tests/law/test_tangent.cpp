// The implicit (backward Euler) scheme's consistent tangent (docs/model.md
// 7.5), the derivative of its stress update: against central differences of
// the whole update (integrate_increment from a copied state, perturbed
// increment), the secant on elastic increments, and the flag where it is not
// exact. Its observed order is in test_convergence.cpp; the invariants of
// docs/model.md 10 run it with the other schemes. The explicit schemes'
// continuum tangent (Eq. 20) against the rate statement it linearises.
#include <catch2/catch.hpp>

#include <vector>

#include "mortar/integration/rate_statement.hpp"
#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"
#include "mortar/physics/elasticity.hpp"
#include "mortar/physics/yield_surface.hpp"
#include "paper_sets.hpp"
#include "formatted.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {

Model implicit_model(const Parameters& p) { return model_with(p, Scheme::implicit); }

// The consistent tangent of one increment and its central-difference check:
// relative Frobenius error of T against the differences of the traction of
// integrate_increment from copies of the start state.
struct TangentCheck {
  Mat3 tangent, fd;
  IncrementResult result;
  double error = 0;
};
TangentCheck check_tangent(const Model& M, const State& start, const Vec3& d, double rel_step = 1e-6) {
  TangentCheck c;
  State s = start;
  c.result = integrate_increment(M, s, d, &c.tangent);
  const double h = rel_step * d.norm();
  for (int j = 0; j < 3; ++j) {
    Vec3 dp = d, dm = d;
    dp[j] += h;
    dm[j] -= h;
    State a = start, b = start;
    c.fd.col(j) = (integrate_increment(M, a, dp).traction - integrate_increment(M, b, dm).traction) / (2 * h);
  }
  c.error = (c.tangent - c.fd).norm() / c.tangent.norm();
  return c;
}

}  // namespace

TEST_CASE("Implicit: the consistent tangent matches central differences of the stress update", "[implicit][tangent]") {
  struct Case {
    const char* name;
    Model M;
    State start;
    Vec3 d;
  };
  std::vector<Case> cases;
  {
    // Closed regime, shear at compression (the main Abaqus/Standard use):
    // on the softening branch, and from inside the surface in one large
    // increment (the elastic-plastic intersection moves with the increment).
    const Model M = implicit_model(van_der_pluijm(-0.5));
    State compressed;
    integrate_increment(M, compressed, Vec3(-0.5 / M.p.kn, 0, 0));
    State softening = compressed;
    for (int i = 0; i < 10; ++i) integrate_increment(M, softening, Vec3(0, 0.002, 0));
    REQUIRE(surface_of(M, softening).s < 0.9);
    cases.push_back({"closed: shear at compression, softening", M, softening, Vec3(-1e-4, 2e-3, 5e-4)});
    cases.push_back({"closed: elastic to plastic in one increment", M, compressed, Vec3(-1e-4, 2e-2, 5e-3)});
    cases.push_back({"closed: 2D slip reversal beyond the surface", M, softening, Vec3(-2e-5, -0.03, 0)});
  }
  {
    // Open regime, tension softening (both damages from the secant rule):
    // from a softened state, and from the bonded state through the peak.
    const Model M = implicit_model(almeida_m15());
    State open;
    integrate_increment(M, open, Vec3(0.004, 0, 0));
    REQUIRE(open.dn > 0.3);
    cases.push_back({"open: tension softening", M, open, Vec3(1e-3, 0, 0)});
    cases.push_back({"open: bonded through the peak", M, State{}, Vec3(0.004, 0, 0)});
    // Mixed: opening and sliding together.
    cases.push_back({"mixed: softened, opening and sliding", M, open, Vec3(1e-3, 2e-4, 1e-4)});
    cases.push_back({"mixed: bonded, opening and sliding", M, State{}, Vec3(0.002, 0.004, 0.001)});
    const Model M34 = implicit_model(almeida_m34());
    State worn;
    integrate_increment(M34, worn, Vec3(0.001, 0.003, 0));
    cases.push_back({"mixed: worn M34, sliding on", M34, worn, Vec3(1e-4, 1e-3, -5e-4)});
  }
  int substepped = 0;
  for (const Case& c : cases) {
    const TangentCheck t = check_tangent(c.M, c.start, c.d);
    CAPTURE(c.name, t.tangent, t.fd, t.result.status.substeps_accepted);
    REQUIRE(t.result.status.ok());
    CHECK(t.result.status.plastic);
    CHECK_FALSE(t.result.status.tangent_approximate);
    CHECK(t.error < 1e-6);
    substepped += t.result.status.substeps_accepted > 1;
  }
  // The error control cuts most of these increments into substeps: the
  // tangent checked is that of the composed map (docs/model.md 7.5).
  CHECK(substepped >= 6);
}

TEST_CASE("Implicit: a substep that lands on complete normal damage flags the tangent", "[implicit][tangent]") {
  // Where the landing substep ends depends on the increment (the bracket of
  // the substepper); the tangent holds it fixed and says so.
  const Model M34 = implicit_model(almeida_m34());
  State worn;
  integrate_increment(M34, worn, Vec3(0.001, 0.003, 0));
  REQUIRE(worn.dn < 1);
  Mat3 T;
  const IncrementResult r = integrate_increment(M34, worn, Vec3(2e-4, 2e-3, -1e-3), &T);
  REQUIRE(r.status.ok());
  CHECK(worn.dn == 1);
  CHECK(r.status.tangent_approximate);
  CHECK(T.allFinite());
}

TEST_CASE("Implicit: the tangent of an elastic increment is the secant stiffness", "[implicit][tangent]") {
  const Model M = implicit_model(almeida_m15());
  State s;
  integrate_increment(M, s, Vec3(0.004, 0.0005, 0));  // damaged, open
  const double dp = s.plastic[0];
  Mat3 T;
  State a = s;
  // Unloading on the secant, still open.
  integrate_increment(M, a, Vec3(-0.3 * (s.separation[0] - dp), 0, 0), &T);
  const Vec3 K = secant_stiffness(M, a.dn, a.ds, true);
  CHECK((T - Mat3(K.asDiagonal())).norm() <= 1e-12 * K.norm());
  // Zero increment (what UINTER's linear perturbation asks for).
  State b = s;
  integrate_increment(M, b, Vec3::Zero(), &T);
  CHECK((T - Mat3(secant_stiffness(M, s.dn, s.ds, s.open).asDiagonal())).norm() <= 1e-12 * K.norm());
}

TEST_CASE("Implicit: a tangent across a regime switch with plastic flow is flagged approximate", "[implicit][tangent]") {
  // Excluded from the finite-difference check: where the increment switches
  // regime after plastic flow (or returns at fixed separation), the switch
  // point is held fixed, and a one-sided difference sees the kink of the
  // stiffness jump. The tangent is still finite and flagged.
  const Model M = implicit_model(almeida_m34());
  State s;
  integrate_increment(M, s, Vec3(0.002, 0.004, 0));
  Mat3 T;
  const IncrementResult r = integrate_increment(M, s, Vec3(-0.004, 0.004, 0), &T);
  REQUIRE(r.status.ok());
  CHECK(r.status.regime_switches > 0);
  CHECK(r.status.tangent_approximate);
  CHECK(T.allFinite());
}

TEST_CASE("Explicit: the continuum tangent after closing an open joint unloads the closing on the normal secant",
          "[tangent][closing]") {
  // An open, damaged, softening joint closed against its elastic opening
  // while it slides (docs/model.md 6, Decision - closing on the tension cap):
  // the rate statement takes the closing on kn (1 - dn) (rate_stiffness_over),
  // and the continuum tangent after such an increment must be the derivative
  // of that rate statement for increments in the same direction.
  for (const Scheme scheme : {Scheme::modified_euler, Scheme::forward_euler}) {
    const Model M = model_with(almeida_m15(), scheme);
    State start;
    integrate_increment(M, start, Vec3(0.004, 0, 0));
    integrate_increment(M, start, Vec3(0, 2e-3, 0));
    for (const Vec3& d : {Vec3(-5e-5, 2e-4, 0), Vec3(-5e-5, 2e-4, 1e-4)}) {
      State s = start;
      Mat3 T;
      const IncrementResult r = integrate_increment(M, s, d, &T);
      CAPTURE(scheme_name(scheme), d.transpose());
      REQUIRE(r.status.ok());
      REQUIRE(r.status.plastic);
      REQUIRE(r.status.regime_switches == 0);
      REQUIRE(s.open);
      REQUIRE(s.elastic_separation()[0] > 0);
      REQUIRE(s.dn > 0.5);
      CHECK(r.status.tangent_approximate);
      const Point P{s, r.traction};
      const Vec3 u = d.normalized();
      REQUIRE(stage(M, P, u).plastic);
      REQUIRE((stage(M, P, u).grow.normal && stage(M, P, u).grow.shear));
      // The rate statement is homogeneous of degree 1 in the increment and
      // linear inside the cone of closing increments on these branches:
      // central differences about the increment's direction give its matrix.
      Mat3 R;
      const double eps = 1e-3;
      for (int j = 0; j < 3; ++j) {
        Vec3 up = u, um = u;
        up[j] += eps;
        um[j] -= eps;
        R.col(j) = (stage(M, P, up).dsigma - stage(M, P, um).dsigma) / (2 * eps);
      }
      // The continuum tangent of the same point for an opening increment takes
      // the separation on kn: on closing, its normal column scales by (1 - dn),
      // the shear columns stay.
      Vec3 opening = d;
      opening[0] = -d[0];
      const Mat3 T_open = continuum_tangent(M, s, r.traction, opening);
      // The whole update continued a little further in the same direction.
      const double h = 1e-8;
      State c = s;
      const Vec3 rate = (integrate_increment(M, c, h * u).traction - r.traction) / h;
      const double rate_error = (T * u - rate).norm() / rate.norm();
      const double matrix_error = (T - R).norm() / R.norm();
      CAPTURE(T, R, T_open, rate.transpose(), (T * u).transpose());
      INFO(mj_test::formatted(
          "[tangent] closing, %s, d = (%g, %g, %g): T_nn %.6g (rate statement %.6g, opening %.6g), "
          "|T - R|/|R| %.2e, |T u - rate|/|rate| %.2e",
          scheme_name(scheme), d[0], d[1], d[2], T(0, 0), R(0, 0), T_open(0, 0), matrix_error, rate_error));
      CHECK(matrix_error < 1e-8);
      CHECK(rate_error < 1e-4);
      CHECK((T.col(0) - (1 - s.dn) * T_open.col(0)).norm() <= 1e-12 * T_open.norm());
      CHECK((T.rightCols<2>() - T_open.rightCols<2>()).norm() <= 1e-12 * T_open.norm());
    }
  }
}

TEST_CASE("Implicit: the consistent tangent through the cap and the corner matches central differences",
          "[implicit][tangent][cap]") {
  // van der Pluijm's set (sigma_n = -0.5 MPa) with a cap of fc = 12 MPa, Cs =
  // 9, Gfc = 5 N/mm, kappa_p = 0.05 mm (docs/model.md 12): the cap's step
  // (its Newton on sigma, lc) and the corner's (sigma, w, l1, lc)
  // differentiated at their solutions, the intersection on the cap. GIIC
  // ten times Table 1's: with 0.058 N/mm, sliding at fixed opening from
  // sigma_n = -1.7 MPa or below, Eq. 2 alone snaps back on reaching it (with
  // or without a cap), the point drops at fixed separation and the tangent
  // is flagged approximate.
  Controls ctl;
  ctl.scheme = Scheme::implicit;
  Parameters p = van_der_pluijm(-0.5);
  p.GIIC = 0.58;
  const Model M = make_model_checked(p, ctl, CompressionCap{12.0, 9.0, 5.0, 0.05});
  State pressed;  // sigma_n = -2.5 MPa: inside the initial cap, fc/3 = 4
  integrate_increment(M, pressed, Vec3(-2.5 / M.p.kn, 0, 0));
  State crushed = pressed;  // past the peak
  while (crushed.kappa_c < 0.06) integrate_increment(M, crushed, Vec3(-0.005, 0, 0));
  State sliding = pressed;  // on the cap, the hyperbola not yet met
  for (int i = 0; i < 15; ++i) integrate_increment(M, sliding, Vec3(0, 1e-3, 0));
  REQUIRE(sliding.kappa_c > 0);
  REQUIRE(sliding.wII == 0);
  State corner = sliding;  // the first increment on which Eq. 2 flows too
  State before = corner;
  while (corner.wII == 0) {
    before = corner;
    integrate_increment(M, corner, Vec3(0, 1e-4, 0));
  }
  struct Case {
    const char* name;
    State start;
    Vec3 d;
    bool crushes, slides;  // kappa_c grows; Eq. 2 flows (wII grows)
  };
  const std::vector<Case> cases = {
      {"elastic to the cap in one increment, crushing", pressed, Vec3(-8e-3, 0, 0), true, false},
      {"crushing past the peak", crushed, Vec3(-2e-3, 0, 0), true, false},
      {"sliding along the cap", sliding, Vec3(-1e-5, 1e-3, 2e-4), true, false},
      {"onto the corner", before, Vec3(0, 2e-4, 0), true, true},
  };
  for (const Case& c : cases) {
    const TangentCheck t = check_tangent(M, c.start, c.d);
    State end = c.start;
    integrate_increment(M, end, c.d);
    CAPTURE(c.name, t.tangent, t.fd, t.result.status.substeps_accepted, t.result.status.relaxations, t.result.status.fallback_pieces, t.result.status.regime_switches, t.error, end.kappa_c - c.start.kappa_c,
            end.wII - c.start.wII);
    REQUIRE(t.result.status.ok());
    CHECK((end.kappa_c > c.start.kappa_c) == c.crushes);
    CHECK((end.wII > c.start.wII) == c.slides);
    CHECK_FALSE(t.result.status.tangent_approximate);
    CHECK(t.error < 1e-6);
  }
}
