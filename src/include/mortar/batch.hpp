// A batch of points through the elastic kernel (mortar/elastic.hpp) two at a
// time, one per lane of a vector of doubles: each lane decides and books as
// elastic_increment() does for one point, being the same template; a lane it
// does not prove goes to the caller's per-point path. GCC and Clang only
// (MORTAR_ELASTIC_LANES).
#pragma once

#include "mortar/elastic.hpp"
#include "mortar/lanes.hpp"

namespace mortar {
namespace lanes {

#if MORTAR_ELASTIC_LANES
// The lanes' start; `candidate` has all bits set in the lanes the caller
// found valid, unworn (w_III = 0: tan(phi) = tan(phi0)) and in their range.
struct ElasticLanes : ElasticStart<D> {
  Mask candidate;
};
// The lanes' end; `elastic` has all bits set in the lanes proved elastic.
struct ElasticLaneResult : ElasticEnd<D> {
  Mask elastic;
};

inline ElasticLaneResult elastic_increment_lanes(const Model& M, const ElasticLanes& y) {
  const Mask open = y.h != 0.0;
  ElasticLaneResult r;
  // An open joint with complete normal damage may move delta_p_n: left to
  // the per-point path, which reads delta_cr_n.
  const Mask taken = y.candidate && !(open && y.dn >= 1.0);
  r.elastic = elastic_end(M, y, open, taken, M.tan_phi0, M.cohesion_over_tan_phi0, r);
  return r;
}
#endif

}  // namespace lanes
}  // namespace mortar
