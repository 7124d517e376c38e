#include "calibration/acceptance.hpp"

#include "calibration/curve_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mortar::harness {

namespace {

std::string g(double x) { return number_text(x, 3); }

}  // namespace

Verdict judge(const FitResult& fit, const std::vector<std::pair<std::string, Parameters>>& sets) {
  Verdict v;
  if (!fit.converged) v.reasons.push_back("the least squares did not converge (" + fit.status + ")");
  if (!(fit.rms <= kMaxMisfit))
    v.reasons.push_back("RMS misfit " + g(fit.rms) + " of the curves' scale is above " + g(kMaxMisfit) +
                        ": the law with these parameters does not describe the curves");
  for (const CurveMisfit& m : fit.misfit) {
    if (m.failed) v.reasons.push_back(m.curve + ": the law's run of this curve could not be completed");
    else if (!(m.rms_scaled <= kMaxCurveMisfit))
      v.reasons.push_back(m.curve + ": RMS misfit " + g(m.rms_scaled) + " of its scale is above " + g(kMaxCurveMisfit) +
                          " (a specimen unlike the others, or a wrong sigma_n?)");
  }
  for (size_t k = 0; k < fit.unknowns.size(); ++k) {
    const FitUnknown& u = fit.unknowns[k];
    const double x = fit.value[long(k)];
    if (!std::isfinite(x)) v.reasons.push_back(u.label() + " is not finite");
    else if (on_bound(u, x))
      v.reasons.push_back(u.label() + " = " + g(x) + " is on a bound of the fit [" + g(u.lo) + ", " + g(u.hi) +
                          "]: the bound stopped it, not the data");
  }
  for (const auto& [label, p] : sets) {
    bool finite = true;
    for (int i = 0; i < kParameterCount; ++i)
      if (!std::isfinite(parameter_at(p, i))) {
        finite = false;
        v.reasons.push_back(label + std::string(kParameterInfo[size_t(i)].name) + " is not finite");
      }
    if (!finite) continue;
    const ValidationError r = validate(p);
    if (!r.ok()) v.reasons.push_back(label + "the set breaks a rule of the law: " + r.message());
  }
  return v;
}

void judge_entries(const Calibration& cal, Verdict& v) {
  for (int i = 0; i < kParameterCount; ++i) {
    const CalibratedParameter& e = cal.entries[size_t(i)];
    const std::string name = kParameterInfo[size_t(i)].name;
    if (!std::isfinite(e.value)) v.reasons.push_back(name + " is not finite");
    else if (e.stage != Stage::not_determined && std::isnan(e.std_error))
      v.reasons.push_back(name + ": its standard error is not a number");
  }
}

std::vector<std::string> outliers(const FitResult& fit, const std::vector<TestCurve>& curves) {
  std::vector<double> a(size_t(fit.residuals.size()));
  for (long i = 0; i < fit.residuals.size(); ++i) a[size_t(i)] = std::abs(fit.residuals[i]);
  if (a.empty()) return {};
  std::nth_element(a.begin(), a.begin() + long(a.size() / 2), a.end());
  const double limit = std::max(kOutlierFactor * 1.4826 * a[a.size() / 2], kMaxCurveMisfit);
  std::vector<std::string> out;
  long at = 0;  // the residuals' layout (fit.hpp): per curve, per point, traction then uplift
  for (const TestCurve& c : curves)
    for (size_t i = 0; i < c.x.size(); ++i)
      for (int q = 0; q < (c.has_uplift() ? 2 : 1); ++q, ++at) {
        if (at >= fit.residuals.size() || !(std::abs(fit.residuals[at]) > limit)) continue;
        out.push_back(c.file + ": data row " + std::to_string(i + 1) + ": " + (q ? "uplift " : c.shear() ? "tau " : "sigma ") +
                      g(q ? c.uplift[i] : c.y[i]) + (q ? " mm" : " MPa") + " is an outlier: scaled residual " +
                      g(fit.residuals[at]) + ", beyond " + g(limit) + " (" + g(kOutlierFactor) +
                      " times the robust scatter of all points)");
      }
  return out;
}

}  // namespace mortar::harness
