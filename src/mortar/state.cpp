#include "mortar/state.hpp"

namespace mortar {

const char* const kStateNames[kStateCount] = {
    "dp_n",  "dp_s1", "dp_s2",  "dcr_n",  "dcr_s1", "dcr_s2", "w_I",
    "w_II",  "w_III", "d_n",    "d_s",    "delta_n", "delta_s1", "delta_s2",
    "open",  "D_plastic", "D_damage", "E_unilateral", "substeps_accepted",
    "substeps_rejected", "status", "reference_penetration", "initialised"};

const char* const kLowStateNames[kPairedStateCount - kStateCount] = {
    "dp_n_lo", "dp_s1_lo", "dp_s2_lo", "w_I_lo", "w_II_lo", "w_III_lo",
    "d_n_lo",  "d_s_lo",   "delta_n_lo", "delta_s1_lo", "delta_s2_lo"};

namespace {

// The member behind a paired slot.
double paired_value(const State& s, int high) {
  switch (high) {
    case slot::plastic_n: return s.plastic[0];
    case slot::plastic_s1: return s.plastic[1];
    case slot::plastic_s2: return s.plastic[2];
    case slot::work_I: return s.wI;
    case slot::work_II: return s.wII;
    case slot::work_III: return s.wIII;
    case slot::damage_n: return s.dn;
    case slot::damage_s: return s.ds;
    case slot::separation_n: return s.separation[0];
    case slot::separation_s1: return s.separation[1];
    default: return s.separation[2];
  }
}

}  // namespace

void store_state_pairs(const State& s, float* a) {
  store_state(s, a);
  for (const SlotPair& p : kPairedSlots) a[p.low] = pair_low(paired_value(s, p.high), a[p.high]);
}

}  // namespace mortar
