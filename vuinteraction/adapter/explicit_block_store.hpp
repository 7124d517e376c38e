// ExplicitBlock's full-path stores (integrate_point): a rejected increment
// keeps its start state and outputs; an integrated one goes into the caller's
// arrays, in single precision staged and checked first (docs/model.md 3).
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

// integrate_point's store in double precision: the law's end state,
// traction and energies are finite (integrate_increment's promise, which
// integrate_with checks, d_inelastic() included), and SDV 22 was finite or
// the increment was rejected: everything
// goes straight into the caller's arrays.
template <class Real>
inline int ExplicitBlock<Real>::store_double(const Setup& setup, const StateStorage<Real>& storage, int k, Real* st,
                                             const mortar::State& s, const mortar::IncrementResult& r,
                                             bool first) const {
  storage.store(s, st);
  if (first) mark_initialised(k, st);
  Real stress_end[3];
  abaqus_stress(setup, r.traction, stress_end);
  write_stress(k, stress_end);
  write_energies(k, r.elastic_energy, r.d_inelastic());
  return 0;
}

// integrate_point's store in single precision: the law's result as floats,
// a double beyond a float's range coming back as infinity, checked before
// anything is stored (the state staged in a copy). The count a constant in
// each branch, so that the copies and the finite test are vector code
// rather than calls of memcpy and loops.
template <class Real>
inline int ExplicitBlock<Real>::store_float(const Setup& setup, const StateStorage<Real>& storage, int k, Real* st,
                                            const mortar::State& s, const mortar::IncrementResult& r,
                                            bool first) const {
  if (storage.flags) return store_float_over<mortar::kFlaggedStateCount>(setup, storage, k, st, s, r, first);
  if (storage.pairs) return store_float_over<mortar::kPairedStateCount>(setup, storage, k, st, s, r, first);
  return store_float_over<mortar::kStateCount>(setup, storage, k, st, s, r, first);
}
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
