// Stress integration of the mortar-joint law. The derivation of the rate
// equations and every decision taken here are written up in docs/model.md.
//
// Structure of one increment:
//   - the increment is cut into segments of constant unilateral regime
//     (open h = 1 / closed h = 0, Eq. 13 with the sign of the elastic normal
//     separation); a switch is resolved at the point where it happens;
//   - in a segment: elastic trial with the secant stiffness (Eq. 1, 21); if it
//     leaves the surface, the elastic-plastic intersection (Pegasus), then
//     plastic substeps of the rate statement (Eq. 16-18 with the secant damage
//     rule) by modified Euler with error control or by one forward Euler step;
//   - where no strain-driven solution exists (a closure that jumps the shear
//     stiffness back to ks, or a snap-back where softening outruns the elastic
//     relaxation), a return at fixed separation along the flow direction.
// The implicit scheme (docs/model.md 7.5) keeps this structure and replaces
// the plastic substeps of a segment by backward-Euler steps
// (Stepper::plastic_implicit, local problem in return_mapping.cpp); on
// request it carries the derivatives of the working point with respect to
// the separation increment through every step (Sensitivity), which gives the
// consistent tangent of the whole update.
#include "mortar/integrator.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

namespace mortar {

const char* failure_name(Failure f) {
  switch (f) {
    case Failure::none: return "none";
    case Failure::too_many_substeps: return "too many substeps";
    case Failure::relaxation_failed: return "return at fixed separation did not reach the surface";
    case Failure::too_many_switches: return "too many open/closed switches in one increment";
    case Failure::non_finite_increment: return "separation increment is not finite";
    case Failure::invalid_state: return "invalid state";
    case Failure::non_finite_result: return "non-finite result";
    case Failure::local_solve_failed: return "implicit return mapping did not converge (smallest substep or Newton budget reached)";
  }
  return "unknown";
}

const char* check_state(const State& s) {
  const double v[] = {s.plastic[0], s.plastic[1], s.plastic[2], s.crack[0], s.crack[1],
                      s.crack[2], s.wI, s.wII, s.wIII, s.dn, s.ds, s.separation[0],
                      s.separation[1], s.separation[2], s.dissipation_plastic,
                      s.dissipation_damage, s.energy_unilateral};
  for (double x : v)
    if (!std::isfinite(x)) return "every state variable must be finite";
  if (!(s.dn >= 0 && s.dn <= 1)) return "damage d_n (SDV 10) must lie in [0, 1]";
  if (!(s.ds >= 0 && s.ds <= 1)) return "damage d_s (SDV 11) must lie in [0, 1]";
  if (!(s.wI >= 0)) return "work w_I (SDV 7) must be >= 0";
  // A negative w_II would raise the strength above its initial value (s > 1, Eq. 4).
  if (!(s.wII >= 0)) return "work w_II (SDV 8) must be >= 0";
  if (!(s.wIII >= 0)) return "work w_III (SDV 9) must be >= 0";
  // The damage dissipation only grows from 0 (docs/model.md, energy booking).
  if (!(s.dissipation_damage >= 0)) return "damage dissipation (SDV 17) must be >= 0";
  return nullptr;
}

namespace {

constexpr int kMaxSegments = 32;
constexpr int kMaxRelaxSteps = 20000;
constexpr int kMaxCrossingCuts = 40;
constexpr double kTiny = 1e-300;
// Implicit scheme: Newton iterations (all local solves) allowed per increment.
// A smooth increment takes 3-10; 2e5 bounds the worst case to about 0.3 s
// (tests/law/test_implicit.cpp, invariant 10: 35 of 48 000 extreme
// increments fail on it or at the smallest substep).
constexpr int kMaxNewtonIterations = 200000;

// Increments of everything the rate statement integrates, over one stage.
struct Rates {
  Vec3 dsigma = Vec3::Zero(), dplastic = Vec3::Zero(), dcrack = Vec3::Zero();
  double dwI = 0, dwII = 0, dwIII = 0, dDp = 0;
  bool snapback = false;  // no strain-driven solution: consistency denominator <= 0
};

Vec3 crack_ratio(const Model& M) { return Vec3(M.p.bn, M.p.bs, M.p.bs); }

// Whether the open-regime growing branch keeps the secant damage from
// decreasing for a plastic increment dp: d (dd - dp) <= b dp along the
// elastic separation (derivation in docs/model.md).
bool damage_grows_normal(const Model& M, const State& y, const Vec3& dd, const Vec3& dp) {
  const double e = y.elastic_separation()[0];
  if (!(e > 0)) return true;
  return y.dn * (dd[0] - dp[0]) <= M.p.bn * dp[0] + 1e-14 * std::abs(dd[0]);
}
bool damage_grows_shear(const Model& M, const State& y, const Vec3& dd, const Vec3& dp) {
  const Vec3 e = y.elastic_separation();
  const double es = std::hypot(e[1], e[2]);
  if (!(es > 0)) return true;
  const double de = ((dd[1] - dp[1]) * e[1] + (dd[2] - dp[2]) * e[2]) / es;
  const double dcr = M.p.bs * (dp[1] * e[1] + dp[2] * e[2]) / es;
  return y.ds * de <= dcr + 1e-14 * std::hypot(dd[1], dd[2]);
}

// The working point: state + the traction that goes with it.
struct Point {
  State y;
  Vec3 sigma;
};

void add(Point& P, const Rates& r, double w) {
  P.sigma += w * r.dsigma;
  P.y.plastic += w * r.dplastic;
  P.y.crack += w * r.dcrack;
  P.y.wI += w * r.dwI;
  P.y.wII += w * r.dwII;
  P.y.wIII += w * r.dwIII;
  P.y.dissipation_plastic += w * r.dDp;
}

// Plastic increments for a plastic-multiplier increment dl along the flow.
Rates along_flow(const Model& M, const Vec3& sigma, const Flow& f, double dl) {
  Rates r;
  r.dsigma = -dl * f.k_A_m;
  r.dplastic = dl * f.m;
  r.dcrack = crack_ratio(M).cwiseProduct(r.dplastic);
  r.dwI = dl * f.gI;
  r.dwII = dl * f.gII;
  r.dwIII = dl * f.gIII;
  r.dDp = sigma.dot(r.dplastic);
  return r;
}

// No strain-driven solution: the consistency denominator is not positive
// although the flow changes the traction (softening outruns the elastic
// relaxation: a snap-back of the material point).
bool snaps_back(const Flow& f) {
  const double scale = f.dF.dot(f.k_A_m);
  return scale > 0 && f.denominator <= 1e-12 * scale;
}

// Rates of one stage on given branches of the open regime (rate_stiffness).
Rates branch_rates(const Model& M, const Point& P, const Surface& S, const Vec3& dd, bool grow_n,
                   bool grow_s, Vec3* dp = nullptr) {
  const RateStiffness k = rate_stiffness(M, P.y, grow_n, grow_s);
  const Flow f = flow_of(M, P.sigma, S, k.on_flow);
  const double num = f.dF.dot(k.on_separation.cwiseProduct(dd));
  Rates r;
  // Unloading inside the step, or a flow that no stiffness can feed (open
  // and fully damaged along it): secant elasticity.
  if (num <= 0 || !(f.dF.dot(f.k_A_m) > 0)) {
    r.dsigma = secant_stiffness(M, P.y.dn, P.y.ds, P.y.open).cwiseProduct(dd);
    if (dp) *dp = Vec3::Zero();
    return r;
  }
  if (snaps_back(f)) {
    r.snapback = true;
    return r;
  }
  r = along_flow(M, P.sigma, f, num / f.denominator);
  r.dsigma += k.on_separation.cwiseProduct(dd);
  if (dp) *dp = r.dplastic;
  return r;
}

// One stage of the rate statement (Eq. 16-18; MODEL.md section 6), with dl
// from the consistency condition. In the open regime each component is on
// the damage-growing branch unless the damage it implies would decrease
// (d (dd - dp) > dcr along the component); such a component follows its
// frozen secant instead. Where the frozen branch has no strain-driven
// solution, the growing branch stands (settle keeps the damage from
// decreasing).
Rates stage(const Model& M, const Point& P, const Vec3& dd) {
  const Surface S = surface_of(M, P.y);
  Vec3 dp;
  const Rates grow = branch_rates(M, P, S, dd, true, true, &dp);
  if (!P.y.open || grow.snapback) return grow;
  const bool keep_n = damage_grows_normal(M, P.y, dd, dp);
  const bool keep_s = damage_grows_shear(M, P.y, dd, dp);
  if (keep_n && keep_s) return grow;
  const Rates frozen = branch_rates(M, P, S, dd, keep_n, keep_s);
  return frozen.snapback ? grow : frozen;
}

// An open joint with no strength left (s = 0) can only carry zero traction:
// its surface is the apex of the cone, so the damage is complete (d = 1).
// The elastic energy this releases is booked as damage dissipation.
void disintegrate_if_no_strength(const Model& M, State& y) {
  if (!y.open || surface_of(M, y).s > 0 || (y.dn >= 1 && y.ds >= 1)) return;
  const Vec3 e = y.elastic_separation();
  const double es2 = e[1] * e[1] + e[2] * e[2];
  y.dissipation_damage += 0.5 * M.p.kn * (1 - y.dn) * e[0] * e[0] + 0.5 * M.p.ks * (1 - y.ds) * es2;
  y.dn = 1;
  y.ds = 1;
}

// After plastic flow: damage follows the secant through the plastic
// displacement while the joint is open (MODEL.md section 6), never
// decreases, and the traction is then re-derived from Eq. 1 so that traction
// and state always agree. The energy released by the damage growth is booked
// as damage dissipation, 1/2 kbar (delta_e)^2 dd, trapezoidal in delta_e over
// the step.
void settle(const Model& M, Point& P, const Vec3& e_start) {
  State& y = P.y;
  if (y.open) {
    const Vec3 e = y.elastic_separation();
    const double es = std::hypot(e[1], e[2]), es0 = std::hypot(e_start[1], e_start[2]);
    double dn = y.dn, ds = y.ds;
    if (e[0] > 0) dn = std::clamp(1.0 - P.sigma[0] / (M.p.kn * e[0]), y.dn, 1.0);
    if (es > 0) ds = std::clamp(1.0 - shear_norm(P.sigma) / (M.p.ks * es), y.ds, 1.0);
    y.dissipation_damage += 0.25 * M.p.kn * (dn - y.dn) * (e_start[0] * e_start[0] + e[0] * e[0]) +
                            0.25 * M.p.ks * (ds - y.ds) * (es0 * es0 + es * es);
    y.dn = dn;
    y.ds = ds;
    disintegrate_if_no_strength(M, y);
  }
  P.sigma = traction_of(M, y);
}

// Rates of the return at fixed separation, per unit plastic multiplier.
Rates relaxation_rates(const Model& M, const Point& P, double dl) {
  const Surface S = surface_of(M, P.y);
  return along_flow(M, P.sigma, flow_of(M, P.sigma, S, rate_stiffness(M, P.y).on_flow), dl);
}

// Heun step of the return at fixed separation over dl.
Point relaxation_step(const Model& M, const Point& P, double dl) {
  Point A = P;
  const Rates r1 = relaxation_rates(M, P, dl);
  add(A, r1, 1.0);
  const Rates r2 = relaxation_rates(M, A, dl);
  Point B = P;
  add(B, r1, 0.5);
  add(B, r2, 0.5);
  settle(M, B, P.y.elastic_separation());
  return B;
}

double yield_of(const Model& M, const Point& P) { return yield_function(P.sigma, surface_of(M, P.y)); }

// Return to the surface at fixed separation: march along the flow direction
// (Heun in lambda) with steps that change the traction and the strength by at
// most 5 %, capped by the Newton estimate F / denominator, and stop at the
// first crossing of F = 0, located by Pegasus inside the last step, so the
// return never overshoots the surface or passes the apex. For a snap-back
// (the surface shrinks faster than the traction relaxes: consistency
// denominator <= 0, so F grows along the flow) it marches on until the point
// is back on the surface where the denominator is positive again: the drop
// at fixed separation that a material point under displacement control makes.
bool relax(const Model& M, Point& P, IntegrationStatus& st, bool snapback) {
  ++st.relaxations;
  st.plastic = true;
  for (int step = 0; step < kMaxRelaxSteps; ++step) {
    const Surface S = surface_of(M, P.y);
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
    Point Q = relaxation_step(M, P, dl);
    double FQ = yield_of(M, Q);
    if (FQ < -yield_tolerance(M, Q.sigma) && F > tol) {
      // Pegasus on the fraction of the step.
      double x0 = 0, f0 = F, x1 = 1, f1 = FQ;
      for (int it = 0; it < 60; ++it) {
        const double x = x1 - f1 * (x1 - x0) / (f1 - f0);
        Q = relaxation_step(M, P, x * dl);
        const double fx = yield_of(M, Q);
        if (std::abs(fx) <= yield_tolerance(M, Q.sigma)) break;
        if (fx * f1 < 0) { x0 = x1; f0 = f1; } else { f0 *= f1 / (f1 + fx); }
        x1 = x;
        f1 = fx;
      }
    }
    P = Q;
  }
  return false;
}

// Drift correction after an accepted substep (Sloan et al. 2001): the
// consistent correction along the flow direction, with the hardening it
// implies; where that does not reduce F, a projection normal to the surface,
// realised as a plastic displacement so that Eq. 1 still holds. Only a state
// outside the surface is corrected: one that ends inside (F < 0) is
// admissible, and pulling it out would need a negative plastic multiplier,
// i.e. works and damage that decrease.
void correct_drift(const Model& M, Point& P) {
  for (int it = 0; it < 8; ++it) {
    const Surface S = surface_of(M, P.y);
    const double F = yield_function(P.sigma, S);
    if (F <= yield_tolerance(M, P.sigma)) return;
    const Flow f = flow_of(M, P.sigma, S, rate_stiffness(M, P.y).on_flow);
    const Vec3 e0 = P.y.elastic_separation();
    if (f.denominator > 0) {
      Point C = P;
      add(C, along_flow(M, P.sigma, f, F / f.denominator), 1.0);
      settle(M, C, e0);
      if (std::abs(yield_of(M, C)) < F) {
        P = C;
        continue;
      }
    }
    const double nn = f.dF.squaredNorm();
    if (!(nn > 0)) return;
    const double h = P.y.open ? 1.0 : 0.0;
    const Vec3 kA(M.p.kn * (1 + h * M.p.bn), M.p.ks * (1 + h * M.p.bs), M.p.ks * (1 + h * M.p.bs));
    Point C = P;
    const Vec3 dp = (F / nn) * f.dF.cwiseQuotient(kA);
    C.y.plastic += dp;
    C.y.crack += crack_ratio(M).cwiseProduct(dp);
    C.y.dissipation_plastic += P.sigma.dot(dp);
    C.sigma -= (F / nn) * f.dF;
    settle(M, C, e0);
    if (!(std::abs(yield_of(M, C)) < F)) return;
    P = C;
  }
}

bool crosses(bool open, double e_n) { return open ? e_n < 0 : e_n > 0; }

// ---------------------------------------------------------------------------
// Implicit scheme (docs/model.md 7.5).

using Mat23 = Eigen::Matrix<double, 2, 3>;
using Mat73 = Eigen::Matrix<double, 7, 3>;

// Derivatives of the working point with respect to the separation increment
// of the whole call (the consistent tangent is `sigma` at the end). The
// separation is carried too, because every piece of the increment is the
// rest of it, delta_end - delta_current, whose derivative is I - d delta.
struct Sensitivity {
  Mat3 sigma = Mat3::Zero(), kappa = Mat3::Zero(), plastic = Mat3::Zero(), separation = Mat3::Zero();
  Mat23 damage = Mat23::Zero();  // (d_n, d_s)
};

// d sigma from the secant relation, Eq. 1: sigma = K(d, h) (delta - delta_p).
void secant_sensitivity(const Model& M, const State& y, Sensitivity& D) {
  const Vec3 K = secant_stiffness(M, y.dn, y.ds, y.open);
  D.sigma = K.asDiagonal() * (D.separation - D.plastic);
  if (y.open) {
    const Vec3 e = y.elastic_separation();
    D.sigma.row(0) -= M.p.kn * e[0] * D.damage.row(0);
    D.sigma.row(1) -= M.p.ks * e[1] * D.damage.row(1);
    D.sigma.row(2) -= M.p.ks * e[2] * D.damage.row(1);
  }
}

// Derivatives through settle(): `pre` and `sigma` are the point before it
// (D holds their derivatives), `post` the state after. The branches are those
// settle() took: the secant damage where it lies inside (d_old, 1), the old
// damage where it is clamped from below, 1 (and zero traction) at the top or
// after a disintegration; then Eq. 1.
void settle_sensitivity(const Model& M, const State& pre, const Vec3& sigma, const State& post, Sensitivity& D) {
  // Zero elastic slip (pure opening): settle() leaves d_s alone, but for any
  // slip perturbation the secant damage jumps to its directional limit
  // 1 - (d tau/d slip)/(ks d delta_e_s/d slip), the same in every direction
  // of the plane; the traction that follows is the step's own tau (unclamped
  // limit), the old secant (limit below d_old) or zero (limit at 1).
  enum class ShearLimit { none, step, zero } shear_limit = ShearLimit::none;
  Eigen::Matrix<double, 2, 3> step_shear = D.sigma.bottomRows<2>();
  if (pre.open) {
    const Vec3 e = pre.elastic_separation();
    const Mat3 De = D.separation - D.plastic;
    if (std::hypot(e[1], e[2]) == 0 && De(1, 1) > 0 && post.ds < 1) {
      const double raw = 1.0 - D.sigma(1, 1) / (M.p.ks * De(1, 1));
      if (raw >= 1) shear_limit = ShearLimit::zero;
      else if (!(raw < pre.ds)) shear_limit = ShearLimit::step;
    }
    if (e[0] > 0) {
      const double k = M.p.kn * e[0];
      const double raw = 1.0 - sigma[0] / k;
      if (raw >= 1) D.damage.row(0).setZero();
      else if (!(raw < pre.dn)) D.damage.row(0) = -D.sigma.row(0) / k + (sigma[0] / (k * e[0])) * De.row(0);
    }
    const double es = std::hypot(e[1], e[2]);
    if (es > 0) {
      const double tau = shear_norm(sigma);
      const double k = M.p.ks * es;
      const double raw = 1.0 - tau / k;
      if (raw >= 1) {
        D.damage.row(1).setZero();
      } else if (!(raw < pre.ds)) {
        Eigen::RowVector3d dtau = Eigen::RowVector3d::Zero();
        if (tau > 0) dtau = (sigma[1] * D.sigma.row(1) + sigma[2] * D.sigma.row(2)) / tau;
        const Eigen::RowVector3d des = (e[1] * De.row(1) + e[2] * De.row(2)) / es;
        D.damage.row(1) = -dtau / k + (tau / (k * es)) * des;
      }
    }
    if (post.dn >= 1) D.damage.row(0).setZero();
    if (post.ds >= 1) D.damage.row(1).setZero();
  }
  secant_sensitivity(M, post, D);
  if (shear_limit == ShearLimit::step) D.sigma.bottomRows<2>() = step_shear;
  if (shear_limit == ShearLimit::zero) D.sigma.bottomRows<2>().setZero();
}

// One backward-Euler step of the rate statement from P over dd.
struct BackwardEulerStep {
  bool ok = false;
  bool plastic = false;
  Point N;                  // the end point, before settle()
  LocalProblem problem;     // when plastic: the problem that was solved
  LocalSolution solution;
  LocalDerivatives end;     // flow and works at the end point
  RateStiffness k{Vec3::Zero(), Vec3::Zero()};  // branch stiffnesses used
  bool grow_n = true, grow_s = true;
};

BackwardEulerStep backward_euler(const Model& M, const Point& P, const Vec3& dd, IntegrationStatus& st) {
  BackwardEulerStep out;
  out.N = P;
  out.N.y.separation += dd;
  // Loading or unloading. From inside the surface: the elastic trial with
  // the secant stiffness (Eq. 1), elastic if it stays inside. From on the
  // surface: the rate statement decides (below: the trial on the
  // damage-growing branch), as stage() does with the sign of dF . kS dd. In
  // the open regime the secant kbar (1 - d) can be so small late in the
  // softening (1 - dn ~ 1e-5) that the secant trial rises by less than FTOL
  // while the rate statement is loading; classifying that as elastic would
  // stall the softening.
  const Surface S = surface_of(M, P.y);
  const bool on_surface = yield_function(P.sigma, S) >= -yield_tolerance(M, P.sigma);
  const Vec3 sigma_e = P.sigma + secant_stiffness(M, P.y.dn, P.y.ds, P.y.open).cwiseProduct(dd);
  const RateStiffness k_grow = rate_stiffness(M, P.y);
  const Flow f0 = flow_of(M, P.sigma, S, k_grow.on_flow);
  // As in the explicit stage(): a flow that no stiffness can feed (open and
  // fully damaged along it) leaves only the secant relation.
  if ((!on_surface && yield_function(sigma_e, S) <= yield_tolerance(M, sigma_e)) || !(f0.dF.dot(f0.k_A_m) > 0)) {
    out.N.sigma = traction_of(M, out.N.y);
    out.ok = true;
    return out;
  }
  out.plastic = true;
  const Vec3 kappa(P.y.wI, P.y.wII, P.y.wIII);
  // The branch logic is that of the explicit stage(): on the damage-growing
  // branch first; a trial inside the surface there is unloading, and the
  // step is elastic on the secant (damage frozen); where the growing
  // solution would make the secant damage decrease, the frozen branch for
  // that component, unless it has no plastic solution.
  enum class Outcome { plastic, unloading, failed };
  auto solve = [&](bool grow_n, bool grow_s, BackwardEulerStep& b) {
    b.k = rate_stiffness(M, P.y, grow_n, grow_s);
    b.grow_n = grow_n;
    b.grow_s = grow_s;
    const Vec3 trial = P.sigma + b.k.on_separation.cwiseProduct(dd);
    if (yield_function(trial, S) <= yield_tolerance(M, trial)) return Outcome::unloading;
    b.problem = make_local_problem(M, P.sigma, trial, b.k.on_flow, kappa);
    // Forward-Euler predictor from P (the explicit rate statement over dd),
    // where the consistency denominator there is positive.
    const Flow fP = flow_of(M, P.sigma, S, b.k.on_flow);
    Vec7 predictor;
    const Vec7* start = nullptr;
    if (fP.denominator > 0) {
      const double dl0 = std::max(0.0, yield_function(trial, S)) / fP.denominator;
      predictor << trial - dl0 * fP.k_A_m, dl0, kappa + dl0 * Vec3(fP.gI, fP.gII, fP.gIII);
      if (predictor.allFinite()) start = &predictor;
    }
    b.solution = solve_local(M, b.problem, M.controls.ftol, start);
    st.newton_iterations += b.solution.iterations;
    if (!b.solution.converged) return Outcome::failed;
    b.end = local_derivatives(M, b.solution.x.head<3>(), b.solution.x.tail<3>());
    return Outcome::plastic;
  };
  auto elastic = [&]() {
    out.plastic = false;
    out.N.sigma = traction_of(M, out.N.y);
    out.ok = true;
    return out;
  };
  const Outcome grow = solve(true, true, out);
  if (grow == Outcome::unloading) return elastic();
  if (grow == Outcome::failed) return out;  // the caller halves the step
  if (P.y.open) {
    // Decided with the end-point plastic increment; exact for a finite step:
    // d_old (dd - dp) <= b dp is the secant damage at the end not decreasing.
    const Vec3 dp = out.solution.x[3] * out.end.m;
    const bool keep_n = damage_grows_normal(M, P.y, dd, dp);
    const bool keep_s = damage_grows_shear(M, P.y, dd, dp);
    if (!(keep_n && keep_s)) {
      BackwardEulerStep frozen = out;
      const Outcome f = solve(keep_n, keep_s, frozen);
      if (f == Outcome::unloading) return elastic();
      // No plastic solution on the frozen branch: the growing branch stands
      // and settle() keeps the damage from decreasing.
      if (f == Outcome::plastic) out = frozen;
    }
  }
  const Vec7& x = out.solution.x;
  const double dl = x[3];
  const Vec3 dp = dl * out.end.m;
  Point& N = out.N;
  N.sigma = x.head<3>();
  N.y.plastic += dp;
  N.y.crack += crack_ratio(M).cwiseProduct(dp);
  // gI, gIII >= 0 (Eqs. 7, 9), so the exact solution never lowers wI or
  // wIII; the max only removes Newton's round-off (a work of -1e-22 where
  // the rate is zero), which check_state() would reject.
  N.y.wI = std::max(x[4], P.y.wI);
  N.y.wII = x[5];
  N.y.wIII = std::max(x[6], P.y.wIII);
  // Trapezoidal in the traction: in the closed regime (constant K) this makes
  // trapezoidal external work = elastic energy change + dissipation exactly.
  N.y.dissipation_plastic += 0.5 * (P.sigma + N.sigma).dot(dp);
  out.ok = N.sigma.allFinite() && x.allFinite();
  return out;
}

// The closed-regime step that ends on the regime boundary delta_e_n = 0
// (sigma_n = 0): the part theta of dd after which the backward-Euler end point
// has zero normal traction. Used where a closed step whose trial is tensile
// has no solution in the closed regime: on the fully softened cone (s = 0)
// every admissible point has sigma_n <= 0, so a step that opens the joint
// cannot end in the closed regime, and the crossing bracket of
// plastic_implicit() never sees a crossing point. Returns ok with
// N = the boundary point and `theta` set, or not ok.
struct BoundaryStep {
  bool ok = false;
  double theta = 0;
  Point N;
};

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
    theta = sol.x[0];
    if (!(theta > 0 && theta <= 1)) return out;
    dl = sol.x[3];
    sigma = Vec3(0, sol.x[1], sol.x[2]);
    kappa = sol.x.tail<3>();
    m = local_derivatives(M, sigma, kappa).m;
  }
  const Vec3 dp = dl * m;
  Point& N = out.N;
  N = P;
  N.sigma = sigma;
  N.y.separation += theta * dd;
  N.y.plastic += dp;
  N.y.crack += crack_ratio(M).cwiseProduct(dp);
  N.y.wI = std::max(kappa[0], P.y.wI);
  N.y.wII = kappa[1];
  N.y.wIII = std::max(kappa[2], P.y.wIII);
  N.y.dissipation_plastic += 0.5 * (P.sigma + N.sigma).dot(dp);
  out.theta = theta;
  out.ok = N.sigma.allFinite() && N.y.plastic.allFinite();
  return out;
}

// Derivatives through one backward-Euler step: DP at its start, Ddd the
// derivative of its separation increment. The local residual R(x; sigma_P,
// kappa_P, dd, k) = 0 at the solution gives dx = -J^-1 (dR/dinputs) dinputs.
Sensitivity backward_euler_sensitivity(const Model& M, const Point& P, const Vec3& dd, const BackwardEulerStep& b,
                                       const Sensitivity& DP, const Mat3& Ddd) {
  Sensitivity D = DP;
  D.separation = DP.separation + Ddd;
  if (!b.plastic) {
    secant_sensitivity(M, b.N.y, D);
    return D;
  }
  // Frozen open components have the stiffness k (1 - d) of the damage at P.
  Mat3 Dk = Mat3::Zero();
  if (P.y.open) {
    if (!b.grow_n && P.y.dn < 1) Dk.row(0) = -M.p.kn * DP.damage.row(0);
    if (!b.grow_s && P.y.ds < 1) {
      Dk.row(1) = -M.p.ks * DP.damage.row(1);
      Dk.row(2) = -M.p.ks * DP.damage.row(1);
    }
  }
  const double dl = b.solution.x[3];
  const Mat3 Dtrial = DP.sigma + b.k.on_separation.asDiagonal() * Ddd + dd.asDiagonal() * Dk;
  Mat73 B = Mat73::Zero();
  B.topRows<3>() = -Dtrial + dl * b.end.m.asDiagonal() * Dk;  // k_sep = k_flow on a frozen branch
  B.bottomRows<3>() = -DP.kappa;
  B = b.problem.row_scale.asDiagonal() * B;
  const Mat73 Dx = -Eigen::FullPivLU<Mat7>(b.solution.jacobian).solve(B);
  D.sigma = Dx.topRows<3>();
  D.kappa = Dx.bottomRows<3>();
  const Eigen::RowVector3d Ddl = Dx.row(3);
  const Mat3 Dm = b.end.m_sigma * D.sigma + b.end.m_kappa * D.kappa;
  D.plastic = DP.plastic + b.end.m * Ddl + dl * Dm;
  return D;
}

// Bracket on the substep size around a regime boundary: e_lo, e_hi are the
// elastic normal separations at the ends of substeps of size lo and hi.
struct Bracket {
  bool active = false;
  double lo = 0, e_lo = 0, hi = 0, e_hi = 0;
  double next(int iteration) const {
    double x = lo + (hi - lo) * e_lo / (e_lo - e_hi);
    // Every third try, or when the secant leaves the bracket: bisection.
    if (!(x > lo && x < hi) || iteration % 3 == 2) x = 0.5 * (lo + hi);
    return x;
  }
};

struct Stepper {
  const Model& M;
  Point& P;
  IntegrationStatus& st;
  bool at_boundary = false;
  Sensitivity* sens = nullptr;  // implicit scheme with a tangent requested
  bool sensitivity_lost = false;  // a dependence on the increment was dropped (tangent approximate)
  bool ended_plastic = false;   // the last segment had plastic flow (explicit continuum tangent)

  bool implicit() const { return M.controls.scheme == Scheme::implicit; }
  // A return at fixed separation or a regime switch: the point after it is
  // treated as fixed (docs/model.md 7.5, what the tangent includes).
  // Before any plastic flow in the increment the point does not depend on
  // where a switch happens (elastic paths are path-independent), so nothing
  // is lost then.
  void forget_sensitivity() {
    if (!sens) return;
    if (st.plastic) sensitivity_lost = true;
    *sens = Sensitivity{};
  }

  int substeps() const { return st.substeps_accepted + st.substeps_rejected; }

  // Further outside the surface than a substep may end before the drift
  // correction: 1e-3 of the traction scale (the larger of |sigma| and ft0).
  bool far_outside(const Point& Q) const {
    return yield_of(M, Q) > 1e-3 * std::max(Q.sigma.norm(), M.p.ft0);
  }

  // Plastic substepping over the separation increment d, starting on the
  // surface. Returns the fraction of d done: 1, or less when the regime
  // switched inside (the point is then on the regime boundary).
  double plastic(const Vec3& d) {
    if (implicit()) return plastic_implicit(d);
    const Controls& c = M.controls;
    const bool heun = c.scheme == Scheme::modified_euler;
    double T = 0, dT = 1;
    bool last_rejected = false;
    int cuts = 0;
    Bracket cut;
    // Every pass of the loop counts against the budget, so no path through
    // it (cuts, relaxations) can spin forever.
    for (long pass = 0; T < 1; ++pass) {
      if (substeps() >= c.max_substeps || pass >= 4L * c.max_substeps) {
        st.failure = Failure::too_many_substeps;
        return T;
      }
      dT = std::min(dT, 1 - T);
      const Vec3 dd = dT * d;
      const Rates r1 = stage(M, P, dd);
      if (r1.snapback) {
        if (!relax(M, P, st, true)) { st.failure = Failure::relaxation_failed; return T; }
        continue;
      }
      Point A = P;
      add(A, r1, 1.0);
      A.y.separation += dd;
      Point N = A;
      double err = 0;
      if (heun) {
        const Rates r2 = stage(M, A, dd);
        if (r2.snapback && dT > c.min_substep) {  // the stage entered the snap-back region
          dT = std::max(0.5 * dT, c.min_substep);
          ++st.substeps_rejected;
          continue;
        }
        if (r2.snapback) {  // at the smallest substep: the first stage alone (forward Euler)
          st.min_substep_hit = true;
        } else {
          N = P;
          add(N, r1, 0.5);
          add(N, r2, 0.5);
          N.y.separation += dd;
          err = local_error(r1, r2, N);
        }
        if (err > c.stol && dT > c.min_substep) {
          dT = std::max(std::max(0.9 * std::sqrt(c.stol / err), 0.1) * dT, c.min_substep);
          last_rejected = true;
          ++st.substeps_rejected;
          continue;
        }
        if (err > c.stol) st.min_substep_hit = true;
      }
      // A switch of regime inside the substep: shorten the substep to end on
      // the boundary delta_e_n = 0 (regula falsi on the substep size, with
      // bisection as a safeguard, bracketed between a size that stays in the
      // regime and one that crosses), then switch there.
      const double e0 = P.y.elastic_separation()[0], e1 = N.y.elastic_separation()[0];
      const double near = 1e-9 * std::abs(dd[0]) + boundary_eps(N.y);
      const bool crossed = crosses(P.y.open, e1);
      bool switch_here = false;
      if (crossed && std::abs(e0) <= boundary_eps(P.y)) {  // already on it, moving across
        at_boundary = true;
        return T;
      }
      if (crossed || cut.active) {
        if (!cut.active) cut = Bracket{true, 0.0, e0, dT, e1};
        else if (crossed) { cut.hi = dT; cut.e_hi = e1; }
        else { cut.lo = dT; cut.e_lo = e1; }
        if (std::abs(e1) > near && cuts < kMaxCrossingCuts) {
          dT = cut.next(cuts);
          ++cuts;
          continue;
        }
        switch_here = crossed || std::abs(e1) <= near;
      }
      cuts = 0;
      cut = Bracket{};
      Point Q = N;
      if (switch_here) Q.y.plastic[0] = Q.y.separation[0];  // on the boundary: delta_e_n = 0
      settle(M, Q, P.y.elastic_separation());
      // A Heun substep that ends far outside the surface (an open, damaged
      // joint: the two stages straddle a kink of the flow) is not what the
      // drift correction is for: correcting it can push sigma_n through zero,
      // which the secant damage rule reads as complete normal damage. Such a
      // substep is rejected and halved (docs/robustness.md, defect 8).
      if (heun && !switch_here && dT > c.min_substep && far_outside(Q)) {
        dT = std::max(0.5 * dT, c.min_substep);
        last_rejected = true;
        ++st.substeps_rejected;
        continue;
      }
      P = Q;
      // Not at a switch: the drift correction's plastic displacement would
      // move the point off the boundary again; the switch re-derives the
      // traction in the new regime and returns it to the surface if needed.
      if (heun && !switch_here) correct_drift(M, P);
      ++st.substeps_accepted;
      T += dT;
      if (switch_here) {
        at_boundary = true;
        return std::min(T, 1.0);
      }
      if (heun) {
        double q = std::min(0.9 * std::sqrt(c.stol / std::max(err, kTiny)), 1.1);
        if (last_rejected) q = std::min(q, 1.0);
        dT = std::max(q * dT, c.min_substep);
        last_rejected = false;
      } else {
        dT = 1;
      }
    }
    return 1;
  }

  // The implicit scheme's plastic part (docs/model.md 7.5): backward-Euler
  // steps over the plastic part of the segment, the whole of it first; a
  // step whose Newton iteration fails is halved (recursively, down to the
  // minimum substep, then Failure::local_solve_failed), and after a success
  // the step doubles again. Snap-back at the start of a step and regime
  // crossings are handled exactly as in plastic() above.
  double plastic_implicit(const Vec3& d) {
    const Controls& c = M.controls;
    double T = 0, dT = 1;
    int cuts = 0;
    Bracket cut;
    for (long pass = 0; T < 1; ++pass) {
      if (substeps() >= c.max_substeps || pass >= 4L * c.max_substeps) {
        st.failure = Failure::too_many_substeps;
        return T;
      }
      // The substep budget alone allows millions of Newton iterations (each
      // halving down to min_substep restarts the local solves); a solver
      // waiting on this point would see a hang, so the work is capped too.
      if (st.newton_iterations > kMaxNewtonIterations) {
        st.failure = Failure::local_solve_failed;
        return T;
      }
      dT = std::min(dT, 1 - T);
      const Vec3 dd = dT * d;
      if (stage(M, P, dd).snapback) {  // no strain-driven solution from here
        if (!relax(M, P, st, true)) { st.failure = Failure::relaxation_failed; return T; }
        forget_sensitivity();
        continue;
      }
      const BackwardEulerStep b = backward_euler(M, P, dd, st);
      if (!b.ok && !P.y.open && P.sigma[0] + M.p.kn * dd[0] > 0) {
        // No closed-regime solution and a tensile trial: the step may cross
        // into the open regime where no closed point exists; end it on the
        // boundary instead (backward_euler_to_boundary()).
        const BoundaryStep e = backward_euler_to_boundary(M, P, dd, st);
        if (e.ok) {
          const Vec3 e_start = P.y.elastic_separation();
          P = e.N;
          P.y.plastic[0] = P.y.separation[0];  // on the boundary: delta_e_n = 0
          settle(M, P, e_start);
          forget_sensitivity();
          ++st.substeps_accepted;
          at_boundary = true;
          return std::min(T + e.theta * dT, 1.0);
        }
      }
      if (!b.ok) {
        if (dT > c.min_substep) {
          dT = std::max(0.5 * dT, c.min_substep);
          ++st.substeps_rejected;
          continue;
        }
        st.failure = Failure::local_solve_failed;
        return T;
      }
      const Point& N = b.N;
      // Regime crossing inside the step: as in plastic().
      const double e0 = P.y.elastic_separation()[0], e1 = N.y.elastic_separation()[0];
      const double near = 1e-9 * std::abs(dd[0]) + boundary_eps(N.y);
      const bool crossed = crosses(P.y.open, e1);
      bool switch_here = false;
      if (crossed && std::abs(e0) <= boundary_eps(P.y)) {
        at_boundary = true;
        return T;
      }
      if (crossed || cut.active) {
        if (!cut.active) cut = Bracket{true, 0.0, e0, dT, e1};
        else if (crossed) { cut.hi = dT; cut.e_hi = e1; }
        else { cut.lo = dT; cut.e_lo = e1; }
        if (std::abs(e1) > near && cuts < kMaxCrossingCuts) {
          dT = cut.next(cuts);
          ++cuts;
          continue;
        }
        switch_here = crossed || std::abs(e1) <= near;
      }
      cuts = 0;
      cut = Bracket{};
      Point Q = N;
      if (switch_here) Q.y.plastic[0] = Q.y.separation[0];  // on the boundary: delta_e_n = 0
      const State pre = Q.y;
      const Vec3 sigma_pre = Q.sigma;
      settle(M, Q, P.y.elastic_separation());
      // The end point lies on the surface unless settle() had to keep the
      // secant damage from decreasing (an open step whose frozen-branch
      // solve failed): the traction re-derived from Eq. 1 then differs from
      // the return's. Such a step is halved; at the smallest substep the
      // drift correction of the explicit scheme returns it, and the tangent
      // becomes approximate.
      bool drift_corrected = false;
      if (!switch_here && yield_of(M, Q) > 10 * yield_tolerance(M, Q.sigma)) {
        if (dT > c.min_substep) {
          dT = std::max(0.5 * dT, c.min_substep);
          ++st.substeps_rejected;
          continue;
        }
        correct_drift(M, Q);
        drift_corrected = true;
      }
      if (sens && !drift_corrected) {
        // This step covers dT/(1 - T) of what is left of the increment.
        const Mat3 Ddd = (dT / (1 - T)) * (Mat3::Identity() - sens->separation);
        *sens = backward_euler_sensitivity(M, P, dd, b, *sens, Ddd);
      }
      P = Q;
      if (sens && !drift_corrected) settle_sensitivity(M, pre, sigma_pre, P.y, *sens);
      if (drift_corrected) forget_sensitivity();
      ++st.substeps_accepted;
      T += dT;
      if (switch_here) {
        at_boundary = true;
        return std::min(T, 1.0);
      }
      dT = 2 * dT;
    }
    return 1;
  }

  // Local error of the Heun pair relative to the end values (Sloan et al.
  // 2001, Eq. for R_n+1), over the traction, the softening factor and the
  // wear exponent; the traction norm is floored at 1e-3 ft0 so that states
  // near zero traction do not force endless subdivision.
  double local_error(const Rates& r1, const Rates& r2, const Point& N) const {
    const double floor = 1e-3 * M.stress_scale;
    const double e_sigma = 0.5 * (r2.dsigma - r1.dsigma).norm() / std::max(N.sigma.norm(), floor);
    const double e_s = 0.5 * std::abs((r2.dwI - r1.dwI) / M.p.GIC + (r2.dwII - r1.dwII) / M.p.GIIC);
    const double e_t = 0.5 * M.p.m * std::abs(r2.dwIII - r1.dwIII);
    return std::max(e_sigma, std::max(e_s, e_t));
  }

  double boundary_eps(const State& y) const {
    return 1e-12 * std::max({std::abs(y.separation[0]), std::abs(y.plastic[0]), M.p.ft0 / M.p.kn});
  }

  // One segment of constant regime over the separation increment `rest`.
  // An elastic path would reach the regime boundary at the fraction `frac`
  // (1 when it does not); the plastic part is integrated over all of `rest`
  // and finds its own boundary crossing. Returns the fraction of `rest` done;
  // sets at_boundary when it stopped on the boundary.
  double segment(const Vec3& rest, double frac, bool boundary) {
    at_boundary = false;
    const Vec3 K = secant_stiffness(M, P.y.dn, P.y.ds, P.y.open);
    const Vec3 e0 = P.y.elastic_separation();
    const Surface S = surface_of(M, P.y);
    auto F_at = [&](double a) { return yield_function(K.cwiseProduct(e0 + a * rest), S); };
    auto tol_at = [&](double a) { return yield_tolerance(M, K.cwiseProduct(e0 + a * rest)); };
    const double F0 = yield_function(P.sigma, S), tol0 = tol_at(0);
    const Vec3 n = flow_of(M, P.sigma, S, rate_stiffness(M, P.y).on_flow).dF;
    const Vec3 dsig = K.cwiseProduct(rest);
    const bool on_surface = std::abs(F0) <= tol0;
    const bool loading = n.dot(dsig) > 0;
    const bool at_edge = frac * std::abs(rest[0]) <= boundary_eps(P.y);
    // Implicit scheme: a point on the surface that the rate statement loads
    // (dF . kS rest > 0, kS on the damage-growing branch) is plastic however
    // small the increment (see backward_euler()).
    const bool rate_loading =
        implicit() && on_surface && n.dot(rate_stiffness(M, P.y).on_separation.cwiseProduct(rest)) > 0;
    if (F_at(frac) <= tol_at(frac) && !(on_surface && loading && at_edge) && !rate_loading) {
      P.y.separation += frac * rest;
      P.sigma = traction_of(M, P.y);
      if (sens) {
        sens->separation += frac * (Mat3::Identity() - sens->separation);
        secant_sensitivity(M, P.y, *sens);
      }
      ended_plastic = false;
      at_boundary = boundary;
      return frac;
    }
    double a_y = 0;
    if (F0 > tol0 && M.controls.scheme == Scheme::modified_euler) {
      if (!relax(M, P, st, false)) { st.failure = Failure::relaxation_failed; return 0; }
    } else if (F0 < -tol0) {
      a_y = pegasus(F_at, tol_at, 0, F0, frac, F_at(frac));
    } else if (on_surface && n.dot(dsig) < -1e-9 * n.norm() * dsig.norm()) {
      // On the surface but unloading first: reloading inside the same
      // increment? Scan for the first fraction with F < 0 (Sloan et al.).
      for (int i = 1; i <= 10; ++i) {
        const double a = 0.1 * i * frac;
        if (F_at(a) < -tol_at(a)) {
          a_y = pegasus(F_at, tol_at, a, F_at(a), frac, F_at(frac));
          break;
        }
      }
    }
    if (a_y > 0 && implicit()) a_y = refine_intersection(a_y, frac, rest, K, e0, S);
    if (a_y > 0) {
      P.y.separation += a_y * rest;
      P.sigma = traction_of(M, P.y);
      if (sens) intersection_sensitivity(a_y, rest, K);
    }
    st.plastic = true;
    ended_plastic = true;
    const double done = plastic((1 - a_y) * rest);
    return a_y + (1 - a_y) * done;
  }

  // Implicit scheme: Newton on the intersection fraction, from Pegasus's
  // answer (within FTOL) to round-off, so that the update is a smooth function
  // of the increment and its tangent can be checked by finite differences.
  double refine_intersection(double a, double frac, const Vec3& rest, const Vec3& K, const Vec3& e0,
                             const Surface& S) const {
    auto F_at = [&](double x) { return yield_function(K.cwiseProduct(e0 + x * rest), S); };
    double f = F_at(a);
    for (int it = 0; it < 4 && f != 0; ++it) {
      const Vec3 sigma = K.cwiseProduct(e0 + a * rest);
      const double slope = flow_of(M, sigma, S, K).dF.dot(K.cwiseProduct(rest));
      if (!(slope > 0)) break;
      const double an = std::clamp(a - f / slope, 0.0, frac);
      const double fn = F_at(an);
      if (!(std::abs(fn) < std::abs(f))) break;
      a = an;
      f = fn;
    }
    return a;
  }

  // The intersection fraction a moves with the increment: F(K o (e0 + a
  // rest), kappa) = 0 with rest = delta_end - delta_start gives
  // da = -(dF . dsigma|_a + dF/dkappa . dkappa) / (dF . K o rest).
  void intersection_sensitivity(double a, const Vec3& rest, const Vec3& K) {
    Sensitivity& D = *sens;
    D.separation += a * (Mat3::Identity() - D.separation);
    secant_sensitivity(M, P.y, D);  // at fixed a
    const LocalDerivatives ld = local_derivatives(M, P.sigma, Vec3(P.y.wI, P.y.wII, P.y.wIII));
    const Vec3 k_rest = K.cwiseProduct(rest);
    const double slope = ld.F_sigma.dot(k_rest);
    if (!(std::abs(slope) > 0)) return;
    const Eigen::RowVector3d da =
        -(ld.F_sigma.transpose() * D.sigma + ld.F_kappa.transpose() * D.kappa) / slope;
    D.separation += rest * da;
    D.sigma += k_rest * da;
  }

  template <class Fn, class Tol>
  static double pegasus(Fn F, Tol tol, double x0, double f0, double x1, double f1) {
    for (int it = 0; it < 100; ++it) {
      const double x = x1 - f1 * (x1 - x0) / (f1 - f0);
      const double fx = F(x);
      if (std::abs(fx) <= tol(x)) return x;
      if (fx * f1 < 0) { x0 = x1; f0 = f1; } else { f0 *= f1 / (f1 + fx); }
      x1 = x;
      f1 = fx;
    }
    return x1;
  }

  // Switch of the unilateral regime at the current separation (Eq. 13): the
  // stiffness jumps, the traction is re-derived from Eq. 1, the elastic
  // energy that the jump removes (opening) or adds (closing) is booked, and a
  // closing that lands outside the surface returns to it at fixed separation.
  bool switch_regime() {
    forget_sensitivity();
    const double before = elastic_energy(M, P.y);
    P.y.open = !P.y.open;
    P.y.energy_unilateral += before - elastic_energy(M, P.y);
    ++st.regime_switches;
    disintegrate_if_no_strength(M, P.y);
    P.sigma = traction_of(M, P.y);
    if (yield_of(M, P) > yield_tolerance(M, P.sigma)) {
      // The return depends on where the switch happened: treated as fixed.
      sensitivity_lost = true;
      return relax(M, P, st, false);
    }
    return true;
  }
};

bool finite(const State& s) {
  return check_state(s) == nullptr;
}

}  // namespace

Mat3 continuum_tangent(const Model& M, const State& y, const Vec3& sigma) {
  const Vec3 K = secant_stiffness(M, y.dn, y.ds, y.open);
  const Surface S = surface_of(M, y);
  const RateStiffness k = rate_stiffness(M, y);
  const Flow f = flow_of(M, sigma, S, k.on_flow);
  if (yield_function(sigma, S) < -yield_tolerance(M, sigma) || !(f.denominator > 0)) return K.asDiagonal();
  // Eq. 20: dsigma = kS (dd - m dl), dl = dF . kS dd / denominator.
  return Mat3(k.on_separation.asDiagonal()) -
         f.k_A_m * f.dF.cwiseProduct(k.on_separation).transpose() / f.denominator;
}

IncrementResult integrate_increment(const Model& M, State& state, const Vec3& d) {
  return integrate_increment(M, state, d, nullptr);
}

IncrementResult integrate_increment(const Model& M, State& state, const Vec3& d, Mat3* tangent) {
  IncrementResult res;
  IntegrationStatus& st = res.status;
  auto fail = [&](Failure f) {
    st.failure = f;
    state.status = static_cast<int>(f);
    state.substeps_accepted = st.substeps_accepted;
    state.substeps_rejected = st.substeps_rejected;
    // The start values, when they are finite (a state that obeys every rule
    // can still hold separations whose traction or energy overflows).
    const bool valid = check_state(state) == nullptr;
    const Vec3 sigma0 = valid ? traction_of(M, state) : Vec3::Zero();
    const double energy0 = valid ? elastic_energy(M, state) : 0.0;
    res.traction = sigma0.allFinite() ? sigma0 : Vec3::Zero();
    res.elastic_energy = std::isfinite(energy0) ? energy0 : 0.0;
    if (tangent) {
      // The secant of the start state: finite, and the stiffness a solver
      // that cuts the increment back will meet first.
      *tangent = check_state(state) ? Mat3(Vec3(M.p.kn, M.p.ks, M.p.ks).asDiagonal())
                                    : Mat3(secant_stiffness(M, state.dn, state.ds, state.open).asDiagonal());
      st.tangent_approximate = true;
    }
    return res;
  };
  if (check_state(state)) return fail(Failure::invalid_state);
  if (!d.allFinite()) return fail(Failure::non_finite_increment);

  Point P{state, traction_of(M, state)};
  Stepper step{M, P, st};
  Sensitivity sensitivity;
  if (tangent && M.controls.scheme == Scheme::implicit) step.sens = &sensitivity;
  const Vec3 sep_end = state.separation + d;
  double left = 1;  // fraction of d still to integrate
  for (int seg = 0; left > 1e-15; ++seg) {
    if (seg >= kMaxSegments) return fail(Failure::too_many_switches);
    const double e_n = P.y.elastic_separation()[0];
    const double eps = step.boundary_eps(P.y);
    // Regime flag inconsistent with the sign of delta_e_n (beyond round-off):
    // switch before integrating.
    if ((P.y.open && e_n < -eps) || (!P.y.open && e_n > eps)) {
      if (!step.switch_regime()) return fail(Failure::relaxation_failed);
      continue;
    }
    const Vec3 rest = left * d;
    // Where an elastic path would cross delta_e_n = 0.
    double frac = 1;
    bool boundary = false;
    if (crosses(P.y.open, e_n + rest[0]) && std::abs(e_n + rest[0]) > eps) {
      frac = std::clamp(-e_n / rest[0], 0.0, 1.0);
      boundary = true;
    }
    const double done = step.segment(rest, frac, boundary);
    if (!st.ok()) return fail(st.failure);
    left *= 1 - done;
    if (step.at_boundary && !step.switch_regime()) return fail(Failure::relaxation_failed);
  }
  // The pieces add up to d up to round-off; land exactly on the end point.
  if (P.y.separation != sep_end) {
    P.y.separation = sep_end;
    P.sigma = traction_of(M, P.y);
  }
  // Eq. 8 on the fully softened cone (s = 0) is |tau| - <-sigma_n> tan(phi)
  // = 0 up to round-off, which can leave w_II a few ulps below zero; w_II no
  // longer affects the strength there, and check_state() requires w_II >= 0.
  if (P.y.wII < 0) P.y.wII = 0;
  if (!finite(P.y) || !P.sigma.allFinite()) return fail(Failure::non_finite_result);
  // Finite separations can still give an elastic energy or a dissipation
  // increment beyond double's range (increments near 1e155 mm).
  const double energy_end = elastic_energy(M, P.y);
  const double d_plastic = P.y.dissipation_plastic - state.dissipation_plastic;
  const double d_damage = P.y.dissipation_damage - state.dissipation_damage;
  const double d_unilateral = P.y.energy_unilateral - state.energy_unilateral;
  if (!std::isfinite(energy_end) || !std::isfinite(d_plastic + d_damage + d_unilateral))
    return fail(Failure::non_finite_result);

  if (tangent) {
    if (step.sens) {
      *tangent = sensitivity.sigma;
      st.tangent_approximate = step.sensitivity_lost;
    } else {
      *tangent = step.ended_plastic ? continuum_tangent(M, P.y, P.sigma)
                                    : Mat3(secant_stiffness(M, P.y.dn, P.y.ds, P.y.open).asDiagonal());
      st.tangent_approximate = step.ended_plastic;
    }
    if (!tangent->allFinite()) return fail(Failure::non_finite_result);
  }
  res.d_dissipation_plastic = d_plastic;
  res.d_dissipation_damage = d_damage;
  res.d_energy_unilateral = d_unilateral;
  P.y.substeps_accepted = st.substeps_accepted;
  P.y.substeps_rejected = st.substeps_rejected;
  P.y.status = 0;
  state = P.y;
  res.traction = P.sigma;
  res.elastic_energy = energy_end;
  return res;
}

}  // namespace mortar
