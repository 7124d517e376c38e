#include "calibration/uncertainty.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <Eigen/Dense>

namespace mortar::harness {

Uncertainty uncertainty_from(const FitResult& fit) {
  const Eigen::MatrixXd& J = fit.jacobian;
  const Eigen::VectorXd& r = fit.residuals;
  Uncertainty u;
  const long P = J.cols();
  u.dof = static_cast<int>(J.rows() - P);
  u.s2 = u.dof > 0 ? r.squaredNorm() / u.dof : NAN;
  // Pseudo-inverse through the SVD: a singular direction left in J gives
  // infinite errors on the parameters in it, not a wrong finite number.
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd sv = svd.singularValues();
  Eigen::VectorXd inv2(P);
  for (long i = 0; i < P; ++i) inv2[i] = sv[i] > kSingular * kSingular * sv[0] ? 1 / (sv[i] * sv[i]) : INFINITY;
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(P, P);
  for (long i = 0; i < P; ++i) {
    if (std::isinf(inv2[i])) {
      for (long j = 0; j < P; ++j)
        if (std::abs(svd.matrixV()(j, i)) > 1e-3) cov(j, j) = INFINITY;
      continue;
    }
    cov += inv2[i] * svd.matrixV().col(i) * svd.matrixV().col(i).transpose();
  }
  cov *= u.s2;
  // The direct values the fit holds carry their own errors: to first order
  // they move the optimum by G = -J^+ J_d per unit, so their covariance C_d
  // adds G C_d G^T (harness/README.md, calibrate: Uncertainty).
  if (fit.direct_jacobian.cols() > 0) {
    Eigen::VectorXd inv(P);
    for (long i = 0; i < P; ++i) inv[i] = std::isinf(inv2[i]) ? 0 : 1 / sv[i];
    const Eigen::MatrixXd G = -(svd.matrixV() * inv.asDiagonal() * svd.matrixU().transpose() * fit.direct_jacobian);
    cov += G * fit.direct_covariance * G.transpose();
  }
  u.std_error = cov.diagonal().cwiseSqrt();
  u.correlation = Eigen::MatrixXd::Identity(P, P);
  for (long i = 0; i < P; ++i)
    for (long j = 0; j < P; ++j)
      if (i != j) u.correlation(i, j) = cov(i, j) / (u.std_error[i] * u.std_error[j]);
  return u;
}

namespace {

std::string describe(const Eigen::VectorXd& v, const std::vector<int>& cols, const std::vector<std::string>& names) {
  std::string s;
  char buf[64];
  for (long i = 0; i < v.size(); ++i) {
    if (std::abs(v[i]) < 0.1) continue;
    std::snprintf(buf, sizeof buf, "%sln %s %+.2f", s.empty() ? "" : ", ", names[static_cast<size_t>(cols[i])].c_str(),
                  v[i]);
    s += buf;
  }
  return s;
}

}  // namespace

std::vector<Unidentifiable> unidentifiable(const Eigen::MatrixXd& J, const Eigen::VectorXd& values,
                                           const std::vector<std::string>& names,
                                           const std::vector<int>& prefer_first) {
  std::vector<int> kept(static_cast<size_t>(J.cols()));
  for (size_t i = 0; i < kept.size(); ++i) kept[i] = static_cast<int>(i);
  std::vector<Unidentifiable> out;
  while (!kept.empty()) {
    Eigen::MatrixXd scaled(J.rows(), static_cast<long>(kept.size()));
    for (size_t i = 0; i < kept.size(); ++i) scaled.col(long(i)) = J.col(kept[i]) * values[kept[i]];
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled, Eigen::ComputeThinV);
    const Eigen::VectorXd sv = svd.singularValues();
    const long last = sv.size() - 1;
    if (sv[0] > 0 && sv[last] > kSingular * sv[0]) break;
    const Eigen::VectorXd null = svd.matrixV().col(last);
    // The preferred unknown in the direction if it carries a fair share of
    // it, otherwise the one with the largest share.
    long pick = 0;
    null.cwiseAbs().maxCoeff(&pick);
    for (int p : prefer_first) {
      const auto at = std::find(kept.begin(), kept.end(), p);
      if (at != kept.end() && std::abs(null[at - kept.begin()]) > 0.3) {
        pick = at - kept.begin();
        break;
      }
    }
    out.push_back({kept[static_cast<size_t>(pick)], describe(null, kept, names)});
    kept.erase(kept.begin() + pick);
  }
  return out;
}

void apply_fit(Calibration& cal, const FitResult& fit, const Uncertainty& u) {
  for (size_t k = 0; k < fit.unknowns.size(); ++k) {
    CalibratedParameter& e = cal.entries[size_t(fit.unknowns[k].index)];
    e.value = fit.value[long(k)];
    e.std_error = u.std_error[long(k)];
    if (e.stage != Stage::refined) e.stage = Stage::fit, e.how = "least squares on the whole curves";
    else e.how += ", refined by least squares on the whole curves";
    // A value on its bound (within 1 %) is where the bounds stopped the
    // fit, not where the data put it: the one-set misfit of curves whose m
    // and n differ by level ends so (m at 1e5, n at 1 on van der Pluijm's).
    const FitUnknown& f = fit.unknowns[k];
    if (on_bound(f, e.value))
      cal.notes.push_back(f.label() + " = " + std::to_string(e.value) + " is on its bound [" + std::to_string(f.lo) +
                          ", " + std::to_string(f.hi) + "]: the fit was stopped there, not by the data; its value and "
                          "standard error are not estimates (if m or n, compare the misfit of m and n per sigma_n)");
    if (!(e.std_error <= kPoorlyDetermined * std::abs(e.value)))
      cal.notes.push_back(std::string(kParameterInfo[size_t(fit.unknowns[k].index)].name) +
                          " is poorly determined by these data (relative standard error " +
                          std::to_string(int(std::lround(100 * e.std_error / std::abs(e.value)))) +
                          " %, above " + std::to_string(int(100 * kPoorlyDetermined)) + " %): its digits are not to be trusted");
  }
  for (const std::string& h : fit.held) {
    const std::string name = h.substr(0, h.find(':'));
    CalibratedParameter& e = cal[name.c_str()];
    e.stage = Stage::not_determined;
    e.std_error = NAN;
    e.how = "held at its starting value (" + e.how + "): the data determine only a combination " + h.substr(h.find('('));
  }
}

}  // namespace mortar::harness
