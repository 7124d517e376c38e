// props(1..19) of a call, from mortar::to_props (the law's one props
// builder), and props(21..24) with a compression cap. The harness passes
// props(20), the adapters' shear sign, only as 0 (with a cap), so their
// defaults hold (abi/vuinteraction_signs.hpp, abi/uinter_call.hpp).
#pragma once

#include <vector>

#include "mortar/parameters.hpp"

namespace mortar::harness {

// The 14 parameters, the scheme, and STOL and the substep budget when given
// (0 keeps the routine's default, as an absent or zero prop does); with
// cap.on() props(20) = 0 and the cap in props(21..24).
std::vector<double> props_for(const Parameters& p, Scheme scheme, double stol, int max_substeps = 0,
                              const CompressionCap& cap = CompressionCap{});

// The state count (DEPVAR, NSTATV) the harness's calls of the double-precision
// routines declare: SDV 1-23 and the integration flags (SDV 35), and with a
// cap kappa_c (SDV 36).
int state_count_for(const CompressionCap& cap);

}  // namespace mortar::harness
