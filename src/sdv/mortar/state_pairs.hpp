// Single precision's float pairs (docs/model.md 3): a double state variable
// as a float rounded from it (its own slot, what users read) and the
// remainder rounded to float (its low slot, SDV 24-34). How a value becomes
// a pair, which pairs this layout can have written (consistent, canonical),
// and the loads and the store of a state with pairs.
#pragma once

#include <cstdint>
#include <cstring>

#include "mortar/state_layout.hpp"

namespace mortar {

// A double as a float pair: high = the value rounded to float, low = the
// remainder rounded to float; high + low (in double) carries about 48 bits,
// enough for increments of 1e-8 mm on separations of about 1 mm
// (docs/model.md 3). The remainder value - high is exact in double.
inline float pair_low(double value, float high) { return float(value - double(high)); }
inline double pair_value(float high, float low) { return double(high) + double(low); }

// A low part belongs to its high part: at most one float spacing of it
// (pair_low gives at most half). Anything else is not a pair this layout
// wrote (a corrupted restart, slots some other code filled). Inline: it runs
// for 11 slots on every point-update of the single-precision routine.
inline bool pair_consistent(float high, float low) {
  // On the bit patterns of the magnitudes, so that a loop over the pairs
  // vectorises: finite below the pattern of infinity, and the next float up
  // from |high| has the next pattern, for every finite |high| (FLT_MAX's
  // successor is +inf, 0's the least denormal).
  std::uint32_t h_bits, l_bits;
  std::memcpy(&h_bits, &high, sizeof h_bits);
  std::memcpy(&l_bits, &low, sizeof l_bits);
  h_bits &= 0x7fffffffu;
  l_bits &= 0x7fffffffu;
  const std::uint32_t next_bits = h_bits + 1;
  float h, l, next;
  std::memcpy(&h, &h_bits, sizeof h);
  std::memcpy(&l, &l_bits, sizeof l);
  std::memcpy(&next, &next_bits, sizeof next);
  constexpr std::uint32_t kInfinity = 0x7f800000u;
  return (h_bits < kInfinity) & (l_bits < kInfinity) & (l <= next - h);
}

// A pair is canonical when storing its own value again writes it unchanged:
// The rest: docs/numerics.md, section 18.
inline bool pair_canonical(float high, float low, double value) {
  const float h = float(value), l = float(value - double(high));
  std::uint32_t hb, lb, high_b, low_b;
  std::memcpy(&hb, &h, sizeof hb);
  std::memcpy(&lb, &l, sizeof lb);
  std::memcpy(&high_b, &high, sizeof high_b);
  std::memcpy(&low_b, &low, sizeof low_b);
  return ((hb ^ high_b) | (lb ^ low_b)) == 0;
}

// store_state_pairs' rounding of one value, for the paths that store a few
// pairs inline. The empty asm hides that high is float(value): GCC at
// -O2/-O3 otherwise miscompiles float(value - double(float(value))) when it
// vectorises two such lanes (below, load_state_pairs), taking the extension
// of the truncation for value itself and writing a low part 0.
inline void split_into_pair(double value, float& high, float& low) {
  float h = float(value);
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
  asm("" : "+x"(h));
#elif defined(__GNUC__) && defined(__aarch64__)
  asm("" : "+w"(h));
#elif defined(__GNUC__)
  asm("" : "+m"(h));
#endif
  high = h;
  low = pair_low(value, h);
}

// kPairedSlots as runs of consecutive high and low slots, for loops over the
// pairs that vectorise.
struct PairRun {
  int high, low, count;
};
inline constexpr PairRun kPairRuns[] = {{slot::plastic_n, low_slot::plastic_n, 3}, {slot::work_I, low_slot::work_I, 8}};
constexpr bool runs_are_pairs() {
  int n = 0;
  for (const PairRun& r : kPairRuns)
    for (int i = 0; i < r.count; ++i, ++n)
      if (kPairedSlots[n].high != r.high + i || kPairedSlots[n].low != r.low + i) return false;
  return n == kPairedStateCount - kStateCount;
}
static_assert(runs_are_pairs(), "kPairRuns lists kPairedSlots");

// Calls f(high slot, low slot, member) for each paired variable of s (State
// or const State), in the order of kPairedSlots.
template <class S, class F>
inline void for_each_pair(S& s, F f) {
  for (int i = 0; i < 3; ++i) f(slot::plastic_n + i, low_slot::plastic_n + i, s.plastic[i]);
  f(slot::work_I, low_slot::work_I, s.wI);
  f(slot::work_II, low_slot::work_II, s.wII);
  f(slot::work_III, low_slot::work_III, s.wIII);
  f(slot::damage_n, low_slot::damage_n, s.dn);
  f(slot::damage_s, low_slot::damage_s, s.ds);
  for (int i = 0; i < 3; ++i) f(slot::separation_n + i, low_slot::separation_n + i, s.separation[i]);
}

// Calls f(i, high slot, low slot) for the pairs i = 0 .. 10 in the order of
// kPairedSlots, one loop per run, so that the compiler can vectorise f.
template <class F>
inline void for_each_pair_slot(F f) {
  static_assert(sizeof kPairRuns / sizeof kPairRuns[0] == 2, "one loop per run");
  constexpr PairRun a = kPairRuns[0], b = kPairRuns[1];
  for (int i = 0; i < a.count; ++i) f(i, a.high + i, a.low + i);
  for (int i = 0; i < b.count; ++i) f(a.count + i, b.high + i, b.low + i);
}

inline constexpr int kPairCount = kPairedStateCount - kStateCount;

// The paired variables' values, in the order of kPairedSlots, from the array.
inline void pair_values(const float* a, double (&v)[kPairCount]) {
  for_each_pair_slot([&](int i, int high, int low) { v[i] = pair_value(a[high], a[low]); });
}

// The paired members of s from the array's pairs (as load_state_pairs sets
// them), and whether every pair is canonical (pair_canonical), as one test
// without a branch per pair. With GCC or Clang in vectors of four pairs, the
// runs read whole: the first run's fourth lane (SDV 4 and its neighbour SDV
// 27, within the pairs' 34 slots) is read and left out.
#if defined(__GNUC__)
namespace pair_vectors {
typedef float F4 __attribute__((vector_size(16)));
typedef double D4 __attribute__((vector_size(32)));
typedef std::int32_t I4 __attribute__((vector_size(16)));
// Four pairs from high slot h and low slot l on: their values, and the lanes
// (all bits set) that are not canonical.
inline I4 values(const float* a, int h, int l, D4& v) {
  F4 high, low;
  std::memcpy(&high, a + h, sizeof high);
  std::memcpy(&low, a + l, sizeof low);
  const D4 high_d = __builtin_convertvector(high, D4);
  v = high_d + __builtin_convertvector(low, D4);
  const F4 h2 = __builtin_convertvector(v, F4), l2 = __builtin_convertvector(v - high_d, F4);
  I4 hb, lb, h2b, l2b;
  std::memcpy(&hb, &high, sizeof hb);
  std::memcpy(&lb, &low, sizeof lb);
  std::memcpy(&h2b, &h2, sizeof h2b);
  std::memcpy(&l2b, &l2, sizeof l2b);
  return (hb ^ h2b) | (lb ^ l2b);
}
// Four pairs from high slot h and low slot l on: the lanes (all bits set)
// that are not pair_consistent, by the same test on the lanes' magnitudes.
typedef std::uint32_t U4 __attribute__((vector_size(16)));
inline I4 inconsistent(const float* a, int h, int l) {
  U4 hb, lb;
  std::memcpy(&hb, a + h, sizeof hb);
  std::memcpy(&lb, a + l, sizeof lb);
  hb &= 0x7fffffffu;
  lb &= 0x7fffffffu;
  const U4 next_b = hb + 1u;
  F4 high, low, next;
  std::memcpy(&high, &hb, sizeof high);
  std::memcpy(&low, &lb, sizeof low);
  std::memcpy(&next, &next_b, sizeof next);
  constexpr std::uint32_t kInfinity = 0x7f800000u;
  return ~((hb < kInfinity) & (lb < kInfinity) & (low <= next - high));
}
}  // namespace pair_vectors
// The pairs' values in the order of kPairedSlots (value(i), i = 0 .. 10,
// constant indices once unrolled), and whether every pair is canonical.
struct PairValues {
  pair_vectors::D4 v0, v1, v2;
  bool canonical;
  double value(int i) const { return i < 3 ? v0[i] : i < 7 ? v1[i - 3] : v2[i - 7]; }
};
inline PairValues canonical_pair_values(const float* a) {
  static_assert(kPairRuns[0].count == 3 && kPairRuns[1].count == 8 && kPairRuns[0].low + 3 == kPairRuns[1].low,
                "the runs as the vectors read them");
  namespace pv = pair_vectors;
  PairValues p;
  pv::I4 bad = pv::values(a, kPairRuns[0].high, kPairRuns[0].low, p.v0) & pv::I4{-1, -1, -1, 0};
  bad |= pv::values(a, kPairRuns[1].high, kPairRuns[1].low, p.v1);
  bad |= pv::values(a, kPairRuns[1].high + 4, kPairRuns[1].low + 4, p.v2);
  p.canonical = (bad[0] | bad[1] | bad[2] | bad[3]) == 0;
  return p;
}
inline bool canonical_pairs_into(const float* a, State& s) {
  const PairValues p = canonical_pair_values(a);
  // Straight from the lanes into the members: through an array in memory,
  // the members' later wider loads would wait on narrower stores (no store
  // forwarding).
  int i = 0;
  for_each_pair(s, [&](int, int, double& x) { x = p.value(i++); });
  return p.canonical;
}
// Whether every pair of the array is pair_consistent, as one test: the
// single-precision routines' full path runs it on every point-update.
inline bool pairs_consistent(const float* a) {
  namespace pv = pair_vectors;
  pv::I4 bad = pv::inconsistent(a, kPairRuns[0].high, kPairRuns[0].low) & pv::I4{-1, -1, -1, 0};
  bad |= pv::inconsistent(a, kPairRuns[1].high, kPairRuns[1].low);
  bad |= pv::inconsistent(a, kPairRuns[1].high + 4, kPairRuns[1].low + 4);
  return (bad[0] | bad[1] | bad[2] | bad[3]) == 0;
}
#else
inline bool pairs_consistent(const float* a) {
  int all = 1;
  for_each_pair_slot([&](int, int high, int low) { all &= pair_consistent(a[high], a[low]); });
  return all;
}
inline bool canonical_pairs_into(const float* a, State& s) {
  int all = 1;
  for_each_pair(s, [&](int high, int low, double& x) {
    x = pair_value(a[high], a[low]);
    all &= pair_canonical(a[high], a[low], x);
  });
  return all;
}
#endif

// load_state / store_state with the paired variables as float pairs: the
// array holds at least kPairedStateCount values. The load is the plain form
// (the adapters load through canonical_pairs_into, tested against it). The
// store stays out of line, as scalar code: GCC at -O2 and -O3 miscompiles
// float(x - double(float(x))) when it vectorises two such lanes within a block
// (the extension of the truncation becomes x, the low part 0; observed on
// x86-64, reproduced in ten lines), which is what pair_low computes.
inline void load_state_pairs(const float* a, State& s) {
  load_state(a, s);
  double v[kPairCount];
  pair_values(a, v);
  int i = 0;
  for_each_pair(s, [&](int, int, double& x) { x = v[i++]; });
}
void store_state_pairs(const State& s, float* a);

// The cap's kappa_c as a float pair (high part SDV 36, low part SDV 37),
// kept only by a deck with a cap: its value and whether the pair is
// canonical; the pair's rule (consistent, its value >= 0: kappa_c_valid);
// and the store, split as every other pair.
inline double load_kappa_c_pair(const float* a, bool& canonical) {
  const float high = a[cap_slot::kappa_c], low = a[cap_slot::kappa_c_low];
  const double value = pair_value(high, low);
  canonical = pair_canonical(high, low, value);
  return value;
}
inline bool kappa_c_pair_valid(const float* a) {
  const float high = a[cap_slot::kappa_c], low = a[cap_slot::kappa_c_low];
  return pair_consistent(high, low) && kappa_c_valid(pair_value(high, low));
}
inline void store_kappa_c_pair(double kappa_c, float* a) {
  split_into_pair(kappa_c, a[cap_slot::kappa_c], a[cap_slot::kappa_c_low]);
}

}  // namespace mortar
