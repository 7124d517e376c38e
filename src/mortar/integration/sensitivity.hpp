// Derivatives of the working point with respect to the separation increment
// of the whole call, carried through every piece of an implicit increment;
// at the end `sigma` is the consistent tangent (docs/model.md 7.5).
#pragma once

#include <Eigen/Core>

#include "mortar/integration/backward_euler.hpp"

namespace mortar {

using Mat23 = Eigen::Matrix<double, 2, 3>;

// The separation is carried too, because every piece of the increment is the
// rest of it, delta_end - delta_current, whose derivative is I - d delta.
struct Sensitivity {
  Mat3 sigma = Mat3::Zero(), kappa = Mat3::Zero(), plastic = Mat3::Zero(), separation = Mat3::Zero();
  Mat23 damage = Mat23::Zero();  // (d_n, d_s)
  Eigen::RowVector3d kappa_c = Eigen::RowVector3d::Zero();  // the cap's (docs/model.md 12)
};

// The sensitivity of one increment, when a consistent tangent is requested.
// A return at fixed separation or a regime switch: the point after it is
// treated as fixed (docs/model.md 7.5, what the tangent includes). Before any
// plastic flow in the increment the point does not depend on where a switch
// happens (elastic paths are path-independent), so nothing is lost then.
struct TangentTracker {
  Sensitivity* D = nullptr;  // null: no consistent tangent tracked
  bool lost = false;         // a dependence on the increment was dropped (tangent approximate)
  explicit operator bool() const { return D != nullptr; }
  void forget(const IntegrationStatus& st) {
    if (!D) return;
    if (st.plastic) lost = true;
    *D = Sensitivity{};
  }
};

// d sigma from the secant relation, Eq. 1: sigma = K(d, h) (delta - delta_p).
void secant_sensitivity(const Model& M, const State& y, Sensitivity& D);

// Derivatives through settle(): `pre` and `sigma` are the point before it
// (D holds their derivatives), `post` the state after. The branches are those
// settle() took: the secant damage where it lies inside (d_old, 1), the old
// damage where it is clamped from below, 1 (and zero traction) at the top or
// after a disintegration; then Eq. 1.
void settle_sensitivity(const Model& M, const State& pre, const Vec3& sigma, const State& post, Sensitivity& D);

// Derivatives through one backward-Euler step: DP at its start, Ddd the
// derivative of its separation increment. The local residual R(x; sigma_P,
// kappa_P, dd, k) = 0 at the solution gives dx = -J^-1 (dR/dinputs) dinputs.
Sensitivity backward_euler_sensitivity(const Model& M, const Point& P, const Vec3& dd, const BackwardEulerStep& b,
                                       const Sensitivity& DP, const Mat3& Ddd);

// The elastic part of a segment up to the elastic-plastic intersection at
// the fraction a of `rest` (K the secant stiffness): the intersection
// fraction moves with the increment, F(K o (e0 + a rest), kappa) = 0 gives
// da = -(dF . dsigma|_a + dF/dkappa . dkappa) / (dF . K o rest). `y` and
// `sigma` are the point at the intersection.
// On a closed joint with a cap, the surface the intersection lies on is the
// one whose F is the larger there (trial_yield): the cap's F_c(sigma,
// kappa_c) where `on_cap`.
void intersection_sensitivity(const Model& M, const State& y, const Vec3& sigma, double a, const Vec3& rest,
                              const Vec3& K, Sensitivity& D, bool on_cap = false);

}  // namespace mortar
