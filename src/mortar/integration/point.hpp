// The working point of the integration: a state and the traction that goes
// with it (Eq. 1 after every settle()).
#pragma once

#include "mortar/physics/damage.hpp"
#include "mortar/physics/elasticity.hpp"
#include "mortar/physics/yield_surface.hpp"
#include "mortar/state.hpp"

namespace mortar {

struct Point {
  State y;
  Vec3 sigma;
};

inline double yield_of(const Model& M, const Point& P) { return yield_function(P.sigma, surface_of(M, P.y)); }
inline bool outside_surface(const Model& M, const Point& P) {
  return active_surfaces(M, P.sigma, surface_of(M, P.y)).any();
}

// settle() of the point's state and traction (docs/model.md 6).
inline void settle(const Model& M, Point& P, const Vec3& e_start, Branches grow = {}) {
  settle(M, P.y, P.sigma, e_start, grow);
}

}  // namespace mortar
