// The one substepper of the plastic part of a segment, for every scheme
// (docs/model.md 7.1, 7.2, 7.5): the substep budget, the return at fixed
// separation where the rate statement has no strain-driven solution, the
// regime-crossing bracket that ends a substep on the boundary delta_e_n = 0
// (6), the separation bracket that ends it on s = kSeparated (6), the
// normal-completion bracket that ends it where dn = 1 (6), settle() and the
// step-size control, which the scheme (scheme.hpp) steers. Each run() starts
// with every bracket closed.
#pragma once

#include <algorithm>
#include <cmath>

#include "mortar/integration/cap.hpp"
#include "mortar/integration/root_finder.hpp"
#include "mortar/integration/scheme.hpp"

namespace mortar {

class Substepper {
 public:
  Substepper(const Model& M, Point& P, IntegrationStatus& st, TangentTracker& tangent, SubstepScheme& scheme)
      : M_(M), P_(P), st_(st), tangent_(tangent), scheme_(scheme),
        apex_(M, st, tangent, M.controls.scheme == Scheme::implicit) {}

  // Plastic substepping over the separation increment d, starting on the
  // surface; `at` is the surface at P (surface_at). Returns the fraction of
  // d done: 1, or less when the regime switched inside (the point is then on
  // the regime boundary) or on failure (st.failure set).
  double run(const Vec3& d, const SurfaceAt& at);
  bool at_boundary() const { return at_boundary_; }  // the last run() stopped on the regime boundary

 private:
  // What the crossing bracket makes of a substep that ends at N.
  enum class Crossing {
    none,              // stays in the regime: accept
    cut,               // crossed (or bracketing): retry with the new dT
    ends_on_boundary,  // ends on delta_e_n = 0: accept and switch there
    from_boundary,     // P is on the boundary already and the step moves across
  };
  Crossing crossing(const Point& N, const Vec3& dd, double& dT);
  // What a one-sided bracket (complete separation, complete normal damage)
  // makes of a substep that ends at N (SN: the surface of its works).
  enum class Landing {
    none,   // stays on the near side (or was there already)
    cut,    // went past (or bracketing): retry with the new dT
    lands,  // ends on the boundary: accept, settle() completes the damage
  };
  Landing separation(const Surface& SN, double& dT);
  Landing normal_completion(const Point& N, const Surface& SN, double& dT);
  Landing surface_reached(const Point& N, const Surface& SN, double& dT);
  Landing one_sided(CrossingBracket& b, int& cuts, double& dT, double g0, double g1, bool past, bool within,
                    bool lands);
  double end_on_boundary(const Point& N, double done);

  const Model& M_;
  Point& P_;
  IntegrationStatus& st_;
  TangentTracker& tangent_;
  SubstepScheme& scheme_;
  BackwardEuler apex_;  // the apex zone's substeps, every scheme
  bool at_boundary_ = false;
  SurfaceAt surface_at_start_;  // the surface at P, evaluated once per substep state
  CrossingBracket cut_;
  int cuts_ = 0;
  CrossingBracket sep_cut_;
  int sep_cuts_ = 0;
  CrossingBracket dn_cut_;
  int dn_cuts_ = 0;
  CrossingBracket reach_cut_;  // the second surface reached (the cap, or Eq. 2 from the cap)
  int reach_cuts_ = 0;
  bool reach_on_cap_ = false;
};

// The apex zone of a worn open joint (docs/model.md 6, Decision - the apex
// zone): open, the normal not completed, its traction inside the blend of the
// normal flow (0 < sigma_n < ft, docs/model.md 5) on a joint whose whole
// tension cap lies below the local error's traction floor (ft = s ft0 <
// 1e-3 ft0). There the blend's slope (tan phi - tan psi)/ft makes the normal
// a stiff relaxation that explicit substeps resolve only at the floor.
inline bool in_apex_zone(const Model& M, const Point& P, const SurfaceAt& at) {
  const double ft = M.p.ft0 * at.S.s;
  return P.y.open && P.y.dn < 1 && ft < 1e-3 * M.p.ft0 && P.sigma[0] > 0 && P.sigma[0] < ft && at.radius.tau > 0;
}

// Round-off scale of the regime boundary delta_e_n = 0 at a state.
inline double boundary_eps(const Model& M, const State& y) {
  return boundary_eps_of(M, y.separation[0], y.plastic[0]);
}

}  // namespace mortar
