// What one increment reports besides the state: traction, energy terms and
// the integration status (docs/model.md 7, 9).
#pragma once

#include "mortar/failure.hpp"
#include "mortar/parameters.hpp"
#include "mortar/state.hpp"

namespace mortar {

// What an increment's integration was besides converged (docs/model.md 9):
// bits of IntegrationStatus::flags and, OR'd over a point's history, of
// State::integration_flags (SDV 35). None is a failure: SDV 21 stays 0.
namespace integration_flag {
enum : int {
  fallback_rung_1 = 1,   // the fallback chain's modified Euler over 8 pieces integrated it
  fallback_rung_2 = 2,   // modified Euler over 64 pieces
  fallback_rung_3 = 4,   // forward Euler over 1024 pieces (no error control; its end checked on the surface)
  floor_above_stol = 8,  // a substep was accepted at the minimum substep with its error above STOL
};
inline constexpr int kCount = 4;
// Each bit's short name, in bit order ("fallback_rung_1", ...).
inline constexpr const char* kNames[kCount] = {"fallback_rung_1", "fallback_rung_2", "fallback_rung_3",
                                               "floor_above_stol"};
}  // namespace integration_flag

struct IntegrationStatus {
  int substeps_accepted = 0;
  int substeps_rejected = 0;
  int regime_switches = 0;    // open <-> closed inside the increment
  int relaxations = 0;        // returns at fixed separation (closure jump, snap-back)
  int relaxation_steps = 0;   // their steps, spent from the substep budget like substeps
  // Substeps and relaxation steps: what Controls::max_substeps bounds.
  long work() const { return long(substeps_accepted) + substeps_rejected + relaxation_steps; }
  bool plastic = false;       // any plastic flow in the increment
  bool min_substep_hit = false;  // a substep was accepted at the minimum size above STOL
  Failure failure = Failure::none;
  int newton_iterations = 0;     // implicit scheme: Newton iterations of all local solves
  // The tangent returned on request is not the exact derivative of this
  // update: an explicit scheme (continuum tangent, Eq. 20), a return at fixed
  // separation, or a regime switch in an increment with plastic flow (the
  // switch point is held fixed); docs/model.md 7.5.
  bool tangent_approximate = false;
  // The chosen scheme failed on this increment with first_failure, and a rung
  // of the fallback chain integrated it: fallback_scheme over fallback_pieces
  // equal pieces (docs/model.md 9). The counts above are then the pieces'
  // sums, and the tangent is approximate. fallback_pieces is 0 otherwise.
  Failure first_failure = Failure::none;
  Scheme fallback_scheme = Scheme::modified_euler;
  int fallback_pieces = 0;
  bool fell_back() const { return fallback_pieces > 0; }
  // This increment's integration_flag bits (min_substep_hit, the rung).
  int flags = 0;
  bool ok() const { return failure == Failure::none; }
};

// Result of one increment: the traction at its end and the energy terms.
struct IncrementResult {
  Vec3 traction = Vec3::Zero();   // law signs: sigma_n > 0 tension
  double elastic_energy = 0;      // at the end of the increment [N/mm]
  double d_dissipation_plastic = 0;
  double d_dissipation_damage = 0;
  double d_energy_unilateral = 0;
  IntegrationStatus status;

  // Every inelastic energy increment of the law (the adapters' spd), summed
  // in the order integrate_increment checks finite.
  double d_inelastic() const { return d_dissipation_plastic + d_dissipation_damage + d_energy_unilateral; }
};

}  // namespace mortar
