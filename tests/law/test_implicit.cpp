// The implicit (backward Euler) return mapping, MODEL.md section 7.3, and its
// consistent tangent (docs/model.md 7.5):
//   - the consistent tangent against central differences of the whole stress
//     update (integrate_increment from a copied state, perturbed increment);
//   - the observed order on the smooth plastic path of test_convergence.cpp;
//   - the acceptance invariants of MODEL.md section 8 that apply, run with
//     the implicit scheme, at the tolerances it meets (stated per test).
#include <catch2/catch.hpp>

#include <cstdio>
#include <random>
#include <vector>

#include "mortar/return_mapping.hpp"
#include "mortar/surface.hpp"
#include "paper_sets.hpp"
#include "paths.hpp"
#include "random_parameters.hpp"

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

// The path of test_convergence.cpp: compress, shear with dilatancy and
// softening, then open while shearing; the end traction.
Vec3 end_traction(const Model& M, int n, int* newton = nullptr, int* plastic_increments = nullptr) {
  DisplacementDriver d(M);
  d.ramp(Vec3(-0.002, 0.0, 0), 1);
  d.ramp(Vec3(0.0, 0.02, 0.0), n);
  d.ramp(Vec3(0.003, 0.01, 0.0), n);
  REQUIRE(d.curve().all_ok);
  if (newton) {
    *newton = 0;
    *plastic_increments = 0;
    for (const Sample& s : d.curve().samples) {
      *newton += s.result.status.newton_iterations;
      if (s.result.status.newton_iterations > 0) ++*plastic_increments;
    }
  }
  return d.curve().samples.back().traction;
}

double loglog_slope(const std::vector<double>& x, const std::vector<double>& e) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    const double lx = std::log(x[i]), ly = std::log(e[i]);
    sx += lx; sy += ly; sxx += lx * lx; sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

TEST_CASE("Implicit: scheme 3 is read from props(15) and named", "[implicit]") {
  const Parameters p = almeida_m15();
  std::vector<double> props(15);
  for (int i = 0; i < 14; ++i) props[i] = parameter_at(p, i);
  props[14] = 3;
  Parameters q;
  Controls c;
  REQUIRE(read_props(props.data(), 15, q, c).ok());
  CHECK(c.scheme == Scheme::implicit);
  CHECK(std::string(scheme_name(Scheme::implicit)) == "backward-euler");
  props[14] = 4;
  const ValidationError e = read_props(props.data(), 15, q, c);
  CHECK_FALSE(e.ok());
  CHECK(e.index == 14);
}

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
    cases.push_back({"mixed: worn M34, sliding on", M34, worn, Vec3(2e-4, 2e-3, -1e-3)});
  }
  for (const Case& c : cases) {
    const TangentCheck t = check_tangent(c.M, c.start, c.d);
    CAPTURE(c.name, t.tangent, t.fd);
    REQUIRE(t.result.status.ok());
    CHECK(t.result.status.plastic);
    CHECK_FALSE(t.result.status.tangent_approximate);
    CHECK(t.error < 1e-6);
    std::printf("[tangent] %-46s rel. error %.2e  substeps %d/%d  Newton %d\n", c.name, t.error,
                t.result.status.substeps_accepted, t.result.status.substeps_rejected,
                t.result.status.newton_iterations);
  }
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

TEST_CASE("Implicit: observed order on a smooth plastic path is one", "[implicit][order]") {
  const Parameters p = van_der_pluijm(-0.5);
  // Reference as test_convergence.cpp: modified Euler at STOL 1e-11, 20000
  // increments per leg (error about 1e-12).
  const Vec3 ref = end_traction(model_with(p, Scheme::modified_euler, 1e-11), 20000);
  const Model M = implicit_model(p);
  std::vector<double> h, e;
  for (int n : {20, 40, 80, 160, 320}) {
    int newton = 0, plastic = 0;
    const Vec3 t = end_traction(M, n, &newton, &plastic);
    h.push_back(1.0 / n);
    e.push_back((t - ref).norm() / ref.norm());
    std::printf("[order] %4d increments per leg: rel. error %.3e, %.2f Newton iterations per plastic increment\n", n,
                e.back(), double(newton) / std::max(plastic, 1));
  }
  const double slope = loglog_slope(h, e);
  std::printf("[order] slope %.3f\n", slope);
  CAPTURE(e, slope);
  CHECK(slope > 0.85);
  CHECK(slope < 1.15);
}

// ---------------------------------------------------------------------------
// MODEL.md section 8 with the implicit scheme.

TEST_CASE("Implicit, invariant 1: elastic inside the surface, reversible, no dissipation", "[implicit][invariant1]") {
  for (const Parameters& p : {van_der_pluijm(-0.5), atkinson(), almeida_m15()}) {
    const Model M = implicit_model(p);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> un(-p.c0 / p.kn, p.ft0 / (3 * p.kn));
    std::uniform_real_distribution<double> us(-p.c0 / (3 * p.ks * 1.5), p.c0 / (3 * p.ks * 1.5));
    DisplacementDriver drive(M);
    for (int k = 0; k < 200; ++k) {
      const Vec3 target(un(rng), us(rng), us(rng));
      drive.step(target - drive.state().separation);
      const Sample& s = drive.curve().samples.back();
      CHECK_FALSE(s.result.status.plastic);
      CHECK(s.result.status.newton_iterations == 0);
      for (int i = 0; i < 3; ++i)
        CHECK(s.traction[i] == Approx((i == 0 ? p.kn : p.ks) * target[i]).epsilon(1e-12).margin(1e-15));
    }
    drive.step(-drive.state().separation);
    const State& s = drive.state();
    CHECK(drive.curve().samples.back().traction.norm() < 1e-14);
    CHECK(s.dissipation_plastic + s.dissipation_damage + s.energy_unilateral == 0);
  }
}

TEST_CASE("Implicit, invariant 2: pure opening peaks at ft0, dissipates GIC and ends separated", "[implicit][invariant2]") {
  const Parameters p = GENERATE(almeida_m15(), almeida_m34(), van_der_pluijm(-0.5), atkinson());
  CAPTURE(p.kn, p.ft0, p.GIC);
  const Model M = implicit_model(p);
  DisplacementDriver drive(M);
  // The increments of test_tension.cpp: 1e-5 mm, 1e-8 mm around the peak.
  const double elastic_limit = p.ft0 / p.kn, end = p.ft0 / p.kn + 15.0 * p.GIC / p.ft0;
  drive.ramp_to(Vec3(0.99 * elastic_limit, 0, 0), 100);
  drive.ramp_to(Vec3(1.01 * elastic_limit, 0, 0), static_cast<int>(0.02 * elastic_limit / 1e-8));
  drive.ramp_to(Vec3(end, 0, 0), static_cast<int>(end / 1e-5));
  const Curve& c = drive.curve();
  REQUIRE(c.all_ok);
  CHECK(c.max_traction(0) == Approx(p.ft0).epsilon(1e-3));
  const double area = c.external_work();
  std::printf("[invariant 2] GIC area rel. error %.2e (ft0 %.3g)\n", (area - p.GIC) / p.GIC, p.ft0);
  CHECK(area == Approx(p.GIC).epsilon(5e-3));
  CHECK(std::abs(c.samples.back().traction[0]) < 1e-5 * p.ft0);
  CHECK(drive.state().dn == Approx(1.0).margin(1e-5));
}

TEST_CASE("Implicit, invariants 3 and 4: secant unloading to delta_p, full kn when pressed shut", "[implicit][invariant3]") {
  const Parameters p = almeida_m15();
  const Model M = implicit_model(p);
  DisplacementDriver drive(M);
  drive.ramp(Vec3(0.004, 0, 0), 400);
  const State loaded = drive.state();
  const double sigma0 = drive.curve().samples.back().traction[0];
  REQUIRE(sigma0 < 0.9 * p.ft0);
  REQUIRE(sigma0 > 0.2 * p.ft0);
  const double back = 0.5 * (loaded.separation[0] - loaded.plastic[0]);
  drive.ramp(Vec3(-back, 0, 0), 50);
  const double sigma1 = drive.curve().samples.back().traction[0];
  const double slope = (sigma0 - sigma1) / back;
  CHECK(slope == Approx(p.kn * (1 - loaded.dn)).epsilon(1e-10));
  CHECK(drive.state().plastic == loaded.plastic);
  CHECK(loaded.separation[0] - sigma0 / slope == Approx(loaded.plastic[0]).epsilon(1e-10));
  const double delta_in = loaded.plastic[0] + loaded.crack[0];
  CHECK(loaded.plastic[0] == Approx(delta_in / (1 + p.bn)).epsilon(1e-12));
  CHECK(loaded.dn == Approx(p.bn * loaded.plastic[0] / (loaded.separation[0] - loaded.plastic[0])).epsilon(1e-6));
  // Invariant 4: close past delta_p in one increment, then a little further.
  const double dp = drive.state().plastic[0];
  drive.step(Vec3(dp - drive.state().separation[0] - 1e-4, 0, 0));
  const double s1 = drive.curve().samples.back().traction[0];
  drive.step(Vec3(-1e-4, 0, 0));
  const double s2 = drive.curve().samples.back().traction[0];
  CHECK(s1 == Approx(-p.kn * 1e-4).epsilon(1e-9));
  CHECK((s1 - s2) / 1e-4 == Approx(p.kn).epsilon(1e-9));
}

TEST_CASE("Implicit, invariants 5 and 6: shear peak at constant compression, isotropy", "[implicit][invariant5]") {
  const double sigma_n = GENERATE(-0.1, -0.5, -1.0);
  const Parameters p = van_der_pluijm(sigma_n);
  const Model M = implicit_model(p);
  const double t = std::tan(p.phi0 * M_PI / 180);
  const double beta = 0.5 * (p.c0 * p.c0 / (p.ft0 * t) + p.ft0 * t);
  const double alpha = 0.5 * (p.c0 * p.c0 / (p.ft0 * t) - p.ft0 * t);
  const double peak = std::sqrt(std::pow(beta - sigma_n * t, 2) - alpha * alpha);
  const Curve c = shear_at_constant_normal(M, sigma_n, 1.02 * peak / p.ks, 5000);
  REQUIRE(c.all_ok);
  double max_tau = 0;
  for (const Sample& s : c.samples) max_tau = std::max(max_tau, shear_norm(s.traction));
  CHECK(max_tau == Approx(peak).epsilon(1e-3));
  if (sigma_n == -0.5) {
    const Curve ref = shear_at_constant_normal(M, sigma_n, 0.1, 500, 0.0);
    for (double angle_deg : {30.0, 135.0, 250.0}) {
      const Curve d = shear_at_constant_normal(M, sigma_n, 0.1, 500, angle_deg * M_PI / 180);
      double worst = 0;
      for (size_t i = 0; i < d.samples.size(); ++i)
        worst = std::max(worst, std::abs(shear_norm(d.samples[i].traction) - shear_norm(ref.samples[i].traction)));
      CAPTURE(angle_deg);
      CHECK(worst < 1e-9);
    }
  }
}

TEST_CASE("Implicit, invariant 7: energy closure", "[implicit][invariant7]") {
  // Backward Euler is first order; the closure error falls with the
  // increment. Stated tolerance: 1e-4 at the increments below.
  auto closure = [](const Model& M, const Curve& c) {
    const double W = c.external_work();
    return std::abs(W - c.stored_plus_dissipated(M)) / std::abs(W);
  };
  {
    const Model M = implicit_model(van_der_pluijm(-0.5));
    const Curve c = shear_at_constant_normal(M, -0.5, 0.1, 5000);
    REQUIRE(c.all_ok);
    std::printf("[invariant 7] shear at constant compression: closure %.2e\n", closure(M, c));
    CHECK(closure(M, c) < 1e-4);
  }
  {
    const Model M = implicit_model(almeida_m15());
    DisplacementDriver drive(M);
    drive.ramp(Vec3(0.006, 0, 0), 3000);
    drive.ramp(Vec3(-0.004, 0, 0), 500);
    drive.ramp(Vec3(0.02, 0, 0), 5000);
    REQUIRE(drive.curve().all_ok);
    std::printf("[invariant 7] opening, closing, reopening: closure %.2e\n", closure(M, drive.curve()));
    CHECK(closure(M, drive.curve()) < 1e-4);
  }
  {
    const Model M = implicit_model(almeida_m34());
    DisplacementDriver drive(M);
    drive.ramp(Vec3(0.002, 0.004, 0), 2000);
    drive.ramp(Vec3(0.0, 0.01, 0.005), 2000);
    drive.ramp(Vec3(-0.004, 0, 0), 2000);
    drive.ramp(Vec3(0, -0.03, 0), 3000);
    REQUIRE(drive.curve().all_ok);
    std::printf("[invariant 7] opening, sliding, closing: closure %.2e\n", closure(M, drive.curve()));
    CHECK(closure(M, drive.curve()) < 1e-4);
  }
}

namespace {
using mj_test::log_uniform;
using mj_test::uniform;
// The generators of test_robustness.cpp (tests/support/random_parameters.hpp),
// with their own seed.
Parameters random_parameters(std::mt19937& rng) {
  const Parameters p = mj_test::random_parameters(rng);
  REQUIRE(validate(p).ok());
  return p;
}
Vec3 random_increment(std::mt19937& rng, const Parameters& p, int family) {
  const double un = p.ft0 / p.kn, us = p.c0 / p.ks;
  switch (family) {
    case 0: return Vec3(uniform(rng, -3, 3.2) * un, uniform(rng, -0.1, 0.1) * us, 0);
    case 1: return Vec3(uniform(rng, -0.2, 0.2) * un, uniform(rng, -4, 4) * us, uniform(rng, -1, 1) * us);
    case 2: return Vec3(uniform(rng, -40, 40) * un, uniform(rng, -10, 10) * us, uniform(rng, -10, 10) * us);
    default:
      return Vec3(log_uniform(rng, 1e-12, 10) * (uniform(rng, 0, 1) < 0.5 ? -1 : 1),
                  log_uniform(rng, 1e-12, 10) * (uniform(rng, 0, 1) < 0.5 ? -1 : 1),
                  uniform(rng, 0, 1) < 0.5 ? 0.0 : log_uniform(rng, 1e-12, 1));
  }
}
struct Tally {
  int increments = 0, plastic = 0, failures = 0, off_surface = 0, approximate = 0, max_newton = 0;
  long newton = 0, rejected = 0;
  int failures_by_family[4] = {0, 0, 0, 0};
};
void run_path(const Model& M, std::mt19937& rng, int family, State start, Tally& t) {
  State s = start;
  for (int k = 0; k < 60; ++k) {
    const State before = s;
    Mat3 T;
    const IncrementResult r = integrate_increment(M, s, random_increment(rng, M.p, family), &T);
    ++t.increments;
    if (r.status.plastic) ++t.plastic;
    t.newton += r.status.newton_iterations;
    t.max_newton = std::max(t.max_newton, r.status.newton_iterations);
    t.rejected += r.status.substeps_rejected;
    if (r.status.tangent_approximate) ++t.approximate;
    if (!r.status.ok()) {
      ++t.failures;
      ++t.failures_by_family[family];
      // A failure is reported and keeps the start state (the solver cuts back).
      const bool exhausted = r.status.failure == Failure::local_solve_failed ||
                             r.status.failure == Failure::too_many_substeps;
      CHECK(exhausted);
      CHECK(s.plastic == before.plastic);
      CHECK(s.separation == before.separation);
    }
    REQUIRE(r.traction.allFinite());
    REQUIRE(T.allFinite());
    REQUIRE(std::isfinite(r.elastic_energy));
    REQUIRE(check_state(s) == nullptr);
    CHECK(s.dn >= before.dn);
    CHECK(s.ds >= before.ds);
    CHECK(s.wI >= before.wI);
    const double F = yield_function(r.traction, surface_of(M, s));
    if (r.status.ok() && F > 10 * yield_tolerance(M, r.traction)) {
      ++t.off_surface;
      if (t.off_surface <= 3)
        std::printf("[invariant 10] off the surface: family %d, F = %.3g, tol = %.3g, sigma = (%.3g, %.3g, %.3g), s = %.3g, open %d\n",
                    family, F, yield_tolerance(M, r.traction), r.traction[0], r.traction[1], r.traction[2],
                    surface_of(M, s).s, int(s.open));
    }
  }
}
}  // namespace

TEST_CASE("Implicit, invariant 10: random parameters and paths never give NaN, failure or hang",
          "[implicit][invariant10]") {
  // 100 sets (the explicit test runs 200): the extreme families cost the
  // implicit scheme many Newton iterations (docs/model.md 7.5).
  std::mt19937 rng(20261123);
  Tally t;
  for (int set = 0; set < 100; ++set) {
    const Parameters p = random_parameters(rng);
    const Model M = implicit_model(p);
    CAPTURE(set, p.kn, p.ks, p.ft0, p.c0, p.GIC, p.GIIC, p.phi0, p.phir, p.m, p.psi0, p.psir, p.n, p.bn, p.bs);
    for (int family = 0; family < 4; ++family) run_path(M, rng, family, State{}, t);
    // Fully softened joint. One increment is not enough here: backward Euler
    // decays the strength as 1/(1 + x) per step, not exp(-x) (x = ft0
    // delta_in / GIC), so the opening of test_robustness.cpp is cut in 100.
    State softened;
    for (int i = 0; i < 100; ++i) integrate_increment(M, softened, Vec3(2 * p.ft0 / p.kn + 200 * p.GIC / p.ft0, 0, 0) / 100);
    REQUIRE(softened.dn == Approx(1.0).margin(1e-6));
    for (int family = 0; family < 4; ++family) run_path(M, rng, family, softened, t);
  }
  std::printf("[invariant 10] %d increments, %d plastic, %d failures (by family %d %d %d %d), %d off the surface, "
              "%d approximate tangents, %.1f Newton iterations per plastic increment (max %d), %ld halvings\n",
              t.increments, t.plastic, t.failures, t.failures_by_family[0], t.failures_by_family[1],
              t.failures_by_family[2], t.failures_by_family[3], t.off_surface, t.approximate,
              double(t.newton) / std::max(t.plastic, 1), t.max_newton, t.rejected);
  CAPTURE(t.increments, t.failures, t.off_surface);
  // Stated tolerance (docs/model.md 7.5): no failure on the moderate families
  // (opening-closing, shear reversals: increments up to a few elastic
  // limits); on the extreme ones (jumps of 10-40 elastic limits across the
  // apex, and increments from 1e-12 to 10 mm, up to 1e5 elastic limits) the
  // local solve may fail at the smallest substep for a few in 1e4
  // increments, reported as Failure::local_solve_failed or, once,
  // too_many_substeps (34 of 96000 over 200 sets when measured); the explicit schemes have
  // none there.
  // Every converged increment ends on or inside the surface (within 10 FTOL):
  // 131 of 48 000 did not before plastic_implicit() halved the open steps
  // whose secant damage would have decreased (docs/robustness.md, defect 11).
  CHECK(t.off_surface == 0);
  CHECK(t.failures_by_family[0] == 0);
  CHECK(t.failures_by_family[1] == 0);
  CHECK(t.failures <= t.increments / 1000);
}
