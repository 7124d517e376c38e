// Honest uncertainty of least-squares estimates, from the Jacobian J of the
// scaled residuals r at the optimum (the usual linearisation):
// covariance = s^2 (J^T J)^-1 with s^2 = |r|^2 / (N - P), standard errors its
// diagonal's roots, correlations its normalised off-diagonal. Directions in
// which J is (nearly) singular are combinations of parameters the data cannot
// separate: they are named rather than given false precision.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "calibration/calibration.hpp"
#include "calibration/fit.hpp"

namespace mortar::harness {

// A parameter whose relative standard error exceeds this is reported as
// poorly determined: its value is the data's, its digits are not to be trusted.
inline constexpr double kPoorlyDetermined = 0.10;
// J's columns scaled by the parameters (sensitivity to a relative change)
// whose smallest singular value is below this fraction of the largest are
// singular for the purpose of the fit. Measured on van der Pluijm's curves:
// bn (no effect at all) 4e-9, bs (only GIIC/(1 + bs) and m(1 + bs) matter
// under compression, Eqs. 8-9 with Eq. 17) 3e-6, the smallest genuine
// direction 1e-4.
inline constexpr double kSingular = 1e-5;

struct Uncertainty {
  Eigen::VectorXd std_error;     // [parameter units]
  Eigen::MatrixXd correlation;   // P x P
  double s2 = 0;                 // residual variance per point
  int dof = 0;                   // N - P
};

// The fit's own covariance plus what the direct values it holds carry into
// it (two stages: their errors taken as independent of the fit's residuals).
Uncertainty uncertainty_from(const FitResult& fit);

// Unknowns that the data cannot separate: while the scaled Jacobian (columns
// times `values`) is singular (kSingular), the unknown with the largest share
// in its null direction is taken out, preferring those in `prefer_first`.
// Returns the taken-out columns in order, each with the null direction's
// description ("ln bs +0.71, ln GIIC -0.70").
struct Unidentifiable {
  int column = 0;
  std::string direction;
};
std::vector<Unidentifiable> unidentifiable(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& values,
                                           const std::vector<std::string>& names, const std::vector<int>& prefer_first);

// Puts a one-set fit into `cal`: values, standard errors, the held unknowns
// as not determined (with the combination the data do determine), and a note
// for every parameter whose relative standard error exceeds kPoorlyDetermined.
void apply_fit(Calibration& cal, const FitResult& fit, const Uncertainty& u);

}  // namespace mortar::harness
