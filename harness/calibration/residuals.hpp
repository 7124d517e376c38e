// The scaled residuals of a whole data set (calibration/fit.hpp): every curve
// simulated with the unknowns' values over the base set, a penalty for a set
// that breaks a rule of the law or a run that cannot be completed, and their
// forward-difference Jacobian.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "calibration/fit.hpp"

namespace mortar::harness {

class Residuals {
 public:
  Residuals(const std::vector<TestCurve>& curves, const Parameters& base, const FitOptions& o);
  long size() const { return size_; }
  long evaluations() const { return evaluations_; }

  // Per data point, (simulated - measured)/the curve's largest |value|,
  // traction then uplift; `misfit` (optional) gets each curve's summary.
  Eigen::VectorXd operator()(const std::vector<FitUnknown>& unknowns, const Eigen::VectorXd& v,
                             std::vector<CurveMisfit>* misfit = nullptr);

  // Forward differences, steps of 1e-3 of each value (of 1 for a linear
  // unknown below 1, which may be 0): far above the integration's own noise
  // (STOL), small against the curvature.
  Eigen::MatrixXd jacobian(const std::vector<FitUnknown>& unknowns, const Eigen::VectorXd& v, const Eigen::VectorXd& r0);

  // d residuals / d the base set's parameter `index` (a value the fit
  // holds), by the same forward difference.
  Eigen::VectorXd base_derivative(int index, const std::vector<FitUnknown>& unknowns, const Eigen::VectorXd& v,
                                  const Eigen::VectorXd& r0);

 private:
  const std::vector<TestCurve>& curves_;
  Parameters base_;
  const FitOptions& o_;
  long size_ = 0, evaluations_ = 0;
};

}  // namespace mortar::harness
