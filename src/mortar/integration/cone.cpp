#include "mortar/integration/cone.hpp"

#include <algorithm>
#include <cmath>

#include "mortar/integration/substepper.hpp"

namespace mortar {

namespace {
constexpr int kMaxNewton = 60;
}  // namespace

// docs/model.md 6, Decision - sliding on the cone: with sigma_n = 0 the work
// rates are dwI = dwIII = 0 and dwII = t dy (y the inelastic slip along the
// elastic slip, t = |tau|), so on the surface t = c0 s and s = s0 exp(-y/u),
// u = GIIC/c0; the rate statement along the slip, t = t0 + kS q - kY y
// (q the slip applied), closes it in y.
ConeStep cone_step(const Model& M, Point& P, const SurfaceAt& at, const Vec3& d, Branches grow) {
  const Parameters& p = M.p;
  const Surface& S = at.S;
  State& y = P.y;
  if (!y.open || !(y.dn >= 1) || !(y.ds < 1) || !(S.s_raw > kSeparated) || P.sigma[0] != 0) return {};
  const Vec3 e = y.elastic_separation();
  const double es = hypot_of(e[1], e[2]), t0 = at.radius.tau;
  if (!(es > 0) || !(t0 > 0)) return {};
  const double ex = e[1] / es, ey = e[2] / es;
  const double q = d[1] * ex + d[2] * ey;
  const double across = std::abs(d[2] * ex - d[1] * ey);
  if (!(q > 0) || across > 1e-12 * hypot_of(d[1], d[2])) return {};

  // Along the elastic slip: kS on the slip applied, kY per unit inelastic slip.
  const RateStiffness k = rate_stiffness_over(M, y, d, grow.normal, grow.shear);
  const double kS = k.on_separation[1], kY = k.on_flow[1] / (1 + p.bs);
  const double s0 = S.s_raw, u = p.GIIC / p.c0, c0s0 = p.c0 * s0;
  // A snap-back (kY <= c0 s0 / u) is the return at fixed separation's.
  if (!(kS > 0) || !(kY > c0s0 / u)) return {};
  auto g = [&](double x, double qq) { return t0 + kS * qq - kY * x - c0s0 * std::exp(-x / u); };
  // g is concave and decreasing in x: Newton from 0 overshoots once, then
  // falls monotonically to the root.
  auto solve = [&](double qq) {
    double x = 0;
    for (int it = 0; it < kMaxNewton; ++it) {
      const double step = g(x, qq) / (-kY + c0s0 / u * std::exp(-x / u));
      const double next = std::max(0.0, x - step);
      const bool done = std::abs(next - x) <= 1e-15 * next;
      x = next;
      if (done) break;
    }
    return x;
  };
  if (!(g(0, q) > 0)) return {};
  double theta = 1, x = solve(q);
  bool separates = false;
  if (s0 * std::exp(-x / u) <= kSeparated) {
    // Ends on complete separation: the slip that brings s to kSeparated.
    x = u * std::log(s0 / kSeparated);
    theta = std::clamp((p.c0 * kSeparated - t0 + kY * x) / (kS * q), 0.0, 1.0);
    separates = true;
  }
  // The normal flow at sigma_n = 0 is tan(psi), and R/t = beta/(c0 s) = b/c0
  // on the surface: d lambda = (b/c0) dy/(1 + bs).
  const double dp_s = x / (1 + p.bs), dp_n = S.tan_psi * (S.b / p.c0) * dp_s;
  if (!(e[0] + theta * d[0] - dp_n > boundary_eps(M, y))) return {};

  const double E0 = elastic_energy(M, y), D0 = y.dissipation_damage;
  const double s1 = separates ? kSeparated : s0 * std::exp(-x / u);
  const double dwII = p.GIIC * (s0 - s1);
  y.plastic += Vec3(dp_n, dp_s * ex, dp_s * ey);
  y.crack += Vec3(p.bn * dp_n, p.bs * dp_s * ex, p.bs * dp_s * ey);
  y.wII += dwII;
  // Landing on kSeparated within the round-off of the summed works.
  for (int i = 0; separates && i < 64 && !separated(1.0 - y.wI / p.GIC - y.wII / p.GIIC); ++i)
    y.wII = std::nextafter(y.wII, HUGE_VAL);
  y.dissipation_plastic += dwII / (1 + p.bs);
  y.separation += theta * d;
  const double t1 = p.c0 * s1;
  P.sigma = Vec3(0, t1 * ex, t1 * ey);
  settle(M, P, e, grow);
  // External work along the slip, W = (t1^2 - t0^2)/(2 kS) + (kY/kS) dwII;
  // what the elastic energy and the plastic dissipation do not take is the
  // damage's (docs/model.md 6, Energy).
  const double W = (t1 * t1 - t0 * t0) / (2 * kS) + kY / kS * dwII;
  y.dissipation_damage = D0 + (W - (elastic_energy(M, y) - E0) - dwII / (1 + p.bs));
  return {theta, separates};
}

}  // namespace mortar
