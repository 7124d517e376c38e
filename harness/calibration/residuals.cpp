#include "calibration/residuals.hpp"

#include <algorithm>
#include <cmath>

#include "solvers/mixed_control.hpp"

namespace mortar::harness {

namespace {
double scale(const std::vector<double>& y) {
  double m = 0;
  for (double x : y) m = std::max(m, std::abs(x));
  return m > 0 ? m : 1;
}
}  // namespace

Residuals::Residuals(const std::vector<TestCurve>& curves, const Parameters& base, const FitOptions& o)
    : curves_(curves), base_(base), o_(o) {
  for (const TestCurve& c : curves) size_ += long(c.x.size() * (c.has_uplift() ? 2 : 1));
}

Eigen::VectorXd Residuals::operator()(const std::vector<FitUnknown>& unknowns, const Eigen::VectorXd& v,
                                      std::vector<CurveMisfit>* misfit) {
  ++evaluations_;
  Eigen::VectorXd r(size_);
  long at = 0;
  for (const TestCurve& c : curves_) {
    CurveMisfit m{c.name};
    SimulatedCurve sim;
    const Parameters p = parameters_for(c, base_, unknowns, v);
    // A set that breaks a rule of the law (phir > phi0, c0 <= ft0 tan phi0)
    // or a run that cannot be completed: a penalty the solver steps away from.
    m.failed = !validate(p).ok();
    try {
      if (!m.failed) sim = simulate(p, c, o_.simulation);
    } catch (const RunFailure&) {
      m.failed = true;
    }
    const double sy = scale(c.y), su = c.has_uplift() ? scale(c.uplift) : 1;
    double ey = 0, eu = 0;
    const long first = at;
    for (size_t i = 0; i < c.x.size(); ++i) {
      const double d = m.failed ? 10 * sy : sim.y[i] - c.y[i];
      r[at++] = d / sy, ey += d * d;
      if (!c.has_uplift()) continue;
      const double e = m.failed ? 10 * su : sim.uplift[i] - c.uplift[i];
      r[at++] = e / su, eu += e * e;
    }
    m.rms_scaled = std::sqrt(r.segment(first, at - first).squaredNorm() / double(at - first));
    m.rms_traction = std::sqrt(ey / c.x.size());
    if (c.has_uplift()) m.rms_uplift = std::sqrt(eu / c.x.size());
    if (misfit) misfit->push_back(m);
  }
  return r;
}

Eigen::MatrixXd Residuals::jacobian(const std::vector<FitUnknown>& unknowns, const Eigen::VectorXd& v,
                                    const Eigen::VectorXd& r0) {
  Eigen::MatrixXd J(size_, v.size());
  for (long j = 0; j < v.size(); ++j) {
    Eigen::VectorXd w = v;
    w[j] += 1e-3 * (unknowns[size_t(j)].linear ? std::max(std::abs(v[j]), 1.0) : v[j]);
    J.col(j) = ((*this)(unknowns, w) - r0) / (w[j] - v[j]);
  }
  return J;
}

Eigen::VectorXd Residuals::base_derivative(int index, const std::vector<FitUnknown>& unknowns, const Eigen::VectorXd& v,
                                           const Eigen::VectorXd& r0) {
  const Parameters kept = base_;
  const double h = 1e-3 * parameter_at(base_, index);
  parameter_at(base_, index) += h;
  const Eigen::VectorXd r = (*this)(unknowns, v);
  base_ = kept;
  return (r - r0) / h;
}

}  // namespace mortar::harness
