#include "mortar/integration/rate_statement.hpp"

#include "mortar/integration/cap.hpp"

namespace mortar {

// Every increment built in place (a default Rates would write its zeros
// first, and they stay: the members are then written through Eigen's
// assignments).
Rates along_flow(const Model& M, const Vec3& sigma, const Flow& f, double dl) {
  const Vec3 dplastic = dl * f.m;
  return Rates{-dl * f.k_A_m, dplastic, crack_ratio(M).cwiseProduct(dplastic), dl * f.gI, dl * f.gII, dl * f.gIII,
               sigma.dot(dplastic), false, false, Branches{}};
}

namespace {

// Rates of one stage on given branches of the open regime (rate_stiffness).
Rates branch_rates(const Model& M, const Point& P, const Surface& S, const ShearRadius& radius, const Vec3& dd,
                   bool grow_n, bool grow_s, Vec3* dp = nullptr) {
  const RateStiffness k = rate_stiffness_over(M, P.y, dd, grow_n, grow_s);
  const Flow f = flow_of(M, P.sigma, S, k.on_flow, radius);
  const Vec3 k_dd = k.times_separation(dd);
  const double num = f.dF.dot(k_dd);
  // Unloading inside the step, or a flow that no stiffness can feed (open
  // and fully damaged along it): secant elasticity.
  if (num <= 0 || !(f.dF.dot(f.k_A_m) > 0)) {
    Rates r;
    r.dsigma = secant_stiffness(M, P.y.dn, P.y.ds, P.y.open).cwiseProduct(dd);
    if (dp) *dp = Vec3::Zero();
    return r;
  }
  if (snaps_back(f)) {
    Rates r;
    r.snapback = true;
    return r;
  }
  Rates r = along_flow(M, P.sigma, f, num / f.denominator);
  r.dsigma += k_dd;
  r.plastic = true;
  if (dp) *dp = r.dplastic;
  return r;
}

// The secant (elastic) predictor leaves the surface: dF . K dd > 0.
bool secant_loads(const Model& M, const Point& P, const Surface& S, const ShearRadius& radius, const Vec3& dd) {
  const Vec3 K = secant_stiffness(M, P.y.dn, P.y.ds, P.y.open);
  return flow_of(M, P.sigma, S, K, radius).dF.dot(K.cwiseProduct(dd)) > 0;
}

}  // namespace

Rates stage(const Model& M, const Point& P, const Vec3& dd, Branches allowed) {
  return stage(M, P, surface_at(M, P), dd, allowed);
}

Rates stage(const Model& M, const Point& P, const SurfaceAt& at, const Vec3& dd, Branches allowed) {
  const Surface& S = at.S;
  const ShearRadius& radius = at.radius;
  if (cap_applies(M, P.y)) {
    Rates r;
    if (capped_stage(M, P, at, dd, r)) return r;
  }
  if (!P.y.open) return branch_rates(M, P, S, radius, dd, true, true);
  // From the most growing candidate the secant rule admits, freeze each
  // component whose damage the candidate's solution would decrease, until
  // the branches agree with their own solution (at most two freezes). A
  // slip against the elastic slip is frozen from the start, so that its
  // growing-branch solution does not decide the normal branch.
  Branches b{allowed.normal, allowed.shear && !slip_reverses(P.y, dd)};
  Vec3 dp;
  Rates r = branch_rates(M, P, S, radius, dd, b.normal, b.shear, &dp);
  if (r.snapback && b.shear != allowed.shear) {
    // The unloading slip has no strain-driven solution: the growing branch
    // stands, as for any frozen branch below.
    b = allowed;
    r = branch_rates(M, P, S, radius, dd, b.normal, b.shear, &dp);
  }
  r.grow = b;
  if (r.snapback) return r;
  for (int pass = 0; pass < 2; ++pass) {
    const Branches next{b.normal && damage_grows_normal(M, P.y, dd, dp),
                        b.shear && damage_grows_shear(M, P.y, dd, dp)};
    if (next.normal == b.normal && next.shear == b.shear) break;
    Rates frozen = branch_rates(M, P, S, radius, dd, next.normal, next.shear, &dp);
    // No strain-driven solution on the frozen branch (a snap-back, or no
    // flow although the secant predictor leaves the surface): the more
    // growing one stands (settle keeps the damage from decreasing).
    if (frozen.snapback || (!frozen.plastic && secant_loads(M, P, S, radius, dd))) break;
    b = next;
    r = frozen;
    r.grow = b;
  }
  return r;
}

}  // namespace mortar
