// props(1..19) of a call, from mortar::to_props (the law's one props
// builder). The harness never passes props(20), the adapters' shear sign, so
// their defaults hold (abi/vuinteraction_signs.hpp, abi/uinter_call.hpp).
#pragma once

#include <vector>

#include "mortar/parameters.hpp"

namespace mortar::harness {

// The 14 parameters, the scheme, and STOL and the substep budget when given
// (0 keeps the routine's default, as an absent or zero prop does).
std::vector<double> props_for(const Parameters& p, Scheme scheme, double stol, int max_substeps = 0);

}  // namespace mortar::harness
