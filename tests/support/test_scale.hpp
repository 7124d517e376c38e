// The size of the randomised tests (the property tests, the law's invariant
// 10): n parameter sets, times MJ_PROPERTY_SCALE when that is set to a number
// in (0, 1]. tools/sanitize.sh runs them under the sanitizers at a tenth of
// their size, where the law runs some 20 times slower; every path is still
// checked the same way, and the sets run are the first of the full run's
// (same seeds, same draw order).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace mj_test {

inline double property_scale() {
  static const double scale = [] {
    const char* v = std::getenv("MJ_PROPERTY_SCALE");
    const double x = v ? std::atof(v) : 1.0;
    return (x > 0 && x <= 1) ? x : 1.0;
  }();
  return scale;
}
inline int scaled(int n) { return std::max(1, int(std::lround(n * property_scale()))); }

}  // namespace mj_test
