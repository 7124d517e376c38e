// `masonry-joint bench`: the work-precision study and the stability map of
// the three stress-integration schemes.
//
// Every scheme (forward Euler; modified Euler at STOL 1e-1 ... 1e-8; the
// implicit return mapping) is driven displacement-controlled along the
// separation history of every bench path (bench/paths.hpp), discretised at
// every increment size h, through vuinteraction_. Against a reference (modified
// Euler at a very tight STOL and FTOL, each increment split into short calls,
// along the same discretised path) it records the
// relative traction error, the relative error in dissipated energy, the cost
// per point-update and the outcome (accurate, inaccurate, drifted off the
// yield surface, failed, non-finite). Files: bench.csv, reference.csv,
// stability.md, summary.md, work_precision.{gp,png,svg} and
// stability_map.{gp,png,svg} in the output folder (harness/README.md).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "bench/drive.hpp"

namespace mortar::harness {

struct BenchOptions {
  std::string out_dir = "out/bench";
  std::string data_dir;             // calibration_data/
  bool quick = false;               // fewer increment sizes, tolerances and paths (CI)
  std::vector<std::string> paths;   // only these paths (ids); all when empty
  double budget_seconds = 60;       // wall time allowed for one run of one point along one path
  bool plots = true;
  bool quiet = false;
  bool wide = false;  // the summary on stdout as summary.md has it, not fitted to 100 columns
};

enum class Outcome { accurate, inaccurate, drifted, failed, non_finite };
const char* outcome_name(Outcome o);

// A traction error below this is "accurate" on the stability map.
inline constexpr double kAccurateError = 1e-3;
// The error level at which the summary reports each scheme's cost.
inline constexpr double kTargetError = 1e-4;

// The reference: modified Euler at a very tight STOL and FTOL, every
// increment of the path split into calls of at most `sub_increment`; and the
// check it is measured against: STOL tighter still, every call split again.
// FTOL also sets how closely the elastic-plastic intersection and the drift
// correction meet the surface; at the default 1e-8 it, not STOL, would limit
// the reference (measured: the softened_reopened path). Below about 1e-12 it
// is under the round-off of F itself, and on a nearly separated open joint a
// start that round-off puts inside the band becomes an elastic gap of
// |F|/kn(1 - dn) (measured: 3.6e-7 mm of plastic separation lost over one
// opening at FTOL 1e-13), so the check tightens STOL and the cuts only.
// The cuts by ten: the law's answer must not depend on how a path is cut
// into calls (model.md 6 and 7.1; test_splitting.cpp hands an increment over
// as 1, 20 or 100 calls), and a check that only halves them would hide a
// dependence that grows with the number of cuts.
struct ReferenceSettings {
  double stol = 1e-10, ftol = 1e-12;
  double check_stol = 1e-12, check_ftol = 1e-12;
  double sub_increment = 1e-5;  // mm
  int check_split_factor = 10;
};
// Full study: as above. Quick: calls of up to 1e-4 mm and the check at
// STOL 1e-11 (still split by ten), to keep CI short.
ReferenceSettings reference_settings(bool quick);
// The study needs its reference to move by less than this when tightened
// (a tenth of the "accurate" limit); otherwise the bench exits 1.
inline constexpr double kReferenceRequired = 1e-4;

struct BenchScheme {
  std::string name;  // forward-euler, modified-euler, implicit
  SchemeControls controls;
  std::string label() const;  // "modified-euler STOL=1e-05"
};

struct ReferenceRecord {
  std::string path;
  double h = 0;
  long increments = 0;
  int split = 0, check_split = 0;
  double difference_traction = 0, difference_energy = 0;  // reference vs tightened reference
  double seconds = 0;
};

struct BenchRow {
  std::string path;
  BenchScheme scheme;
  double h = 0;
  long increments = 0;
  double error_traction = 0, error_energy = 0;  // NaN when the run did not complete
  Outcome outcome = Outcome::accurate;
  std::string why;        // for failed and non-finite rows: what the routine reported
  double drift = 0;       // largest F / yield tolerance at an increment end
  long drifted_increments = 0;
  Timing timing;          // zero when not timed (runs that did not complete)
  double seconds = 0;     // the recorded one-point run
  // Cost of the whole path for one point [microseconds].
  double path_microseconds() const { return timing.median_ns * double(increments) * 1e-3; }
};

struct BenchResult {
  ReferenceSettings reference;
  std::vector<double> increment_sizes;
  std::vector<BenchScheme> schemes;
  std::vector<std::string> paths, path_titles;
  std::vector<ReferenceRecord> references;
  std::vector<BenchRow> rows;
  double seconds = 0;
};

// The whole study (no files). InputError for bad options or data.
BenchResult run_bench(const BenchOptions& options, std::ostream& err);

// The scheme's cheapest run (least cost for the whole path) on `path` whose
// traction error is at most `target`, or nullptr.
const BenchRow* cheapest_reaching(const BenchResult& r, const std::string& path, const std::string& scheme,
                                  double target);

}  // namespace mortar::harness
