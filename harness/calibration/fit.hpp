// The second stage of the calibration: the softening and wear parameters
// (GIIC, m, n, bn, bs, and psi0 where dilatancy was measured) by least
// squares on the whole curves, every test simulated through the harness
// (calibration/simulation.hpp), with the direct parameters held.
//
// Residuals: per data point, (simulated - measured)/scale, the scale being
// the curve's largest |traction| (and, for the uplift, its largest |uplift|),
// so that curves of different strength weigh alike and the misfit reads as
// a fraction of each curve's size.
//
// Bounds by a transform (the solver itself is unbounded): each parameter p in
// [lo, hi] is p = exp(ln lo + (ln hi - ln lo) / (1 + exp(-t))) of an
// unbounded t (logistic on a log scale: positive, bounded, and steps of equal
// relative size across decades). The solver is Eigen's Levenberg-Marquardt
// (unsupported/Eigen/NonLinearOptimization, MINPACK's lmder) on t, with a
// forward-difference Jacobian.
//
// Parameters the data cannot move independently are found from the Jacobian
// (calibration/uncertainty.hpp) at the start and again at the solution, where
// it counts: one found there is held at its placeholder and the rest refitted
// (a forward-difference Jacobian at the start alone missed bs where psir > 0:
// bs ran to its bound with GIIC 26 times too large). Held ones are named.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "calibration/calibration.hpp"
#include "calibration/simulation.hpp"
#include "calibration/test_curve.hpp"

namespace mortar::harness {

// One unknown of the fit: a Table 1 parameter, shared by every curve, or (m
// and n per normal stress) belonging to the shear curves at one sigma_n.
struct FitUnknown {
  int index = 0;             // Table 1 position
  double sigma_n = NAN;      // the level it belongs to; NaN: every curve
  double lo = 0, hi = 0;     // bounds [parameter unit]
  bool linear = false;       // linear logistic transform: lo may be 0, a value the law allows (psir)
  std::string label() const; // "m" or "m @ -0.5 MPa"
};

// A value within 1 % of a bound the fit imposed (not one the law imposes: a
// linear unknown's lower bound is the law's own, psir = 0): there the bound
// stopped the fit, not the data.
bool on_bound(const FitUnknown& u, double value);

struct FitProgress {
  int iteration = 0;
  long evaluations = 0;
  double rms = 0;  // of the scaled residuals
};

struct FitOptions {
  SimulationSettings simulation;
  bool per_sigma_n = false;  // m and n per normal stress (the paper's Table 1 practice)
  int max_evaluations = 400; // simulations of the whole data set
  std::function<void(const FitProgress&)> progress;
};

// The misfit of one curve at the fitted values.
struct CurveMisfit {
  std::string curve;
  double rms_traction = 0;  // [MPa]
  double rms_uplift = NAN;  // [mm], NaN without uplift
  double rms_scaled = 0;    // RMS of its scaled residuals (traction and uplift)
  bool failed = false;      // the simulation could not be completed
};

struct FitResult {
  std::vector<FitUnknown> unknowns;
  Eigen::VectorXd value;     // at the optimum [parameter units]
  Eigen::VectorXd residuals; // scaled, at the optimum
  Eigen::MatrixXd jacobian;  // d residuals / d value at the optimum
  std::vector<std::string> held;  // unknowns held at their placeholder, with why
  std::vector<CurveMisfit> misfit;
  double rms = 0;            // of the scaled residuals
  long evaluations = 0;
  int iterations = 0;
  // The direct rules' values the fit holds (Table 1 positions), their
  // covariance (standard errors and correlations), and d residuals / d them
  // at the optimum: what their uncertainty does to the fitted values
  // (calibration/uncertainty.hpp).
  std::vector<int> direct_index;
  Eigen::MatrixXd direct_covariance;
  Eigen::MatrixXd direct_jacobian;
  std::string status;        // why the solver stopped
  bool converged = false;    // the solver met a convergence test (not the budget, not machine precision)
};

// Fits the unknowns, starting from (and holding every other parameter at)
// `start`. Throws InputError when the data give nothing to fit.
FitResult fit_softening(const std::vector<TestCurve>& curves, const Calibration& start, const FitOptions& options);

// The parameters of curve `c` for the unknowns' values `v` over `base`.
Parameters parameters_for(const TestCurve& c, const Parameters& base, const std::vector<FitUnknown>& unknowns,
                          const Eigen::VectorXd& v);

}  // namespace mortar::harness
