#include "mortar/integration/backward_euler.hpp"

#include <algorithm>
#include <cmath>

namespace mortar {

namespace {

enum class Outcome { plastic, unloading, failed };

// The step on given branches of the open regime (rate_stiffness): unloading
// when the trial on them stays inside the surface, else the local problem
// solved from the forward-Euler predictor (the explicit rate statement over
// dd, where the consistency denominator at P is positive).
Outcome solve_on_branches(const Model& M, const Point& P, const Surface& S, const Vec3& dd, bool grow_n,
                          bool grow_s, BackwardEulerStep& b, IntegrationStatus& st) {
  const Vec3 kappa(P.y.wI, P.y.wII, P.y.wIII);
  b.k = rate_stiffness_over(M, P.y, dd, grow_n, grow_s);
  b.grow_n = grow_n;
  b.grow_s = grow_s;
  const Vec3 trial = P.sigma + b.k.times_separation(dd);
  if (yield_function(trial, S) <= yield_tolerance(M, trial)) return Outcome::unloading;
  b.problem = make_local_problem(M, P.sigma, trial, b.k.on_flow, kappa);
  const Flow fP = flow_of(M, P.sigma, S, b.k.on_flow);
  Vec7 predictor;
  const Vec7* start = nullptr;
  if (fP.denominator > 0) {
    const double dl0 = std::max(0.0, yield_function(trial, S)) / fP.denominator;
    predictor = LocalUnknowns{trial - dl0 * fP.k_A_m, dl0, kappa + dl0 * Vec3(fP.gI, fP.gII, fP.gIII)}.vector();
    if (predictor.allFinite()) start = &predictor;
  }
  b.solution = solve_local(M, b.problem, M.controls.ftol, start);
  st.newton_iterations += b.solution.iterations;
  if (!b.solution.converged) return Outcome::failed;
  const LocalUnknowns u = b.solution.unknowns();
  b.end = local_derivatives(M, u.sigma, u.kappa);
  return Outcome::plastic;
}

}  // namespace

void end_plastic_step(const Model& M, const Point& P, Point& N, const Vec3& sigma, const Vec3& dp,
                      const Vec3& kappa) {
  N.sigma = sigma;
  N.y.plastic += dp;
  N.y.crack += crack_ratio(M).cwiseProduct(dp);
  // gI, gIII >= 0 (Eqs. 7, 9), so the exact solution never lowers wI or
  // wIII; the max only removes Newton's round-off (a work of -1e-22 where
  // the rate is zero), which check_state() would reject.
  N.y.wI = std::max(kappa[0], P.y.wI);
  N.y.wII = kappa[1];
  N.y.wIII = std::max(kappa[2], P.y.wIII);
  // Trapezoidal in the traction: in the closed regime (constant K) this makes
  // trapezoidal external work = elastic energy change + dissipation exactly.
  N.y.dissipation_plastic += 0.5 * (P.sigma + N.sigma).dot(dp);
}

BackwardEulerStep backward_euler(const Model& M, const Point& P, const Vec3& dd, IntegrationStatus& st,
                                 bool stage_branches) {
  BackwardEulerStep out;
  out.N = P;
  out.N.y.separation += dd;
  // Loading or unloading. From inside the surface: the elastic trial with
  // the secant stiffness (Eq. 1), elastic if it stays inside. From on the
  // surface: the rate statement decides (the trial on the damage-growing
  // branch), as stage() does with the sign of dF . kS dd. In the open regime
  // the secant kbar (1 - d) can be so small late in the softening
  // (1 - dn ~ 1e-5) that the secant trial rises by less than FTOL while the
  // rate statement is loading; classifying that as elastic would stall the
  // softening.
  const Surface S = surface_of(M, P.y);
  const bool on_surface = yield_function(P.sigma, S) >= -yield_tolerance(M, P.sigma);
  const Vec3 sigma_e = P.sigma + secant_stiffness(M, P.y.dn, P.y.ds, P.y.open).cwiseProduct(dd);
  const Flow f0 = flow_of(M, P.sigma, S, rate_stiffness(M, P.y).on_flow);
  auto elastic = [&]() {
    out.plastic = false;
    out.N.sigma = traction_of(M, out.N.y);
    out.ok = true;
    return out;
  };
  // As in the explicit stage(): a flow that no stiffness can feed (open and
  // fully damaged along it) leaves only the secant relation.
  if ((!on_surface && yield_function(sigma_e, S) <= yield_tolerance(M, sigma_e)) || !(f0.dF.dot(f0.k_A_m) > 0))
    return elastic();
  out.plastic = true;
  // The branch logic is that of the explicit stage() (docs/model.md 7.5): a
  // slip against the elastic slip starts on its frozen branch (the growing
  // one where that has no solution); a trial inside the surface is unloading,
  // elastic on the secant; a component whose secant damage the solution
  // would decrease is re-solved frozen (at most two passes), unless that has
  // no solution, or unloads although the secant loads: the more growing
  // branch then stands (settle keeps the damage from decreasing).
  const bool freeze_slip = stage_branches && P.y.open && slip_reverses(P.y, dd);
  bool grow_n = true, grow_s = !freeze_slip;
  Outcome o = solve_on_branches(M, P, S, dd, grow_n, grow_s, out, st);
  if (o == Outcome::failed && freeze_slip) {
    grow_s = true;
    o = solve_on_branches(M, P, S, dd, grow_n, grow_s, out, st);
  }
  if (o == Outcome::unloading) return elastic();
  if (o == Outcome::failed) return out;  // the caller halves the step
  for (int pass = 0; P.y.open && pass < (stage_branches ? 2 : 1); ++pass) {
    // Decided with the end-point plastic increment; exact for a finite step:
    // d_old (dd - dp) <= b dp is the secant damage at the end not decreasing.
    const Vec3 dp = out.solution.unknowns().dl * out.end.m;
    const bool keep_n = grow_n && damage_grows_normal(M, P.y, dd, dp);
    const bool keep_s = grow_s && damage_grows_shear(M, P.y, dd, dp);
    if (keep_n == grow_n && keep_s == grow_s) break;
    BackwardEulerStep frozen = out;
    const Outcome f = solve_on_branches(M, P, S, dd, keep_n, keep_s, frozen, st);
    if (f == Outcome::failed || (stage_branches && f == Outcome::unloading && f0.dF.dot(sigma_e - P.sigma) > 0)) break;
    if (f == Outcome::unloading) return elastic();
    out = frozen;
    grow_n = keep_n;
    grow_s = keep_s;
  }
  const LocalUnknowns x = out.solution.unknowns();
  end_plastic_step(M, P, out.N, x.sigma, x.dl * out.end.m, x.kappa);
  out.ok = out.N.sigma.allFinite() && out.solution.x.allFinite();
  return out;
}

BoundaryStep backward_euler_to_boundary(const Model& M, const Point& P, const Vec3& dd, IntegrationStatus& st) {
  BoundaryStep out;
  const RateStiffness k = rate_stiffness(M, P.y);
  const Vec3 k_dd = k.on_separation.cwiseProduct(dd);
  if (!(k_dd[0] > 0) || !(P.sigma[0] <= 0)) return out;
  const Surface S = surface_of(M, P.y);
  double theta = 0, dl = 0;
  Vec3 m = Vec3::Zero(), sigma = Vec3::Zero(), kappa(P.y.wI, P.y.wII, P.y.wIII);
  if (S.s_raw <= 0) {
    // The cone |tau| + sigma_n tan(phi) = 0: the boundary point is its apex,
    // sigma = 0, where the works do not change (g = 0, Eqs. 7-9) and the flow
    // is (tan(psi), e) with |e| <= 1 (subgradient of |tau|). The shear
    // returns to zero: dl kF_s e = tau_trial(theta); the normal: dl kF_n
    // tan(psi) = sigma_n,trial(theta). With tan(psi) = 0 theta follows from
    // the normal alone; otherwise h(theta) = theta k_dd_n + sigma_n,P -
    // kF_n tan(psi) |tau_trial(theta)| / kF_s is increasing... solved by
    // bisection on [0, 1] (h(0) = sigma_n,P <= 0).
    const double tp = S.tan_psi;
    auto tau_trial = [&](double th) { return Vec3(0, P.sigma[1] + th * k_dd[1], P.sigma[2] + th * k_dd[2]); };
    auto h = [&](double th) {
      return th * k_dd[0] + P.sigma[0] - k.on_flow[0] * tp * tau_trial(th).norm() / k.on_flow[1];
    };
    if (!(k.on_flow[1] > 0)) return out;
    if (tp == 0) {
      theta = -P.sigma[0] / k_dd[0];
    } else {
      if (!(h(1) >= 0)) return out;
      double lo = 0, hi = 1;
      for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) (h(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
      theta = hi;
    }
    if (!(theta > 0 && theta <= 1)) return out;
    const Vec3 t = tau_trial(theta);
    dl = t.norm() / k.on_flow[1];
    m = Vec3(tp, dl > 0 ? t[1] / (dl * k.on_flow[1]) : 0.0, dl > 0 ? t[2] / (dl * k.on_flow[1]) : 0.0);
  } else {
    const LocalProblem lp = make_boundary_problem(M, P.sigma, k_dd, k.on_flow, kappa);
    const LocalSolution sol = solve_local(M, lp, M.controls.ftol);
    st.newton_iterations += sol.iterations;
    if (!sol.converged) return out;
    const LocalUnknowns u = sol.unknowns();
    theta = sol.x[unknown::theta];
    if (!(theta > 0 && theta <= 1)) return out;
    dl = u.dl;
    sigma = Vec3(0, u.sigma[1], u.sigma[2]);
    kappa = u.kappa;
    m = local_derivatives(M, sigma, kappa).m;
  }
  out.N = P;
  out.N.y.separation += theta * dd;
  end_plastic_step(M, P, out.N, sigma, dl * m, kappa);
  out.theta = theta;
  out.ok = out.N.sigma.allFinite() && out.N.y.plastic.allFinite();
  return out;
}

}  // namespace mortar
