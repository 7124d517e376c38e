// ExplicitBlock's elastic lanes: the elastic shortcut for two points at once
// (mortar::lanes::elastic_increment_lanes, one point per lane of a vector of
// doubles), between the solver's arrays and the elastic store.
// The rest: docs/adapters.md, section 2.
#pragma once

namespace mj_adapter {

#if MJ_ELASTIC_LANES
// What the lanes' check (lane_candidates) reads besides the increment's
// start: the state's other rules and the point's call arguments.
template <class Real>
struct ExplicitBlock<Real>::LaneCheckInputs {
  mortar::lanes::D wIII, dissipation_damage, penetration, substeps_accepted, initialised, turn;
  mortar::lanes::Mask loaded;  // finite SDV 1-18, every float pair canonical, SDV 35 valid where kept
};

template <class Real>
MORTAR_KERNEL_INLINE void ExplicitBlock<Real>::load_lane(const StateStorage<Real>& storage, int k, int lane,
                                    mortar::lanes::ElasticLanes& y, LaneCheckInputs& checks) const {
  namespace slot = mortar::slot;
  const Real* st = state_of(k);
  const double pen = penetration_of(k);
  // v: plastic separation 0-2, wI, wII, wIII, dn, ds 3-7, separation 8-10
  // (mortar::kPairedSlots).
  double v[mortar::kPairCount];
  const bool canonical = storage.lane_values(st, v), finite = all_finite(st, slot::substeps_accepted);
  for (int i = 0; i < 3; ++i) {
    y.plastic[i][lane] = v[i];
    y.separation[i][lane] = v[8 + i];
  }
  y.wI[lane] = v[3];
  y.wII[lane] = v[4];
  y.dn[lane] = v[6];
  y.ds[lane] = v[7];
  y.h[lane] = double(st[slot::open]);
  // separation_increment(), not a first call.
  const Real* dd = d_rel_disp_of(k);
  y.d[0][lane] = (double(st[slot::reference_penetration]) - pen) - v[8];
  y.d[1][lane] = double(dd[1]);
  y.d[2][lane] = counts.n_dir > 2 ? double(dd[2]) : 0.0;
  checks.wIII[lane] = v[5];
  checks.dissipation_damage[lane] = double(st[slot::dissipation_damage]);
  checks.penetration[lane] = pen;
  checks.substeps_accepted[lane] = double(st[slot::substeps_accepted]);
  checks.initialised[lane] = double(st[slot::initialised]);
  checks.turn[lane] = may_turn() ? double(distance_from_identity(d_rot_of(k))) : 0.0;
  const bool flags_valid =
      !storage.flags || mortar::integration_flags_valid(double(st[mortar::flag_slot::integration_flags]));
  checks.loaded[lane] = (canonical & finite & flags_valid) ? -1 : 0;
}

// The lanes that integrate_point's shortcut would take and that need none of
// its special cases: the state's rules (mortar::adapter_slots_valid's and
// mortar::ranges_hold, over the lanes) with w_III = 0 and SDV 23 = 1 (not a
// first call), paired, SDV 19 = 0, dRot the identity.
template <class Real>
mortar::lanes::Mask ExplicitBlock<Real>::lane_candidates(const mortar::lanes::ElasticLanes& y, const LaneCheckInputs& r) {
  const mortar::lanes::Mask rules =
      mortar::flag_valid(y.h) & mortar::ranges_hold(y.dn, y.ds, y.wI, y.wII, r.wIII, r.dissipation_damage);
  return r.loaded && rules && r.wIII == 0.0 && r.initialised == 1.0 && r.penetration > kUnpairedPenetration &&
         r.substeps_accepted == 0.0 && r.turn == 0.0;
}

// The lanes proved elastic whose end values all fit in Real. In single
// precision: the separation, traction and energy at most FLT_MAX in
// magnitude, so that their conversions to float (the stress, sed, the
// separation's pairs, whose low parts lie within a spacing of their high
// parts) are finite, in any rounding mode. (SDV 22, which store_elastic
// tests too, is finite in a lane proved elastic: its increment is computed ...
// The rest: docs/adapters.md, section 3.
template <class Real>
mortar::lanes::Mask ExplicitBlock<Real>::fits_in_real(const mortar::lanes::ElasticLaneResult& r) {
  if constexpr (!StateStorage<Real>::kSingle) {
    return r.elastic;  // a finite double is itself
  } else {
    using mortar::abs_of;
    const double most = std::numeric_limits<float>::max();
    mortar::lanes::Mask fits = r.elastic && abs_of(r.energy) <= most;
    for (int i = 0; i < 3; ++i) fits = fits && abs_of(r.separation[i]) <= most && abs_of(r.traction[i]) <= most;
    return fits;
  }
}

template <class Real>
MORTAR_KERNEL_INLINE unsigned ExplicitBlock<Real>::elastic_lanes(const Setup& setup, const StateStorage<Real>& storage, int k) const {
  namespace slot = mortar::slot;
  using mortar::lanes::kWidth;
  mortar::lanes::ElasticLanes y;
  LaneCheckInputs checks;
  for (int l = 0; l < kWidth; ++l) load_lane(storage, k + l, l, y, checks);
  y.candidate = lane_candidates(y, checks);
  const mortar::lanes::ElasticLaneResult r = mortar::lanes::elastic_increment_lanes(setup.model, y);
  const mortar::lanes::Mask take = fits_in_real(r);
  unsigned done = 0;
  for (int l = 0; l < kWidth; ++l) {
    if (!take[l]) continue;
    Real* st = state_of(k + l);
    // The end state as store_elastic reads it: the separation booked, the
    // tangential plastic and crack components as they are (no turn), the
    // open flag kept, no substeps.
    mortar::State s;
    s.separation = mortar::Vec3(r.separation[0][l], r.separation[1][l], r.separation[2][l]);
    s.plastic = mortar::Vec3(y.plastic[0][l], y.plastic[1][l], y.plastic[2][l]);
    s.crack = mortar::Vec3(0.0, double(st[slot::crack_s1]), double(st[slot::crack_s2]));
    s.open = y.h[l] != 0;
    const mortar::Vec3 traction(r.traction[0][l], r.traction[1][l], r.traction[2][l]);
    store_elastic<true>(setup, storage, k + l, st, s, traction, r.energy[l], false, false);
    MJ_COUNT_PATH(lanes);
    done |= 1u << l;
  }
  return done;
}
#endif

}  // namespace mj_adapter
