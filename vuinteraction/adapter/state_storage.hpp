// How the Abaqus/Explicit routines keep the law's double-precision state in
// the solver's array of their precision (docs/model.md 3).
//
//   double   the 23 slots of mortar::slot; slots beyond them are not touched.
//   cap      a deck with a compression cap also keeps kappa_c in SDV 36 (37:
//            its float pair's low part in single precision); without a cap
//            SDV 36-37 are never read or written.
// The rest: docs/adapters.md, section 7.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <type_traits>

#include "adapter/report.hpp"
#include "mortar/finite.hpp"
#include "mortar/batch.hpp"
#include "mortar/state_pairs.hpp"

namespace mj_adapter {

template <class Real>
struct StateStorage {
  static constexpr bool kSingle = std::is_same_v<Real, float>;

  bool pairs = false;               // float pairs in SDV 24-34
  bool flags = false;               // integration flags in SDV 35
  bool cap = false;                 // kappa_c in SDV 36 (and 37)
  int count = mortar::kStateCount;  // slots read and written per point

  // The DEPVAR a deck with a cap needs in this precision (run_call checks it,
  // so that a capped storage always has the pairs and the flags too).
  static constexpr int kCappedCount = kSingle ? mortar::kCappedStateCountSingle : mortar::kCappedStateCountDouble;

  static StateStorage of(int n_states, bool capped = false) {
    StateStorage s;
    s.pairs = kSingle && n_states >= mortar::kPairedStateCount;
    s.flags = n_states >= mortar::kFlaggedStateCount;
    s.cap = capped && n_states >= kCappedCount;
    s.count = s.cap     ? kCappedCount
              : s.flags ? mortar::kFlaggedStateCount
              : s.pairs ? mortar::kPairedStateCount
                        : mortar::kStateCount;
    return s;
  }

  // Single precision with too few slots for the pairs.
  bool plain_float() const { return kSingle && !pairs; }

  // The adapter's own slots obey their rules (mortar::adapter_slots_valid).
  // With a cap, kappa_c too (mortar::kappa_c_valid; in single precision its
  // pair consistent as well).
  bool slots_valid(const Real* st) const {
    if (!mortar::adapter_slots_valid(st, flags)) return false;
    if (!cap) return true;
    if constexpr (kSingle) {
      return mortar::kappa_c_pair_valid(st);
    } else {
      return mortar::kappa_c_valid(mortar::load_kappa_c(st));
    }
  }

  // Every low part belongs to its high part (mortar::pair_consistent).
  // `well_formed` (SDV 1-18 finite and every pair canonical) implies it: a
  // canonical pair with a finite high part is consistent, so the pairs are
  // tested one by one only otherwise.
  bool consistent(const Real* st, bool well_formed) const {
    if constexpr (kSingle) {
      if (pairs && !well_formed) return mortar::pairs_consistent(st);
    }
    return true;
  }

  // SDV 1-23 (the pairs' values where kept, the integration flags and
  // kappa_c where kept) into s; whether every float pair is canonical
  // (mortar::pair_canonical: store() would write it unchanged), always true
  // without pairs.
  bool load(const Real* st, mortar::State& s) const {
    if (flags) s.integration_flags = mortar::load_integration_flags(st);
    mortar::load_state(st, s);
    if constexpr (kSingle) {
      if (!pairs) return true;
      bool cap_canonical = true;
      if (cap) s.kappa_c = mortar::load_kappa_c_pair(st, cap_canonical);
      return mortar::canonical_pairs_into(st, s) & cap_canonical;
    } else {
      if (cap) s.kappa_c = mortar::load_kappa_c(st);
      return true;
    }
  }

  // The elastic lanes' load (ExplicitBlock::elastic_lanes): the paired
  // variables' values, in the order of mortar::kPairedSlots, and whether the
  // lanes may take the state: always in double precision; with float pairs
  // when every pair is canonical (as load() tells, so that store_elastic()
  // may leave them where they are). Not for plain floats.
#if MORTAR_ELASTIC_LANES
  bool lane_values(const Real* st, double (&v)[mortar::kPairCount]) const {
    if constexpr (kSingle) {
      const mortar::PairValues p = mortar::canonical_pair_values(st);
      for (int i = 0; i < mortar::kPairCount; ++i) v[i] = p.value(i);
      return p.canonical;
    } else {
      mortar::for_each_pair_slot([&](int i, int high, int) { v[i] = double(st[high]); });
      return true;
    }
  }
#endif

  // What store() changes after an elastic increment (mortar::elastic_increment):
  // the separation, after a turn the tangential plastic and crack
  // components, and the counts. In single precision every value is tested to
  // fit in a float first, unless kChecked (the lanes tested them in double).
  // False, nothing written, when one does not fit. Float pairs must all be
  // canonical (the caller's condition).
  // The rest: docs/adapters.md, section 8.
  template <bool kChecked>
  bool store_elastic(const mortar::State& s, bool turned, const Real (&outputs)[4], Real* st) const {
    namespace slot = mortar::slot;
    if constexpr (kSingle) {
      if (pairs) return store_elastic_pairs<kChecked>(s, turned, outputs, st);
    }
    const Real v[] = {Real(s.plastic[1]), Real(s.plastic[2]),    Real(s.crack[1]),     Real(s.crack[2]),
                      Real(s.separation[0]), Real(s.separation[1]), Real(s.separation[2]), outputs[0],
                      outputs[1], outputs[2], outputs[3]};
    if constexpr (kSingle && !kChecked) {  // a finite double is itself
      if (!mortar::all_finite(v, 11)) return false;
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
    if (cap) store_kappa_c(s, st);
    if (flags) mortar::store_integration_flags(s.integration_flags, st);
    store_without_flags(s, st);
  }
  // store() into an array of kCount values (single precision's staging copy,
  // ExplicitBlock::store_float_over): the flags' and kappa_c's slots only
  // where the array holds them, which the dispatch on `flags` and `cap`
  // already ensures at run time.
  template <int kCount>
  void store_into(const mortar::State& s, Real (&a)[kCount]) const {
    if constexpr (kCount >= kCappedCount) {
      store(s, a);
    } else if constexpr (kCount > mortar::flag_slot::integration_flags) {
      if (flags) mortar::store_integration_flags(s.integration_flags, a);
      store_without_flags(s, a);
    } else {
      store_without_flags(s, a);
    }
  }

 private:
  static void store_kappa_c(const mortar::State& s, Real* st) {
    if constexpr (kSingle) {
      mortar::store_kappa_c_pair(s.kappa_c, st);
    } else {
      mortar::store_kappa_c(s.kappa_c, st);
    }
  }

  void store_without_flags(const mortar::State& s, Real* st) const {
    if constexpr (kSingle) {
      if (pairs) return mortar::store_state_pairs(s, st);
    }
    mortar::store_state(s, st);
  }

  // store_elastic() with float pairs: the separation's three pairs and, after
  // a turn, the tangential plastic pairs and crack components, checked with
  // the outputs, in one test, before any is stored. The reference
  // penetration (SDV 22, which a first call replaces only afterwards) is
  // tested too, as the full store tests every slot it leaves, so that both
  // reject the same points.
  template <bool kChecked>
  static bool store_elastic_pairs(const mortar::State& s, bool turned, const float (&outputs)[4], float* st) {
    namespace slot = mortar::slot;
    namespace low = mortar::low_slot;
    // The separation's high and low parts, the reference penetration, the
    // outputs (12 values: three vectors for the test); after a turn the
    // plastic pairs and the crack components.
    float sep[6], tan[6];
    separation_pairs(s, sep);
    if constexpr (!kChecked) {
      const float tested[12] = {sep[0], sep[1], sep[2], sep[3], sep[4], sep[5], st[slot::reference_penetration],
                                outputs[0], outputs[1], outputs[2], outputs[3], 0};
      if (!mortar::all_finite_values(tested)) return false;
    }
    if (turned) {
      mortar::split_into_pair(s.plastic[1], tan[0], tan[2]);
      mortar::split_into_pair(s.plastic[2], tan[1], tan[3]);
      tan[4] = float(s.crack[1]);
      tan[5] = float(s.crack[2]);
      if (!mortar::all_finite(tan, 6)) return false;
    }
    store_separation_pairs(sep, st);
    if (turned) {
      st[slot::plastic_s1] = tan[0];
      st[slot::plastic_s2] = tan[1];
      st[low::plastic_s1] = tan[2];
      st[low::plastic_s2] = tan[3];
      st[slot::crack_s1] = tan[4];
      st[slot::crack_s2] = tan[5];
    }
    store_counts(s, st);
    return true;
  }

  // The separation's float pairs: high parts in sep[0..2], low parts in
  // sep[3..5].
  static void separation_pairs(const mortar::State& s, float (&sep)[6]) {
    for (int i = 0; i < 3; ++i) mortar::split_into_pair(s.separation[i], sep[i], sep[3 + i]);
  }
  static void store_separation_pairs(const float (&sep)[6], float* st) {
    for (int i = 0; i < 3; ++i) {
      st[mortar::slot::separation_n + i] = sep[i];
      st[mortar::low_slot::separation_n + i] = sep[3 + i];
    }
  }

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
