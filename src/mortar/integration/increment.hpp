// One increment of one point cut into segments of constant unilateral regime
// (Eq. 13, docs/model.md 6-7): in each, the elastic part with the secant
// stiffness (Eq. 1, 21) up to the elastic-plastic intersection (Pegasus),
// then the substepper over the plastic part; a switch of regime is resolved
// at the point where it happens.
#pragma once

#include "mortar/integration/substepper.hpp"

namespace mortar {

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
  double refine_intersection(double a, double frac, const Vec3& rest, const Vec3& K, const Vec3& e0,
                             const Surface& S) const;
  bool switch_regime();

  const Model& M_;
  Point& P_;
  IntegrationStatus& st_;
  TangentTracker& tangent_;
  SubstepScheme& scheme_;
  Substepper substepper_;
  bool at_boundary_ = false;
  bool ended_plastic_ = false;
};

}  // namespace mortar
