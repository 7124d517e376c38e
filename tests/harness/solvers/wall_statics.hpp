// What the wall tests' closed forms share: the vertical load the base joint
// carries under a scene's full self-weight and precompression.
#pragma once

#include "input/scene_file.hpp"
#include "scenes/wall.hpp"

namespace mortar::harness::test {

// The blocks' and the beam's weight [N].
inline double wall_weight(const SceneSpec& spec) {
  const WallModel m = build_wall(spec.wall);
  double w = 0;
  for (size_t b = 1; b < m.bodies.size(); ++b) w += m.bodies[b].mass * spec.loading.gravity;
  return w;
}

// The precompression over the wall's top face plus the weight [N].
inline double base_load(const SceneSpec& spec) {
  const WallModel m = build_wall(spec.wall);
  return spec.loading.precompression * m.length * spec.wall.unit_depth + wall_weight(spec);
}

}  // namespace mortar::harness::test
