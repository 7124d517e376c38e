#include "mortar/integration/scheme.hpp"

#include <algorithm>
#include <cmath>

#include "mortar/integration/cap.hpp"
#include "mortar/integration/drift_correction.hpp"

namespace mortar {

namespace {

constexpr double kTiny = 1e-300;
// The local error of a closed joint's softening factor is relative to what is
// left of it down to this share of the strength (docs/model.md 7.1).
constexpr double kClosedStrengthFloor = 1e-5;
// Implicit scheme: Newton iterations (all local solves) allowed per increment,
// per substep of the budget props(18) (docs/model.md 9), so that the budget
// bounds this scheme's work too. A smooth increment takes 3-10; at the
// default budget of 10^5 substeps, 2e5 iterations bound the worst case to
// about 0.3 s (tests/law/test_robustness.cpp, invariant 10: 35 of 48 000
// extreme increments fail on it or at the smallest substep).
constexpr long kNewtonIterationsPerSubstep = 2;

Attempt step_to(Point& N) { return Attempt{Attempt::step, &N}; }
Attempt retry_with(double size) {
  Attempt a;
  a.kind = Attempt::retry;
  a.size = size;
  return a;
}
double halved(double floor, double dT) { return std::max(0.5 * dT, floor); }

// The implicit scheme keeps backward Euler's end point, whose local error is
// the estimate itself (modified Euler keeps the Heun point, one order better
// than its estimate): it holds the estimate to this share of STOL
// (docs/model.md 7.5, Decision - error control of the implicit scheme).
constexpr double kImplicitStolShare = 0.1;
double implicit_tolerance(const Model& M) { return kImplicitStolShare * M.controls.stol; }

// The end of the first stage: P + r1 over dd.
Point first_stage_end(const Point& P, const Vec3& dd, const Rates& r1) {
  Point A = P;
  add(A, r1, 1.0);
  A.y.separation += dd;
  return A;
}

}  // namespace

// ---------------------------------------------------------------------------
// Forward Euler (docs/model.md 7.2).

Attempt ForwardEuler::attempt(const Point& P, const Vec3& dd, double, const Rates& first_stage) {
  end_ = first_stage_end(P, dd, first_stage);
  return step_to(end_);
}

// ---------------------------------------------------------------------------
// Modified Euler (docs/model.md 7.1).

Attempt ModifiedEuler::attempt(const Point& P, const Vec3& dd, double dT, const Rates& r1) {
  const Controls& c = M_.controls;
  const Point A = first_stage_end(P, dd, r1);
  const Vec3 e0 = P.y.elastic_separation();
  start_ = DamageStart{P.y.dn, P.y.ds, e0[0] * e0[0], e0[1] * e0[1] + e0[2] * e0[2]};
  grow_ = r1.grow;
  error_ = 0;
  const SurfaceAt at_A = surface_at(M_, A);
  const Rates r2 = stage(M_, A, at_A, dd, r1.grow);
  // The second stage entered the snap-back region: halve; at the smallest
  // substep the first stage alone stands (forward Euler).
  if (r2.snapback && dT > floor_) return retry_with(halved(floor_, dT));
  if (r2.snapback) {
    st_.min_substep_hit = true;
    end_ = A;
    end_surface_ = at_A.S;
  } else {
    end_ = P;
    add(end_, r1, 0.5);
    add(end_, r2, 0.5);
    end_.y.separation += dd;
    shape_into(M_, end_.y.wI, end_.y.wII, end_.y.wIII, end_surface_);
    error_ = local_error(M_, P, r1, r2, end_, end_surface_);
  }
  if (error_ > c.stol && dT > floor_) {
    last_rejected_ = true;
    return retry_with(std::max(std::max(0.9 * std::sqrt(c.stol / error_), 0.1) * dT, floor_));
  }
  if (error_ > c.stol) st_.min_substep_hit = true;
  Attempt a = step_to(end_);
  a.surface = &end_surface_;
  return a;
}

// A Heun substep that ends far outside the surface (an open, damaged joint:
// the two stages straddle a kink of the flow) is not what the drift
// correction is for: correcting it can push sigma_n through zero, which the
// secant damage rule reads as complete normal damage. Such a substep is
// rejected and halved (docs/robustness.md). Far: beyond 1e-3 of the traction
// scale, the larger of |sigma| and ft0.
// The rest: docs/numerics.md, section 8.
double ModifiedEuler::recheck(Point& Q, SurfaceAt& at, double dT, bool switch_here) {
  if (switch_here || !(dT > floor_)) return 0;
  if (yield_of_surfaces(M_, Q, at) > 1e-3 * std::max(Q.sigma.norm(), M_.p.ft0)) {
    last_rejected_ = true;
    return halved(floor_, dT);
  }
  const Vec3 e = Q.y.elastic_separation();
  const double es2 = e[1] * e[1] + e[2] * e[2];
  const double booking = 0.25 * std::max(M_.p.kn * (Q.y.dn - start_.dn) * std::abs(e[0] * e[0] - start_.en2) / M_.p.GIC,
                                         M_.p.ks * (Q.y.ds - start_.ds) * std::abs(es2 - start_.es2) / M_.p.GIIC);
  if (!(booking > M_.controls.stol)) return 0;
  last_rejected_ = true;
  return std::max(std::max(0.9 * std::sqrt(M_.controls.stol / booking), 0.1) * dT, floor_);
}

// Not at a switch: the drift correction's plastic displacement would move
// the point off the boundary again; the switch re-derives the traction in the
// new regime and returns it to the surface if needed.
void ModifiedEuler::commit(Point& P, const Point& Q, SurfaceAt& at, const Vec3&, double, double, bool switch_here) {
  P = Q;
  if (switch_here) return;
  correct_drift(M_, P, at, grow_);
  if (cap_applies(M_, P.y)) {
    correct_cap_drift(M_, P);
    at.radius = shear_radius(P.sigma, at.S);
  }
}

double ModifiedEuler::next_size(double dT) {
  const Controls& c = M_.controls;
  double q = std::min(0.9 * std::sqrt(c.stol / std::max(error_, kTiny)), 1.1);
  if (last_rejected_) q = std::min(q, 1.0);
  last_rejected_ = false;
  return std::max(q * dT, floor_);
}

// Local error of the Heun pair relative to the end values (Sloan et al.
// 2001, Eq. for R_n+1), over the traction, the softening factor (relative)
// and the wear exponent; the traction norm is floored at 1e-3 ft0 so that
// states near zero traction do not force endless subdivision.
// The implicit scheme passes its step's increments as r2 (docs/model.md 7.5).
double local_error(const Model& M_, const Point& P, const Rates& r1, const Rates& r2, const Point& N,
                   const Surface& S) {
  const double floor = 1e-3 * M_.stress_scale;
  const double e_sigma = 0.5 * (r2.dsigma - r1.dsigma).norm() / std::max(N.sigma.norm(), floor);
  // The softening factor relative to what is left of it (docs/model.md 7.1):
  // where s runs out an absolute error lets the place of the separation
  // depend on the cuts. A fully softened joint has no error in its surface;
  // a closed one is measured against kClosedStrengthFloor.
  // The rest: docs/numerics.md, section 20.
  const bool softened = 1.0 - P.y.wI / M_.p.GIC - P.y.wII / M_.p.GIIC <= 0;
  const double left = std::max(S.s, P.y.open ? kSeparated : kClosedStrengthFloor);
  const double e_s =
      softened ? 0.0 : 0.5 * std::abs((r2.dwI - r1.dwI) / M_.p.GIC + (r2.dwII - r1.dwII) / M_.p.GIIC) / left;
  const double e_t = 0.5 * M_.p.m * std::abs(r2.dwIII - r1.dwIII);
  const double error = std::max(e_sigma, std::max(e_s, e_t));
  if (!M_.cap.on()) return error;
  // The cap's strength, relative to fc (docs/model.md 12): its steepest
  // softening slope is fc / (kappa_m - kappa_p).
  const double e_c = 0.5 * std::abs(r2.dkappa_c - r1.dkappa_c) / M_.cap_softening_span;
  return std::max(error, e_c);
}

// ---------------------------------------------------------------------------
// Backward Euler (docs/model.md 7.5).

// The substep budget alone allows millions of Newton iterations (each
// halving down to min_substep restarts the local solves); a solver waiting
// on this point would see a hang, so the work is capped too.
Failure BackwardEuler::budget_spent(const IntegrationStatus& st) const {
  const long allowed = kNewtonIterationsPerSubstep * M_.controls.max_substeps;
  return st.newton_iterations > allowed ? Failure::local_solve_failed : Failure::none;
}

// The whole plastic part first; a step whose Newton iteration fails is halved
// (down to the minimum substep, then Failure::local_solve_failed).
Attempt BackwardEuler::attempt(const Point& P, const Vec3& dd, double dT, const Rates& r1) {
  cap_step_ = false;
  // A closed joint whose trial lies beyond the cap, or whose step of Eq. 2
  // ends beyond it: the step onto the cap or the corner (integration/cap.hpp).
  const bool capped = cap_applies(M_, P.y);
  if (capped) {
    const CapStep c = cap_backward_euler(M_, P, dd, nullptr, st_);
    if (c.involved) return cap_attempt(c, P, dT, r1);
  }
  step_ = backward_euler(M_, P, dd, st_, error_control_);
  if (capped && step_.ok && step_.plastic) {
    const CapStep c = cap_backward_euler(M_, P, dd, &step_.N, st_);
    if (c.involved) return cap_attempt(c, P, dT, r1);
  }
  if (!step_.ok && !P.y.open && P.sigma[0] + M_.p.kn * dd[0] > 0) {
    // No closed-regime solution and a tensile trial: the step may cross into
    // the open regime where no closed point exists; end it on the boundary.
    boundary_ = backward_euler_to_boundary(M_, P, dd, st_);
    if (boundary_.ok) {
      // The step to the boundary covers theta dd: its error is against the
      // forward-Euler stage over theta dd, theta r1 (one stage is linear in
      // its separation increment).
      if (error_control_ && dT > floor_ && step_error(P, boundary_.N, r1, boundary_.theta) > implicit_tolerance(M_)) {
        last_rejected_ = true;
        return retry_with(halved(floor_, dT));
      }
      Attempt a{Attempt::on_boundary, &boundary_.N};
      a.theta = boundary_.theta;
      return a;
    }
  }
  if (step_.ok) return end_at(step_.N, P, dT, r1);
  return halved_or_failed(dT);
}

// The step's end N accepted as the substep's end, under error control when
// the scheme has it: the step's increments against the forward-Euler stage
// differ by twice backward Euler's local error to leading order
// (docs/model.md 7.5).
Attempt BackwardEuler::end_at(const Point& N, const Point& P, double dT, const Rates& r1) {
  end_ = N;
  if (!error_control_) return step_to(end_);
  error_ = step_error(P, end_, r1, 1.0);
  if (error_ > implicit_tolerance(M_) && dT > floor_) {
    last_rejected_ = true;
    return retry_with(halved(floor_, dT));
  }
  if (error_ > implicit_tolerance(M_)) st_.min_substep_hit = true;
  Attempt a = step_to(end_);
  a.surface = &end_surface_;
  return a;
}

// A failed local solve: halved, down to the minimum substep.
Attempt BackwardEuler::halved_or_failed(double dT) {
  if (dT > M_.controls.min_substep) return retry_with(halved(M_.controls.min_substep, dT));
  Attempt a{Attempt::fail};
  a.failure = Failure::local_solve_failed;
  return a;
}

// A step onto the cap or the corner (cap_backward_euler), kept for its
// tangent (cap_step_sensitivity).
Attempt BackwardEuler::cap_attempt(const CapStep& c, const Point& P, double dT, const Rates& r1) {
  if (!c.ok) return halved_or_failed(dT);
  cap_step_ = true;
  cap_ = c;
  return end_at(cap_.N, P, dT, r1);
}

// Without error control the step doubles. With it the sizes stay halvings
// and doublings of the plastic part (docs/model.md 7.5): the step doubles when
// its error, second order in the step, would stay within the tolerance.
double BackwardEuler::next_size(double dT) {
  const bool grow = !error_control_ || (!last_rejected_ && 4 * error_ <= implicit_tolerance(M_));
  last_rejected_ = false;
  return grow ? 2 * dT : dT;
}

// local_error of a step from P to N (before settle) against the forward-Euler
// stage r1 scaled by the part of the substep the step covers.
double BackwardEuler::step_error(const Point& P, const Point& N, const Rates& r1, double part) {
  Rates fe, be;
  fe.dsigma = part * r1.dsigma;
  fe.dwI = part * r1.dwI;
  fe.dwII = part * r1.dwII;
  fe.dwIII = part * r1.dwIII;
  fe.dkappa_c = part * r1.dkappa_c;
  be.dsigma = N.sigma - P.sigma;
  be.dwI = N.y.wI - P.y.wI;
  be.dwII = N.y.wII - P.y.wII;
  be.dwIII = N.y.wIII - P.y.wIII;
  be.dkappa_c = N.y.kappa_c - P.y.kappa_c;
  shape_into(M_, N.y.wI, N.y.wII, N.y.wIII, end_surface_);
  return local_error(M_, P, fe, be, N, end_surface_);
}

void BackwardEuler::before_settle(const Point& Q) {
  pre_settle_ = Q.y;
  sigma_pre_settle_ = Q.sigma;
}

// The end point lies on the surface unless settle() had to keep the secant
// damage from decreasing (an open step whose frozen-branch solve failed):
// the traction re-derived from Eq. 1 then differs from the return's. Such a
// step is halved; at the smallest substep the drift correction of the
// explicit scheme returns it, and the tangent becomes approximate.
double BackwardEuler::recheck(Point& Q, SurfaceAt& at, double dT, bool switch_here) {
  drift_corrected_ = false;
  if (switch_here || !(yield_of_surfaces(M_, Q, at) > 10 * yield_tolerance(M_, Q.sigma))) return 0;
  if (dT > M_.controls.min_substep) return halved(M_.controls.min_substep, dT);
  correct_drift(M_, Q, at);
  if (cap_applies(M_, Q.y)) {
    correct_cap_drift(M_, Q);
    at.radius = shear_radius(Q.sigma, at.S);
  }
  drift_corrected_ = true;
  return 0;
}

void BackwardEuler::commit(Point& P, const Point& Q, SurfaceAt&, const Vec3& dd, double T, double dT, bool) {
  const bool carry = tangent_ && !drift_corrected_;
  if (carry) {
    // This step covers dT/(1 - T) of what is left of the increment.
    Sensitivity& D = *tangent_.D;
    const Mat3 Ddd = (dT / (1 - T)) * (Mat3::Identity() - D.separation);
    D = cap_step_ ? cap_step_sensitivity(M_, P, cap_, D, Ddd) : backward_euler_sensitivity(M_, P, dd, step_, D, Ddd);
  }
  P = Q;
  if (carry) settle_sensitivity(M_, pre_settle_, sigma_pre_settle_, P.y, *tangent_.D);
  if (drift_corrected_) tangent_.forget(st_);
}

}  // namespace mortar
