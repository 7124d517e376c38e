#include "calibration/tension_rules.hpp"

#include <cmath>
#include <functional>

#include <Eigen/Dense>
#include <unsupported/Eigen/NonLinearOptimization>

#include "calibration/curve_reading.hpp"
#include "input/input_error.hpp"

namespace mortar::harness {

namespace {

struct Point {
  double d = 0, sigma = 0;
};

// The traction on the surface after the peak, sigma = A exp(-r (d - sigma/kn))
// (r = ft0/GIC), on the stable branch r sigma < kn, and the derivatives of ln
// sigma with respect to ln A, r and kn. Newton in u = ln sigma from
// ln A - r d, left of the root: h(u) = u - ln A + r d - r e^u/kn is concave
// and increasing there, so the iterates rise monotonically to the root.
struct OnSurface {
  double sigma = 0, du_dlnA = 0, du_dr = 0, du_dkn = 0;
};
OnSurface on_surface(double A, double r, double kn, double d) {
  double u = std::log(A) - r * d, hu = 1;
  for (int it = 0; it < 200; ++it) {
    const double h = u - std::log(A) + r * d - r * std::exp(u) / kn;
    hu = 1 - r * std::exp(u) / kn;
    if (!(hu > 1e-12)) break;  // past the branch's top: no stable root (only while a fit wanders)
    const double step = -h / hu;
    u += step;
    if (std::abs(step) < 1e-13) break;
  }
  const double s = std::exp(u);
  hu = std::max(1 - r * s / kn, 1e-12);
  return {s, 1 / hu, -(d - s / kn) / hu, -r * s / (kn * kn) / hu};
}

// Least squares of the traction by Eigen's Levenberg-Marquardt (MINPACK's
// lmder) on log-parameters, and the covariance of those from the Jacobian at
// the optimum, s^2 (J^T J)^-1.
using Model = std::function<void(const Eigen::VectorXd& theta, Eigen::VectorXd& r, Eigen::MatrixXd* J)>;
struct Functor {
  const Model& model;
  long m, n;
  int values() const { return int(m); }
  int inputs() const { return int(n); }
  int operator()(const Eigen::VectorXd& t, Eigen::VectorXd& r) const { return model(t, r, nullptr), 0; }
  int df(const Eigen::VectorXd& t, Eigen::MatrixXd& J) const {
    Eigen::VectorXd r(m);
    return model(t, r, &J), 0;
  }
};
struct LeastSquares {
  Eigen::VectorXd theta;
  Eigen::MatrixXd cov;
};
LeastSquares least_squares(const Model& model, Eigen::VectorXd theta, long points) {
  Functor f{model, points, theta.size()};
  Eigen::LevenbergMarquardt<Functor> lm(f);
  lm.parameters.xtol = 1e-12;
  lm.parameters.ftol = 1e-14;
  lm.minimize(theta);
  Eigen::VectorXd r(points);
  Eigen::MatrixXd J(points, theta.size());
  model(theta, r, &J);
  const double s2 = r.squaredNorm() / double(std::max<long>(points - theta.size(), 1));
  return {theta, s2 * (J.transpose() * J).inverse()};
}

// Both branches with ft0 = A at the peak: theta = (ln kn, ln ft0, ln GIC).
Model closed_form(const std::vector<Point>& pts) {
  return [&pts](const Eigen::VectorXd& t, Eigen::VectorXd& res, Eigen::MatrixXd* J) {
    const double kn = std::exp(t[0]), f = std::exp(t[1]), G = std::exp(t[2]), r = f / G;
    if (J) J->setZero(long(pts.size()), 3);
    for (size_t i = 0; i < pts.size(); ++i) {
      const long k = long(i);
      if (pts[i].d <= f / kn) {
        res[k] = kn * pts[i].d - pts[i].sigma;
        if (J) (*J)(k, 0) = kn * pts[i].d;
        continue;
      }
      const OnSurface s = on_surface(f, r, kn, pts[i].d);
      res[k] = s.sigma - pts[i].sigma;
      if (J) (*J)(k, 0) = s.sigma * kn * s.du_dkn, (*J)(k, 1) = s.sigma * (s.du_dlnA + r * s.du_dr),
             (*J)(k, 2) = -s.sigma * r * s.du_dr;
    }
  };
}

// The stable tail after a snap-back, kn held: theta = (ln A, ln r).
Model tail(const std::vector<Point>& pts, double kn) {
  return [&pts, kn](const Eigen::VectorXd& t, Eigen::VectorXd& res, Eigen::MatrixXd* J) {
    const double A = std::exp(t[0]), r = std::exp(t[1]);
    for (size_t i = 0; i < pts.size(); ++i) {
      const OnSurface s = on_surface(A, r, kn, pts[i].d);
      res[long(i)] = s.sigma - pts[i].sigma;
      if (J) (*J)(long(i), 0) = s.sigma * s.du_dlnA, (*J)(long(i), 1) = s.sigma * r * s.du_dr;
    }
  };
}

const char* const kClosedForm = "tension curve in closed form (model.md 4), least squares on both branches: ";

}  // namespace

TensionRules tension_rules(const std::vector<TestCurve>& curves) {
  std::vector<double> ex, ey;
  std::vector<Point> pts;
  double peak_sum = 0, drop_x_sum = 0, area = 0, tension_curves = 0;
  for (const TestCurve& curve : curves) {
    if (curve.shear()) continue;
    const TestCurve c = envelope_of(curve);
    elastic_points(c, ex, ey);
    const size_t end = first_branch_end(c), p = index_of_peak(c.y, end);
    // Where the curve drops most between two points: after a snap-back the
    // peak is the last point before that drop (the largest sample can be a
    // point before it that noise lifted).
    size_t drop = p;
    for (size_t i = 0; i + 1 < end; ++i)
      if (c.y[i] - c.y[i + 1] > c.y[drop] - c.y[std::min(drop + 1, end - 1)]) drop = i;
    peak_sum += c.y[p], drop_x_sum += c.x[drop], tension_curves += 1;
    for (size_t i = 0; i < end; ++i) {
      pts.push_back({c.x[i], c.y[i]});
      if (i > 0) area += 0.5 * (c.y[i] + c.y[i - 1]) * (c.x[i] - c.x[i - 1]);
    }
  }
  if (ex.size() < 2)
    throw InputError("the tension curves have fewer than 2 points on their elastic branch (before the peak, below 90 % "
                     "of it): the initial slope gives kn");
  const Estimate kn0 = slope_through_origin(ex, ey);
  const double peak = peak_sum / tension_curves, peak_x = drop_x_sum / tension_curves;
  TensionRules out;
  // Start: the initial slope, the largest sample, and the area less the
  // elastic energy at the peak (the tail's area beyond the data is small).
  Eigen::VectorXd theta(3);
  theta << std::log(kn0.value), std::log(peak),
      std::log(std::max(area / tension_curves - peak * peak / (2 * kn0.value), 1e-3 * peak * peak / kn0.value));
  if (pts.size() > 3) {
    const Model model = closed_form(pts);
    const LeastSquares fit = least_squares(model, theta, long(pts.size()));
    const double kn = std::exp(fit.theta[0]), f = std::exp(fit.theta[1]), G = std::exp(fit.theta[2]);
    if (fit.cov.allFinite() && f * f / (G * kn) < 1) {
      auto se = [&](int k, double v) { return v * std::sqrt(fit.cov(k, k)); };
      out.kn = {kn, Stage::direct, std::string(kClosedForm) + "the initial slope", se(0, kn)};
      out.ft0 = {f, Stage::direct, std::string(kClosedForm) + "the peak", se(1, f)};
      out.GIC = {G, Stage::direct, std::string(kClosedForm) + "the area", se(2, G)};
      for (int i = 0; i < 3; ++i)  // of the logs, the same as of the values to first order
        for (int j = 0; j < 3; ++j) out.correlation[i][j] = fit.cov(i, j) / std::sqrt(fit.cov(i, i) * fit.cov(j, j));
      return out;
    }
  }
  // A snap-back: the elastic branch, the elastic line at the peak, the tail.
  out.kn = {kn0.value, Stage::direct, "initial slope of the tension curves", kn0.se};
  out.ft0 = {kn0.value * peak_x, Stage::direct, "the elastic line at the peak, the last point before the curve's drop (it snaps back)",
             kn0.se * peak_x};
  double ssr = 0;
  for (size_t i = 0; i < ex.size(); ++i) ssr += std::pow(ey[i] - kn0.value * ex[i], 2);
  const double noise = std::sqrt(ssr / double(ex.size())), floor = std::max(3 * noise, 1e-3 * out.ft0.value);
  std::vector<Point> tail_pts;
  for (const TestCurve& curve : curves) {
    if (curve.shear()) continue;
    const TestCurve c = envelope_of(curve);
    const size_t end = first_branch_end(c);
    for (size_t i = index_of_peak(c.y, end) + 1; i < end; ++i)
      if (c.y[i] > floor) tail_pts.push_back({c.x[i], c.y[i]});
  }
  const double bound = out.ft0.value * out.ft0.value / (2 * out.kn.value);
  char ratio[160];
  if (tail_pts.size() < 3) {
    out.GIC = {bound, Stage::not_determined,
               "the tension curve snaps back and separates at its peak: GIC <= ft0^2/(2 kn), the elastic energy there "
               "(model.md 6, snap-back); set to that bound"};
    std::snprintf(ratio, sizeof ratio, "%zu point(s) after the peak above 3 times the noise (%.3g MPa), 3 needed",
                  tail_pts.size(), floor);
    out.notes.push_back("GIC is not determined: the tension softening snaps back (its curve drops at the peak) and leaves " +
                        std::string(ratio) + "; GIC is set to its bound ft0^2/(2 kn) = " + std::to_string(bound) +
                        " N/mm. A test with a stiffer machine or a shorter specimen would show the softening.");
    return out;
  }
  // Start of the tail: ln sigma = ln A - r d_in by unweighted regression.
  std::vector<double> d_in, ln_sigma;
  for (const Point& q : tail_pts) d_in.push_back(q.d - q.sigma / out.kn.value), ln_sigma.push_back(std::log(q.sigma));
  const Line start = line_through(d_in, ln_sigma);
  Eigen::VectorXd t2(2);
  t2 << start.a, std::log(std::max(-start.b, 1e-6 * out.ft0.value / bound));
  const Model model = tail(tail_pts, out.kn.value);
  const LeastSquares fit = least_squares(model, t2, long(tail_pts.size()));
  const double r = std::exp(fit.theta[1]), G = out.ft0.value / r;
  out.GIC = {G, Stage::direct, "decay of the tension curve's tail after its snap-back (model.md 4, 6)",
             G * std::hypot(out.ft0.std_error / out.ft0.value, std::sqrt(fit.cov(1, 1)))};
  std::snprintf(ratio, sizeof ratio, "%.3g", out.ft0.value * out.ft0.value / (G * out.kn.value));
  out.notes.push_back("the tension softening snaps back (ft0^2/(GIC kn) = " + std::string(ratio) +
                      " > 1): GIC from the decay of the " + std::to_string(tail_pts.size()) +
                      " points after the drop, ft0 from the elastic line at the peak");
  return out;
}

}  // namespace mortar::harness
