// Stress integration of one increment for one interface point (MODEL.md 7),
// and the same over a block of points in the solver's array layout.
#pragma once

#include "mortar/parameters.hpp"
#include "mortar/return_mapping.hpp"
#include "mortar/state.hpp"
#include "mortar/surface.hpp"

namespace mortar {

// Why an increment failed. Stored (as a number) in state slot 21.
enum class Failure : int {
  none = 0,
  too_many_substeps = 1,     // accepted + rejected substeps exceeded Controls::max_substeps
  relaxation_failed = 2,     // return at fixed separation found no surface point
  too_many_switches = 3,     // more open/closed switches in one increment than allowed
  non_finite_increment = 4,  // the separation increment holds NaN or infinity
  invalid_state = 5,         // the incoming state breaks a rule (see check_state)
  non_finite_result = 6,     // a result (traction, energy, state) beyond the floating-point range: start state kept
  local_solve_failed = 7,    // implicit scheme: Newton failed at the smallest substep, or spent its budget
};
const char* failure_name(Failure f);

struct IntegrationStatus {
  int substeps_accepted = 0;
  int substeps_rejected = 0;
  int regime_switches = 0;    // open <-> closed inside the increment
  int relaxations = 0;        // returns at fixed separation (closure jump, snap-back)
  bool plastic = false;       // any plastic flow in the increment
  bool min_substep_hit = false;  // a substep was accepted at the minimum size above STOL
  Failure failure = Failure::none;
  int newton_iterations = 0;     // implicit scheme: Newton iterations of all local solves
  // The tangent returned on request is not the exact derivative of this
  // update: an explicit scheme (continuum tangent, Eq. 20), a return at fixed
  // separation, or a regime switch in an increment with plastic flow (the
  // switch point is held fixed); docs/model.md 7.5.
  bool tangent_approximate = false;
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
};

// The first rule the state breaks, or nullptr: finite values, 0 <= d <= 1,
// works >= 0, open flag 0 or 1.
const char* check_state(const State& s);

// Integrates the separation increment d_separation (law signs) from `state`
// and overwrites `state` with the end state. On failure the state is left as
// it was and the result holds the start traction; nothing returned is ever
// NaN or infinite.
IncrementResult integrate_increment(const Model& model, State& state, const Vec3& d_separation);

// The same, and, when `tangent` is not null, the tangent d traction_end /
// d d_separation (law signs) of this update (docs/model.md 7.5):
//   - implicit scheme: the consistent (algorithmic) tangent of the backward
//     Euler update, through the elastic-plastic intersection, every plastic
//     substep (linearised local residuals at convergence) and the secant
//     damage rule; exact except where status.tangent_approximate says;
//   - explicit schemes: the continuum elastic-plastic tangent (Eq. 20) at the
//     end point after plastic flow, else the secant stiffness;
//   - elastic increment: the secant stiffness K(d, h) (Eq. 21);
//   - failed increment: the secant stiffness of the start state.
// Fixed-size, allocates nothing.
IncrementResult integrate_increment(const Model& model, State& state, const Vec3& d_separation, Mat3* tangent);

// The continuum (rate) tangent of Eq. 20 at a state and its traction, on the
// damage-growing branch: kS - (kF o m)(dF o kS)^T / denominator when the
// point is on the surface and the denominator is positive, else K(d, h).
Mat3 continuum_tangent(const Model& model, const State& state, const Vec3& traction);

// Runs integrate_increment over a block of points whose states lie in the
// solver's flat array: point k's state starts at state + k * state_stride.
// The caller's point_io supplies what differs between solvers:
//   bool increment(int k, const Real* flat_state, const State& s, Vec3& d)
//        the separation increment of point k (law signs); false skips the point;
//   void finish(int k, Real* flat_state, const State& s, const IncrementResult& r)
//        writes point k's outputs (after its state has been stored back).
// On failure a point keeps its start state with its Failure in slot 21.
// Returns the number of points that failed. No allocation.
template <class Real, class PointIO>
int integrate_block(const Model& model, int n_points, long state_stride, Real* state, PointIO& point_io) {
  int failures = 0;
  for (int k = 0; k < n_points; ++k) {
    Real* flat = state + k * state_stride;
    State s;
    load_state(flat, s);
    Vec3 d;
    if (!point_io.increment(k, static_cast<const Real*>(flat), s, d)) continue;
    const IncrementResult r = integrate_increment(model, s, d);
    store_state(s, flat);
    point_io.finish(k, flat, s, r);
    if (!r.status.ok()) ++failures;
  }
  return failures;
}

// Per-point energies a plain block may also return (nullptr to skip).
struct BlockOutputs {
  double* elastic_energy = nullptr;  // n_points
  double* d_dissipation = nullptr;   // n_points: plastic + damage + unilateral
};

// The same over plain arrays in the solver layout: separation increments
// (n_dir x n_points, column-major, law signs), state (n_states x n_points),
// traction out (n_dir x n_points). n_dir is 2 (one slip) or 3.
template <class Real>
int integrate_block(const Model& model, int n_points, int n_dir, int n_states, const Real* d_separation,
                    Real* state, Real* traction, BlockOutputs out = {}) {
  struct PlainArrays {
    int n_dir;
    const Real* d_separation;
    Real* traction;
    BlockOutputs out;
    bool increment(int k, const Real*, const State&, Vec3& d) const {
      const Real* dk = d_separation + static_cast<long>(k) * n_dir;
      d = Vec3(double(dk[0]), double(dk[1]), n_dir > 2 ? double(dk[2]) : 0.0);
      return true;
    }
    void finish(int k, Real*, const State&, const IncrementResult& r) const {
      Real* tk = traction + static_cast<long>(k) * n_dir;
      for (int i = 0; i < n_dir; ++i) tk[i] = Real(r.traction[i]);
      if (out.elastic_energy) out.elastic_energy[k] = r.elastic_energy;
      if (out.d_dissipation)
        out.d_dissipation[k] = r.d_dissipation_plastic + r.d_dissipation_damage + r.d_energy_unilateral;
    }
  } io{n_dir, d_separation, traction, out};
  return integrate_block(model, n_points, static_cast<long>(n_states), state, io);
}

}  // namespace mortar
