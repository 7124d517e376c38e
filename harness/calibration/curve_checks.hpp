// What a test curve's values must satisfy before anything is read off them,
// beyond the format (test_curve.hpp): values within a stated plausible range
// per quantity, a traction that is not zero throughout, the law's signs, and
// a peak followed by the softening. Each breach is an InputError (exit 2)
// naming the file, the row and the rule, so that a typo or a sign mistake is
// reported as such rather than read as a property of the joint.
#pragma once

#include <string>

#include "calibration/test_curve.hpp"

namespace mortar::harness {

// Plausible magnitudes: far beyond any masonry joint test, so only mistakes
// (a unit slip, a typo, a value of 1e30) fall outside.
inline constexpr double kMaxTraction = 100;     // |tau|, |sigma|, |sigma_n| [MPa]: above the strongest brick's compressive strength
inline constexpr double kMaxDisplacement = 100; // |slip|, |opening|, |uplift| [mm]: a block's size

// x in %g with `digits` significant digits, for the messages here and in
// acceptance.cpp.
std::string number_text(double x, int digits = 6);

// Throws InputError (file, row, value, rule) for the first breach.
void check_curve_values(const TestCurve& c);

}  // namespace mortar::harness
