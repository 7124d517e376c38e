// Elasticity of the joint: the secant relation (Eq. 1) with the stiffness of
// Eq. 21, and the stiffnesses of the rate statement (docs/model.md 6).
// Knows nothing of integration schemes.
#pragma once

#include <cmath>

#include <Eigen/Core>

#include "mortar/elastic.hpp"
#include "mortar/parameters.hpp"
#include "mortar/physics/norms.hpp"
#include "mortar/state.hpp"

namespace mortar {

// Stiffnesses of the rate statement (docs/model.md 6), per component:
//   closed:                 dsigma = kbar (dd - m dl)
//   open, damage growing:   dsigma = kbar (dd - (1 + b) m dl)   (the paper's Eq. 16-17)
//   open, damage frozen:    dsigma = kbar (1 - d) (dd - m dl)   (secant, Eq. 1)
// The rest: docs/numerics.md, section 15.
struct RateStiffness {
  Vec3 on_separation;  // multiplies the separation increment (along the elastic slip, for the shear)
  Vec3 on_flow;        // multiplies m dl
  double across_drop = 0;    // ks ds: taken off on_separation for slip across the elastic slip
  double axis[2] = {0, 0};   // the unit elastic slip, where across_drop > 0

  // The traction change the separation increment dd drives.
  Vec3 times_separation(const Vec3& dd) const {
    Vec3 r = on_separation.cwiseProduct(dd);
    if (across_drop > 0) {
      const double along = dd[1] * axis[0] + dd[2] * axis[1];
      r[1] -= across_drop * (dd[1] - along * axis[0]);
      r[2] -= across_drop * (dd[2] - along * axis[1]);
    }
    return r;
  }
  // The same as a matrix (tangents).
  Eigen::Matrix3d separation_matrix() const {
    Eigen::Matrix3d K = on_separation.asDiagonal();
    if (across_drop > 0) {
      K(1, 1) -= across_drop * (1 - axis[0] * axis[0]);
      K(2, 2) -= across_drop * (1 - axis[1] * axis[1]);
      K(1, 2) += across_drop * axis[0] * axis[1];
      K(2, 1) += across_drop * axis[0] * axis[1];
    }
    return K;
  }
};
inline RateStiffness rate_stiffness(const Model& M, const State& y, bool grow_n = true, bool grow_s = true) {
  const Parameters& p = M.p;
  if (!y.open) return {Vec3(p.kn, p.ks, p.ks), Vec3(p.kn, p.ks, p.ks)};
  auto component = [](double k, double b, double d, bool grow, double& on_sep, double& on_flow) {
    if (d >= 1) { on_sep = on_flow = 0; return; }
    on_sep = grow ? k : k * (1 - d);
    on_flow = grow ? k * (1 + b) : k * (1 - d);
  };
  RateStiffness r;
  component(p.kn, p.bn, y.dn, grow_n, r.on_separation[0], r.on_flow[0]);
  component(p.ks, p.bs, y.ds, grow_s, r.on_separation[1], r.on_flow[1]);
  r.on_separation[2] = r.on_separation[1];
  r.on_flow[2] = r.on_flow[1];
  const Vec3 e = y.elastic_separation();
  const double es = hypot_of(e[1], e[2]);
  if (grow_s && y.ds > 0 && y.ds < 1 && es > 0) {
    r.across_drop = p.ks * y.ds;
    r.axis[0] = e[1] / es;
    r.axis[1] = e[2] / es;
  }
  return r;
}

// The rate stiffness of a step over dd. An open joint closed against its
// elastic opening (dd_n < 0, delta_e_n > 0) unloads that closing on the
// normal secant kn (1 - dn), while the crack growth of its plastic flow stays
// on the branch chosen (docs/model.md 6, Decision - closing on the tension
// cap): on the growing branch the closing would act with the full kn, drive
// sigma_n to zero and the secant damage to 1 within the step, where a finer
// cut unloads elastically between plastic bursts.
inline RateStiffness rate_stiffness_over(const Model& M, const State& y, const Vec3& dd, bool grow_n = true,
                                         bool grow_s = true) {
  RateStiffness k = rate_stiffness(M, y, grow_n, grow_s);
  if (y.open && dd[0] < 0 && y.elastic_separation()[0] > 0) k.on_separation[0] = M.p.kn * (1 - y.dn);
  return k;
}

// Elastic stiffness of Eq. 21 with the unilateral factor h of the regime.
// secant_stiffness (Eq. 21), traction_of (Eq. 1), elastic_energy: mortar/elastic.hpp.

// Crack-to-plastic ratios per component (Eq. 17: delta_cr = b o delta_p).
inline Vec3 crack_ratio(const Model& M) { return Vec3(M.p.bn, M.p.bs, M.p.bs); }

}  // namespace mortar
