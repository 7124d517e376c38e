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

// The surface of a point's works and the shear radius of its traction on it:
// what F (Eq. 2), the flow (Eq. 10) and the rate statement (Eqs. 16-19) read
// at one state. The substepper evaluates it once per substep state and hands
// it along (docs/model.md 7.1): settle() and a landing on the regime boundary
// change no work, so an end point's surface stays that of the step; its
// traction, re-derived by settle(), takes a new radius.
struct SurfaceAt {
  Surface S;
  ShearRadius radius;
};
// The surface is computed into the result rather than copied there: the
// copy's wide loads would wait on the surface's pending stores (no store
// forwarding), on every substep.
inline SurfaceAt surface_at(const Model& M, const Point& P) {
  SurfaceAt at{surface_of(M, P.y), {}};
  at.radius = shear_radius(P.sigma, at.S);
  return at;
}
inline double yield_of(const Point& P, const SurfaceAt& at) { return yield_function(P.sigma, at.S, at.radius); }
inline bool outside_surface(const Model& M, const Point& P) {
  return active_surfaces(M, P.sigma, surface_of(M, P.y)).any();
}

// settle() of the point's state and traction (docs/model.md 6).
inline void settle(const Model& M, Point& P, const Vec3& e_start, Branches grow = {}) {
  settle(M, P.y, P.sigma, e_start, grow);
}

}  // namespace mortar
