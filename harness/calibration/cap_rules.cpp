#include "calibration/cap_rules.hpp"

#include <algorithm>
#include <cmath>

#include "calibration/curve_checks.hpp"
#include "input/input_error.hpp"

namespace mortar::harness {

namespace {

// The plastic closure where |sigma| first crosses `level` (rising before the
// peak, falling after it), interpolated linearly between data points.
double crossing(const std::vector<double>& kappa, const std::vector<double>& s, size_t peak, double level, bool rising) {
  if (rising) {
    for (size_t i = 1; i <= peak; ++i)
      if (s[i] >= level && s[i - 1] < level)
        return kappa[i - 1] + (kappa[i] - kappa[i - 1]) * (level - s[i - 1]) / (s[i] - s[i - 1]);
    return kappa[peak];
  }
  for (size_t i = peak + 1; i < s.size(); ++i)
    if (s[i] <= level && s[i - 1] > level)
      return kappa[i - 1] + (kappa[i] - kappa[i - 1]) * (s[i - 1] - level) / (s[i - 1] - s[i]);
  return kappa.back();
}

// sigma_c(kappa)/fc of docs/model.md 12 (independent of fc).
double shape(double k, double kp, double span) {
  const double si = 1.0 / 3, sm = 0.5, sr = 1.0 / 7;
  if (k < kp) {
    const double x = k / kp;
    return si + (1 - si) * x * (2 - x);
  }
  if (k < kp + span) {
    const double h = (k - kp) / span;
    return 1 + (sm - 1) * h * h;
  }
  return sr + (sm - sr) * std::exp(2 * (sm - 1) / span * (k - kp - span) / (sm - sr));
}

struct OneCurve {
  double fc, kappa_p, span;
};

OneCurve one_curve(const TestCurve& c, double kn) {
  std::vector<double> s, kappa;
  for (size_t i = 0; i < c.x.size(); ++i) s.push_back(-c.y[i]);
  const size_t peak = static_cast<size_t>(std::max_element(s.begin(), s.end()) - s.begin());
  OneCurve r{s[peak], 0, 0};
  for (int pass = 0; pass < 3; ++pass) {
    kappa.clear();
    for (size_t i = 0; i < s.size(); ++i) kappa.push_back(std::max(0.0, c.x[i] - s[i] / kn));
    const double si = r.fc / 3;
    r.kappa_p = 2 * crossing(kappa, s, peak, si + 0.75 * (r.fc - si), true);
    r.span = std::max(crossing(kappa, s, peak, 0.5 * r.fc, false) - r.kappa_p, 1e-9);
    // fc by least squares of |sigma| = fc shape(kappa) over the two
    // parabolas' points (kappa_p/4 to kappa_m): off the elastic branch, where
    // noise in kappa is a large part of it, and off the tail, which hangs on
    // the span.
    double num = 0, den = 0;
    for (size_t i = 0; i < s.size(); ++i)
      if (kappa[i] >= 0.25 * r.kappa_p && kappa[i] <= r.kappa_p + r.span) {
        const double f = shape(kappa[i], std::max(r.kappa_p, 1e-12), r.span);
        num += f * s[i], den += f * f;
      }
    if (den > 0) r.fc = num / den;
  }
  return r;
}

}  // namespace

CapEstimate estimate_cap(const std::vector<TestCurve>& curves, const Parameters& p) {
  CapEstimate e;
  double fc = 0, kp = 0, span = 0;
  int n = 0;
  for (const TestCurve& c : curves) {
    if (!c.compression()) continue;
    const OneCurve r = one_curve(c, p.kn);
    fc += r.fc, kp += r.kappa_p, span += r.span, ++n;
  }
  if (!n) throw InputError("calibrate: no compression curve: the cap's fc, Gfc and kappa_p need one");
  fc /= n, kp /= n, span /= n;
  e.cap.fc = fc;
  e.cap.kappa_p = kp;
  e.cap.Gfc = 481 * fc * span / 588;
  e.cap.Cs = kDefaultCs;
  e.notes.push_back("fc, kappa_p, Gfc: direct rules on " + std::to_string(n) + " compression curve(s)");
  // Cs from the shear curves whose peak lies on the cap: under compression
  // below fc and more than 5 % under the hyperbola of Eqs. 2-3; there the
  // peak is radius fc, tau_p^2 = (fc^2 - sigma_n^2)/Cs.
  const double t = std::tan(p.phi0 * M_PI / 180), C = p.c0 * p.c0 / p.ft0;
  const double alpha = (C / t - p.ft0 * t) / 2, beta = (C / t + p.ft0 * t) / 2;
  double Cs = 0;
  int m = 0;
  for (const TestCurve& c : curves) {
    if (c.kind != TestKind::shear || !(c.sigma_n < 0) || -c.sigma_n >= fc) continue;
    const double peak = *std::max_element(c.y.begin(), c.y.end());
    const double hyperbola = std::sqrt(std::pow(beta - c.sigma_n * t, 2) - alpha * alpha);
    if (!(peak > 0) || peak > 0.95 * hyperbola) continue;
    Cs += (fc * fc - c.sigma_n * c.sigma_n) / (peak * peak), ++m;
  }
  if (m) {
    e.cap.Cs = Cs / m, e.Cs_held = false;
    e.notes.push_back("Cs: tau_p^2 = (fc^2 - sigma_n^2)/Cs on " + std::to_string(m) +
                      " shear curve(s) whose peak lies on the cap (more than 5 % below the hyperbola)");
  } else {
    e.notes.push_back("Cs: held at " + number_text(kDefaultCs) + " (Lourenco & Rots), no shear curve with its peak on the cap");
  }
  const ValidationError v = validate(e.cap, p);
  if (!v.ok())
    throw InputError("calibrate: the cap from the compression curves (fc = " + number_text(fc) + " MPa, Gfc = " +
                     number_text(e.cap.Gfc) + " N/mm, kappa_p = " + number_text(kp) + " mm, Cs = " +
                     number_text(e.cap.Cs) + ") is not valid with the joint's parameters: " + v.message());
  return e;
}

}  // namespace mortar::harness
