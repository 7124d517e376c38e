// How the Abaqus/Explicit routines keep the law's double-precision state in
// the solver's array of their precision (docs/model.md 3).
//
//   double   the 23 slots of mortar::slot; slots beyond them are not touched.
//   float    with DEPVAR >= 34, the variables that accumulate and feed back
//            into the traction (plastic separation, works, damages, total
//            separation) as float pairs: the value rounded to float in its
//            own slot, the remainder in SDV 24-34 (mortar::low_slot). A float
//            alone has a spacing of 4e-9 mm at 0.05 mm, so increments below
//            it are lost or rounded away and softening stalls at the
//            increments Abaqus/Explicit takes; the pair keeps about 48 bits.
//            With DEPVAR 23..33, plain floats, and one warning per process.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <type_traits>

#include "adapter/report.hpp"
#include "mortar/finite.hpp"
#include "mortar/state.hpp"

namespace mj_adapter {

template <class Real>
struct StateStorage {
  static constexpr bool kSingle = std::is_same_v<Real, float>;

  bool pairs = false;               // float pairs in SDV 24-34
  int count = mortar::kStateCount;  // slots read and written per point

  static StateStorage of(int n_states) {
    StateStorage s;
    s.pairs = kSingle && n_states >= mortar::kPairedStateCount;
    s.count = s.pairs ? mortar::kPairedStateCount : mortar::kStateCount;
    return s;
  }

  // Single precision with too few slots for the pairs.
  bool plain_float() const { return kSingle && !pairs; }

  // Every low part belongs to its high part (mortar::pair_consistent).
  bool consistent(const Real* st) const {
    if constexpr (kSingle) {
      if (!pairs) return true;
      // Without a branch per pair: it runs on every point-update.
      int all = 1;
      mortar::for_each_pair_slot([&](int, int high, int low) { all &= mortar::pair_consistent(st[high], st[low]); });
      return all;
    }
    return true;
  }

  void load(const Real* st, mortar::State& s) const {
    if constexpr (kSingle) {
      if (pairs) return mortar::load_state_pairs(st, s);
    }
    mortar::load_state(st, s);
  }

  // What store() changes after an elastic increment (mortar::elastic_increment):
  // the separation (SDV 12-14), the open flag, the counts and status (SDV
  // 19-21) and the tangential components a rotation turns (SDV 2-3, 5-6); the
  // value store() would write into any other slot is the one it read (a
  // finite Real, to double and back). With float pairs everything store()
  // writes, since it rewrites each pair as the rounding of its value (a pair
  // it did not write itself may round differently). False, with nothing
  // written, when a value does not fit in Real (the full path's rejection).
  bool store_elastic(const mortar::State& s, Real* st) const {
    namespace slot = mortar::slot;
    if constexpr (kSingle) {
      if (pairs) {
        // Every slot store() writes, through a copy checked before it is
        // stored: the pairs' rounding stays out of line (mortar::store_state_pairs).
        float end[mortar::kPairedStateCount];
        std::copy(st, st + mortar::kPairedStateCount, end);
        mortar::store_state_pairs(s, end);
        if (!mortar::all_finite(end, mortar::kPairedStateCount)) return false;
        std::copy(end, end + mortar::kPairedStateCount, st);
        return true;
      }
    }
    const Real v[] = {Real(s.plastic[1]), Real(s.plastic[2]),    Real(s.crack[1]),     Real(s.crack[2]),
                      Real(s.separation[0]), Real(s.separation[1]), Real(s.separation[2])};
    if constexpr (kSingle) {  // a finite double is itself
      if (!mortar::all_finite(v, 7)) return false;
    }
    st[slot::plastic_s1] = v[0];
    st[slot::plastic_s2] = v[1];
    st[slot::crack_s1] = v[2];
    st[slot::crack_s2] = v[3];
    for (int i = 0; i < 3; ++i) st[slot::separation_n + i] = v[4 + i];
    store_counts(s, st);
    return true;
  }

  void store(const mortar::State& s, Real* st) const {
    if constexpr (kSingle) {
      if (pairs) return mortar::store_state_pairs(s, st);
    }
    mortar::store_state(s, st);
  }

 private:
  static void store_counts(const mortar::State& s, Real* st) {
    namespace slot = mortar::slot;
    st[slot::open] = Real(s.open ? 1 : 0);
    st[slot::substeps_accepted] = Real(s.substeps_accepted);
    st[slot::substeps_rejected] = Real(s.substeps_rejected);
    st[slot::status] = Real(s.status);
  }
};

// The plain-float fallback loses small increments silently, so it is named
// once per process (in Abaqus: once per analysis, in the log). The flag is the
// adapters' only static: it decides whether this line is written, never a
// result, and is atomic because Abaqus calls from several threads.
inline void warn_plain_float(const Caller& who, int n_states) {
  static std::atomic<bool> warned{false};
  if (warned.exchange(true)) return;
  char what[400];
  std::snprintf(what, sizeof what,
                "warning: DEPVAR = %d is below %d: single precision keeps the state as plain floats, which lose "
                "increments below their spacing (softening stalls at small increments); DEPVAR=%d keeps it as "
                "float pairs (SDV 24-%d). Reported once.",
                n_states, mortar::kPairedStateCount, mortar::kPairedStateCount, mortar::kPairedStateCount);
  report(who, what);
}

}  // namespace mj_adapter
