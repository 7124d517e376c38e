// The elastic shortcut (elastic_shortcut.hpp) for two points at once, one per
// lane of a vector of doubles: most point-updates of an Abaqus/Explicit
// analysis are elastic, and their arithmetic then runs at two points per
// instruction on any x86-64 (SSE2, lanes.hpp). Every lane takes the scalar shortcut's
// operations in the scalar shortcut's order (its two tests are one template,
// instantiated for both), so a lane decides and books bit for bit as
// elastic_increment() does; a lane it cannot prove goes to the caller's
// scalar path, which decides exactly.
//
// GCC and Clang only: MORTAR_ELASTIC_LANES (lanes.hpp) says whether it is
// there.
#pragma once

#include "mortar/integration/elastic_shortcut.hpp"
#include "mortar/integration/lanes.hpp"

namespace mortar {
namespace lanes {

#if MORTAR_ELASTIC_LANES
// The lanes' start state (only what an unworn joint's elastic increment
// reads) and separation increment d, law signs; `candidate` has all bits set
// in the lanes the caller found valid, unworn (w_III = 0) and in their range.
struct ElasticLanes {
  D plastic[3], separation[3];
  D wI, wII, dn, ds;
  D h;  // 1 open, 0 closed (Eq. 13)
  D d[3];
  Mask candidate;
};

// The increments the lanes book: end separation, traction (Eq. 1) and
// elastic energy; `elastic` has all bits set in the lanes proved elastic
// with a finite end (elastic_increment's true), the others hold nothing.
struct ElasticLaneResult {
  D separation[3], traction[3], energy;
  Mask elastic;
};

// elastic_increment() in each lane of an unworn joint (tan(phi) = tan(phi0)):
// certainly_elastic()'s tests, then the booking of one elastic segment,
// separation += d and Eq. 1 with the sums in Eigen's order for a Vec3, left
// to right.
inline ElasticLaneResult elastic_increment_lanes(const Model& M, const ElasticLanes& y) {
  const Parameters& p = M.p;
  const D e_n = y.separation[0] - y.plastic[0];
  const D eps = 1e-12 * larger(larger(magnitude(y.separation[0]), magnitude(y.plastic[0])), M.separation_floor);
  const Mask open = y.h != 0.0;
  // An open joint with complete normal damage may move delta_p_n
  // (follow_opening): left to the scalar shortcut, which reads delta_cr_n.
  Mask elastic = y.candidate && !(open && y.dn >= 1.0) && regime_kept(open, e_n, e_n + y.d[0], eps);

  const D s_raw = 1.0 - y.wI / p.GIC - y.wII / p.GIIC;
  const D s = 0.0 < s_raw ? s_raw : D{};  // std::max(0.0, s_raw)
  const double t = M.tan_phi0, C_t = M.cohesion_over_tan_phi0;
  const D alpha = s * 0.5 * (C_t - p.ft0 * t), beta = s * 0.5 * (C_t + p.ft0 * t);
  const D K[3] = {p.kn * (1 - y.dn * y.h), p.ks * (1 - y.ds * y.h), p.ks * (1 - y.ds * y.h)};
  D start[3], end[3];
  for (int i = 0; i < 3; ++i) {
    const D e0 = y.separation[i] - y.plastic[i];
    start[i] = K[i] * e0;
    end[i] = K[i] * (e0 + y.d[i]);
  }
  elastic = elastic && inside_by_bounds(M, alpha, beta, t, start[0], start[1], start[2]) &&
            inside_by_bounds(M, alpha, beta, t, end[0], end[1], end[2]);

  ElasticLaneResult r;
  D e[3];
  for (int i = 0; i < 3; ++i) {
    r.separation[i] = y.separation[i] + y.d[i];
    e[i] = r.separation[i] - y.plastic[i];
    r.traction[i] = K[i] * e[i];
  }
  r.energy = 0.5 * (r.traction[0] * e[0] + r.traction[1] * e[1] + r.traction[2] * e[2]);
  const D sum = r.separation[0] + r.separation[1] + r.separation[2] + (r.traction[0] + r.traction[1] + r.traction[2]) +
                r.energy;
  r.elastic = elastic && sum - sum == 0.0;
  return r;
}
#endif

}  // namespace lanes
}  // namespace mortar
