// What the direct rules read off a curve's points: its first loading branch,
// its largest sample, and a regression through the origin with its standard
// error. Shared by the tension rules and the shear rules.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "calibration/test_curve.hpp"

namespace mortar::harness {

// A value and its standard error.
struct Estimate {
  double value = 0, se = NAN;
};

// Least squares slope through the origin of the points (x_i, y_i).
inline Estimate slope_through_origin(const std::vector<double>& x, const std::vector<double>& y) {
  double sxx = 0, sxy = 0;
  for (size_t i = 0; i < x.size(); ++i) sxx += x[i] * x[i], sxy += x[i] * y[i];
  Estimate k{sxy / sxx};
  if (x.size() < 2) return k;
  double ssr = 0;
  for (size_t i = 0; i < x.size(); ++i) ssr += std::pow(y[i] - k.value * x[i], 2);
  k.se = std::sqrt(ssr / double(x.size() - 1) / sxx);
  return k;
}

// The line y = a + b x through the points (x_i, y_i) by least squares.
struct Line {
  double a = 0, b = 0;
};
inline Line line_through(const std::vector<double>& x, const std::vector<double>& y) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < x.size(); ++i) n += 1, sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  const double b = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  return {(sy - b * sx) / n, b};
}

// The index of the largest of y[0, end).
inline size_t index_of_peak(const std::vector<double>& y, size_t end) {
  return static_cast<size_t>(std::max_element(y.begin(), y.begin() + long(end)) - y.begin());
}

// The first loading branch: up to the first reversal of the abscissa.
inline size_t first_branch_end(const TestCurve& c) {
  for (size_t i = 1; i < c.x.size(); ++i)
    if (c.x[i] < c.x[i - 1]) return i;
  return c.x.size();
}

// The loading envelope: the points beyond every abscissa before them. A
// monotonic curve is its own envelope; with unloading-reloading it is the
// virgin curve, which the monotonic rules read.
inline TestCurve envelope_of(const TestCurve& c) {
  TestCurve e = c;
  e.x.clear(), e.y.clear(), e.uplift.clear();
  double reached = -INFINITY;
  for (size_t i = 0; i < c.x.size(); ++i) {
    if (c.x[i] < reached) continue;
    reached = c.x[i];
    e.x.push_back(c.x[i]), e.y.push_back(c.y[i]);
    if (c.has_uplift()) e.uplift.push_back(c.uplift[i]);
  }
  return e;
}

// The points of the elastic branch: before the largest sample, below 90 % of
// it (the law is elastic up to the peak; the margin keeps out a post-peak
// point that noise lifted above the true peak's neighbours).
inline void elastic_points(const TestCurve& c, std::vector<double>& x, std::vector<double>& y) {
  const size_t end = first_branch_end(c), peak = index_of_peak(c.y, end);
  for (size_t i = 0; i < peak; ++i)
    if (c.x[i] > 0 && c.y[i] <= 0.9 * c.y[peak]) x.push_back(c.x[i]), y.push_back(c.y[i]);
}

}  // namespace mortar::harness
