#include "mortar/integration/rate_statement.hpp"

namespace mortar {

void add(Point& P, const Rates& r, double w) {
  P.sigma += w * r.dsigma;
  P.y.plastic += w * r.dplastic;
  P.y.crack += w * r.dcrack;
  P.y.wI += w * r.dwI;
  P.y.wII += w * r.dwII;
  P.y.wIII += w * r.dwIII;
  P.y.dissipation_plastic += w * r.dDp;
}

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

namespace {

// Rates of one stage on given branches of the open regime (rate_stiffness).
Rates branch_rates(const Model& M, const Point& P, const Surface& S, const Vec3& dd, bool grow_n, bool grow_s,
                   Vec3* dp = nullptr) {
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
  r.plastic = true;
  if (dp) *dp = r.dplastic;
  return r;
}

}  // namespace

Rates stage(const Model& M, const Point& P, const Vec3& dd, Branches allowed) {
  const Surface S = surface_of(M, P.y);
  Vec3 dp;
  const Rates grow = branch_rates(M, P, S, dd, true, true, &dp);
  if (!P.y.open || grow.snapback) return grow;
  const bool keep_n = allowed.normal && damage_grows_normal(M, P.y, dd, dp);
  const bool keep_s = allowed.shear && damage_grows_shear(M, P.y, dd, dp);
  if (keep_n && keep_s) return grow;
  Rates frozen = branch_rates(M, P, S, dd, keep_n, keep_s);
  if (frozen.snapback) return grow;
  frozen.grow = Branches{keep_n, keep_s};
  return frozen;
}

}  // namespace mortar
