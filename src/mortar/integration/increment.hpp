// One increment of one point cut into segments of constant unilateral regime
// (Eq. 13, docs/model.md 6-7): in each, the elastic part with the secant
// stiffness (Eq. 1, 21) up to the elastic-plastic intersection (Pegasus),
// then the substepper over the plastic part; a switch of regime is resolved
// at the point where it happens.
#pragma once

#include "mortar/integration/substepper.hpp"

namespace mortar {

constexpr int kMaxSegments = 32;  // regime segments in one increment (docs/model.md 9, code 3)

// What the loop of one increment's segments has done so far, and the bound it
// has reached (docs/model.md 9). A segment ends on a regime switch, or is
// restarted in the same regime where the substepper hands the rest back (the
// point left the surface, the normal completed, the joint separated). Only
// the switches make regime segments (code 3). A restart follows at least one
// accepted substep, so the substep budget bounds the restarts (code 1); the
// count is the guard that the loop ends even where a restart would not.
struct SegmentCount {
  int switches = 0;
  long restarts = 0;
  // Before the next segment: Failure::none, or why the loop stops.
  Failure check(const Controls& c) const {
    if (switches >= kMaxSegments) return Failure::too_many_switches;
    if (restarts > c.max_substeps) return Failure::too_many_substeps;
    return Failure::none;
  }
};

class IncrementIntegration {
 public:
  IncrementIntegration(const Model& M, Point& P, IntegrationStatus& st, TangentTracker& tangent,
                       SubstepScheme& scheme)
      : M_(M), P_(P), st_(st), tangent_(tangent), scheme_(scheme), substepper_{M, P, st, tangent, scheme} {}

  // Integrates the separation increment d from P; Failure::none or why not.
  Failure run(const Vec3& d);
  // The last segment had plastic flow (the explicit schemes' continuum tangent).
  bool ended_plastic() const { return ended_plastic_; }

 private:
  double segment(const Vec3& rest, double frac, bool boundary);
  double reentry(double frac, const Vec3& rest, const Vec3& K, const Vec3& e0, const Surface& S) const;
  double refine_intersection(double a, double frac, const Vec3& rest, const Vec3& K, const Vec3& e0,
                             const Surface& S) const;
  bool switch_regime();
  double trial_yield(const Vec3& sigma, const Surface& S) const;
  double trial_slope(const Vec3& sigma, const Surface& S, const Vec3& K, const Vec3& dsig) const;
  bool return_to_surfaces();

  const Model& M_;
  Point& P_;
  IntegrationStatus& st_;
  TangentTracker& tangent_;
  SubstepScheme& scheme_;
  Substepper substepper_;
  bool at_boundary_ = false;
  bool ended_plastic_ = false;
  bool capped_ = false;  // the segment's joint is closed and has a cap (cap_applies)
  double kappa_c_ = 0;   // its kappa_c, fixed along the elastic part
};

}  // namespace mortar
