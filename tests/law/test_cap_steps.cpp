// docs/model.md 12, the implicit scheme's steps with a cap
// (integration/cap.hpp): the cap's step and the corner's, each found on the
// crush path of the splitting study, and their derivatives
// (cap_step_sensitivity) against central differences of the step itself in
// its separation increment. The whole update's tangent through them:
// test_tangent.cpp.
#include <catch2/catch.hpp>

#include "formatted.hpp"
#include "splitting_paths.hpp"

#include "mortar/integration/cap.hpp"

using namespace mortar;
using namespace mj_test::splitting;

namespace {

// The first increment of the crush path (van der Pluijm -0.5, h = 1e-3 mm,
// the implicit scheme) whose step from its start is the cap's alone
// (corner = false) or the corner's.
struct Found {
  bool ok = false;
  State start;
  Vec3 dd = Vec3::Zero();
};
Found first_step(const Model& M, const Path& w, bool corner) {
  Found f;
  State s;
  Vec3 from = Vec3::Zero();
  for (const Leg& leg : w) {
    const Vec3 d = leg.to - from;
    from = leg.to;
    const int n = std::max(1, int(std::ceil(d.norm() / 1e-3 - 1e-9)));
    for (int i = 0; i < n; ++i) {
      const Point P{s, traction_of(M, s)};
      IntegrationStatus st;
      const CapStep c = cap_applies(M, s) ? cap_backward_euler(M, P, d / n, nullptr, st) : CapStep{};
      if (c.involved && c.ok && c.corner == corner) return {true, s, d / n};
      integrate_increment(M, s, d / n);
    }
  }
  return f;
}

}  // namespace

TEST_CASE("Cap: the derivatives of the cap's and the corner's steps match central differences", "[cap][tangent]") {
  const NamedSet ns = set_named("vdP-0.5");
  Controls ctl;
  ctl.scheme = Scheme::implicit;
  const Model M = make_model(ns.p, ctl, crush_cap(ns.p));
  const Path w = path_of("crush", ns.p, 0);
  for (const bool corner : {false, true}) {
    const Found f = first_step(M, w, corner);
    REQUIRE(f.ok);
    const Point P{f.start, traction_of(M, f.start)};
    IntegrationStatus st0;
    const CapStep step = cap_backward_euler(M, P, f.dd, nullptr, st0);
    const Sensitivity D = cap_step_sensitivity(M, P, step, Sensitivity{}, Mat3::Identity());
    Mat3 fd_sigma, fd_plastic;
    Eigen::RowVector3d fd_kappa_c;
    const double h = 1e-6 * f.dd.norm();
    for (int j = 0; j < 3; ++j) {
      Vec3 e = Vec3::Zero();
      e[j] = h;
      IntegrationStatus st;
      const CapStep a = cap_backward_euler(M, P, f.dd + e, nullptr, st);
      const CapStep b = cap_backward_euler(M, P, f.dd - e, nullptr, st);
      REQUIRE((a.ok && b.ok && a.corner == corner && b.corner == corner));
      fd_sigma.col(j) = (a.N.sigma - b.N.sigma) / (2 * h);
      fd_plastic.col(j) = (a.N.y.plastic - b.N.y.plastic) / (2 * h);
      fd_kappa_c[j] = (a.N.y.kappa_c - b.N.y.kappa_c) / (2 * h);
    }
    const double e_sigma = (D.sigma - fd_sigma).norm() / fd_sigma.norm();
    const double e_plastic = (D.plastic - fd_plastic).norm() / fd_plastic.norm();
    const double e_kappa = (D.kappa_c - fd_kappa_c).norm() / fd_kappa_c.norm();
    INFO(mj_test::formatted("[cap] %s step: sigma %.2e, plastic %.2e, kappa_c %.2e (relative to the differences)",
                            corner ? "corner" : "cap", e_sigma, e_plastic, e_kappa));
    CAPTURE(D.sigma, fd_sigma);
    CHECK(e_sigma < 1e-6);
    CHECK(e_plastic < 1e-6);
    CHECK(e_kappa < 1e-6);
  }
}
