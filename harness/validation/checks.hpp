// The validation checks of one case, computed from the curve the harness
// recorded (tractions, separations and the routine's outputs), never taken
// from the law's own claims: peaks are maxima of the returned tractions,
// areas are trapezoidal sums over the returned curve, the closed-form peak is
// recomputed here from the parameters. Limits are constants below and in
// harness/README.md.
#pragma once

#include <string>
#include <vector>

#include "output/csv.hpp"
#include "solvers/explicit_run.hpp"
#include "validation/calibration_data.hpp"

namespace mortar::harness {

namespace limits {
inline constexpr double tension_peak = 1e-3;        // relative, peak sigma_n vs ft0
inline constexpr double fracture_energy = 5e-3;     // relative, area and dissipation vs GIC
inline constexpr double final_traction = 1e-3;      // |sigma_n| at the end, relative to ft0
inline constexpr double final_damage = 1e-3;        // 1 - d_n at the end
inline constexpr double shear_peak = 1e-3;          // relative, peak tau vs the closed form
inline constexpr double residual_shear = 0.02;      // (tau_end - tan(phir)|sigma_n|) / that, at most
// External work (trapezoidal) vs elastic + dissipated, relative: limited by
// the trapezoidal rule at the kinks of the curve, so looser for the cyclic
// test, whose reversals come every few thousand increments.
inline constexpr double energy_closure = 1e-6;
inline constexpr double energy_closure_cyclic = 1e-4;
inline constexpr double bookkeeping = 1e-9;         // relative, sum of spd vs SDV16 + SDV17 + SDV18
inline constexpr double regression = 1e-6;          // relative to the curve's scale, fresh vs reference
}  // namespace limits

struct CheckRow {
  enum class Verdict { pass, fail, info };
  std::string quantity;  // what is measured, with its unit
  std::string value, expected, error, limit;
  Verdict verdict = Verdict::info;
};

// The peak shear stress of docs/model.md 4 at normal traction sigma_n < 0,
// recomputed from the parameters: sqrt((beta0 - sigma_n tan phi0)^2 - alpha0^2).
double closed_form_peak_shear(const Parameters& p, double sigma_n);

std::vector<CheckRow> check_case(SeriesKind kind, const std::vector<Sample>& curve, const Parameters& p,
                                 const IndependentValues& independent, double traction_tolerance);

// Fresh curve against the stored reference: worst difference over the
// reference rows, relative to each quantity's scale.
CheckRow compare_with_reference(const std::vector<Sample>& curve, const CsvTable& reference);

// Digitised experimental curve (slip_mm,tau_MPa or opening_mm,sigma_MPa):
// RMS difference at the experiment's points, matched by path length along
// the abscissa (so cyclic loops compare in test order).
CheckRow compare_with_experiment(SeriesKind kind, const std::vector<Sample>& curve, const CsvTable& experiment);

// The reference CSV written from a curve: a subset of the run columns, at
// most about 1000 rows plus the last.
void write_reference(const std::string& path, const std::vector<Sample>& curve);

std::string format_number(double x, int digits = 6);

}  // namespace mortar::harness
