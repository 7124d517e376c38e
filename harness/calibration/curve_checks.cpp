#include "calibration/curve_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "input/input_error.hpp"

namespace mortar::harness {

std::string number_text(double x, int digits) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

namespace {

std::string value(double x) { return number_text(x); }

void check_range(const TestCurve& c, const std::vector<double>& v, const char* what, const char* unit, double limit) {
  for (size_t i = 0; i < v.size(); ++i)
    if (!(std::abs(v[i]) <= limit))
      throw InputError(c.file + ": data row " + std::to_string(i + 1) + ": " + what + " = " + value(v[i]) + " " + unit +
                       " is outside the plausible range |" + what + "| <= " + value(limit) + " " + unit +
                       " of a masonry joint test: a typo or a unit mistake?");
}

// The index of the largest |value| (the first of equal ones).
size_t largest_magnitude(const std::vector<double>& v) {
  size_t k = 0;
  for (size_t i = 1; i < v.size(); ++i)
    if (std::abs(v[i]) > std::abs(v[k])) k = i;
  return k;
}

// Law signs: the closure >= 0 (minus the normal separation) and sigma <= 0;
// a tension value is a sign mistake or a test that opened the joint.
void check_compression_values(const TestCurve& c) {
  const size_t k = largest_magnitude(c.y);
  // Noise about zero at the start is no tension: 5 % of the peak is allowed.
  const double tension_limit = 0.05 * std::abs(c.y[k]);
  for (size_t i = 0; i < c.x.size(); ++i) {
    const std::string row = c.file + ": data row " + std::to_string(i + 1) + ": ";
    if (c.x[i] < 0)
      throw InputError(row + "closure = " + value(c.x[i]) + " mm is negative: a compression curve's closure is >= 0 "
                             "(minus the normal separation; an opening belongs to a tension curve)");
    if (c.y[i] > tension_limit)
      throw InputError(row + "sigma = " + value(c.y[i]) + " MPa is a tension: a compression curve holds sigma <= 0 "
                             "(law signs, compression negative; noise up to 5 % of the peak allowed)");
  }
  double after = c.y[k];
  for (size_t i = k + 1; i < c.y.size(); ++i) after = std::max(after, c.y[i]);
  if (!(after > 0.5 * c.y[k]))
    throw InputError(c.file + ": the compression curve never falls below half its peak (" + value(c.y[k]) +
                     " MPa at data row " + std::to_string(k + 1) + ") after it: it records no softening (Gfc, kappa_m); "
                     "give the whole curve, through the peak and below fc/2");
}

}  // namespace

void check_curve_values(const TestCurve& c) {
  const bool shear = c.shear();
  const char* x = shear ? "slip" : c.compression() ? "closure" : "opening";
  const char* y = shear ? "tau" : "sigma";
  check_range(c, c.x, x, "mm", kMaxDisplacement);
  check_range(c, c.y, y, "MPa", kMaxTraction);
  check_range(c, c.uplift, "uplift", "mm", kMaxDisplacement);
  if (shear && !(-c.sigma_n <= kMaxTraction))
    throw InputError(c.file + ": sigma_n = " + value(c.sigma_n) + " MPa is outside the plausible range |sigma_n| <= " +
                     value(kMaxTraction) + " MPa of a masonry joint test");
  const size_t k = largest_magnitude(c.y);
  if (c.y[k] == 0)
    throw InputError(c.file + ": every " + y + " is zero: the curve records no traction (an empty column, or the " +
                     "wrong column exported?)");
  if (c.kind == TestKind::cyclic_shear) return;  // both signs are part of a cyclic test
  if (c.compression()) return check_compression_values(c);
  // Law signs (docs/model.md 1): the opening and the tension positive; the
  // slip positive in the direction of shearing and tau with it.
  if (c.y[k] < 0 || c.x.back() < 0)
    throw InputError(c.file + ": " + (c.y[k] < 0 ? std::string(y) + " is negative (largest |" + y + "| = " + value(c.y[k]) +
                                                       " MPa at data row " + std::to_string(k + 1) + ")"
                                                 : std::string(x) + " ends negative (" + value(c.x.back()) + " mm)") +
                     ": the sign convention is " +
                     (shear ? "slip and tau positive in the direction of shearing (flip the sign of both columns of a "
                              "test sheared the other way)"
                            : "opening and tension positive (law signs)") +
                     "; a sign mistake?");
  // The peak must be followed by the softening: a curve whose largest
  // sample is its last (or, tension, that never falls below 90 % of its
  // largest after it) was cut before or at its peak, and gives no peak
  // strength or fracture energy. (A snap-back falls, so it passes.)
  const size_t peak = k;
  double after = c.y[peak];
  for (size_t i = peak + 1; i < c.y.size(); ++i) after = std::min(after, c.y[i]);
  if (peak + 1 == c.y.size() || (!shear && after > 0.9 * c.y[peak]))
    throw InputError(c.file + ": the " + (shear ? "shear" : "tension") + " curve ends " +
                     (peak + 1 == c.y.size() ? "at its largest value (" : "within 10 % of its largest value (") +
                     value(c.y[peak]) + " MPa at data row " + std::to_string(peak + 1) + " of " +
                     std::to_string(c.y.size()) + "): it was cut before or at its peak, so it records no " +
                     (shear ? "peak strength or softening" : "softening (GIC)") +
                     "; give the whole curve, through the peak and its softening");
}

}  // namespace mortar::harness
