// The yield surface, its gradient, the flow direction and the hardening term
// of the consistency condition, against finite differences and closed forms.
#include <catch2/catch.hpp>

#include <random>

#include "mortar/physics/elasticity.hpp"
#include "mortar/physics/yield_surface.hpp"
#include "paper_sets.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {
Vec3 kbar_of(const Model& M) { return Vec3(M.p.kn, M.p.ks, M.p.ks); }
}  // namespace

TEST_CASE("Surface: dF/dsigma matches central differences", "[surface]") {
  const Model M = make_model_checked(van_der_pluijm(-0.5));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.5, 0.6), w(0, 1);
  for (int k = 0; k < 200; ++k) {
    const Surface S = surface_of(M, 0.3 * M.p.GIC * w(rng), 0.3 * M.p.GIIC * w(rng), 1e-4 * w(rng));
    const Vec3 sigma(u(rng), u(rng), u(rng));
    const Vec3 dF = flow_of(M, sigma, S, kbar_of(M)).dF;
    for (int i = 0; i < 3; ++i) {
      const double h = 1e-6;
      Vec3 a = sigma, b = sigma;
      a[i] += h;
      b[i] -= h;
      const double fd = (yield_function(a, S) - yield_function(b, S)) / (2 * h);
      CHECK(dF[i] == Approx(fd).margin(1e-7));
    }
  }
}

TEST_CASE("Surface: the hardening term is dF/dkappa along the flow", "[surface]") {
  // hardening = d F(sigma, kappa(lambda)) / d lambda at fixed sigma, with
  // kappa = (wI, wII, wIII) growing by (gI, gII, gIII) per unit lambda.
  for (const Parameters& p : {van_der_pluijm(-0.1), almeida_m15(), atkinson()}) {
    const Model M = make_model_checked(p);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0), w(0, 1);
    for (int k = 0; k < 100; ++k) {
      const double wI = 0.4 * p.GIC * w(rng), wII = 0.4 * p.GIIC * w(rng), wIII = 2e-3 * w(rng);
      const Vec3 sigma(p.ft0 * u(rng), p.c0 * u(rng), p.c0 * u(rng));
      const Surface S = surface_of(M, wI, wII, wIII);
      const Flow f = flow_of(M, sigma, S, kbar_of(M));
      const double h = 1e-7;
      auto F_at = [&](double l) {
        return yield_function(sigma, surface_of(M, wI + l * f.gI, wII + l * f.gII, wIII + l * f.gIII));
      };
      const double fd = (F_at(h) - F_at(-h)) / (2 * h);
      CAPTURE(sigma, wI, wII, wIII);
      CHECK(f.hardening == Approx(fd).epsilon(1e-5).margin(1e-6));
    }
  }
}

TEST_CASE("Surface: peak shear strength and residual of section 4", "[surface]") {
  const Model M = make_model_checked(van_der_pluijm(-0.5));
  const Surface S = surface_of(M, 0, 0, 0);
  for (double sn : {-0.1, -0.5, -1.0}) {
    const double peak = std::sqrt(std::pow(M.beta0 - sn * M.tan_phi0, 2) - M.alpha0 * M.alpha0);
    CHECK(yield_function(Vec3(sn, peak, 0), S) == Approx(0).margin(1e-14));
  }
  // Fully softened and worn: the Coulomb cone |tau| + sigma_n tan(phir) = 0.
  const Surface R = surface_of(M, 10 * M.p.GIC, 0, 1e3);
  CHECK(R.alpha == 0);
  CHECK(R.beta == 0);
  CHECK(R.tan_phi == Approx(M.tan_phir).epsilon(1e-12));
  CHECK(yield_function(Vec3(-0.5, 0.5 * M.tan_phir, 0), R) == Approx(0).margin(1e-14));
  // Tension cut-off at tau = 0 is ft = s ft0.
  const Surface H = surface_of(M, 0.25 * M.p.GIC, 0.25 * M.p.GIIC, 0);
  CHECK(yield_function(Vec3(0.5 * M.p.ft0, 0, 0), H) == Approx(0).margin(1e-14));
}

TEST_CASE("Surface: flow direction blends from tan(psi) to tan(phi) across the open regime", "[surface][decision]") {
  const Model M = make_model_checked(almeida_m15());
  const Surface S = surface_of(M, 0, 0, 0);
  const Vec3 k = kbar_of(M);
  // Closed: the paper's potential, Eq. 10 (regularised with alpha).
  CHECK(flow_of(M, Vec3(-1, 0.3, 0), S, k).m[0] == Approx(S.tan_psi));
  // Continuous at sigma_n = 0 from both sides.
  CHECK(flow_of(M, Vec3(1e-12, 0.3, 0), S, k).m[0] == Approx(S.tan_psi).epsilon(1e-9));
  // Associated at the tension cut-off (pure tension softens even with psi = 0).
  CHECK(flow_of(M, Vec3(M.p.ft0, 0, 0), S, k).m[0] == Approx(S.tan_phi));
  CHECK(flow_of(M, Vec3(0.5 * M.p.ft0, 0, 0), S, k).m[0] ==
        Approx(S.tan_psi + 0.5 * (S.tan_phi - S.tan_psi)));
  // Shear part is the gradient of the regularised G: tau / sqrt(alpha^2 + tau^2).
  const Flow f = flow_of(M, Vec3(-1, 0.3, 0.4), S, k);
  CHECK(f.m[1] == Approx(0.3 / std::hypot(S.alpha, 0.5)));
  CHECK(f.m[2] == Approx(0.4 / std::hypot(S.alpha, 0.5)));
  // At the apex of the fully softened cone the shear part is zero, not NaN.
  const Surface R = surface_of(M, 10 * M.p.GIC, 0, 0);
  const Flow a = flow_of(M, Vec3(0, 0, 0), R, k);
  CHECK(a.m.allFinite());
  CHECK(a.m[1] == 0);
}

TEST_CASE("Surface: asking for the derivatives leaves the values of the flow unchanged", "[surface]") {
  // flow_of is one evaluation for values and derivatives: the values must be
  // the same bits with and without the derivatives.
  const Model M = make_model_checked(almeida_m15());
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-3, 2), w(0, 1);
  for (int k = 0; k < 500; ++k) {
    const Surface S = surface_of(M, 1.2 * M.p.GIC * w(rng), 0.5 * M.p.GIIC * w(rng), 1e-3 * w(rng));
    const Vec3 sigma(u(rng), k % 7 == 0 ? 0.0 : u(rng), u(rng));
    LocalDerivatives d;
    const Flow a = flow_of(M, sigma, S, kbar_of(M));
    const Flow b = flow_of(M, sigma, S, kbar_of(M), &d);
    CHECK(a.dF == b.dF);
    CHECK(a.m == b.m);
    CHECK(a.k_A_m == b.k_A_m);
    CHECK(a.gI == b.gI);
    CHECK(a.gII == b.gII);
    CHECK(a.gIII == b.gIII);
    CHECK(a.denominator == b.denominator);
    CHECK(d.m == a.m);
    CHECK(d.g == Vec3(a.gI, a.gII, a.gIII));
  }
}

TEST_CASE("Surface: the work rates' derivatives match central differences", "[surface]") {
  const Model M = make_model_checked(van_der_pluijm(-0.5));
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1.5, 0.5), w(0, 1);
  for (int k = 0; k < 200; ++k) {
    const Vec3 kappa(0.3 * M.p.GIC * w(rng), 0.3 * M.p.GIIC * w(rng), 1e-4 * w(rng));
    const Vec3 sigma(u(rng), u(rng), u(rng));
    if (std::abs(sigma[0]) < 1e-3) continue;  // the kink of <sigma_n>
    const LocalDerivatives d = local_derivatives(M, sigma, kappa);
    for (int j = 0; j < 3; ++j) {
      const double h = 1e-7;
      Vec3 a = sigma, b = sigma;
      a[j] += h;
      b[j] -= h;
      const Vec3 fd = (local_derivatives(M, a, kappa).g - local_derivatives(M, b, kappa).g) / (2 * h);
      for (int i = 0; i < 3; ++i) CHECK(d.g_sigma(i, j) == Approx(fd[i]).margin(1e-6));
    }
  }
}
