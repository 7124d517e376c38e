#include "calibration/pipeline.hpp"

namespace mortar::harness {

CalibrationRun calibrate_curves(const std::vector<TestCurve>& curves, const CalibrationSettings& s) {
  CalibrationRun r;
  r.direct = apply_direct_rules(curves);
  FitOptions one = s.fit;
  one.per_sigma_n = false;
  r.one_set = fit_softening(curves, r.direct.calibration, one);
  r.one_set_uncertainty = uncertainty_from(r.one_set.jacobian, r.one_set.residuals);
  r.final = r.direct.calibration;
  apply_fit(r.final, r.one_set, r.one_set_uncertainty);
  fill_placeholders(r.final["kn"].stage == Stage::direct, r.final);
  if (!s.per_sigma_n) return r;
  // m and n per sigma_n start where the one set started, from the rules: the
  // one set's optimum is no start for them when the levels' m and n differ
  // widely. On van der Pluijm's curves made with Table 1's m and n per level,
  // one set ends with m and n at their bounds and psi0 near 0 (RMS misfit
  // 0.23); from there n has no effect, is held as undetermined, and the
  // per-level fit stayed at 0.23, against 0.0096 from the rules.
  FitOptions per = s.fit;
  per.per_sigma_n = true;
  per.progress = s.per_level_progress;
  r.per_level = fit_softening(curves, r.direct.calibration, per);
  r.per_level_base = r.direct.calibration.values();
  // One set is a special case of m and n per level, so the per-level misfit
  // cannot exceed the one set's at the optimum; where it does, the fit from
  // the rules stopped in a worse minimum: start again from the one set.
  if (r.per_level.rms > r.one_set.rms) {
    FitResult from_one = fit_softening(curves, r.final, per);
    if (from_one.rms < r.per_level.rms) r.per_level = std::move(from_one), r.per_level_base = r.final.values();
  }
  r.per_level_uncertainty = uncertainty_from(r.per_level.jacobian, r.per_level.residuals);
  r.per_level_fitted = true;
  return r;
}

}  // namespace mortar::harness
