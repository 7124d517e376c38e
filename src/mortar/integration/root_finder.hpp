// The one-dimensional root finders of the integration: Pegasus (Dowell &
// Jarratt 1972) for the elastic-plastic intersection (docs/model.md 7.1) and
// the end of a return at fixed separation (6, closure jump), and the
// safeguarded regula falsi on the substep size that ends a substep on the
// regime boundary (6, regime switches inside an increment).
#pragma once

#include <cmath>

namespace mortar {

// A value of the function whose root is sought, and the tolerance within
// which |value| counts as zero at that point.
struct RootSample {
  double value = 0;
  double tolerance = 0;
};

// Pegasus on [x0, x1] with f(x0) = f0, f(x1) = f1 of opposite signs.
// `sample(x)` returns the RootSample at x. Returns the first x with
// |f(x)| <= tolerance(x), or after max_iterations the last x tried.
template <class Sample>
double pegasus(Sample&& sample, double x0, double f0, double x1, double f1, int max_iterations) {
  for (int it = 0; it < max_iterations; ++it) {
    const double x = x1 - f1 * (x1 - x0) / (f1 - f0);
    const RootSample fx = sample(x);
    if (std::abs(fx.value) <= fx.tolerance) return x;
    if (fx.value * f1 < 0) {
      x0 = x1;
      f0 = f1;
    } else {
      f0 *= f1 / (f1 + fx.value);  // Pegasus: scale the retained end
    }
    x1 = x;
    f1 = fx.value;
  }
  return x1;
}

// Bracket on the substep size around a boundary the substep must end on
// (the regime boundary delta_e_n = 0, or complete separation): e_lo, e_hi are
// the boundary function at the ends of substeps of size lo and hi
// (docs/model.md 6). The next size is the regula falsi point, bisection
// every third try or when the secant leaves the bracket.
struct CrossingBracket {
  bool active = false;
  double lo = 0, e_lo = 0, hi = 0, e_hi = 0;
  // A trial substep of size dT ended at e (across the boundary or not); the
  // first one opens the bracket from the substep's start, where it is e0.
  void record(double dT, double e, bool across, double e0) {
    if (!active) {
      *this = CrossingBracket{true, 0.0, e0, dT, e};
    } else if (across) {
      hi = dT;
      e_hi = e;
    } else {
      lo = dT;
      e_lo = e;
    }
  }
  double next(int iteration) const {
    double x = lo + (hi - lo) * e_lo / (e_lo - e_hi);
    if (!(x > lo && x < hi) || iteration % 3 == 2) x = 0.5 * (lo + hi);
    return x;
  }
};

}  // namespace mortar
