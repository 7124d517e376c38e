// Abaqus/Explicit's block of points (VUINTERACTION and VUINTER) over the law,
// in either precision (Real = mj_real); the law itself always runs in double
// precision. This is where Abaqus/Explicit's conventions meet the law's
// (docs/abaqus.md; law signs: docs/model.md 1):
// The rest: docs/adapters.md, section 1.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "adapter/arguments.hpp"
#include "adapter/path_counters.hpp"
#include "adapter/report.hpp"
#include "adapter/rotation.hpp"
#include "adapter/state_storage.hpp"
#include "mortar/batch.hpp"
#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"

// The elastic lanes: where the compiler has vector types and the fast paths
// are built (MJ_FAST_PATHS).
#define MJ_ELASTIC_LANES (MORTAR_ELASTIC_LANES && MORTAR_FAST_PATHS)

namespace mj_adapter {

// Point-failure messages printed per call before a summary line.
constexpr int kMaxPointMessages = 5;

// Abaqus/Explicit: props(15) = 0 is modified Euler, props(20) = 0 is -1.
constexpr Defaults kExplicitDefaults = {mortar::Scheme::modified_euler, -1.0,
                                        "props(20) is 0 (default, = -1), -1 or +1"};

// The outputs a value of the caller's becomes when it is not finite.
template <class Real>
double finite_or_zero(Real x) {
  return std::isfinite(double(x)) ? double(x) : 0.0;
}

using mortar::all_finite;

// One call in the adapter's own terms: points k = 0 .. n_points-1, each
// entry point filling in where its arguments lie.
template <class Real>
struct ExplicitBlock {
  Counts counts;
  int n_points = 0;
  long state_stride = 0;           // distance between the states of points k and k+1
  const Real* penetration = nullptr;
  long penetration_stride = 1;     // 1 (VUINTERACTION) or nDir (VUINTER: rdisp(1,k))
  const Real* d_rel_disp = nullptr;  // (nDir, n_points)
  const Real* d_rot = nullptr;       // (2, 2, n_points)
  const int* node = nullptr;       // user node number of point k, for messages
  long node_stride = 1;
  const Real* props = nullptr;
  Real *stress = nullptr, *state = nullptr, *sed = nullptr;
  Real *spd = nullptr, *sfd = nullptr, *scd = nullptr, *svd = nullptr;
  Real *flux_slv = nullptr, *flux_mst = nullptr;

  // The arrays the routine writes, in the order both argument lists share.
  void set_outputs(Real* stress, Real* state, Real* sed, Real* spd, Real* sfd, Real* scd, Real* svd, Real* flux_slv,
                   Real* flux_mst) {
    this->stress = stress;
    this->state = state;
    this->sed = sed;
    this->spd = spd;
    this->sfd = sfd;
    this->scd = scd;
    this->svd = svd;
    this->flux_slv = flux_slv;
    this->flux_mst = flux_mst;
  }

  Real* state_of(int k) const { return state + k * state_stride; }
  Real* stress_of(int k) const { return stress + static_cast<long>(k) * counts.n_dir; }
  const Real* d_rel_disp_of(int k) const { return d_rel_disp + static_cast<long>(k) * counts.n_dir; }
  const Real* d_rot_of(int k) const { return d_rot + 4L * k; }
  double penetration_of(int k) const { return double(penetration[k * penetration_stride]); }
  int node_of(int k) const { return node ? node[k * node_stride] : 0; }

  // A rejected block: finite outputs and the code in SDV 21 of every point,
  // as far as the arrays the caller declared reach (nDir and the state count
  // may be the bad arguments themselves).
  void reject(int code) const {
    for (int k = 0; k < n_points; ++k) {
      if (counts.n_dir > 0) {
        keep_start_outputs(k);
      } else {
        write_energies(k, finite_or_zero(sed[k]), 0.0);
      }
      if (counts.n_states > mortar::slot::status && counts.n_node_states >= 1)
        state_of(k)[mortar::slot::status] = Real(code);
    }
  }

  // Whether a paired point's dRot may turn its directions (3D): check_points
  // finds out; until it has, every point's dRot is tested where it is used.
  bool any_turn = true;
  bool may_turn() const { return counts.n_dir == 3 && any_turn; }

  // The per-point arguments' rules, before any point is integrated: the
  // first paired point (in 3D) whose dRot is not a rotation is reported and
  // rejects the block. Returns its adapter code, or 0. Sets any_turn: where
  // no paired point turns (every unrotated or 2D analysis), the per-point
  // paths skip their own test of dRot.
  int check_points(const Caller& who, const ArgumentNames& names) {
    any_turn = false;
    if (counts.n_dir != 3) return 0;
    for (int k = 0; k < n_points; ++k) {
      if (penetration_of(k) <= kUnpairedPenetration) continue;  // not integrated: dRot not used
      if (is_identity(d_rot_of(k))) continue;                     // a joint whose directions do not turn
      any_turn = true;
      const RotationCheck c = check_rotation(d_rot_of(k));
      if (c.ok()) continue;
      char index[16], where[96];
      std::snprintf(index, sizeof index, ",%d", k + 1);
      std::snprintf(where, sizeof where, "point %d of %d, slave node %d", k + 1, n_points, node_of(k));
      report_rotation(who, names.rotation, index, where, d_rot_of(k), c);
      return kBadRotation;
    }
    return 0;
  }

  // Integrates every point; reports the failed ones. False when any failed.
  bool integrate(const Caller& who, const Setup& setup) const {
    const StateStorage<Real> storage = StateStorage<Real>::of(counts.n_states, setup.model.cap.on());
    if (storage.plain_float()) warn_plain_float(who, counts.n_states);
    int failures = 0;
    auto integrate_one = [&](int k) {
      const int failure = integrate_point(setup, storage, k);
      if (failure != 0 && ++failures <= kMaxPointMessages) report_point(who, k, failure);
    };
    int k = 0;
#if MJ_ELASTIC_LANES
    // The points in pairs through the elastic lanes first; a point they do
    // not take goes the way of every other, in the same order. The lanes
    // prove "inside" against the shear-tension surface alone: a deck with a
    // cap sends every point through integrate_point.
    using mortar::lanes::kWidth;
    if (!storage.plain_float() && !storage.cap)
      for (; k + kWidth <= n_points; k += kWidth) {
        // Points whose last increment was plastic (SDV 19 > 0) go the full
        // path at once (integrate_point): a pair of them is not loaded into
        // the lanes at all, which spares the plastic path their cost.
        bool elastic_last = false;
        for (int l = 0; l < kWidth; ++l) elastic_last |= state_of(k + l)[mortar::slot::substeps_accepted] == Real(0);
        const unsigned done = elastic_last ? elastic_lanes(setup, storage, k) : 0u;
        for (int l = 0; l < kWidth; ++l)
          if (!((done >> l) & 1u)) integrate_one(k + l);
      }
#endif
    for (; k < n_points; ++k) integrate_one(k);
    if (failures > kMaxPointMessages) {
      char what[160];
      std::snprintf(what, sizeof what, "%d points of %d failed in this call (first %d shown)", failures, n_points,
                    kMaxPointMessages);
      report(who, what);
    }
    return failures == 0;
  }

 private:
  void write_energies(int k, double sed_k, double spd_k) const {
    sed[k] = Real(sed_k);
    spd[k] = Real(spd_k);
    sfd[k] = scd[k] = svd[k] = Real(0);
    flux_slv[k] = flux_mst[k] = Real(0);
  }

  // Outputs of a point that is not integrated: stress and sed as they came
  // in (made finite), no dissipation.
  void keep_start_outputs(int k) const {
    Real* s = stress_of(k);
    for (int i = 0; i < counts.n_dir; ++i) s[i] = Real(finite_or_zero(s[i]));
    write_energies(k, finite_or_zero(sed[k]), 0.0);
  }

  // A point that is not integrated: its start state (the caller's array,
  // untouched but for the status), its stress and sed as they came in.
  int reject_point(int k, mortar::Failure failure) const {
    state_of(k)[mortar::slot::status] = Real(static_cast<int>(failure));
    keep_start_outputs(k);
    return static_cast<int>(failure);
  }

  void report_point(const Caller& who, int k, int failure) const {
    char what[400];
    std::snprintf(what, sizeof what,
                  "point %d of %d (slave node %d): the law rejected the increment: %s (SDV 21 = %d); "
                  "the point keeps its start state",
                  k + 1, n_points, node_of(k), mortar::failure_name(static_cast<mortar::Failure>(failure)), failure);
    report(who, what);
  }

  // The separation increment of point k (law signs), from its state and
  // inputs. The first call defines the zero, so it contributes no increment;
  // a non-finite penetration yields a non-finite increment, which the law
  // rejects.
  mortar::Vec3 separation_increment(int k, const Real* st, const mortar::State& s) const {
    const double pen = penetration_of(k);
    const bool first = st[mortar::slot::initialised] == Real(0);
    if (first) return std::isfinite(pen) ? mortar::Vec3::Zero() : mortar::Vec3::Constant(NAN);
    const double reference = double(st[mortar::slot::reference_penetration]);
    const Real* dd = d_rel_disp_of(k);
    return mortar::Vec3((reference - pen) - s.separation[0], double(dd[1]), counts.n_dir > 2 ? double(dd[2]) : 0.0);
  }

  // The law's traction in Abaqus's signs: pressure positive, shear_sign * tau.
  // Always three values, the third 0 in 2D (not an output), so that the
  // callers' finite tests run over a fixed count: with a count of n_dir, GCC's
  // vectorised test at -mavx2 and above warns of the elements beyond it.
  void abaqus_stress(const Setup& setup, const mortar::Vec3& traction, Real* stress_k) const {
    stress_k[0] = Real(-traction[0]);
    stress_k[1] = Real(setup.shear_sign * traction[1]);
    stress_k[2] = counts.n_dir == 2 ? Real(0) : Real(setup.shear_sign * traction[2]);
  }

#if MJ_ELASTIC_LANES
  // The elastic shortcut for points k .. k + kWidth - 1 at once
  // (adapter/explicit_block_lanes.hpp).
  unsigned elastic_lanes(const Setup& setup, const StateStorage<Real>& storage, int k) const;
  struct LaneCheckInputs;
  void load_lane(const StateStorage<Real>& storage, int k, int lane, mortar::lanes::ElasticLanes& y,
                 LaneCheckInputs& checks) const;
  static mortar::lanes::Mask lane_candidates(const mortar::lanes::ElasticLanes& y, const LaneCheckInputs& checks);
  static mortar::lanes::Mask fits_in_real(const mortar::lanes::ElasticLaneResult& r);
#endif

  // A first call's reference (SDV 22, 23), into the state array `st` or a
  // copy of it.
  void mark_initialised(int k, Real* st) const {
    st[mortar::slot::reference_penetration] = Real(penetration_of(k));
    st[mortar::slot::initialised] = Real(1);
  }

  // Point k's stress, component by component: a copy of n_dir values would
  // be a call of memmove.
  void write_stress(int k, const Real* out) const {
    Real* stress_k = stress_of(k);
    stress_k[0] = out[0];
    stress_k[1] = out[1];
    if (counts.n_dir == 3) stress_k[2] = out[2];
  }

  // The two stores (adapter/explicit_block_store.hpp): an elastic
  // increment's (the shortcut's and the lanes'), which writes only the slots
  // such an increment changes; any other's, the whole state. Besides, the
  // writers of a point that keeps its start state: keep_rejected (the law
  // rejected the increment) and reject_point.
  template <bool kChecked>
  int store_elastic(const Setup& setup, const StateStorage<Real>& storage, int k, Real* st, const mortar::State& s,
                    const mortar::Vec3& traction, double energy, bool turned, bool first) const;
  int store_full(const Setup& setup, const StateStorage<Real>& storage, int k, Real* st, const mortar::State& s,
                 const mortar::IncrementResult& r, bool first) const;
  template <int kCount>
  int store_float_over(const Setup& setup, const StateStorage<Real>& storage, int k, Real* st, const mortar::State& s,
                       const mortar::IncrementResult& r, bool first) const;
  int keep_rejected(const Setup& setup, int k, Real* st, const mortar::State& s,
                    const mortar::IncrementResult& r) const;

  // Whether the elastic shortcut may try point k's increment: its last
  // increment elastic (SDV 19 = 0: a plastic one most likely left it on the
  // surface, where the shortcut proves nothing), the state well formed (SDV
  // 1-18 finite, every float pair canonical, so that the elastic store may
  // leave unchanged pairs as they are) and in range, and what the turn and a
  // first call bring finite.
  bool shortcut_may_try(const Real* st, const mortar::State& s, bool well_formed, bool turned, bool first) const {
    namespace slot = mortar::slot;
    if (!(MORTAR_FAST_PATHS && st[slot::substeps_accepted] == Real(0))) return false;
    if (!well_formed || !mortar::state_in_range(s)) return false;
    if (turned) {
      const double v[] = {s.plastic[1], s.plastic[2], s.crack[1], s.crack[2], s.separation[1], s.separation[2]};
      if (!all_finite(v, 6)) return false;
    }
    return !first || std::isfinite(double(st[slot::reference_penetration]));
  }

  // Integrates point k and writes its outputs: check the point's slots, load
  // its state once, turn it by dRot, form the increment, integrate (by the
  // elastic shortcut where it proves the increment elastic, else the law's
  // full integration: the same result), store. Returns the Failure code.
  int integrate_point(const Setup& setup, const StateStorage<Real>& storage, int k) const {
    namespace slot = mortar::slot;
    if (penetration_of(k) <= kUnpairedPenetration) {  // no opposite surface: no interaction
      std::fill(stress_of(k), stress_of(k) + counts.n_dir, Real(0));
      write_energies(k, 0.0, 0.0);
      MJ_COUNT_PATH(unpaired);
      return 0;
    }
    Real* st = state_of(k);
    mortar::State s;
    const bool canonical = storage.load(st, s);
    const bool well_formed = canonical & all_finite(st, slot::substeps_accepted);
    if (!storage.slots_valid(st) || !storage.consistent(st, well_formed)) {
      MJ_COUNT_PATH(full);  // as the law's own rejections
      return reject_point(k, mortar::Failure::invalid_state);
    }
    const bool turned = may_turn() && !is_identity(d_rot_of(k));
    if (turned) rotate_tangential_state(d_rot_of(k), s);
    const bool first = st[slot::initialised] == Real(0);
    const mortar::Vec3 d = separation_increment(k, st, s);
    if (shortcut_may_try(st, s, well_formed, turned, first)) {
      mortar::IncrementResult r;
      if (mortar::elastic_increment(setup.model, s, d, r)) {
        MJ_COUNT_PATH(shortcut);
        return store_elastic<false>(setup, storage, k, st, s, r.traction, r.elastic_energy, turned, first);
      }
    }
    MJ_COUNT_PATH(full);
    // A copy for the law to overwrite, so that s itself never has its
    // address taken and stays in registers on the shortcut's path.
    mortar::State end = s;
    const mortar::IncrementResult r = mortar::integrate_full(setup.model, end, d);
    if (!r.status.ok()) return keep_rejected(setup, k, st, end, r);
    return store_full(setup, storage, k, st, end, r, first);
  }
};

}  // namespace mj_adapter

#include "adapter/explicit_block_lanes.hpp"
#include "adapter/explicit_block_store.hpp"
