#include "mortar/state_pairs.hpp"

namespace mortar {

const char* const kStateNames[kStateCount] = {
    "dp_n",  "dp_s1", "dp_s2",  "dcr_n",  "dcr_s1", "dcr_s2", "w_I",
    "w_II",  "w_III", "d_n",    "d_s",    "delta_n", "delta_s1", "delta_s2",
    "open",  "D_plastic", "D_damage", "E_unilateral", "substeps_accepted",
    "substeps_rejected", "status", "reference_penetration", "initialised"};

const char* const kLowStateNames[kPairedStateCount - kStateCount] = {
    "dp_n_lo", "dp_s1_lo", "dp_s2_lo", "w_I_lo", "w_II_lo", "w_III_lo",
    "d_n_lo",  "d_s_lo",   "delta_n_lo", "delta_s1_lo", "delta_s2_lo"};

// Each pair straight from its member: split_into_pair's high part is store_state's
// float(value), and its guard keeps the pairs' rounding from the vectorised
// miscompile (state.hpp, load_state_pairs).
void store_state_pairs(const State& s, float* a) {
  store_state(s, a);
  for_each_pair(s, [&](int high, int low, double x) { split_into_pair(x, a[high], a[low]); });
}

}  // namespace mortar
