#include "bench/bench.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>

#include "bench/paths.hpp"
#include "bench/plots.hpp"
#include "input/input_error.hpp"
#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"
#include "output/output_paths.hpp"
#include "output/plots.hpp"
#include "validation/checks.hpp"

namespace fs = std::filesystem;

namespace mortar::harness {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Controls the reference runs need beyond STOL: substeps small and many
// enough that STOL, not the substep floor, decides the accuracy.
constexpr double kReferenceMinSubstep = 1e-9;  // fraction of a call's increment
constexpr double kReferenceMaxSubsteps = 1e8;
constexpr double kReferenceBudgetSeconds = 3600;  // per reference run

// Timing: sweeps of the whole path by a block of at most kBlockPoints points
// (Abaqus/Explicit's blocks are of this order, nBlock <= 136 by default),
// repeated to take about `seconds` of wall time per configuration, judged
// from the one-point run, within [min_repeats, max_repeats].
struct TimingPolicy {
  double seconds;
  int min_repeats, max_repeats;
};
constexpr int kBlockPoints = 128;

std::vector<double> increment_sizes(bool quick) {
  if (quick) return {1e-4, 1e-3, 1e-2};
  return {1e-5, 1e-4, 1e-3, 1e-2};
}

std::vector<BenchScheme> schemes(bool quick) {
  std::vector<BenchScheme> s;
  s.push_back({"forward-euler", {Scheme::forward_euler}});
  const std::vector<double> stols =
      quick ? std::vector<double>{1e-2, 1e-4, 1e-5, 1e-6, 1e-8}
            : std::vector<double>{1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
  for (double stol : stols) s.push_back({"modified-euler", {Scheme::modified_euler, stol}});
  s.push_back({"implicit", {Scheme::implicit}});
  return s;
}

}  // namespace

ReferenceSettings reference_settings(bool quick) {
  ReferenceSettings r;
  if (quick) {
    r.sub_increment = 1e-4;
    r.check_stol = 1e-11;
  }
  return r;
}

namespace {

SchemeControls reference_controls(double stol, double ftol) {
  SchemeControls c{Scheme::modified_euler, stol};
  c.ftol = ftol;
  c.min_substep = kReferenceMinSubstep;
  c.max_substeps = kReferenceMaxSubsteps;
  return c;
}

int reference_split(double h, double sub_increment) {
  return std::max(1, static_cast<int>(std::ceil(h / sub_increment - 1e-9)));
}

// max_i |a_i - b_i| / max_i |b_i| over the recorded points (Euclidean norms).
double relative_traction_error(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double diff = 0, scale = 0;
  for (size_t i = 0; i < b.size(); ++i) {
    diff = std::max(diff, (a[i] - b[i]).norm());
    scale = std::max(scale, b[i].norm());
  }
  return diff / scale;
}

double relative_energy_error(double d, double d_ref) { return std::abs(d - d_ref) / std::abs(d_ref); }

std::string describe_failure(const Trajectory& t) {
  std::ostringstream s;
  if (t.budget_exceeded) {
    s << "time budget spent after " << t.completed << " increments (" << format_number(t.seconds, 3) << " s)";
  } else if (t.non_finite) {
    s << "non-finite output at increment " << t.failure_increment;
  } else {
    s << "SDV 21 = " << t.failure << " ("
      << (t.failure > 0 ? failure_name(static_cast<Failure>(t.failure)) : "adapter rejected the call")
      << ") at increment " << t.failure_increment;
  }
  return s.str();
}

Outcome classify(const Trajectory& t, long increments, double error) {
  if (t.non_finite) return Outcome::non_finite;
  if (!t.complete(increments)) return Outcome::failed;
  if (t.drifted_increments > 0) return Outcome::drifted;
  return error < kAccurateError ? Outcome::accurate : Outcome::inaccurate;
}

class Study {
 public:
  Study(const BenchOptions& o, std::ostream& err) : o_(o), err_(err) {
    policy_ = o.quick ? TimingPolicy{0.02, 3, 15} : TimingPolicy{0.3, 5, 51};
  }

  BenchResult run() {
    const auto t0 = std::chrono::steady_clock::now();
    BenchResult r;
    r.reference = reference_settings(o_.quick);
    r.increment_sizes = increment_sizes(o_.quick);
    r.schemes = schemes(o_.quick);
    for (const BenchPath& path : selected_paths()) {
      r.paths.push_back(path.id);
      r.path_titles.push_back(path.title);
      run_path(path, r);
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
  }

 private:
  std::vector<BenchPath> selected_paths() const {
    return bench_paths(o_.data_dir, o_.quick && o_.paths.empty(), o_.paths);
  }

  void run_path(const BenchPath& path, BenchResult& r) {
    const auto t0 = std::chrono::steady_clock::now();
    for (double h : r.increment_sizes) {
      const std::vector<Vec3> history = discretise(path, h);
      const Trajectory ref = reference(path, h, history, r);
      for (const BenchScheme& s : r.schemes) r.rows.push_back(run_scheme(path, s, h, history, ref));
    }
    if (!o_.quiet)
      err_ << "bench: " << path.id << " (" << format_number(path_length(path), 4) << " mm of path): "
           << r.schemes.size() * r.increment_sizes.size() << " runs and their references in "
           << format_number(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 3)
           << " s\n";
  }

  // The reference along `history`, and its check: the same with STOL
  // tightened and every call split in two. A reference that does not
  // complete is an error of the study, not an outcome.
  Trajectory reference(const BenchPath& path, double h, const std::vector<Vec3>& history, BenchResult& r) {
    const auto t0 = std::chrono::steady_clock::now();
    const ReferenceSettings& rs = r.reference;
    const int split = reference_split(h, rs.sub_increment);
    const long n = static_cast<long>(history.size()) - 1;
    // Not --budget: a reference that cannot finish is a failure of the study.
    const double budget = kReferenceBudgetSeconds;
    Trajectory ref = drive_point(path.parameters, path.cap, path.directions, reference_controls(rs.stol, rs.ftol),
                                 history, split, budget, false);
    const Trajectory check =
        drive_point(path.parameters, path.cap, path.directions, reference_controls(rs.check_stol, rs.check_ftol),
                    history, rs.check_split_factor * split, budget, false);
    for (const Trajectory* t : {static_cast<const Trajectory*>(&ref), &check})
      if (!t->complete(n))
        throw std::runtime_error("bench: the reference of path " + path.id + " at h = " + format_number(h, 3) +
                                 " mm did not complete: " + describe_failure(*t));
    ReferenceRecord rec;
    rec.path = path.id;
    rec.h = h;
    rec.increments = n;
    rec.split = split;
    rec.check_split = rs.check_split_factor * split;
    rec.difference_traction = relative_traction_error(ref.traction, check.traction);
    rec.difference_energy = relative_energy_error(ref.dissipation, check.dissipation);
    rec.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.references.push_back(rec);
    return ref;
  }

  BenchRow run_scheme(const BenchPath& path, const BenchScheme& s, double h, const std::vector<Vec3>& history,
                      const Trajectory& ref) {
    BenchRow row;
    row.path = path.id;
    row.scheme = s;
    row.h = h;
    row.increments = static_cast<long>(history.size()) - 1;
    const TimingWindows windows = timing_windows(row.increments, kBlockPoints);
    const Trajectory t = drive_point(path.parameters, path.cap, path.directions, s.controls, history, 1,
                                     o_.budget_seconds, true, windows.start);
    row.seconds = t.seconds;
    row.drift = t.drift;
    row.drifted_increments = t.drifted_increments;
    const bool complete = t.complete(row.increments);
    row.error_traction = complete ? relative_traction_error(t.traction, ref.traction) : kNaN;
    row.error_energy = complete ? relative_energy_error(t.dissipation, ref.dissipation) : kNaN;
    row.outcome = classify(t, row.increments, row.error_traction);
    if (!complete) row.why = describe_failure(t);
    if (complete) row.timing = time_it(path, s, history, windows, t);
    return row;
  }

  // Repeats so that the timing takes about policy_.seconds, from the
  // one-point run's time (which also paid for the surface check, so it
  // overestimates a sweep).
  Timing time_it(const BenchPath& path, const BenchScheme& s, const std::vector<Vec3>& history,
                 const TimingWindows& windows, const Trajectory& t) {
    const double sweep = std::max(t.seconds, 1e-7);
    // Long sweeps vary little between repeats; three give the median and spread.
    const int min_repeats = sweep > 0.1 ? std::min(3, policy_.min_repeats) : policy_.min_repeats;
    const int repeats = std::clamp(static_cast<int>(policy_.seconds / sweep), min_repeats, policy_.max_repeats);
    return time_history(path.parameters, path.cap, path.directions, s.controls, history, windows, t.snapshots,
                        repeats);
  }

  const BenchOptions& o_;
  std::ostream& err_;
  TimingPolicy policy_;
};

std::string plain_number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

void check_options(const BenchOptions& o) {
  if (!(std::isfinite(o.budget_seconds) && o.budget_seconds > 0))
    throw InputError("--budget " + plain_number(o.budget_seconds) +
                     " violates the rule: a finite number of seconds > 0 (wall time allowed per run)");
  std::error_code ec;
  if (!fs::is_directory(o.data_dir, ec))
    throw InputError("--data " + o.data_dir + ": not a directory (the calibration_data/ folder is expected)");
  prepare_output_folder(o.out_dir, "--out");
}

}  // namespace

const char* outcome_name(Outcome o) {
  switch (o) {
    case Outcome::accurate: return "accurate";
    case Outcome::inaccurate: return "inaccurate";
    case Outcome::drifted: return "drifted";
    case Outcome::failed: return "failed";
    case Outcome::non_finite: return "non-finite";
  }
  return "?";
}

std::string BenchScheme::label() const {
  if (controls.scheme != Scheme::modified_euler) return name;
  return name + " STOL=" + format_number(controls.stol, 2);
}

BenchResult run_bench(const BenchOptions& options, std::ostream& err) {
  check_options(options);
  return Study(options, err).run();
}

const BenchRow* cheapest_reaching(const BenchResult& r, const std::string& path, const std::string& scheme,
                                  double target) {
  const BenchRow* best = nullptr;
  for (const BenchRow& row : r.rows) {
    if (row.path != path || row.scheme.name != scheme || row.timing.repeats == 0) continue;
    if (!(row.error_traction <= target)) continue;
    if (!best || row.path_microseconds() < best->path_microseconds()) best = &row;
  }
  return best;
}

}  // namespace mortar::harness
