// The local problem of one backward-Euler substep (docs/model.md 7.5): its
// analytic Jacobian against central differences of the residual, at the trial
// point, on the way and at the solution, for each regime and for the step that
// ends on the regime boundary.
#include <catch2/catch.hpp>

#include <vector>

#include "mortar/integration/local_problem.hpp"
#include "mortar/physics/elasticity.hpp"
#include "mortar/physics/yield_surface.hpp"
#include "paper_sets.hpp"
#include "formatted.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {

Model implicit_model(const Parameters& p) {
  Controls c;
  c.scheme = Scheme::implicit;
  return make_model_checked(p, c);
}

// Central differences of the local residual, column by column.
Mat7 fd_jacobian(const Model& M, const LocalProblem& lp, const Vec7& x) {
  Mat7 J;
  for (int j = 0; j < 7; ++j) {
    // Step relative to the variable, floored at its scale (traction, a
    // multiplier of 1e-5 mm, the work scales of the problem).
    const double floor = j < 3 ? 1 / lp.row_scale[0] : (j == 3 ? 1e-5 : 1 / lp.row_scale[j]);
    const double h = 1e-6 * std::max(std::abs(x[j]), floor);
    Vec7 xp = x, xm = x;
    xp[j] += h;
    xm[j] -= h;
    J.col(j) = (local_residual(M, lp, xp) - local_residual(M, lp, xm)) / (2 * h);
  }
  return J;
}

}  // namespace

TEST_CASE("Implicit: the analytic Jacobian of the local problem matches central differences", "[implicit][jacobian]") {
  struct Case {
    const char* name;
    Parameters p;
    Vec3 sigma_start, d_sep;
    Vec3 kappa;
    bool open;
  };
  const std::vector<Case> cases = {
      {"closed, shear at compression", van_der_pluijm(-0.5), Vec3(-0.5, 1.2, 0.3), Vec3(-1e-4, 3e-3, 1e-3),
       Vec3(0, 4e-3, 2e-4), false},
      {"open, tension below ft (blend)", almeida_m15(), Vec3(1.0, 0.2, -0.1), Vec3(1e-3, 2e-4, 0), Vec3(2e-3, 1e-3, 0),
       true},
      {"open, mixed, wear", almeida_m34(), Vec3(0.3, 0.6, 0.2), Vec3(5e-4, 1e-3, 5e-4), Vec3(5e-4, 2e-3, 1e-4), true},
      {"closed, fully softened cone (s = 0)", atkinson(), Vec3(-0.3, 0.15, 0.0), Vec3(0, 2e-3, 0), Vec3(0.01, 0.15, 5e-3),
       false},
  };
  for (const Case& c : cases) {
    const Model M = implicit_model(c.p);
    State y;
    y.open = c.open;
    const RateStiffness k = rate_stiffness(M, y);
    const Vec3 trial = c.sigma_start + k.on_separation.cwiseProduct(c.d_sep);
    const LocalProblem lp = make_local_problem(M, c.sigma_start, trial, k.on_flow, c.kappa);
    // At the trial point (dl = 0), on the way (dl > 0, works moved) and at the solution.
    Vec7 x0;
    x0 << trial, 0.0, c.kappa;
    const LocalSolution sol = solve_local(M, lp, 1e-8);
    REQUIRE(sol.converged);
    Vec7 mid = 0.5 * (x0 + sol.x);
    mid[1] *= 1.01;
    for (const Vec7& x : {x0, mid, sol.x}) {
      Mat7 J;
      local_residual(M, lp, x, &J);
      const Mat7 fd = fd_jacobian(M, lp, x);
      const double err = (J - fd).norm() / J.norm();
      CAPTURE(c.name, x.transpose(), J, fd);
      CHECK(err < 1e-7);
    }
  }
  // The step that ends on the regime boundary (sigma_n = 0 imposed, x[0] the
  // fraction of the step): closed, sheared, opened.
  const Model M = implicit_model(van_der_pluijm(-0.5));
  const Vec3 kbar(M.p.kn, M.p.ks, M.p.ks);
  const LocalProblem lp = make_boundary_problem(M, Vec3(-0.3, 1.0, 0.2), kbar.cwiseProduct(Vec3(8e-3, 2e-3, 0)), kbar,
                                                Vec3(0, 2e-3, 1e-4));
  const LocalSolution sol = solve_local(M, lp, 1e-8);
  REQUIRE(sol.converged);
  CHECK(sol.x[0] > 0);
  CHECK(sol.x[0] < 1);
  Mat7 J;
  local_residual(M, lp, sol.x, &J);
  const double err = (J - fd_jacobian(M, lp, sol.x)).norm() / J.norm();
  INFO(mj_test::formatted("[jacobian] %-32s theta %.3f  rel. error %.2e", "closed, step ending on the boundary",
                          sol.x[0], err));
  CHECK(err < 1e-7);
}


TEST_CASE("Implicit: the named unknowns map to and from Newton's vector", "[implicit]") {
  const Vec7 x = (Vec7() << 1, 2, 3, 4, 5, 6, 7).finished();
  const LocalUnknowns u = LocalUnknowns::of(x);
  CHECK(u.sigma == Vec3(1, 2, 3));
  CHECK(u.dl == 4);
  CHECK(u.kappa == Vec3(5, 6, 7));
  CHECK(u.vector() == x);
  CHECK(x[unknown::theta] == 1);  // the boundary step's theta shares sigma_n's place
  // The residual's consistency row sits at the multiplier's place: F at the trial point.
  const Model M = implicit_model(almeida_m15());
  const Vec3 trial(0.5, 4.0, 0.0);
  const LocalProblem lp = make_local_problem(M, Vec3::Zero(), trial, Vec3(M.p.kn, M.p.ks, M.p.ks), Vec3::Zero());
  const Vec7 r = local_residual(M, lp, trial_point(lp));
  CHECK(r[unknown::multiplier] == Approx(yield_function(trial, surface_of(M, 0, 0, 0)) * lp.row_scale[3]));
  CHECK(r.segment<3>(unknown::sigma_n).norm() == 0);
  CHECK(r.segment<3>(unknown::work_I).norm() == 0);
}
