#include "bench/report.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "input/input_error.hpp"
#include "output/output_paths.hpp"
#include "validation/checks.hpp"

namespace mortar::harness {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string number(double x) { return std::isfinite(x) ? format_number(x, 6) : "nan"; }

// Free text in a CSV field: no commas or quotes, so that the field splits plainly.
std::string csv_text(std::string s) {
  std::replace(s.begin(), s.end(), ',', ';');
  std::replace(s.begin(), s.end(), '"', '\'');
  return s;
}

std::string reference_line(const BenchResult& r) {
  const ReferenceSpread s = reference_spread(r);
  std::ostringstream o;
  const ReferenceSettings& rs = r.reference;
  o << "reference: modified Euler at STOL " << format_number(rs.stol, 2) << ", FTOL " << format_number(rs.ftol, 2)
    << ", calls of at most " << format_number(rs.sub_increment, 2) << " mm; tightened to STOL "
    << format_number(rs.check_stol, 2) << ", FTOL " << format_number(rs.check_ftol, 2) << " with every call split in "
    << rs.check_split_factor << ", it moves by at most " << format_number(s.traction, 2)
    << " (traction, relative) and " << format_number(s.energy, 2)
    << " (dissipated energy, relative) over every path and increment size";
  return o.str();
}

std::string h_text(double h) { return format_number(h, 2) + " mm"; }

// "cost to reach 1e-4" line of one scheme on one path.
std::string target_line(const BenchResult& r, const std::string& path, const std::string& scheme) {
  std::ostringstream o;
  o << scheme << ": ";
  const BenchRow* best = cheapest_reaching(r, path, scheme, kTargetError);
  if (!best) {
    o << "cannot (no increment size or tolerance of the study reaches it)";
    return o.str();
  }
  o << format_number(best->timing.median_ns, 3) << " ns per point-update (" << format_number(best->timing.min_ns, 3)
    << "-" << format_number(best->timing.max_ns, 3) << ") at h = " << h_text(best->h);
  if (best->scheme.controls.stol > 0) o << ", STOL " << format_number(best->scheme.controls.stol, 2);
  o << ", error " << format_number(best->error_traction, 2) << "; " << format_number(best->path_microseconds(), 3)
    << " us per point for the whole path (" << best->increments << " increments)";
  return o.str();
}

// Per scheme and increment size: accurate paths of all, the worst error.
std::string summary_table(const BenchResult& r) {
  std::ostringstream t;
  t << "| scheme |";
  for (double h : r.increment_sizes) t << " h = " << h_text(h) << " |";
  t << "\n|---|";
  for (size_t i = 0; i < r.increment_sizes.size(); ++i) t << "---|";
  t << "\n";
  for (const BenchScheme& s : r.schemes) {
    t << "| " << s.label() << " |";
    for (double h : r.increment_sizes) {
      int accurate = 0, total = 0;
      double worst = -1, ns = 0;
      std::map<std::string, int> bad;
      for (const BenchRow& row : r.rows) {
        if (row.scheme.label() != s.label() || row.h != h) continue;
        ++total;
        if (row.outcome == Outcome::accurate) ++accurate;
        else ++bad[outcome_name(row.outcome)];
        if (std::isfinite(row.error_traction)) worst = std::max(worst, row.error_traction);
        if (row.path == "vdp_sn0.5") ns = row.timing.median_ns;
      }
      t << " " << accurate << "/" << total << " accurate";
      for (const auto& [name, count] : bad) t << ", " << count << " " << name;
      t << "; worst error " << (worst >= 0 ? format_number(worst, 2) : "–") << "; " << (ns > 0 ? format_number(ns, 3) : "–")
        << " ns |";
    }
    t << "\n";
  }
  return t.str();
}

// Per scheme and increment size on one path: the cheapest run reaching the
// target error, or the smallest error reached.
std::string target_table(const BenchResult& r, const std::string& path) {
  std::ostringstream t;
  t << "Cheapest run reaching a relative traction error of " << format_number(kTargetError, 2) << " on " << path
    << " (ns per point-update, median; in brackets the tolerance, and the cost of the whole path per point):\n\n"
    << "| scheme |";
  for (double h : r.increment_sizes) t << " h = " << h_text(h) << " |";
  t << "\n|---|";
  for (size_t i = 0; i < r.increment_sizes.size(); ++i) t << "---|";
  t << "\n";
  for (const char* scheme : {"forward-euler", "modified-euler", "implicit"}) {
    t << "| " << scheme << " |";
    for (double h : r.increment_sizes) {
      const BenchRow* best = nullptr;
      double smallest = kNaN;
      for (const BenchRow& row : r.rows) {
        if (row.path != path || row.scheme.name != scheme || row.h != h || row.timing.repeats == 0) continue;
        if (!(smallest <= row.error_traction)) smallest = row.error_traction;
        if (row.error_traction <= kTargetError && (!best || row.timing.median_ns < best->timing.median_ns))
          best = &row;
      }
      if (best) {
        t << " " << format_number(best->timing.median_ns, 3) << " ns (";
        if (best->scheme.controls.stol > 0) t << "STOL " << format_number(best->scheme.controls.stol, 2) << "; ";
        t << format_number(best->path_microseconds(), 3) << " us) |";
      } else {
        t << " not reached (best " << (std::isfinite(smallest) ? format_number(smallest, 2) : "none") << ") |";
      }
    }
    t << "\n";
  }
  return t.str();
}

}  // namespace

// Free text in a CSV field: no commas or quotes, so that the field splits plainly.
void write_rows_csv(const std::string& file, const BenchResult& r) {
  std::ofstream f(file);
  if (!f) throw InputError(cannot_write(file));
  f << "path,scheme,stol,increment_mm,increments,error_traction,error_energy,ns_per_update,ns_min,ns_max,"
       "points,calls,repeats,reproduced,path_us_per_point,outcome,drift_ratio,drifted_increments,seconds_one_point,why\n";
  for (const BenchRow& row : r.rows) {
    const bool timed = row.timing.repeats > 0;
    f << row.path << "," << row.scheme.name << "," << number(row.scheme.controls.stol) << "," << number(row.h)
      << "," << row.increments << "," << number(row.error_traction) << "," << number(row.error_energy) << ","
      << (timed ? number(row.timing.median_ns) : "nan") << "," << (timed ? number(row.timing.min_ns) : "nan")
      << "," << (timed ? number(row.timing.max_ns) : "nan") << "," << row.timing.points << ","
      << row.timing.calls << "," << row.timing.repeats << "," << (row.timing.reproduced ? 1 : 0) << "," << (timed ? number(row.path_microseconds()) : "nan") << ","
      << outcome_name(row.outcome) << "," << number(row.drift) << "," << row.drifted_increments << ","
      << number(row.seconds) << ",\"" << csv_text(row.why) << "\"\n";
  }
  if (!f) throw InputError(file + ": write failed");
}

void write_references_csv(const std::string& file, const BenchResult& r) {
  std::ofstream f(file);
  if (!f) throw InputError(cannot_write(file));
  f << "path,increment_mm,increments,stol,ftol,split,check_stol,check_ftol,check_split,difference_traction,"
       "difference_energy,seconds\n";
  const ReferenceSettings& rs = r.reference;
  for (const ReferenceRecord& x : r.references)
    f << x.path << "," << number(x.h) << "," << x.increments << "," << number(rs.stol) << "," << number(rs.ftol) << ","
      << x.split << "," << number(rs.check_stol) << "," << number(rs.check_ftol) << "," << x.check_split << "," << number(x.difference_traction) << ","
      << number(x.difference_energy) << "," << number(x.seconds) << "\n";
  if (!f) throw InputError(file + ": write failed");
}

ReferenceSpread reference_spread(const BenchResult& r) {
  ReferenceSpread s;
  for (const ReferenceRecord& x : r.references) {
    s.traction = std::max(s.traction, x.difference_traction);
    s.energy = std::max(s.energy, x.difference_energy);
  }
  return s;
}

std::string stability_list(const BenchResult& r) {
  std::ostringstream o;
  o << "# Stability map: where each scheme fails and why\n\n"
    << "Outcome of every scheme x increment size x path (`masonry-joint bench"
    << (r.increment_sizes.size() < 4 ? " --quick" : "") << "`). accurate: relative traction error < "
    << format_number(kAccurateError, 2)
    << "; inaccurate: it completed, off by more; drifted: at some increment end F exceeds the yield tolerance "
       "(FTOL x max(|sigma|, ft0)); failed: the routine reported a failure in SDV 21, or the run exceeded its "
       "time budget; non-finite: NaN or infinity returned.\n\n";
  for (const BenchScheme& s : r.schemes) {
    o << "## " << s.label() << "\n\n";
    std::map<std::string, int> count;
    for (const BenchRow& row : r.rows)
      if (row.scheme.label() == s.label()) ++count[outcome_name(row.outcome)];
    for (const auto& [name, n] : count) o << (name == count.begin()->first ? "" : ", ") << n << " " << name;
    o << " (of " << r.paths.size() * r.increment_sizes.size() << ")\n\n";
    int listed = 0;
    for (const BenchRow& row : r.rows) {
      if (row.scheme.label() != s.label() || row.outcome == Outcome::accurate) continue;
      ++listed;
      o << "- " << row.path << ", h = " << h_text(row.h) << ": **" << outcome_name(row.outcome) << "**";
      if (row.outcome == Outcome::inaccurate) o << ", traction error " << format_number(row.error_traction, 2);
      if (row.outcome == Outcome::drifted)
        o << ", F up to " << format_number(row.drift, 3) << " x the yield tolerance at " << row.drifted_increments
          << " of " << row.increments << " increment ends (traction error " << format_number(row.error_traction, 2)
          << ")";
      if (!row.why.empty()) o << ": " << row.why;
      o << "\n";
    }
    if (listed == 0) o << "- accurate on every path at every increment size\n";
    o << "\n";
  }
  return o.str();
}

void write_text(const std::string& file, const std::string& text) {
  std::ofstream f(file);
  if (!f) throw InputError(cannot_write(file));
  f << text;
  if (!f) throw InputError(file + ": write failed");
}

std::string bench_summary(const BenchResult& r) {
  std::ostringstream summary;
  summary << "bench: " << r.rows.size() << " runs (" << r.schemes.size() << " schemes x "
          << r.increment_sizes.size() << " increment sizes x " << r.paths.size() << " paths) in "
          << format_number(r.seconds, 3) << " s\n"
          << "bench: " << reference_line(r) << "\n";
  const bool has_vdp = std::find(r.paths.begin(), r.paths.end(), "vdp_sn0.5") != r.paths.end();
  if (has_vdp)
    for (const char* s : {"forward-euler", "modified-euler", "implicit"})
      summary << "bench: relative traction error " << format_number(kTargetError, 2) << " on vdp_sn0.5: "
              << target_line(r, "vdp_sn0.5", s) << "\n";
  summary << "\n" << summary_table(r);
  if (has_vdp) summary << "\n" << target_table(r, "vdp_sn0.5");
  return summary.str();
}

}  // namespace mortar::harness
