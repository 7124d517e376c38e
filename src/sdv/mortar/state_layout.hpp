// The named layout of a point's state over the solver-owned flat array
// (docs/model.md 3; positions 1-14 are a user-facing contract; 24-34 hold
// single precision's float pairs, state_pairs.hpp).
#pragma once

#include "mortar/result.hpp"
#include "mortar/state.hpp"

namespace mortar {

// Positions in the flat state array, 0-based (docs and Abaqus SDV numbers are
// these + 1). 1-14 as docs/model.md 3; 15 onwards implementation-defined.
namespace slot {
enum : int {
  plastic_n = 0, plastic_s1, plastic_s2,  // 1-3   delta_p            [mm]
  crack_n, crack_s1, crack_s2,            // 4-6   delta_cr           [mm]
  work_I,                                 // 7     w_I                [N/mm]
  work_II,                                // 8     w_II               [N/mm]
  work_III,                               // 9     w_III              [N/mm]
  damage_n,                               // 10    d_n                [-]
  damage_s,                               // 11    d_s                [-]
  separation_n, separation_s1, separation_s2,  // 12-14 delta         [mm]
  open,                                   // 15    1 open (h = 1), 0 closed
  dissipation_plastic,                    // 16    sum sigma . d(delta_p)           [N/mm]
  dissipation_damage,                     // 17    sum 1/2 h k (delta_e)^2 dd       [N/mm]
  energy_unilateral,                      // 18    elastic energy released at regime switches, >= 0 [N/mm]
  substeps_accepted,                      // 19    last increment
  substeps_rejected,                      // 20    last increment
  status,                                 // 21    last increment: 0 ok, else Failure code
  reference_penetration,                  // 22    Abaqus adapter: penetration at first call [mm]
  initialised,                            // 23    Abaqus adapter: 1 once the reference is set
  count                                   // = 23 state variables
};
}  // namespace slot
inline constexpr int kStateCount = slot::count;
// The law itself uses slots 1-21; the adapters add 22-23.
inline constexpr int kLawStateCount = slot::reference_penetration;

// Single precision: the low parts of the float pairs (docs/model.md 3). The
// state variables that accumulate and feed back into the traction keep their
// rounded value in their own slot (the high part, what users read) and the
// rest, value - high rounded to float, here (SDV 24-34), one slot each, in
// the order of kPairedSlots.
namespace low_slot {
enum : int {
  plastic_n = slot::count, plastic_s1, plastic_s2,  // 24-26
  work_I, work_II, work_III,                        // 27-29
  damage_n, damage_s,                               // 30-31
  separation_n, separation_s1, separation_s2,       // 32-34
  end                                               // = 34 state variables
};
}  // namespace low_slot
// The DEPVAR the single-precision routines need for float pairs; the double
// ones need kStateCount.
inline constexpr int kPairedStateCount = low_slot::end;

// SDV 35, both precisions, written only with DEPVAR >= 35 (docs/model.md 3):
// the point's integration flags (mortar::integration_flag, result.hpp), OR'd
// over its history. An elastic increment sets none, so the elastic paths
// leave the slot as it is.
namespace flag_slot {
enum : int {
  integration_flags = low_slot::end,  // 35
  end                                 // = 35 state variables
};
}  // namespace flag_slot
// The DEPVAR (NSTATV) from which the routines keep the integration flags.
inline constexpr int kFlaggedStateCount = flag_slot::end;

// SDV 36 (and 37, its float pair's low part, in single precision): the
// compression cap's kappa_c (docs/model.md 12), kept only by a deck with a
// cap, which needs DEPVAR >= 36 (double) or 37 (single). A deck without a cap
// keeps today's layout and DEPVAR.
namespace cap_slot {
enum : int {
  kappa_c = flag_slot::end,  // 36
  kappa_c_low,               // 37, single precision
  end                        // = 37 state variables
};
}  // namespace cap_slot
inline constexpr int kCappedStateCountDouble = cap_slot::kappa_c + 1;
inline constexpr int kCappedStateCountSingle = cap_slot::end;

// Each paired variable's high slot and its low slot.
struct SlotPair {
  int high, low;
};
inline constexpr SlotPair kPairedSlots[] = {
    {slot::plastic_n, low_slot::plastic_n},         {slot::plastic_s1, low_slot::plastic_s1},
    {slot::plastic_s2, low_slot::plastic_s2},       {slot::work_I, low_slot::work_I},
    {slot::work_II, low_slot::work_II},             {slot::work_III, low_slot::work_III},
    {slot::damage_n, low_slot::damage_n},           {slot::damage_s, low_slot::damage_s},
    {slot::separation_n, low_slot::separation_n},   {slot::separation_s1, low_slot::separation_s1},
    {slot::separation_s2, low_slot::separation_s2},
};
static_assert(sizeof kPairedSlots / sizeof kPairedSlots[0] == kPairedStateCount - kStateCount,
              "one low slot per paired variable");

// A count or status slot (SDV 19-21) as an int. These slots are outputs of
// the last increment, so garbage in them (a corrupted restart) must not
// matter; converting a NaN or a value beyond int's range would be undefined
// behaviour, so such values read as 0.
template <class Real>
int int_slot(Real x) {
  const double v = double(x);
  const bool in_range = (v >= -2147483648.0) & (v <= 2147483647.0);
  return int(in_range ? v : 0.0);
}

// Named mapping between State and the flat array of one point (any precision).
template <class Real>
inline void load_state(const Real* a, State& s) {
  auto v3 = [&](int i) { return Vec3(double(a[i]), double(a[i + 1]), double(a[i + 2])); };
  s.plastic = v3(slot::plastic_n);
  s.crack = v3(slot::crack_n);
  s.wI = double(a[slot::work_I]);
  s.wII = double(a[slot::work_II]);
  s.wIII = double(a[slot::work_III]);
  s.dn = double(a[slot::damage_n]);
  s.ds = double(a[slot::damage_s]);
  s.separation = v3(slot::separation_n);
  s.open = double(a[slot::open]) != 0.0;
  s.dissipation_plastic = double(a[slot::dissipation_plastic]);
  s.dissipation_damage = double(a[slot::dissipation_damage]);
  s.energy_unilateral = double(a[slot::energy_unilateral]);
  s.substeps_accepted = int_slot(a[slot::substeps_accepted]);
  s.substeps_rejected = int_slot(a[slot::substeps_rejected]);
  s.status = int_slot(a[slot::status]);
}

template <class Real>
inline void store_state(const State& s, Real* a) {
  auto put3 = [&](int i, const Vec3& v) {
    for (int k = 0; k < 3; ++k) a[i + k] = Real(v[k]);
  };
  put3(slot::plastic_n, s.plastic);
  put3(slot::crack_n, s.crack);
  a[slot::work_I] = Real(s.wI);
  a[slot::work_II] = Real(s.wII);
  a[slot::work_III] = Real(s.wIII);
  a[slot::damage_n] = Real(s.dn);
  a[slot::damage_s] = Real(s.ds);
  put3(slot::separation_n, s.separation);
  a[slot::open] = Real(s.open ? 1 : 0);
  a[slot::dissipation_plastic] = Real(s.dissipation_plastic);
  a[slot::dissipation_damage] = Real(s.dissipation_damage);
  a[slot::energy_unilateral] = Real(s.energy_unilateral);
  a[slot::substeps_accepted] = Real(s.substeps_accepted);
  a[slot::substeps_rejected] = Real(s.substeps_rejected);
  a[slot::status] = Real(s.status);
}

// SDV 35 as the flags it holds (what no flags can be, a negative value or
// int_slot's garbage, reads as none); and back.
template <class Real>
int load_integration_flags(const Real* a) {
  const int v = int_slot(a[flag_slot::integration_flags]);
  return v > 0 ? v : 0;
}
template <class Real>
void store_integration_flags(int flags, Real* a) {
  a[flag_slot::integration_flags] = Real(flags);
}

// The adapters' own slots obey their rules (docs/model.md 3): the open flag
// (SDV 15) and the initialised flag (SDV 23) are 0 or 1; SDV 35, where kept
// (`flags`), a whole number of integration flags from 0 to 15. The law reads
// them as a bool and an int, so a corrupted 0.5 or NaN would silently become
// something else. For one value (T = double) or the points in vector lanes
// (T = lanes::D, a mask); x + 2^52 - 2^52 is x for a whole x below 2^52 and
// a whole number for any other, in every rounding mode.
template <class T>
auto flag_valid(T x) {
  return (x == 0.0) | (x == 1.0);
}
template <class T>
auto integration_flags_valid(T x) {
  constexpr double most = (1 << integration_flag::kCount) - 1, whole = 4503599627370496.0;  // 2^52
  return (x >= 0.0) & (x <= most) & ((x + whole) - whole == x);
}
template <class Real>
bool adapter_slots_valid(const Real* a, bool flags) {
  return flag_valid(double(a[slot::open])) & flag_valid(double(a[slot::initialised])) &
         (!flags || integration_flags_valid(double(a[flag_slot::integration_flags])));
}

// SDV 36 in double precision (single precision keeps a float pair in SDV
// 36-37, state_pairs.hpp): the cap's kappa_c, read and written only by a
// deck with a cap. Its rule: finite and >= 0 (a plastic closure); anything
// else is not a value the routine wrote (a corrupted restart or initial
// condition) and the point is rejected as an invalid state, as SDV 35 is.
inline bool kappa_c_valid(double x) { return (x >= 0.0) & (x <= 1.7976931348623157e308); }
inline double load_kappa_c(const double* a) { return a[cap_slot::kappa_c]; }
inline void store_kappa_c(double kappa_c, double* a) { a[cap_slot::kappa_c] = kappa_c; }

// Short names of the state variables in slot order (for CSV headers, docs).
extern const char* const kStateNames[kStateCount];
// The same for the low parts, SDV 24-34 ("dp_n_lo", ...).
extern const char* const kLowStateNames[kPairedStateCount - kStateCount];

}  // namespace mortar
