// ExplicitBlock's two stores (integrate_point, elastic_lanes): an elastic
// increment's slots, or an integrated increment's whole state, in single
// precision checked before any is stored (docs/model.md 3); and a rejected
// increment, which keeps its start state and outputs.
#pragma once

namespace mj_adapter {

// The law rejected the increment: it kept the start state; only the counts
// and the status change, and the start traction goes out if finite.
template <class Real>
inline int ExplicitBlock<Real>::keep_rejected(const Setup& setup, int k, Real* st, const mortar::State& s,
                                              const mortar::IncrementResult& r) const {
  st[mortar::slot::substeps_accepted] = Real(s.substeps_accepted);
  st[mortar::slot::substeps_rejected] = Real(s.substeps_rejected);
  st[mortar::slot::status] = Real(s.status);
  Real* stress_k = stress_of(k);
  Real stress_start[3];
  abaqus_stress(setup, r.traction, stress_start);
  std::copy(stress_start, stress_start + counts.n_dir, stress_k);
  write_energies(k, r.elastic_energy, 0.0);
  if (!all_finite(stress_k, counts.n_dir) || !std::isfinite(double(sed[k]))) keep_start_outputs(k);
  return static_cast<int>(r.status.failure);
}

// An elastic increment (the shortcut's or the lanes'): only the slots it
// changes (StateStorage::store_elastic); kChecked when the lanes have tested
// already that every value fits in Real. No dissipation: spd is 0.
template <class Real>
template <bool kChecked>
inline int ExplicitBlock<Real>::store_elastic(const Setup& setup, const StateStorage<Real>& storage, int k, Real* st,
                                              const mortar::State& s, const mortar::Vec3& traction, double energy,
                                              bool turned, bool first) const {
  // Fixed counts, so that the checks and copies need no loops: in 2D the
  // third component is not an output.
  Real out[4];
  abaqus_stress(setup, traction, out);
  out[3] = Real(energy);
  if constexpr (kChecked) {  // the lanes: no first call, every value known to fit
    storage.template store_elastic<true>(s, turned, out, st);
  } else {
    if (!storage.template store_elastic<false>(s, turned, out, st))
      return reject_point(k, mortar::Failure::non_finite_result);
    if (first) mark_initialised(k, st);
  }
  write_stress(k, out);
  write_energies(k, double(out[3]), 0.0);
  return 0;
}

// Any other integrated increment: the law's end state, traction and
// energies. In double precision they are finite (integrate_increment's
// promise, d_inelastic() included) and go straight into the caller's
// arrays; in single precision a double beyond a float's range comes back as
// infinity, so the values are staged and checked before any is stored.
template <class Real>
inline int ExplicitBlock<Real>::store_full(const Setup& setup, const StateStorage<Real>& storage, int k, Real* st,
                                           const mortar::State& s, const mortar::IncrementResult& r,
                                           bool first) const {
  if constexpr (StateStorage<Real>::kSingle) {
    // The count a constant in each branch, so that the copies and the finite
    // test are vector code rather than calls of memcpy and loops.
    if (storage.cap) return store_float_over<mortar::kCappedStateCountSingle>(setup, storage, k, st, s, r, first);
    if (storage.flags) return store_float_over<mortar::kFlaggedStateCount>(setup, storage, k, st, s, r, first);
    if (storage.pairs) return store_float_over<mortar::kPairedStateCount>(setup, storage, k, st, s, r, first);
    return store_float_over<mortar::kStateCount>(setup, storage, k, st, s, r, first);
  } else {
    storage.store(s, st);
    if (first) mark_initialised(k, st);
    Real stress_end[3];
    abaqus_stress(setup, r.traction, stress_end);
    write_stress(k, stress_end);
    write_energies(k, r.elastic_energy, r.d_inelastic());
    return 0;
  }
}

// store_full in single precision over the first kCount slots: the state
// staged in a copy, the copy, stress and energies checked, then stored.
template <class Real>
template <int kCount>
inline int ExplicitBlock<Real>::store_float_over(const Setup& setup, const StateStorage<Real>& storage, int k, Real* st,
                                                 const mortar::State& s, const mortar::IncrementResult& r,
                                                 bool first) const {
  Real end[kCount];
  std::copy(st, st + kCount, end);
  storage.store_into(s, end);
  if (first) mark_initialised(k, end);
  Real stress_end[3];
  abaqus_stress(setup, r.traction, stress_end);
  const Real sed_end = Real(r.elastic_energy);
  const Real spd_end = Real(r.d_inelastic());
  const Real energies[2] = {sed_end, spd_end};
  if (!all_finite(end, kCount) || !all_finite(stress_end, 3) || !all_finite(energies, 2))
    return reject_point(k, mortar::Failure::non_finite_result);
  std::copy(end, end + kCount, st);
  write_stress(k, stress_end);
  write_energies(k, double(sed_end), double(spd_end));
  return 0;
}

}  // namespace mj_adapter
