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

std::vector<SyntheticTest> unloading_programme(const Parameters& p, int points) {
  SyntheticTest tension;
  tension.kind = TestKind::cyclic_tension;
  tension.points = points;
  for (double fraction : {0.7, 0.4, 0.15}) {
    // On the softening branch sigma = f ft0 at delta_in = (GIC/ft0) ln(1/f)
    // (docs/model.md 4); the plastic opening is delta_in/(1 + bn).
    const double in = p.GIC / p.ft0 * std::log(1 / fraction), at = in + fraction * p.ft0 / p.kn;
    const double plastic = in / (1 + p.bn);
    tension.path.insert(tension.path.end(), {at, plastic + 0.1 * (at - plastic)});
  }
  tension.travel = p.ft0 / p.kn + 3.5 * p.GIC / p.ft0;
  tension.path.push_back(tension.travel);
  SyntheticTest shear;
  shear.kind = TestKind::cyclic_shear;
  shear.sigma_n = p.ft0 / 10;
  shear.points = points;
  shear.uplift = false;
  // The peak at s = 1 (Eqs. 2-3): tau_p^2 = (beta0 - sigma_n tan phi0)^2 - alpha0^2.
  const double t = std::tan(p.phi0 * M_PI / 180), C = p.c0 * p.c0 / p.ft0;
  const double alpha = (C / t - p.ft0 * t) / 2, beta = (C / t + p.ft0 * t) / 2;
  const double peak_slip = std::sqrt(std::pow(beta - shear.sigma_n * t, 2) - alpha * alpha) / p.ks;
  // Open, the strength s falls per mm of plastic slip by about
  // sigma_n (1 + bn) tan(psi0)/GIC + c0 (1 + bs)/GIIC (Eqs. 4-5, 7-8, 17 with
  // the dilatancy's normal flow), and the joint separates at s = sigma_n/ft0:
  // unload at s of about 0.85, 0.7 and 0.55.
  const double rate = shear.sigma_n * (1 + p.bn) * std::tan(p.psi0 * M_PI / 180) / p.GIC + p.c0 * (1 + p.bs) / p.GIIC;
  for (double s : {0.85, 0.7, 0.55}) {
    const double at = peak_slip + (1 + p.bs) * (1 - s) / rate;
    shear.path.insert(shear.path.end(), {at, 0.4 * at});
  }
  shear.path.push_back(shear.path[shear.path.size() - 2]);
  shear.travel = shear.path.back();
  return {tension, shear};
}

namespace {

// The dense abscissae of a test, in test order: 600 increments over the
// travel, and 300 more over the first `fine` mm, where the elastic branch
// and the peak are.
std::vector<double> dense_path(const SyntheticTest& t, double fine) {
  std::vector<double> corners = {0, std::min(fine, (t.path.empty() ? t.travel : t.path.front()) / 2)};
  if (!t.path.empty()) {
    corners.insert(corners.end(), t.path.begin(), t.path.end());
  } else if (t.kind == TestKind::cyclic_shear) {
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
// the peak among them, and with `corners` every reversal of the abscissa
// (where an unloading branch starts, as a digitiser clicks it).
std::vector<size_t> digitised_indices(const std::vector<double>& x, const std::vector<double>& y, int points,
                                      bool corners) {
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
  for (size_t i = 1; corners && i + 1 < x.size(); ++i)
    if ((x[i] - x[i - 1]) * (x[i + 1] - x[i]) < 0) picked.push_back(i);
  std::sort(picked.begin(), picked.end());
  picked.erase(std::unique(picked.begin(), picked.end()), picked.end());
  return picked;
}

}  // namespace

TestCurve synthetic_curve(const Parameters& p, const SyntheticTest& t, double noise, std::uint32_t seed,
                          const std::string& name, const CompressionCap& cap) {
  TestCurve dense;
  dense.name = name;
  dense.kind = t.kind;
  dense.sigma_n = t.sigma_n;
  // Three times the elastic limit: ft0/kn in tension, at most
  // (c0 + |sigma_n| tan phi0)/ks in shear (Eq. 2 at s = 1).
  // Compression: the elastic closure at fc.
  const double limit = dense.compression() ? cap.fc / p.kn
                       : !dense.shear()    ? p.ft0 / p.kn
                                           : (p.c0 - t.sigma_n * std::tan(p.phi0 * M_PI / 180)) / p.ks;
  dense.x = dense_path(t, 3 * limit);
  SimulationSettings fine;
  fine.increments = static_cast<int>(dense.x.size());
  fine.stol = 1e-7;
  const SimulatedCurve sim = simulate(p, dense, fine, cap);
  TestCurve out = dense;
  out.x.clear();
  const bool uplift = dense.shear() && t.uplift;
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double y_noise = noise * largest_abs(sim.y), u_noise = uplift ? noise * largest_abs(sim.uplift) : 0;
  for (size_t i : digitised_indices(dense.x, sim.y, t.points, !t.path.empty())) {
    out.x.push_back(dense.x[i]);
    out.y.push_back(sim.y[i] + y_noise * gauss(rng));
    if (uplift) out.uplift.push_back(sim.uplift[i] + u_noise * gauss(rng));
  }
  return out;
}

std::vector<TestCurve> without_shear_peaks(std::vector<TestCurve> curves) {
  for (TestCurve& c : curves) {
    if (!c.shear()) continue;
    const auto at = std::max_element(c.y.begin(), c.y.end()) - c.y.begin();
    c.x.erase(c.x.begin() + at), c.y.erase(c.y.begin() + at);
    if (c.has_uplift()) c.uplift.erase(c.uplift.begin() + at);
  }
  return curves;
}

}  // namespace mortar::harness
