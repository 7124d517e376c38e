// The integration schemes (docs/model.md 7): forward Euler (7.2), modified
// Euler with error control (7.1) and backward Euler (7.5), each a small
// strategy behind one interface that the one substepper (substepper.hpp)
// drives. A scheme says how a substep is attempted, what it checks after
// settle(), what it does on acceptance and how the next substep is sized;
// its traits say how a segment treats it. Fourth scheme: one more class here
// and one more case in integrator.cpp.
#pragma once

#include "mortar/integration/backward_euler.hpp"
#include "mortar/integration/cap.hpp"
#include "mortar/integration/rate_statement.hpp"
#include "mortar/integration/sensitivity.hpp"
#include "mortar/result.hpp"

namespace mortar {

// How a segment (integration/increment.cpp) treats a scheme.
struct SchemeTraits {
  // A segment that starts outside the surface returns to it at fixed
  // separation first (else the substeps start from there).
  bool relaxes_start_outside = false;
  // The elastic-plastic intersection is polished to round-off by Newton, so
  // that the update is smooth in the increment (a checkable tangent).
  bool refines_intersection = false;
  // The tangent is the consistent one (TangentTracker), else the continuum
  // tangent of Eq. 20 after plastic flow.
  bool consistent_tangent = false;
  // The damage branches of a substep are those its first stage took (the
  // explicit schemes); the implicit scheme's local solve picks its own.
  bool branches_from_first_stage = false;
};

// The smallest substep of a plastic part of length n (|d|) from a point of
// strength s_raw, as a fraction of it (docs/model.md 7.4): min_substep, but
// never longer than min_substep L / s_raw, L the material length over which
// the joint softens (Model::substep_length). A floor that is a fraction of
// the increment alone grows with the increment, past that length, and the
// substeps accepted there above STOL book energy the law does not dissipate ...
// The rest: docs/numerics.md, section 9.
inline double min_substep_floor(const Model& M, double n, double s_raw) {
  const double c = M.controls.min_substep, L = M.substep_length, ns = n * s_raw;
  return ns > L ? c * (L / ns) : c;
}

// What one attempted substep came to.
struct Attempt {
  enum Kind { step, retry, fail, on_boundary } kind = step;
  Point* end = nullptr;  // step, on_boundary: the end point before settle(), held by the scheme
                         // until its next attempt; the substepper settles a step's in place
  const Surface* surface = nullptr;  // step: the surface of end's works (tan_psi perhaps left to
                                     // with_psi), when the scheme evaluated it
  double size = 0;             // retry: the substep size to try next
  Failure failure = Failure::none;
  double theta = 0;            // on_boundary: the fraction of the substep done
};

class SubstepScheme {
 public:
  explicit SubstepScheme(SchemeTraits t) : traits(t) {}
  const SchemeTraits traits;

  // A budget of the scheme's own spent (checked before each substep).
  virtual Failure budget_spent(const IntegrationStatus&) const { return Failure::none; }
  // One substep from P over dd (the fraction dT of the plastic part);
  // first_stage is the rate statement at P over dd (not a snap-back).
  virtual Attempt attempt(const Point& P, const Vec3& dd, double dT, const Rates& first_stage) = 0;
  // The end point Q, before settle() (the consistent tangent needs it).
  virtual void before_settle(const Point&) {}
  // After settle(): a retry size when the substep is rejected, else 0. `at`
  // is the surface at Q (surface_at), kept so where the scheme changes Q.
  virtual double recheck(Point&, SurfaceAt&, double /*dT*/, bool /*switch_here*/) { return 0; }
  // Accepts Q as the new P; T is the fraction of the plastic part done
  // before. `at`: the surface at Q, on return the surface at P.
  virtual void commit(Point& P, const Point& Q, SurfaceAt&, const Vec3& /*dd*/, double /*T*/, double /*dT*/,
                      bool /*switch_here*/) {
    P = Q;
  }
  // Size of the next substep after an accepted one of size dT.
  virtual double next_size(double dT) = 0;
  // The smallest substep of this run, as a fraction of its separation
  // increment (min_substep_floor); set by the substepper before each run.
  void set_floor(double floor) { floor_ = floor; }

 protected:
  ~SubstepScheme() = default;
  double floor_ = 1e-4;
};

// One explicit step of the rate statement per substep, no error control.
class ForwardEuler final : public SubstepScheme {
 public:
  ForwardEuler() : SubstepScheme(SchemeTraits{false, false, false, true}) {}
  Attempt attempt(const Point& P, const Vec3& dd, double dT, const Rates& first_stage) override;
  double next_size(double) override { return 1; }

 private:
  Point end_;
};

// The Heun pair with local error control and drift correction (Sloan, Abbo &
// Sheng 2001).
class ModifiedEuler final : public SubstepScheme {
 public:
  ModifiedEuler(const Model& M, IntegrationStatus& st)
      : SubstepScheme(SchemeTraits{true, false, false, true}), M_(M), st_(st) {}
  Attempt attempt(const Point& P, const Vec3& dd, double dT, const Rates& first_stage) override;
  double recheck(Point& Q, SurfaceAt& at, double dT, bool switch_here) override;
  void commit(Point& P, const Point& Q, SurfaceAt& at, const Vec3& dd, double T, double dT, bool switch_here) override;
  double next_size(double dT) override;

 private:
  double step_error(const Point& P, const Point& N, const Rates& r1, double part);
  const Model& M_;
  IntegrationStatus& st_;
  Point end_;
  Surface end_surface_;  // of end_'s works: the error estimate's, and the next substep's
  Branches grow_;  // the first stage's damage branches (drift correction)
  // The substep's start: damages and squared elastic separations (normal,
  // in-plane), for the damage booking's check in recheck().
  struct DamageStart {
    double dn = 0, ds = 0, en2 = 0, es2 = 0;
  } start_;
  double error_ = 0;
  bool last_rejected_ = false;
};

// The local error of a substep (docs/model.md 7.1, 7.5): half the difference
// of two estimates of its increments, r2 against the forward-Euler stage r1,
// over the traction, the softening factor (relative) and the wear exponent.
double local_error(const Model& M, const Point& P, const Rates& r1, const Rates& r2, const Point& N,
                   const Surface& S);

// Backward-Euler steps (return mapping), halved on a failed local solve, with
// the consistent tangent carried through every accepted step on request.
// With error control (scheme 3, docs/model.md 7.5) a step whose end differs
// from the forward-Euler stage by more than STOL / 10 (local_error) is cut
// and the branches are stage()'s; the explicit schemes' apex-zone steps
// (substepper.hpp) keep the earlier step.
class BackwardEuler final : public SubstepScheme {
 public:
  BackwardEuler(const Model& M, IntegrationStatus& st, TangentTracker& tangent, bool error_control = false)
      : SubstepScheme(SchemeTraits{false, true, true}), M_(M), st_(st), tangent_(tangent),
        error_control_(error_control) {}
  Failure budget_spent(const IntegrationStatus& st) const override;
  Attempt attempt(const Point& P, const Vec3& dd, double dT, const Rates& first_stage) override;
  void before_settle(const Point& Q) override;
  double recheck(Point& Q, SurfaceAt& at, double dT, bool switch_here) override;
  void commit(Point& P, const Point& Q, SurfaceAt& at, const Vec3& dd, double T, double dT, bool switch_here) override;
  double next_size(double dT) override;

 private:
  double step_error(const Point& P, const Point& N, const Rates& r1, double part);
  Attempt end_at(const Point& N, const Point& P, double dT, const Rates& r1);
  Attempt halved_or_failed(double dT);
  Attempt cap_attempt(const CapStep& c, const Point& P, double dT, const Rates& r1);
  const Model& M_;
  IntegrationStatus& st_;
  TangentTracker& tangent_;
  const bool error_control_;
  double error_ = 0;
  bool last_rejected_ = false;
  Surface end_surface_;
  BackwardEulerStep step_;
  Point end_;  // step_.N, settled in place by the substepper: the tangent reads step_ unsettled
  BoundaryStep boundary_;
  State pre_settle_;
  Vec3 sigma_pre_settle_ = Vec3::Zero();
  bool drift_corrected_ = false;
  bool cap_step_ = false;  // the last step was onto the cap or the corner
  CapStep cap_;            // that step, for its tangent
};

}  // namespace mortar
