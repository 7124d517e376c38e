#include "calibration/synthetic.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace mortar::harness {

std::vector<SyntheticTest> standard_programme(const Parameters& p, int points) {
  std::vector<SyntheticTest> tests;
  SyntheticTest tension;
  tension.kind = TestKind::tension;
  // Pure mode I: sigma = ft0 exp(-ft0 delta_in / GIC) (docs/model.md 4), so
  // 3.5 GIC/ft0 of inelastic opening leaves 3 % of ft0.
  tension.travel = p.ft0 / p.kn + 3.5 * p.GIC / p.ft0;
  tension.points = points;
  tests.push_back(tension);
  // The cohesion is gone after about GIIC/c0 of slip beyond the peak; four
  // times that reaches the residual friction. The peak comes after at most
  // (c0 + |sigma_n| tan phi0)/ks of elastic slip (Eq. 2 at s = 1), largest at
  // -1 MPa: on a soft joint with a small GIIC that is most of the travel
  // (measured on a random set: peak at 0.09 mm of a 0.1 mm test).
  const double elastic = (p.c0 + std::tan(p.phi0 * M_PI / 180)) / p.ks;
  const double slip = std::clamp(elastic + 4 * p.GIIC / p.c0, 0.1, 3.0);
  for (double sigma_n : {-0.1, -0.5, -1.0}) {
    SyntheticTest shear;
    shear.sigma_n = sigma_n;
    shear.travel = slip;
    shear.points = points;
    tests.push_back(shear);
  }
  return tests;
}

namespace {

// The dense abscissae of a test, in test order: 600 increments over the
// travel, and 300 more over the first `fine` mm, where the elastic branch
// and the peak are.
std::vector<double> dense_path(const SyntheticTest& t, double fine) {
  std::vector<double> corners = {0, std::min(fine, t.travel / 2)};
  if (t.kind == TestKind::cyclic_shear) {
    for (double a : t.amplitudes) corners.insert(corners.end(), {a, -a});
    corners.push_back(0);
  } else {
    corners.push_back(t.travel);
  }
  double travel = 0;
  for (size_t i = 1; i < corners.size(); ++i) travel += std::abs(corners[i] - corners[i - 1]);
  std::vector<double> x = {0};
  for (size_t i = 1; i < corners.size(); ++i) {
    const double length = std::abs(corners[i] - corners[i - 1]);
    const int n = i == 1 ? 300 : std::max(1, static_cast<int>(std::ceil(600 * length / travel)));
    for (int k = 1; k <= n; ++k) x.push_back(corners[i - 1] + (corners[i] - corners[i - 1]) * k / n);
  }
  return x;
}

double largest_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// Indices of `points` samples equally spaced in arc length on scaled axes,
// the peak among them.
std::vector<size_t> digitised_indices(const std::vector<double>& x, const std::vector<double>& y, int points) {
  const double xs = std::max(largest_abs(x), 1e-300), ys = std::max(largest_abs(y), 1e-300);
  std::vector<double> arc(x.size(), 0);
  for (size_t i = 1; i < x.size(); ++i)
    arc[i] = arc[i - 1] + std::hypot((x[i] - x[i - 1]) / xs, (y[i] - y[i - 1]) / ys);
  std::vector<size_t> picked;
  for (int k = 0; k < points; ++k) {
    // The last target, arc.back() * (points - 1) / (points - 1), can round
    // above arc.back(): lower_bound then returns the end, one past the data.
    const double target = std::min(arc.back() * k / (points - 1), arc.back());
    picked.push_back(static_cast<size_t>(std::lower_bound(arc.begin(), arc.end(), target) - arc.begin()));
  }
  size_t peak = 0;
  for (size_t i = 0; i < y.size(); ++i)
    if (std::abs(y[i]) > std::abs(y[peak])) peak = i;
  picked.push_back(peak);
  std::sort(picked.begin(), picked.end());
  picked.erase(std::unique(picked.begin(), picked.end()), picked.end());
  return picked;
}

}  // namespace

TestCurve synthetic_curve(const Parameters& p, const SyntheticTest& t, double noise, std::uint32_t seed,
                          const std::string& name) {
  TestCurve dense;
  dense.name = name;
  dense.kind = t.kind;
  dense.sigma_n = t.sigma_n;
  // Three times the elastic limit: ft0/kn in tension, at most
  // (c0 + |sigma_n| tan phi0)/ks in shear (Eq. 2 at s = 1).
  const double limit = t.kind == TestKind::tension ? p.ft0 / p.kn
                                                   : (p.c0 - t.sigma_n * std::tan(p.phi0 * M_PI / 180)) / p.ks;
  dense.x = dense_path(t, 3 * limit);
  SimulationSettings fine;
  fine.increments = static_cast<int>(dense.x.size());
  fine.stol = 1e-7;
  const SimulatedCurve sim = simulate(p, dense, fine);
  TestCurve out = dense;
  out.x.clear();
  const bool uplift = t.kind != TestKind::tension && t.uplift;
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double y_noise = noise * largest_abs(sim.y), u_noise = uplift ? noise * largest_abs(sim.uplift) : 0;
  for (size_t i : digitised_indices(dense.x, sim.y, t.points)) {
    out.x.push_back(dense.x[i]);
    out.y.push_back(sim.y[i] + y_noise * gauss(rng));
    if (uplift) out.uplift.push_back(sim.uplift[i] + u_noise * gauss(rng));
  }
  return out;
}

}  // namespace mortar::harness
