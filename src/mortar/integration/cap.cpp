#include "mortar/integration/cap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/LU>

namespace mortar {

namespace {

constexpr int kMaxNewton = 60;

// The closed joint's stiffness: the rate statement's on both surfaces.
Vec3 closed_stiffness(const Model& M) { return Vec3(M.p.kn, M.p.ks, M.p.ks); }

// The rates of a closed point flowing with multiplier l1 on Eq. 2 (flow f)
// and lc on the cap (direction nc) over dd (Kdd = K dd): the cap's flow adds
// plastic closure and kappa_c, no crack and no work of Eqs. 7-9
// (docs/model.md 12, Decision - crushing apart from shear and tension).
Rates two_surface_rates(const Model& M, const Point& P, const Flow& f, double l1, const Vec3& nc, double lc,
                        const Vec3& Kdd) {
  Rates r = along_flow(M, P.sigma, f, l1);
  const Vec3 dpc = lc * nc;
  r.dsigma += Kdd - lc * closed_stiffness(M).cwiseProduct(nc);
  r.dplastic += dpc;
  r.dDp += P.sigma.dot(dpc);
  r.dkappa_c = lc;
  r.plastic = l1 > 0 || lc > 0;
  return r;
}

// The end of a backward-Euler step with multipliers l1 (flow m1, works w)
// and lc (direction nc); dissipation trapezoidal in the traction, as the
// one-surface step books it.
Point end_of_step(const Model& M, const Point& P, const Vec3& dd, const Vec3& sigma, const Vec3& m1, double l1,
                  const Vec3& w, const Vec3& nc, double lc) {
  Point N = P;
  N.y.separation += dd;
  end_plastic_step(M, P, N, sigma, l1 * m1, w);  // Eq. 2's part
  const Vec3 dpc = lc * nc;                      // the cap's: no crack, no work
  N.y.plastic += dpc;
  N.y.kappa_c += lc;
  N.y.dissipation_plastic += 0.5 * (P.sigma + sigma).dot(dpc);
  return N;
}

using Mat8 = Eigen::Matrix<double, 8, 8>;

// The Newton matrix of the cap's residual (solve_cap) at x.
Eigen::Matrix4d cap_jacobian(const Model& M, const CapSolution& x, double k0) {
  const Vec3 K = closed_stiffness(M), n = cap_gradient(M, x.sigma);
  Eigen::Matrix4d J = Eigen::Matrix4d::Zero();
  J.topLeftCorner<3, 3>() = Mat3::Identity() + x.lc * K.asDiagonal() * cap_hessian(M, x.sigma);
  J.topRightCorner<3, 1>() = K.cwiseProduct(n);
  J.bottomLeftCorner<1, 3>() = n.transpose();
  J(3, 3) = -cap_strength(M, k0 + x.lc).slope;
  return J;
}

// The Newton matrix of the corner's residual (solve_corner) at x, with d Eq.
// 2's derivatives there and ws the works rows' scale.
Mat8 corner_jacobian(const Model& M, const CapSolution& x, const LocalDerivatives& d, double k0, double ws) {
  const Vec3 K = closed_stiffness(M), n = cap_gradient(M, x.sigma);
  Mat8 J = Mat8::Zero();
  J.block<3, 3>(0, 0) = Mat3::Identity() + K.asDiagonal() * (x.l1 * d.m_sigma + x.lc * cap_hessian(M, x.sigma));
  J.block<3, 3>(0, 3) = x.l1 * K.asDiagonal() * d.m_kappa;
  J.block<3, 1>(0, 6) = K.cwiseProduct(d.m);
  J.block<3, 1>(0, 7) = K.cwiseProduct(n);
  J.block<3, 3>(3, 0) = -x.l1 * ws * d.g_sigma;
  J.block<3, 3>(3, 3) = ws * (Mat3::Identity() - x.l1 * d.g_kappa);
  J.block<3, 1>(3, 6) = -ws * d.g;
  J.block<1, 3>(6, 0) = d.F_sigma.transpose();
  J.block<1, 3>(6, 3) = d.F_kappa.transpose();
  J.block<1, 3>(7, 0) = n.transpose();
  J(7, 7) = -cap_strength(M, k0 + x.lc).slope;
  return J;
}

// The cap alone: sigma = sigma_e - lc K m_c(sigma), F_c(sigma, kappa_c + lc) = 0.
CapSolution solve_cap(const Model& M, const Point& P, const Vec3& sigma_e, IntegrationStatus& st) {
  const Vec3 K = closed_stiffness(M);
  const double k0 = P.y.kappa_c, scale = std::max(sigma_e.norm(), M.stress_scale);
  CapSolution s;
  {
    const Vec3 n = cap_gradient(M, sigma_e);
    const CapStrength cs = cap_strength(M, k0);
    const double d = n.dot(K.cwiseProduct(n)) + cs.slope;
    s.lc = d > 0 ? std::max(0.0, cap_radius(M, sigma_e) - cs.value) / d : 0.0;
    s.sigma = sigma_e - s.lc * K.cwiseProduct(n);
  }
  auto residual = [&](const Vec3& sigma, double lc, Eigen::Vector4d& R) {
    R.head<3>() = sigma - sigma_e + lc * K.cwiseProduct(cap_gradient(M, sigma));
    R[3] = cap_function(M, sigma, k0 + lc);
  };
  auto size = [&](const Eigen::Vector4d& R) { return R.norm() / scale; };
  Eigen::Vector4d R;
  residual(s.sigma, s.lc, R);
  for (int it = 0; it < kMaxNewton; ++it, ++st.newton_iterations) {
    if (R.head<3>().norm() <= M.controls.ftol * scale && std::abs(R[3]) <= yield_tolerance(M, s.sigma)) {
      s.ok = s.sigma.allFinite() && std::isfinite(s.lc);
      return s;
    }
    const Eigen::Vector4d dx = cap_jacobian(M, s, k0).partialPivLu().solve(-R);
    if (!dx.allFinite()) return s;
    // Damped: the full step, halved while the residual grows.
    double t = 1;
    for (int h = 0; h < 12; ++h, t *= 0.5) {
      const Vec3 sigma = s.sigma + t * dx.head<3>();
      const double lc = s.lc + t * dx[3];
      Eigen::Vector4d Rt;
      residual(sigma, lc, Rt);
      if (size(Rt) < size(R) || h == 11) {
        s.sigma = sigma;
        s.lc = lc;
        R = Rt;
        break;
      }
    }
  }
  return s;
}

// The corner: Eq. 2 (multiplier l1, its flow and works) and the cap (lc)
// active together, from the start `s`.
CapSolution solve_corner(const Model& M, const Point& P, const Vec3& sigma_e, CapSolution s, IntegrationStatus& st) {
  using Vec8 = Eigen::Matrix<double, 8, 1>;
  const Vec3 K = closed_stiffness(M), w0(P.y.wI, P.y.wII, P.y.wIII);
  const double k0 = P.y.kappa_c, scale = std::max(sigma_e.norm(), M.stress_scale);
  const double wscale = std::max(M.p.GIC, M.p.GIIC);
  s.ok = false;
  auto residual = [&](const CapSolution& x, Vec8& R, LocalDerivatives& d) {
    d = local_derivatives(M, x.sigma, x.w);
    R.segment<3>(0) = x.sigma - sigma_e + x.l1 * K.cwiseProduct(d.m) + x.lc * K.cwiseProduct(cap_gradient(M, x.sigma));
    R.segment<3>(3) = (x.w - w0 - x.l1 * d.g) * (scale / wscale);
    R[6] = d.F;
    R[7] = cap_function(M, x.sigma, k0 + x.lc);
  };
  Vec8 R;
  LocalDerivatives d;
  residual(s, R, d);
  for (int it = 0; it < kMaxNewton; ++it, ++st.newton_iterations) {
    const double tol = yield_tolerance(M, s.sigma);
    if (R.head<6>().norm() <= M.controls.ftol * scale && std::abs(R[6]) <= tol && std::abs(R[7]) <= tol) {
      s.ok = s.sigma.allFinite() && s.w.allFinite() && std::isfinite(s.l1) && std::isfinite(s.lc);
      return s;
    }
    const Vec8 dx = corner_jacobian(M, s, d, k0, scale / wscale).partialPivLu().solve(-R);
    if (!dx.allFinite()) return s;
    double t = 1;
    for (int h = 0; h < 12; ++h, t *= 0.5) {
      CapSolution x = s;
      x.sigma += t * dx.segment<3>(0);
      x.w += t * dx.segment<3>(3);
      x.l1 += t * dx[6];
      x.lc += t * dx[7];
      Vec8 Rt;
      LocalDerivatives dt;
      residual(x, Rt, dt);
      if (Rt.norm() < R.norm() || h == 11) {
        s = x;
        R = Rt;
        d = dt;
        break;
      }
    }
  }
  return s;
}

}  // namespace

bool capped_stage(const Model& M, const Point& P, const SurfaceAt& at, const Vec3& dd, Rates& r) {
  const double tol = on_surface_band(M, P.sigma);
  const CapStrength cs = cap_strength(M, P.y.kappa_c);
  const bool on1 = yield_of(P, at) >= -tol;
  const Vec3 K = closed_stiffness(M), Kdd = K.cwiseProduct(dd);
  if (cap_radius(M, P.sigma) - cs.value < -tol) {
    if (on1) return false;
    r = Rates{};
    r.dsigma = Kdd;
    return true;
  }
  const Vec3 nc = cap_gradient(M, P.sigma), Knc = K.cwiseProduct(nc);
  const double dc = nc.dot(Knc) + cs.slope;  // > 0 by the rule on Gfc (docs/model.md 12)
  const Flow f = flow_of(M, P.sigma, at.S, K, at.radius);
  const double a1 = on1 ? f.dF.dot(Kdd) : 0.0, ac = nc.dot(Kdd);
  // Koiter's rule: the corner where both multipliers come out positive.
  if (on1 && (a1 > 0 || ac > 0)) {
    const double A11 = f.denominator, A12 = f.dF.dot(Knc), A21 = nc.dot(f.k_A_m), A22 = dc;
    const double det = A11 * A22 - A12 * A21;
    if (det > 0) {
      const double l1 = (a1 * A22 - A12 * ac) / det, lc = (A11 * ac - A21 * a1) / det;
      if (l1 > 0 && lc > 0) {
        r = two_surface_rates(M, P, f, l1, nc, lc, Kdd);
        return true;
      }
    }
  }
  // The cap alone, where its flow does not load Eq. 2.
  if (ac > 0 && dc > 0) {
    const double lc = ac / dc;
    if (!on1 || f.dF.dot(Kdd - lc * Knc) <= 0) {
      r = two_surface_rates(M, P, f, 0, nc, lc, Kdd);
      return true;
    }
  }
  // Eq. 2 alone, where its flow does not load the cap.
  if (on1 && a1 > 0 && f.dF.dot(f.k_A_m) > 0) {
    if (snaps_back(f)) {
      r = Rates{};
      r.snapback = true;
      return true;
    }
    const double l1 = a1 / f.denominator;
    if (nc.dot(Kdd - l1 * f.k_A_m) <= 0) {
      r = two_surface_rates(M, P, f, l1, nc, 0, Kdd);
      return true;
    }
  }
  // No set satisfies the rule (the flow of Eq. 2 is not associated): the
  // cap where it is loaded, else elastic.
  r = ac > 0 && dc > 0 ? two_surface_rates(M, P, f, 0, nc, ac / dc, Kdd) : Rates{};
  if (!r.plastic) r.dsigma = Kdd;
  return true;
}

void correct_cap_drift(const Model& M, Point& P) {
  if (!cap_applies(M, P.y)) return;
  const Vec3 K = closed_stiffness(M);
  for (int it = 0; it < 8; ++it) {
    const CapStrength cs = cap_strength(M, P.y.kappa_c);
    const double F = cap_radius(M, P.sigma) - cs.value;
    if (F <= yield_tolerance(M, P.sigma)) return;
    const Vec3 nc = cap_gradient(M, P.sigma);
    const double d = nc.dot(K.cwiseProduct(nc)) + cs.slope;
    if (!(d > 0)) return;
    const Vec3 dp = (F / d) * nc;
    P.y.dissipation_plastic += P.sigma.dot(dp);
    P.y.plastic += dp;
    P.y.kappa_c += F / d;
    P.sigma -= K.cwiseProduct(dp);
  }
}

bool capped_tangent(const Model& M, const State& y, const Vec3& sigma, const Surface& S, const Flow& f, Mat3& D) {
  const double tol = yield_tolerance(M, sigma);
  const CapStrength cs = cap_strength(M, y.kappa_c);
  if (cap_radius(M, sigma) - cs.value < -tol) return false;
  const Vec3 K = closed_stiffness(M), nc = cap_gradient(M, sigma), Knc = K.cwiseProduct(nc);
  const double dc = nc.dot(Knc) + cs.slope;
  if (!(dc > 0)) return false;
  D = K.asDiagonal();
  if (yield_function(sigma, S) < -tol || !(f.denominator > 0)) {
    D -= Knc * Knc.transpose() / dc;
    return true;
  }
  Eigen::Matrix2d A;
  A << f.denominator, f.dF.dot(Knc), nc.dot(f.k_A_m), dc;
  if (!(A.determinant() > 0)) return false;
  Eigen::Matrix<double, 3, 2> flows, normals;
  flows << f.k_A_m, Knc;
  normals << K.cwiseProduct(f.dF), Knc;
  D -= flows * A.inverse() * normals.transpose();
  return true;
}

CapStep cap_backward_euler(const Model& M, const Point& P, const Vec3& dd, const Point* one_surface,
                           IntegrationStatus& st) {
  CapStep out;
  const Vec3 sigma_e = P.sigma + closed_stiffness(M).cwiseProduct(dd);
  const Surface S = surface_of(M, P.y);
  CapSolution start;
  if (one_surface) {
    // The step of Eq. 2 ends beyond the cap: the corner, from its end.
    const Point& E = *one_surface;
    if (cap_function(M, E.sigma, E.y.kappa_c) <= yield_tolerance(M, E.sigma)) return out;
    start.sigma = E.sigma;
    start.w = Vec3(E.y.wI, E.y.wII, E.y.wIII);
    const Vec3 m1 = local_derivatives(M, E.sigma, start.w).m;
    const double mm = m1.squaredNorm();
    start.l1 = mm > 0 ? (E.y.plastic - P.y.plastic).dot(m1) / mm : 0.0;
  } else {
    if (cap_function(M, sigma_e, P.y.kappa_c) <= yield_tolerance(M, sigma_e)) return out;
    // The cap alone; where its end violates Eq. 2, the corner from there.
    start = solve_cap(M, P, sigma_e, st);
    if (start.ok && yield_function(start.sigma, S) <= yield_tolerance(M, start.sigma)) {
      out.involved = out.ok = out.plastic = true;
      out.N = end_of_step(M, P, dd, start.sigma, Vec3::Zero(), 0, Vec3(P.y.wI, P.y.wII, P.y.wIII),
                          cap_gradient(M, start.sigma), start.lc);
      out.x = start;
      return out;
    }
    if (!start.ok) start.sigma = sigma_e, start.lc = 0;
    start.w = Vec3(P.y.wI, P.y.wII, P.y.wIII);
    start.l1 = 0;
  }
  out.involved = true;
  const CapSolution c = solve_corner(M, P, sigma_e, start, st);
  // Koiter's rule: both multipliers non-negative at the corner. From a trial
  // beyond both surfaces where the cap's step ends beyond Eq. 2 and no such
  // corner is found from there, the step of Eq. 2 alone is the candidate
  // (the caller takes it, and comes back here, to the corner from its end,
  // if it ends beyond the cap). Else the step has no consistent active set
  // at this size, and is halved.
  const bool corner = c.ok && c.l1 >= 0 && c.lc >= 0;
  if (!one_surface && !corner && yield_function(sigma_e, S) > yield_tolerance(M, sigma_e)) {
    out.involved = false;
    return out;
  }
  if (!c.ok || c.l1 < 0 || c.lc < 0) return out;
  out.ok = out.plastic = out.corner = true;
  out.N = end_of_step(M, P, dd, c.sigma, local_derivatives(M, c.sigma, c.w).m, c.l1, c.w, cap_gradient(M, c.sigma),
                      c.lc);
  out.x = c;
  return out;
}

// dx = -J^-1 (dR/d inputs) D inputs, with the inputs the trial sigma_P + K dd
// (rows of sigma), the start's works w0 (rows of w) and kappa_c (the cap's
// row). The works rows' scale cancels at R = 0: 1 here.
Sensitivity cap_step_sensitivity(const Model& M, const Point& P, const CapStep& c, const Sensitivity& DP,
                                 const Mat3& Ddd) {
  Sensitivity D = DP;
  D.separation = DP.separation + Ddd;
  const Vec3 K = closed_stiffness(M), nc = cap_gradient(M, c.x.sigma);
  const Mat3 Dtrial = DP.sigma + K.asDiagonal() * Ddd, Hc = cap_hessian(M, c.x.sigma);
  const double k0 = P.y.kappa_c, slope = cap_strength(M, k0 + c.x.lc).slope;
  Eigen::RowVector3d Dlc;
  if (!c.corner) {
    Eigen::Matrix<double, 4, 3> B;
    B << -Dtrial, -slope * DP.kappa_c;
    const Eigen::Matrix<double, 4, 3> Dx = -cap_jacobian(M, c.x, k0).fullPivLu().solve(B);
    D.sigma = Dx.topRows<3>();
    Dlc = Dx.row(3);
    D.plastic = DP.plastic + nc * Dlc + c.x.lc * Hc * D.sigma;
  } else {
    const LocalDerivatives d = local_derivatives(M, c.x.sigma, c.x.w);
    Eigen::Matrix<double, 8, 3> B;
    B << -Dtrial, -DP.kappa, Eigen::RowVector3d::Zero(), -slope * DP.kappa_c;
    const Eigen::Matrix<double, 8, 3> Dx = -corner_jacobian(M, c.x, d, k0, 1.0).fullPivLu().solve(B);
    D.sigma = Dx.topRows<3>();
    const Mat3 Dw = Dx.middleRows<3>(3);
    const Eigen::RowVector3d Dl1 = Dx.row(6);
    Dlc = Dx.row(7);
    // wI and wIII never decrease (end_of_step): where the start's stands,
    // its derivative does.
    D.kappa.row(1) = Dw.row(1);
    if (c.x.w[0] >= P.y.wI) D.kappa.row(0) = Dw.row(0);
    if (c.x.w[2] >= P.y.wIII) D.kappa.row(2) = Dw.row(2);
    D.plastic = DP.plastic + d.m * Dl1 + c.x.l1 * (d.m_sigma * D.sigma + d.m_kappa * Dw) + nc * Dlc +
                c.x.lc * Hc * D.sigma;
  }
  D.kappa_c = DP.kappa_c + Dlc;
  return D;
}

bool return_to_cap(const Model& M, Point& P, IntegrationStatus& st) {
  const CapStep c = cap_backward_euler(M, P, Vec3::Zero(), nullptr, st);
  // Not involved: inside the cap, or no corner from a point beyond Eq. 2.
  if (!c.involved) return cap_function(M, P.sigma, P.y.kappa_c) <= yield_tolerance(M, P.sigma);
  if (!c.ok) return false;
  P = c.N;
  return true;
}

}  // namespace mortar
