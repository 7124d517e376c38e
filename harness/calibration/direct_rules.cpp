#include "calibration/direct_rules.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>

#include <Eigen/Dense>

#include "calibration/curve_reading.hpp"
#include "calibration/tension_rules.hpp"
#include "calibration/unloading_rules.hpp"
#include "input/input_error.hpp"

namespace mortar::harness {

Parameters Calibration::values() const {
  Parameters p;
  for (int i = 0; i < kParameterCount; ++i) parameter_at(p, i) = entries[static_cast<size_t>(i)].value;
  return p;
}

const char* stage_name(Stage s) {
  switch (s) {
    case Stage::direct: return "direct";
    case Stage::refined: return "direct+fit";
    case Stage::fit: return "fit";
    case Stage::not_determined: return "not determined";
  }
  return "unknown";
}

namespace {

Estimate shear_stiffness(const std::vector<TestCurve>& curves) {
  std::vector<double> x, y;
  for (const TestCurve& c : curves)
    if (c.shear()) elastic_points(c, x, y);
  if (x.size() < 2)
    throw InputError("the shear curves have fewer than 2 points on their elastic branch (before the peak, below 90 % "
                     "of it): the initial slope gives ks");
  return slope_through_origin(x, y);
}

ShearPeak shear_peak(const TestCurve& c) {
  ShearPeak p{c.name, c.sigma_n, 0, 0};
  const size_t end = first_branch_end(c);
  p.peak = c.y[index_of_peak(c.y, end)];
  // Residual: the mean |tau| over the last quarter of the slip travelled. On
  // a cyclic curve that quarter includes the elastic parts of its reversals,
  // which lower it: there the fit's refinement of phir matters most.
  double travel = 0;
  std::vector<double> along(c.x.size(), 0);
  for (size_t i = 1; i < c.x.size(); ++i) along[i] = travel += std::abs(c.x[i] - c.x[i - 1]);
  double sum = 0;
  int count = 0;
  for (size_t i = 0; i < c.x.size(); ++i)
    if (along[i] >= 0.75 * travel) sum += std::abs(c.y[i]), ++count;
  p.residual = sum / count;
  return p;
}

// Per-sigma_n means of peaks and residuals, weighted by their scatter.
struct Level {
  double sigma_n = 0, peak = 0, residual = 0, count = 0;
};
std::vector<Level> levels_of(const std::vector<ShearPeak>& peaks) {
  std::map<double, Level> by;
  for (const ShearPeak& p : peaks) {
    Level& l = by[p.sigma_n];
    l.sigma_n = p.sigma_n, l.peak += p.peak, l.residual += p.residual, l.count += 1;
  }
  std::vector<Level> out;
  for (auto& [s, l] : by) out.push_back({s, l.peak / l.count, l.residual / l.count, l.count});
  return out;
}

// Standard errors of f(coefficients) by the delta method, with a numerical
// gradient.
double propagated(const std::function<double(const Eigen::VectorXd&)>& f, const Eigen::VectorXd& c,
                  const Eigen::MatrixXd& cov) {
  Eigen::VectorXd g(c.size());
  for (int j = 0; j < c.size(); ++j) {
    const double h = 1e-6 * std::max(std::abs(c[j]), 1e-12);
    Eigen::VectorXd up = c, down = c;
    up[j] += h, down[j] -= h;
    g[j] = (f(up) - f(down)) / (2 * h);
  }
  return std::sqrt(g.dot(cov * g));
}

// The hyperbola through the peaks: tau_p^2 = A + B sigma_n + D sigma_n^2 with
// A = c0^2, D = tan^2 phi0, B = -(c0^2/ft0 + ft0 tan^2 phi0) (Eqs. 2-3 at s = 1).
// With ft0 known (tension) only A and D are unknown. `sd` is the scatter of a
// peak [MPa].
void hyperbola_rules(const std::vector<Level>& levels, bool ft0_known, double sd, Calibration& cal) {
  const int unknowns = ft0_known ? 2 : 3, m = static_cast<int>(levels.size());
  const double ft0 = cal["ft0"].value;
  Eigen::MatrixXd A(m, unknowns);
  Eigen::VectorXd y(m), w(m);
  for (int i = 0; i < m; ++i) {
    const double s = levels[i].sigma_n;
    y[i] = levels[i].peak * levels[i].peak;
    w[i] = levels[i].count / std::pow(2 * levels[i].peak * sd, 2);  // 1/var(tau_p^2)
    if (ft0_known) A.row(i) << 1 - s / ft0, s * s - ft0 * s;
    else A.row(i) << 1, s, s * s;
  }
  const Eigen::MatrixXd normal = A.transpose() * w.asDiagonal() * A;
  Eigen::VectorXd coef = normal.ldlt().solve(A.transpose() * w.asDiagonal() * y);
  Eigen::MatrixXd cov = normal.inverse();
  std::string how = "hyperbola of Eqs. 2-3 through the peak shear strengths";
  // The law needs phi0 >= phir (docs/model.md 2). Peaks close to a straight
  // line in sigma_n (small curvature, tan^2 phi0, against the scatter) can
  // put the unconstrained curvature below tan^2 phir or below zero: then the
  // least squares on that bound.
  const double floor = std::pow(std::tan(cal["phir"].value * kDegree), 2);
  if (coef[unknowns - 1] < floor) {
    const Eigen::MatrixXd B = A.leftCols(unknowns - 1), nb = B.transpose() * w.asDiagonal() * B;
    coef.head(unknowns - 1) = nb.ldlt().solve(B.transpose() * w.asDiagonal() * (y - floor * A.col(unknowns - 1)));
    coef[unknowns - 1] = floor;
    cov.setZero();
    cov.topLeftCorner(unknowns - 1, unknowns - 1) = nb.inverse();
    how += ", on the law's bound phi0 = phir (unconstrained, the peaks' curvature fell below tan^2 phir)";
  }
  auto c0 = [](const Eigen::VectorXd& k) { return std::sqrt(k[0]); };
  auto phi0 = [&](const Eigen::VectorXd& k) { return std::atan(std::sqrt(k[ft0_known ? 1 : 2])) / kDegree; };
  auto ft0_of = [&](const Eigen::VectorXd& k) {  // the root below c0/tan(phi0): D f^2 + B f + A = 0
    return (-k[1] - std::sqrt(k[1] * k[1] - 4 * k[0] * k[2])) / (2 * k[2]);
  };
  if (coef[0] <= 0 || coef[unknowns - 1] <= 0 || (!ft0_known && !(ft0_of(coef) > 0)))
    throw InputError("the peak shear strengths do not lie on a hyperbola of Eqs. 2-3 (c0^2 = " +
                     std::to_string(coef[0]) + ", tan^2 phi0 = " + std::to_string(coef[unknowns - 1]) +
                     "): check the sigma_n lines and the peaks");
  cal["c0"] = {c0(coef), Stage::refined, how, propagated(c0, coef, cov)};
  cal["phi0"] = {phi0(coef), Stage::refined, how, propagated(phi0, coef, cov)};
  if (!ft0_known) cal["ft0"] = {ft0_of(coef), Stage::refined, how + " (no tension curve)", propagated(ft0_of, coef, cov)};
}

void residual_rule(const std::vector<Level>& levels, double sd, Calibration& cal) {
  std::vector<double> x, y;
  for (const Level& l : levels) x.push_back(-l.sigma_n), y.push_back(l.residual);
  const Estimate t = slope_through_origin(x, y);
  double sxx = 0;
  for (double v : x) sxx += v * v;
  const double se = std::isfinite(t.se) ? t.se : sd / std::sqrt(sxx);
  cal["phir"] = {std::atan(t.value) / kDegree, Stage::refined, "residual strengths, tau_r = tan(phir)|sigma_n|",
                 se / (1 + t.value * t.value) / kDegree};
}

// The scatter of one shear point [MPa]: RMS about the elastic line (the noise
// of the data, which the peaks carry too).
double point_scatter(const std::vector<TestCurve>& curves, double ks) {
  std::vector<double> x, y;
  for (const TestCurve& c : curves)
    if (c.shear()) elastic_points(c, x, y);
  double ssr = 0;
  for (size_t i = 0; i < x.size(); ++i) ssr += std::pow(y[i] - ks * x[i], 2);
  return std::sqrt(ssr / double(std::max<size_t>(x.size() - 1, 1)));
}

// Starting values of the fit's softening parameters:
//  - GIIC: the work beyond the residual, the integral of (tau - tau_r) over
//    the plastic slip x - tau/ks after the peak (Eq. 8 summed to s = 0), or
//    without a monotonic shear curve 10 GIC (Table 1's ratio), or 0.05 N/mm;
//  - bn, bs: Table 1's values (every set there has 10 and 3), replaced by
//    what unloading branches give where the data hold them (unloading_rules.hpp).
void softening_start(const std::vector<TestCurve>& curves, bool tension, Calibration& cal) {
  const double ks = cal["ks"].value;
  double work = 0;
  int n = 0;
  for (const TestCurve& c : curves) {
    if (c.kind != TestKind::shear) continue;
    const double tau_r = std::tan(cal["phir"].value * kDegree) * -c.sigma_n;
    double w = 0;
    for (size_t i = index_of_peak(c.y, c.y.size()) + 1; i < c.x.size(); ++i)
      w += 0.5 * (c.y[i] + c.y[i - 1] - 2 * tau_r) * ((c.x[i] - c.y[i] / ks) - (c.x[i - 1] - c.y[i - 1] / ks));
    work += w, ++n;
  }
  const double GIIC = n ? std::max(work / n, 1e-4) : tension ? 10 * cal["GIC"].value : 0.05;
  cal["GIIC"] = {GIIC, Stage::fit, "starting value: work beyond the residual (Eq. 8)"};
  cal["bn"] = {10, Stage::fit, "starting value: Table 1"};
  cal["bs"] = {3, Stage::fit, "starting value: Table 1"};
}

// Starting values of m and n: the friction is worn out (m wIII ~ 4) over the
// slip of the curves, with wIII ~ |sigma_n| (tan phi0 - tan phir) slip / 2 (Eq. 9).
void wear_start(const std::vector<TestCurve>& curves, Calibration& cal) {
  const double drop = std::tan(cal["phi0"].value * kDegree) - std::tan(cal["phir"].value * kDegree);
  double wear = 0;
  int n = 0;
  for (const TestCurve& c : curves)
    if (c.kind == TestKind::shear) wear += -c.sigma_n * std::max(drop, 1e-3) * c.x.back() / 2, ++n;
  const double m = n ? 4 * n / wear : 1000;
  cal["m"] = {m, Stage::fit, "starting value: friction worn over the curves (Eq. 9)"};
  cal["n"] = {m, Stage::fit, "starting value: as m"};
}

// The dilatancy right after each peak: between the peak and the second point
// after it, d(uplift)/d(plastic slip) = tan(psi0) sqrt(alpha0^2 + tau^2)/tau
// (docs/model.md 5) with alpha0 of Eq. 3 at s = 1.
void dilatancy_start(const std::vector<TestCurve>& curves, Calibration& cal) {
  const double ks = cal["ks"].value, t = std::tan(cal["phi0"].value * kDegree), ft0 = cal["ft0"].value;
  const double alpha0 = (cal["c0"].value * cal["c0"].value / ft0 / t - ft0 * t) / 2;
  double sum = 0;
  int n = 0;
  for (const TestCurve& c : curves) {
    if (!c.has_uplift() || c.sigma_n > 0) continue;
    const size_t p = index_of_peak(c.y, first_branch_end(c)), q = p + 2;
    if (q >= c.x.size()) continue;
    const double slip = (c.x[q] - c.y[q] / ks) - (c.x[p] - c.y[p] / ks);
    if (!(slip > 0)) continue;
    sum += (c.uplift[q] - c.uplift[p]) / slip * c.y[p] / std::hypot(alpha0, c.y[p]), ++n;
  }
  if (n == 0) {
    cal["psi0"] = {0, Stage::not_determined, "no dilatancy measured: 0, no uplift (the conservative choice)"};
    cal["n"] = {0, Stage::not_determined, "no dilatancy measured"};
    return;
  }
  const double psi0 = std::clamp(std::atan(sum / n) / kDegree, 0.5, 60.0);
  cal["psi0"] = {psi0, Stage::fit, "starting value: the initial dilatancy (model.md 5)"};
  cal["psir"] = {0, Stage::fit, "placeholder 0 (no residual dilatancy); fitted where the uplift shows it"};
}

// The starting values that follow the strengths (m, n, psi0, psir): one rule
// for the rules' start and for the raised starts.
void strength_dependent_start(const std::vector<TestCurve>& curves, Calibration& cal) {
  wear_start(curves, cal);
  dilatancy_start(curves, cal);
}

}  // namespace

Calibration raised_start(const std::vector<TestCurve>& curves, const Calibration& rules, double factor) {
  Calibration cal = rules;
  cal["phi0"].value *= factor;
  strength_dependent_start(curves, cal);
  return cal;
}

void fill_placeholders(bool tension, Calibration& cal) {
  if (!tension) {
    cal["kn"] = {2.4 * cal["ks"].value, Stage::not_determined,
                 "no tension curve: 2(1+nu) ks with nu = 0.2, the ratio of every Table 1 set"};
    cal["GIC"] = {cal["GIIC"].value / 10, Stage::not_determined,
                  "no tension curve: GIIC/10, the ratio of Table 1 (wI is 0 under compression)"};
  }
  if (cal["psir"].stage == Stage::not_determined && cal["psir"].how.empty())
    cal["psir"] = {0, Stage::not_determined, "no dilatancy measured: 0, Table 1's value"};
}

DirectResult apply_direct_rules(const std::vector<TestCurve>& curves) {
  DirectResult r;
  Calibration& cal = r.calibration;
  const bool tension = std::any_of(curves.begin(), curves.end(), [](const TestCurve& c) { return !c.shear(); });
  // The hyperbola and the residual friction from the tests under
  // compression; one at constant tension is for bs (unloading_rules.hpp).
  for (const TestCurve& c : curves)
    if (c.shear_under_compression()) r.peaks.push_back(shear_peak(c));
  const std::vector<Level> levels = levels_of(r.peaks);
  if (levels.size() < 2 || (!tension && levels.size() < 3))
    throw InputError("the data hold shear curves at " + std::to_string(levels.size()) +
                     " compressive normal stress(es): the hyperbola needs at least 2 with a tension curve, 3 without one");
  const Estimate ks = shear_stiffness(curves);
  cal["ks"] = {ks.value, Stage::direct, "initial slope of the shear curves", ks.se};
  if (tension) {
    TensionRules t = tension_rules(curves);
    cal["kn"] = t.kn, cal["ft0"] = t.ft0, cal["GIC"] = t.GIC;
    const int at[3] = {parameter_index("kn"), parameter_index("ft0"), parameter_index("GIC")};
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j)
        if (t.correlation[i][j] != 0) cal.correlations.push_back({at[i], at[j], t.correlation[i][j]});
    cal.notes.insert(cal.notes.end(), t.notes.begin(), t.notes.end());
  }
  // Noise-free data (synthetic) would give zero weights' inverse: a floor
  // of 1e-4 of the largest peak (levels in sigma_n order) keeps the regression defined.
  const double sd = std::max(point_scatter(curves, ks.value), 1e-4 * levels.front().peak);
  residual_rule(levels, sd, cal);
  hyperbola_rules(levels, tension, sd, cal);
  softening_start(curves, tension, cal);
  unloading_rules(curves, cal);
  strength_dependent_start(curves, cal);
  fill_placeholders(tension, cal);
  return r;
}

}  // namespace mortar::harness
