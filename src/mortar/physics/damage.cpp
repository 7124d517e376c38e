#include "mortar/physics/damage.hpp"

#include <algorithm>
#include <cmath>

#include "mortar/physics/elasticity.hpp"
#include "mortar/physics/yield_surface.hpp"

namespace mortar {

void disintegrate_if_no_strength(const Model& M, State& y) {
  if (!y.open || !separated(surface_of(M, y).s_raw) || (y.dn >= 1 && y.ds >= 1)) return;
  const Vec3 e = y.elastic_separation();
  const double es2 = e[1] * e[1] + e[2] * e[2];
  y.dissipation_damage += 0.5 * M.p.kn * (1 - y.dn) * e[0] * e[0] + 0.5 * M.p.ks * (1 - y.ds) * es2;
  y.dn = 1;
  y.ds = 1;
}

void complete_normal_damage(const Model& M, State& y) {
  const double e = y.elastic_separation()[0];
  y.dissipation_damage += 0.5 * M.p.kn * (1 - y.dn) * e * e;
  y.dn = 1;
  follow_opening(M, y);
}

void follow_opening(const Model& M, State& y) {
  if (!y.open || y.dn < 1) return;
  const double beyond = (y.separation[0] - y.plastic[0]) - y.crack[0];
  if (!(beyond > 0)) return;
  y.plastic[0] += beyond / (1 + M.p.bn);
  y.crack[0] = y.separation[0] - y.plastic[0];
}

double switch_unilateral_regime(const Model& M, State& y) {
  const Vec3 d(y.dn, y.ds, y.ds);
  const Vec3 e = y.elastic_separation();
  const Vec3 kept = y.open ? Vec3(Vec3::Ones() - d) : Vec3(Vec3::Ones());
  const double released = 0.5 * secant_stiffness(M, 0, 0, false).cwiseProduct(d).cwiseProduct(kept).dot(e.cwiseProduct(e));
  if (y.open) {
    const Vec3 locked = d.cwiseProduct(e);
    y.plastic += locked;
    y.crack -= locked;
  }
  y.open = !y.open;
  return released;
}

void settle(const Model& M, State& y, Vec3& sigma, const Vec3& e_start, Branches grow) {
  if (y.open) {
    const Vec3 e = y.elastic_separation();
    const double es = hypot_of(e[1], e[2]), es0 = hypot_of(e_start[1], e_start[2]);
    double dn = y.dn, ds = y.ds;
    if (grow.normal && e[0] > 0) dn = std::clamp(1.0 - sigma[0] / (M.p.kn * e[0]), y.dn, 1.0);
    if (grow.shear && es > 0) ds = std::clamp(1.0 - shear_norm(sigma) / (M.p.ks * es), y.ds, 1.0);
    y.dissipation_damage += 0.25 * M.p.kn * (dn - y.dn) * (e_start[0] * e_start[0] + e[0] * e[0]) +
                            0.25 * M.p.ks * (ds - y.ds) * (es0 * es0 + es * es);
    y.dn = dn;
    y.ds = ds;
    disintegrate_if_no_strength(M, y);
    follow_opening(M, y);
  }
  sigma = traction_of(M, y);
}

}  // namespace mortar
