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

#include <atomic>
#include <cstdio>
#include <type_traits>

#include "adapter/report.hpp"
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
      for (const mortar::SlotPair& p : mortar::kPairedSlots)
        if (!mortar::pair_consistent(st[p.high], st[p.low])) return false;
    }
    return true;
  }

  void load(const Real* st, mortar::State& s) const {
    if constexpr (kSingle) {
      if (pairs) return mortar::load_state_pairs(st, s);
    }
    mortar::load_state(st, s);
  }

  void store(const mortar::State& s, Real* st) const {
    if constexpr (kSingle) {
      if (pairs) return mortar::store_state_pairs(s, st);
    }
    mortar::store_state(s, st);
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
