#include "mortar/integration/relaxation.hpp"

#include <algorithm>
#include <cmath>

#include "mortar/integration/rate_statement.hpp"
#include "mortar/integration/root_finder.hpp"

namespace mortar {

namespace {

constexpr int kMaxRelaxSteps = 20000;
constexpr double kTiny = 1e-300;

// Rates of the return at fixed separation, per unit plastic multiplier.
Rates relaxation_rates(const Model& M, const Point& P, double dl) {
  const Surface S = surface_of(M, P.y);
  return along_flow(M, P.sigma, flow_of(M, P.sigma, S, rate_stiffness(M, P.y).on_flow), dl);
}

// Heun step of the return at fixed separation over dl, from P with its flow
// f_P (relax evaluates it once per step, for any number of fractions of dl).
Point relaxation_step(const Model& M, const Point& P, const Flow& f_P, double dl) {
  Point A = P;
  const Rates r1 = along_flow(M, P.sigma, f_P, dl);
  add(A, r1, 1.0);
  const Rates r2 = relaxation_rates(M, A, dl);
  Point B = P;
  add(B, r1, 0.5);
  add(B, r2, 0.5);
  settle(M, B, P.y.elastic_separation());
  return B;
}

}  // namespace

bool relax(const Model& M, Point& P, IntegrationStatus& st, bool snapback) {
  ++st.relaxations;
  st.plastic = true;
  // Its steps come out of the increment's substep budget (Controls::
  // max_substeps, docs/model.md 9), so that the fallback chain's pieces, each
  // of which may relax, stay within the chain's bound on work.
  const long steps = std::min<long>(kMaxRelaxSteps, long(M.controls.max_substeps) - st.work());
  // The surface of each point is evaluated once: at the end of a step it
  // gives that step's F, and the next step starts there.
  Surface S = surface_of(M, P.y), S_end;
  auto yield_at_end = [&](const Point& X) {
    S_end = surface_of(M, X.y);
    return yield_function(X.sigma, S_end);
  };
  for (long step = 0; step < steps; ++step, ++st.relaxation_steps) {
    const double F = yield_function(P.sigma, S);
    const double tol = yield_tolerance(M, P.sigma);
    const Flow f = flow_of(M, P.sigma, S, rate_stiffness(M, P.y).on_flow);
    const bool unstable = snaps_back(f);
    if (F <= tol && !(snapback && unstable)) return true;
    const double scale = std::max(P.sigma.norm(), 1e-3 * M.stress_scale);
    double dl = 0.05 * scale / std::max(f.k_A_m.norm(), kTiny);
    const double ds_rate = std::abs(f.gI / M.p.GIC + f.gII / M.p.GIIC);
    if (S.s > 0 && ds_rate > 0) dl = std::min(dl, 0.05 * std::max(S.s, 1e-3) / ds_rate);
    if (M.p.m * f.gIII > 0) dl = std::min(dl, 0.05 / (M.p.m * f.gIII));
    if (F > tol && f.denominator > 0) dl = std::min(dl, F / f.denominator);
    if (!(dl > 0) || !std::isfinite(dl)) return false;
    Point Q = relaxation_step(M, P, f, dl);
    const double FQ = yield_at_end(Q);
    if (FQ < -yield_tolerance(M, Q.sigma) && F > tol) {
      // The crossing inside the step, on the fraction of dl; Q (and S_end)
      // end as the step to the last fraction tried.
      pegasus(
          [&](double x) {
            Q = relaxation_step(M, P, f, x * dl);
            return RootSample{yield_at_end(Q), yield_tolerance(M, Q.sigma)};
          },
          0, F, 1, FQ, 60);
    }
    P = Q;
    S = S_end;
  }
  return false;
}

}  // namespace mortar
