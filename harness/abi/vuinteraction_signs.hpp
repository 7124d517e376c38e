// The one place where the harness converts between the law's signs and the
// arguments of VUINTERACTION, as the adapter (vuinteraction/vuinteraction.cpp,
// docs/abaqus.md) defines them:
//
//  - Normal: the routine measures the opening from the penetration it saw
//    on its first call, delta_n = reference - penetration. The harness makes
//    that first call at zero penetration, so penetration = -delta_n.
//  - stress(1) is the contact pressure: stress(1) = -sigma_n.
//  - Shear: the routine's slips are the running sum of drDisp(2..nDir), in
//    the law's direction; it returns stress(2..nDir) = shear_sign * tau with
//    shear_sign = props(20), default -1. The harness never passes props(20),
//    so tau = -stress(2..nDir).
#pragma once

#include "adapter/arguments.hpp"

namespace mortar::harness::abi_signs {

inline double penetration_for_opening(double opening) { return -opening; }
inline double normal_traction_from_stress(double stress1) { return -stress1; }

// drDisp(1), the increment of the normal relative displacement, is not read
// by the adapter (it takes the normal separation from `penetration`); the
// harness passes it consistently as the increment of penetration.
inline double normal_dr_disp(double d_opening) { return -d_opening; }

// An opening this large is a penetration the adapters take for "no opposite
// surface" (Abaqus passes about -1e36 there): zero traction, the state left
// as it is, no law (docs/abaqus.md, Unpaired slave nodes).
inline bool unpaired(double opening) { return penetration_for_opening(opening) <= mj_adapter::kUnpairedPenetration; }

inline constexpr double kSlipSign = 1.0;    // drDisp(1+i) = kSlipSign * d(delta_s_i)
inline constexpr double kShearSign = -1.0;  // tau_i = kShearSign * stress(1+i), the adapter's default props(20)

}  // namespace mortar::harness::abi_signs
