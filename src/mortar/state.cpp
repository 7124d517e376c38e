#include "mortar/state.hpp"

namespace mortar {

const char* const kStateNames[kStateCount] = {
    "dp_n",  "dp_s1", "dp_s2",  "dcr_n",  "dcr_s1", "dcr_s2", "w_I",
    "w_II",  "w_III", "d_n",    "d_s",    "delta_n", "delta_s1", "delta_s2",
    "open",  "D_plastic", "D_damage", "E_unilateral", "substeps_accepted",
    "substeps_rejected", "status", "reference_penetration", "initialised"};

}  // namespace mortar
