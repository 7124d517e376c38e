// What an adapter leaves in SDV 21 (status) when it does not integrate: the
// adapter's own codes, negative so that they cannot be mistaken for the law's
// Failure codes (positive; their names are mortar::failure_name, the one
// table of those). docs/abaqus.md and docs/robustness.md document both.
#pragma once

#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"

namespace mj_adapter {

enum AdapterCode : int {
  kBadDirections = -1,  // nDir not 2 or 3
  kBadStateCount = -2,  // nStates / nStateVar / NSTATV below the layout's 23 (a cap: 36, single 37)
  kBadPropCount = -3,   // nProps below 14
  kBadProperty = -4,    // a property or control breaks its rule
  kBadNodeStates = -5,  // nNodState < 1
  kBadRotation = -6,    // dRot (drot, DROT) of a point is not a rotation
  kInternalError = -9,  // an exception escaped the law (never expected)
};

// What a status in SDV 21 means, for a caller that reads it back (the harness):
// the law's name for a positive code, the adapter's for a negative one.
inline const char* status_meaning(int status) {
  if (status >= 0) return mortar::failure_name(static_cast<mortar::Failure>(status));
  switch (status) {
    case kBadDirections: return "nDir is not 2 or 3";
    case kBadStateCount: return "fewer than 23 state variables (with a compression cap: 36, single precision 37)";
    case kBadPropCount: return "fewer than 14 properties";
    case kBadProperty: return "a property breaks its rule (the routine's message on stderr names it)";
    case kBadNodeStates: return "nNodState < 1";
    case kBadRotation: return "dRot of a point is not a rotation (the routine's message on stderr names it)";
    default: return "the routine's internal error";
  }
}

}  // namespace mj_adapter
