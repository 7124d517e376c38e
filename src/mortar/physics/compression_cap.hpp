// The compression cap (docs/model.md 12; beyond the paper, in the form of
// Lourenco & Rots 1997): the ellipse sigma_n^2 + Cs tau^2 = sigma_c(kappa_c)^2,
// written in stress units as
//   F_c = sqrt(sigma_n^2 + Cs tau^2) - sigma_c(kappa_c),
// with associated flow m_c = dF_c/dsigma. On the cap sigma . m_c = sigma_c, so
// with kappa_c' = lambda_c the plastic work of crushing is sigma_c dkappa_c.
// Pure functions of (traction, kappa_c); they know nothing of integration.
#pragma once

#include <cmath>

#include "mortar/parameters.hpp"
#include "mortar/state.hpp"

namespace mortar {

// sigma_c(kappa_c) and its slope (docs/model.md 12), continuous with its
// slope: from fc/3 up a parabola to fc at kappa_p (zero slope there), down a
// parabola to fc/2 at kappa_m, then exponentially to the residual fc/7 (the
// three pieces of Lourenco & Rots). kappa_m - kappa_p = 588 Gfc / (481 fc)
// makes the area between the curve and the residual after the peak Gfc.
struct CapStrength {
  double value = 0, slope = 0;
};
inline CapStrength cap_strength(const Model& M, double kappa_c) {
  const CompressionCap& c = M.cap;
  const double k = kappa_c > 0 ? kappa_c : 0.0;
  if (k < c.kappa_p) {
    const double x = k / c.kappa_p, rise = c.fc - M.cap_initial;
    return {M.cap_initial + rise * x * (2 - x), 2 * rise * (1 - x) / c.kappa_p};
  }
  const double span = M.cap_softening_span, mid = 0.5 * c.fc;
  if (k < c.kappa_p + span) {
    const double h = (k - c.kappa_p) / span;
    return {c.fc + (mid - c.fc) * h * h, 2 * (mid - c.fc) * h / span};
  }
  const double slope_m = 2 * (mid - c.fc) / span, above = mid - M.cap_residual;
  const double e = std::exp(slope_m * (k - c.kappa_p - span) / above);
  return {M.cap_residual + above * e, slope_m * e};
}

// sqrt(sigma_n^2 + Cs tau^2): the cap's radius of a traction.
inline double cap_radius(const Model& M, const Vec3& sigma) {
  return std::sqrt(sigma[0] * sigma[0] + M.cap.Cs * (sigma[1] * sigma[1] + sigma[2] * sigma[2]));
}
inline double cap_function(const Model& M, const Vec3& sigma, double kappa_c) {
  return cap_radius(M, sigma) - cap_strength(M, kappa_c).value;
}
// dF_c/dsigma = (sigma_n, Cs tau1, Cs tau2) / radius: the flow direction too
// (associated). The origin, far inside the cap, takes (0, 0, 0).
inline Vec3 cap_gradient(const Model& M, const Vec3& sigma) {
  const double q = cap_radius(M, sigma);
  if (!(q > 0)) return Vec3::Zero();
  return Vec3(sigma[0], M.cap.Cs * sigma[1], M.cap.Cs * sigma[2]) / q;
}
// d m_c / d sigma = (P - m_c m_c^T) / radius, P = diag(1, Cs, Cs).
inline Mat3 cap_hessian(const Model& M, const Vec3& sigma) {
  const double q = cap_radius(M, sigma);
  if (!(q > 0)) return Mat3::Zero();
  const Vec3 m = cap_gradient(M, sigma);
  Mat3 H = Vec3(1, M.cap.Cs, M.cap.Cs).asDiagonal();
  H -= m * m.transpose();
  return H / q;
}

// Whether the cap can act on a point: a cap is given and the joint is closed
// (the validation rule keeps it off open joints, docs/model.md 12).
inline bool cap_applies(const Model& M, const State& y) { return M.cap.on() && !y.open; }

}  // namespace mortar
