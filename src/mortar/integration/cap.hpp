// The compression cap in the integration (docs/model.md 12): the rate
// statement with two active surfaces (Koiter's rule, a multiplier each), the
// drift back onto the cap, and the backward-Euler step onto the cap or the
// corner where it meets the hyperbola of Eq. 2. Only a closed joint with a
// cap comes here (cap_applies); everything else is the one-surface path.
#pragma once

#include "mortar/integration/point.hpp"
#include "mortar/integration/rate_statement.hpp"
#include "mortar/integration/sensitivity.hpp"
#include "mortar/physics/compression_cap.hpp"
#include "mortar/result.hpp"

namespace mortar {

// F of Eq. 2, or where the cap applies the larger of it and F_c: the point is
// inside both surfaces when this is <= FTOL (both are in MPa).
inline double yield_of_surfaces(const Model& M, const Point& P, const SurfaceAt& at) {
  const double F = yield_of(P, at);
  if (!cap_applies(M, P.y)) return F;
  return std::max(F, cap_function(M, P.sigma, P.y.kappa_c));
}
inline double yield_of_surfaces(const Model& M, const Vec3& sigma, const Surface& S, const State& y) {
  const double F = yield_function(sigma, S);
  if (!cap_applies(M, y)) return F;
  return std::max(F, cap_function(M, sigma, y.kappa_c));
}

// The band within which a closed point with a cap counts as on a surface in
// the rate statement: FTOL, or where larger STOL of the traction, within
// which an accepted substep ends (docs/model.md 12).
inline double on_surface_band(const Model& M, const Vec3& sigma) {
  return std::max(yield_tolerance(M, sigma), M.controls.stol * std::max(sigma.norm(), M.stress_scale));
}

// The rate statement of a closed joint on the cap (F_c >= -FTOL) over dd:
// the active set by Koiter's rule (the corner when both multipliers come out
// positive, else the one surface loaded that the other does not see
// violated); elastic where P is on neither. False when P is on Eq. 2 alone:
// the one-surface stage applies.
bool capped_stage(const Model& M, const Point& P, const SurfaceAt& at, const Vec3& dd, Rates& r);

// After an accepted explicit substep: a closed point beyond the cap returns
// to it at fixed separation, with its hardening (the consistent correction
// along K m_c, iterated).
void correct_cap_drift(const Model& M, Point& P);

// The unknowns of the cap's local problem (sigma, lc) or the corner's
// (sigma, w, l1, lc): traction, works of Eqs. 7-9, the multipliers of Eq. 2
// and of the cap.
struct CapSolution {
  bool ok = false;
  Vec3 sigma = Vec3::Zero(), w = Vec3::Zero();
  double l1 = 0, lc = 0;
};

// The backward-Euler step of a closed joint with a cap over dd, where the cap
// is involved: the trial beyond it, or `one_surface` (the step of Eq. 2
// alone, already taken) ending beyond it. Returns involved = false when the
// one-surface step stands; else ok with N (before settle) and the solution x
// (at the corner when `corner`), or not ok (the caller halves).
struct CapStep {
  bool involved = false, ok = false, plastic = false, corner = false;
  Point N;
  CapSolution x;
};
CapStep cap_backward_euler(const Model& M, const Point& P, const Vec3& dd, const Point* one_surface,
                           IntegrationStatus& st);

// The continuum tangent (Eq. 20) of a closed point on the cap: with its flow
// alone, or with both at the corner. False where the point is not on the cap.
bool capped_tangent(const Model& M, const State& y, const Vec3& sigma, const Surface& S, const Flow& f, Mat3& D);

// The derivatives of a cap or corner step's end with respect to the call's
// separation increment (the consistent tangent, docs/model.md 12): its local
// residual at the solution, differentiated in the start point (DP) and the
// step's separation increment (Ddd), through the same Newton matrix.
Sensitivity cap_step_sensitivity(const Model& M, const Point& P, const CapStep& c, const Sensitivity& DP,
                                 const Mat3& Ddd);

// A closed point beyond the cap returned to it at fixed separation (the
// backward-Euler step over dd = 0), the corner included.
bool return_to_cap(const Model& M, Point& P, IntegrationStatus& st);

}  // namespace mortar
