#include "validation/checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mortar::harness {

namespace {

using Verdict = CheckRow::Verdict;
constexpr double kDegree = 3.14159265358979323846 / 180.0;

std::string percent(double relative) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%+.3g %%", 100.0 * relative);
  return buf;
}

double relative(double value, double expected) {
  return expected != 0 ? (value - expected) / std::abs(expected) : value;
}

double shear_norm(const Sample& s) { return std::hypot(s.traction[1], s.traction[2]); }
double slip_norm(const Sample& s) { return std::hypot(s.separation[1], s.separation[2]); }

CheckRow checked(const std::string& quantity, double value, double expected, double rel_limit) {
  const double r = relative(value, expected);
  return {quantity, format_number(value), format_number(expected), percent(r), "+-" + percent(rel_limit).substr(1),
          std::abs(r) <= rel_limit ? Verdict::pass : Verdict::fail};
}

CheckRow info(const std::string& quantity, double value, const std::string& expected = "", double ref = NAN) {
  CheckRow row{quantity, format_number(value), expected, "", "", Verdict::info};
  if (std::isfinite(ref)) row.error = percent(relative(value, ref));
  return row;
}

// d_n and d_s within [0, 1] and never decreasing along the curve.
CheckRow damage_check(const std::vector<Sample>& curve) {
  int bad = 0;
  double worst_drop = 0;
  for (size_t i = 0; i < curve.size(); ++i)
    for (int slot : {slot::damage_n, slot::damage_s}) {
      const double d = curve[i].state[slot];
      if (!(d >= 0 && d <= 1)) ++bad;
      if (i > 0 && d < curve[i - 1].state[slot]) {
        ++bad;
        worst_drop = std::max(worst_drop, curve[i - 1].state[slot] - d);
      }
    }
  const Sample& end = curve.back();
  CheckRow row{"damage d_n, d_s in [0,1], never decreasing",
               "end " + format_number(end.state[slot::damage_n], 4) + ", " + format_number(end.state[slot::damage_s], 4),
               "", bad ? std::to_string(bad) + " violations" : "none", "0 violations",
               bad ? Verdict::fail : Verdict::pass};
  if (worst_drop > 0) row.error += ", largest drop " + format_number(worst_drop, 3);
  return row;
}

CheckRow status_check(const std::vector<Sample>& curve) {
  long bad = 0;
  for (const Sample& s : curve) bad += s.state[slot::status] != 0;
  return {"routine status (SDV21) at every increment", bad ? std::to_string(bad) + " nonzero" : "0",
          "0", "", "", bad ? Verdict::fail : Verdict::pass};
}

// External work (trapezoidal along the curve) against what the routine
// reports as stored (sed) plus dissipated (sum of spd).
CheckRow energy_closure(const std::vector<Sample>& curve, double limit) {
  const Sample& end = curve.back();
  const double work = end.external_work, booked = end.elastic_energy + end.dissipation;
  const double r = (work - booked) / std::max({std::abs(work), std::abs(booked), 1e-300});
  return {"energy: external work vs sed + sum spd [N/mm]", format_number(work, 9), format_number(booked, 9),
          percent(r), "+-" + percent(limit).substr(1), std::abs(r) <= limit ? Verdict::pass : Verdict::fail};
}

// The routine's dissipation output against its state: sum of spd equals
// SDV16 + SDV17 + SDV18 (plastic, damage, unilateral).
CheckRow bookkeeping_check(const std::vector<Sample>& curve) {
  const Sample& end = curve.back();
  const double states = end.state[slot::dissipation_plastic] + end.state[slot::dissipation_damage] +
                        end.state[slot::energy_unilateral];
  const double r = (end.dissipation - states) / std::max({std::abs(states), std::abs(end.dissipation), 1e-300});
  return {"energy: sum spd vs SDV16+17+18 [N/mm]", format_number(end.dissipation), format_number(states),
          percent(r), "+-" + percent(limits::bookkeeping).substr(1),
          std::abs(r) <= limits::bookkeeping ? Verdict::pass : Verdict::fail};
}

// Every traction-controlled component within the run's tolerance of its
// target at the end of every increment.
CheckRow held_traction(const std::vector<Sample>& curve, double tolerance) {
  double worst = 0;
  long controlled = 0;
  for (const Sample& s : curve)
    for (int j = 0; j < 3; ++j)
      if (s.traction_controlled[j]) {
        ++controlled;
        worst = std::max(worst, std::abs(s.traction[j] - s.target[j]));
      }
  return {"controlled traction: worst |sigma - target| [MPa]", format_number(worst, 5),
          std::to_string(controlled) + " controlled", "", "<= " + format_number(tolerance, 3),
          worst <= tolerance ? Verdict::pass : Verdict::fail};
}

double softening_used(const Sample& s, const Parameters& p) {
  return s.state[slot::work_I] / p.GIC + s.state[slot::work_II] / p.GIIC;
}

// Linear interpolation of y at x along the part of the curve where x grows.
double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  for (size_t i = 1; i < xs.size(); ++i)
    if (xs[i] >= x && xs[i] > xs[i - 1]) {
      const double t = (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
      return ys[i - 1] + t * (ys[i] - ys[i - 1]);
    }
  return NAN;
}

void tension_checks(const std::vector<Sample>& curve, const Parameters& p, std::vector<CheckRow>& rows) {
  double peak = -1e300;
  for (const Sample& s : curve) peak = std::max(peak, s.traction[0]);
  rows.push_back(checked("peak sigma_n vs ft0 [MPa]", peak, p.ft0, limits::tension_peak));
  // Area under sigma_n - delta_n, trapezoidal, over the returned curve.
  double area = 0;
  for (size_t i = 1; i < curve.size(); ++i)
    area += 0.5 * (curve[i - 1].traction[0] + curve[i].traction[0]) *
            (curve[i].separation[0] - curve[i - 1].separation[0]);
  rows.push_back(checked("area under sigma_n-delta_n vs GIC [N/mm]", area, p.GIC, limits::fracture_energy));
  const Sample& end = curve.back();
  rows.push_back(checked("dissipated (sum spd) vs GIC [N/mm]", end.dissipation, p.GIC, limits::fracture_energy));
  const double final_ratio = std::abs(end.traction[0]) / p.ft0;
  rows.push_back({"final |sigma_n| / ft0", format_number(final_ratio, 3), "~0", "",
                  "<= " + format_number(limits::final_traction, 3),
                  final_ratio <= limits::final_traction ? Verdict::pass : Verdict::fail});
  const double dn = end.state[slot::damage_n];
  rows.push_back({"final d_n", format_number(dn, 8), "1", format_number(1 - dn, 3),
                  "1 - d_n <= " + format_number(limits::final_damage, 3),
                  1 - dn <= limits::final_damage ? Verdict::pass : Verdict::fail});
  rows.push_back(info("opening at the end [mm]", end.separation[0]));
}

// The first monotonic loading: samples up to the first reversal of the slip.
size_t first_reversal(const std::vector<Sample>& curve) {
  int direction = 0;
  for (size_t i = 1; i < curve.size(); ++i) {
    const double d = curve[i].separation[1] - curve[i - 1].separation[1];
    const int sign = (d > 0) - (d < 0);
    if (sign == 0) continue;
    if (direction == 0) direction = sign;
    else if (sign != direction) return i;
  }
  return curve.size();
}

void shear_checks(SeriesKind kind, const std::vector<Sample>& curve, const Parameters& p,
                  const IndependentValues& iv, std::vector<CheckRow>& rows) {
  const size_t monotonic_end = first_reversal(curve);
  size_t at_peak = 0;
  for (size_t i = 0; i < monotonic_end; ++i)
    if (shear_norm(curve[i]) > shear_norm(curve[at_peak])) at_peak = i;
  const Sample& peak = curve[at_peak];
  const double sigma_n = peak.traction[0];
  if (!(sigma_n < 0)) {
    rows.push_back({"normal traction at the peak [MPa]", format_number(sigma_n), "< 0", "", "",
                    Verdict::fail});
    return;
  }
  rows.push_back(checked("peak |tau| vs closed form (MODEL 4) [MPa]", shear_norm(peak),
                         closed_form_peak_shear(p, sigma_n), limits::shear_peak));
  rows.push_back(info("slip at the peak [mm]", slip_norm(peak)));
  if (iv.peak > 0) rows.push_back(info("peak |tau| vs independent impl. [MPa]", shear_norm(peak),
                                       format_number(iv.peak), iv.peak));
  if (iv.peak_slip > 0) rows.push_back(info("peak slip vs independent impl. [mm]", slip_norm(peak),
                                            format_number(iv.peak_slip), iv.peak_slip));
  std::vector<double> slip, tau;
  for (size_t i = 0; i < monotonic_end; ++i) {
    slip.push_back(slip_norm(curve[i]));
    tau.push_back(shear_norm(curve[i]));
  }
  for (const auto& [s, t] : iv.tau_at)
    rows.push_back(info("|tau| at slip " + format_number(s, 3) + " mm vs independent [MPa]",
                        interpolate(slip, tau, s), format_number(t), t));

  const double residual = std::tan(p.phir * kDegree) * std::abs(sigma_n);
  if (kind == SeriesKind::monotonic_shear) {
    // Residual: approached from above (the friction and the cohesion wear
    // off), and closer at the end than half-way through the slip.
    const Sample& end = curve.back();
    const double r_end = (shear_norm(end) - residual) / residual;
    const double r_mid = (interpolate(slip, tau, 0.5 * slip_norm(end)) - residual) / residual;
    const bool ok = r_end >= -1e-9 && r_end <= limits::residual_shear && std::abs(r_end) < std::abs(r_mid);
    rows.push_back({"residual |tau| at the end vs tan(phir)|sigma_n| [MPa]", format_number(shear_norm(end)),
                    format_number(residual), percent(r_end),
                    "0 .. +" + percent(limits::residual_shear).substr(1) + ", decreasing",
                    ok ? Verdict::pass : Verdict::fail});
    double uplift_start = curve.front().separation[0];
    for (const Sample& s : curve)
      if (slip_norm(s) == 0) uplift_start = s.separation[0];
    const double uplift = end.separation[0] - uplift_start;
    std::string range;
    if (iv.uplift_max > 0) range = format_number(iv.uplift_min, 3) + " .. " + format_number(iv.uplift_max, 3);
    rows.push_back(info("normal uplift during shear (dilatancy) [mm]", uplift, range));
  } else {
    // Cyclic: the friction plateau of the last cycle against the residual.
    const size_t last_quarter = curve.size() - std::min(curve.size(), curve.size() / 8);
    double plateau = 0;
    for (size_t i = last_quarter; i < curve.size(); ++i) plateau = std::max(plateau, shear_norm(curve[i]));
    rows.push_back(info("largest |tau| in the last eighth of the test [MPa]", plateau,
                        "tan(phir)|sigma_n| = " + format_number(residual), residual));
  }
  // The fracture-energy budget: w_II reaches GIIC when the cohesion is gone.
  // What is dissipated also holds the friction work, and only the plastic
  // part of the inelastic slip (1/(1 + bs) of it) dissipates under
  // compression, so the dissipation is not compared with GIIC.
  const Sample& end = curve.back();
  rows.push_back(info("mode II work w_II (SDV8) vs GIIC [N/mm]", end.state[slot::work_II], format_number(p.GIIC),
                      p.GIIC));
  rows.push_back(info("softening used w_I/GIC + w_II/GIIC", softening_used(end, p), "<= 1"));
  rows.push_back(info("dissipated (sum spd) [N/mm]", end.dissipation));
}

}  // namespace

std::string format_number(double x, int digits) {
  if (!std::isfinite(x)) return "n/a";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

double closed_form_peak_shear(const Parameters& p, double sigma_n) {
  const double t = std::tan(p.phi0 * kDegree);
  const double cohesion_term = p.c0 * p.c0 / p.ft0;
  const double alpha = 0.5 * (cohesion_term / t - p.ft0 * t);
  const double beta = 0.5 * (cohesion_term / t + p.ft0 * t);
  const double b = beta - sigma_n * t;
  return std::sqrt(b * b - alpha * alpha);
}

std::vector<CheckRow> check_case(SeriesKind kind, const std::vector<Sample>& curve, const Parameters& p,
                                 const IndependentValues& independent, double traction_tolerance) {
  std::vector<CheckRow> rows;
  if (kind == SeriesKind::tension) tension_checks(curve, p, rows);
  else shear_checks(kind, curve, p, independent, rows);
  rows.push_back(held_traction(curve, traction_tolerance));
  rows.push_back(damage_check(curve));
  rows.push_back(energy_closure(
      curve, kind == SeriesKind::cyclic_shear ? limits::energy_closure_cyclic : limits::energy_closure));
  rows.push_back(bookkeeping_check(curve));
  rows.push_back(status_check(curve));
  return rows;
}

namespace {
const std::vector<std::string> kReferenceColumns = {"increment", "time",      "delta_n",       "delta_s1",
                                                    "delta_s2",  "sigma_n",   "tau_1",         "tau_2",
                                                    "SDV10_d_n", "SDV11_d_s", "dissipation"};
}

void write_reference(const std::string& path, const std::vector<Sample>& curve) {
  const std::vector<std::string>& all = run_columns();
  std::vector<int> index;
  for (const std::string& c : kReferenceColumns)
    index.push_back(static_cast<int>(std::find(all.begin(), all.end(), c) - all.begin()));
  const size_t stride = std::max<size_t>(1, curve.size() / 1000);
  std::vector<std::vector<double>> rows;
  for (size_t i = 0; i < curve.size(); ++i) {
    if (i % stride != 0 && i + 1 != curve.size()) continue;
    const std::vector<double> v = run_row_values(curve[i]);
    std::vector<double> row;
    for (int c : index) row.push_back(v[c]);
    rows.push_back(row);
  }
  write_csv(path, kReferenceColumns, rows);
}

CheckRow compare_with_reference(const std::vector<Sample>& curve, const CsvTable& reference) {
  CheckRow row{"reference curve: worst relative difference", "", "", "",
               "<= " + format_number(limits::regression, 2), Verdict::fail};
  const std::vector<double> increments = reference.values("increment");
  if (increments.empty() || increments.back() != double(curve.back().increment)) {
    row.value = "length differs";
    row.error = "reference ends at increment " +
                (increments.empty() ? std::string("-") : format_number(increments.back(), 10)) + ", run at " +
                std::to_string(curve.back().increment);
    return row;
  }
  // Each quantity is compared relative to the scale of its group: separations
  // and tractions to their largest magnitude in the reference, damage to 1,
  // dissipation to its largest value.
  struct Column {
    int reference, run, group;
  };
  const std::vector<std::vector<std::string>> groups = {
      {"delta_n", "delta_s1", "delta_s2"}, {"sigma_n", "tau_1", "tau_2"}, {"SDV10_d_n", "SDV11_d_s"}, {"dissipation"}};
  const std::vector<std::string>& all = run_columns();
  std::vector<Column> columns;
  std::vector<double> scale(groups.size(), 0.0);
  for (size_t g = 0; g < groups.size(); ++g)
    for (const std::string& name : groups[g]) {
      columns.push_back({reference.require(name), static_cast<int>(std::find(all.begin(), all.end(), name) - all.begin()),
                         static_cast<int>(g)});
      for (const auto& r : reference.rows) scale[g] = std::max(scale[g], std::abs(r[columns.back().reference]));
    }
  scale[2] = 1.0;  // damage
  for (double& s : scale)
    if (s == 0) s = 1;
  double worst = 0;
  std::string where = "-";
  for (size_t r = 0; r < reference.rows.size(); ++r) {
    const long inc = static_cast<long>(increments[r]);
    if (inc < 0 || inc >= static_cast<long>(curve.size())) {
      row.value = "bad increment";
      row.error = "reference row " + std::to_string(r + 2) + " names increment " + std::to_string(inc);
      return row;
    }
    const std::vector<double> fresh = run_row_values(curve[inc]);
    for (const Column& c : columns) {
      const double diff = std::abs(fresh[c.run] - reference.rows[r][c.reference]) / scale[c.group];
      if (diff > worst) {
        worst = diff;
        where = all[c.run] + " at increment " + std::to_string(inc);
      }
    }
  }
  row.value = format_number(worst, 3);
  row.expected = std::to_string(reference.rows.size()) + " rows";
  row.error = where;
  row.verdict = worst <= limits::regression ? Verdict::pass : Verdict::fail;
  return row;
}

CheckRow compare_with_experiment(SeriesKind kind, const std::vector<Sample>& curve, const CsvTable& experiment) {
  const bool tension = kind == SeriesKind::tension;
  const std::vector<double> ex = experiment.values(tension ? "opening_mm" : "slip_mm");
  const std::vector<double> ey = experiment.values(tension ? "sigma_MPa" : "tau_MPa");
  // Path length along the abscissa for both curves.
  std::vector<double> sim_path, sim_y;
  double path = 0;
  for (size_t i = 0; i < curve.size(); ++i) {
    const double x = tension ? curve[i].separation[0] : curve[i].separation[1];
    if (i > 0) path += std::abs(x - (tension ? curve[i - 1].separation[0] : curve[i - 1].separation[1]));
    sim_path.push_back(path);
    sim_y.push_back(tension ? curve[i].traction[0] : curve[i].traction[1]);
  }
  double sum = 0, peak = 0, exp_path = 0;
  long used = 0, outside = 0;
  for (size_t i = 0; i < ex.size(); ++i) {
    if (i > 0) exp_path += std::abs(ex[i] - ex[i - 1]);
    double y = NAN;
    if (exp_path <= sim_path.back()) {
      // The last sample at or before exp_path and the next one along.
      const size_t hi = std::upper_bound(sim_path.begin(), sim_path.end(), exp_path) - sim_path.begin();
      if (hi >= sim_path.size()) y = sim_y.back();
      else {
        const size_t lo = hi - 1;
        const double t = (exp_path - sim_path[lo]) / (sim_path[hi] - sim_path[lo]);
        y = sim_y[lo] + t * (sim_y[hi] - sim_y[lo]);
      }
    }
    if (!std::isfinite(y)) {
      ++outside;
      continue;
    }
    sum += (y - ey[i]) * (y - ey[i]);
    peak = std::max(peak, std::abs(ey[i]));
    ++used;
  }
  CheckRow row{"experimental curve: RMS difference [MPa]", "", "", "", "", Verdict::info};
  if (used == 0) {
    row.value = "n/a";
    row.error = "no experimental point within the simulated range";
    return row;
  }
  const double rms = std::sqrt(sum / double(used));
  row.value = format_number(rms, 4);
  row.expected = std::to_string(used) + " points";
  row.error = peak > 0 ? percent(rms / peak).substr(1) + " of exp. peak" : "";
  if (outside) row.error += ", " + std::to_string(outside) + " beyond the run";
  return row;
}

}  // namespace mortar::harness
