// `masonry-joint bench --quick`: the files the CTest fixture "cli: bench
// --quick" wrote (MJ_BENCH_QUICK_DIR) are complete and well formed, and what
// they measured has the properties the study relies on: the reference is
// converged, modified Euler's error follows STOL, the first-order schemes
// are first order, the accurate outcomes are where they must be, and the
// timed block reproduced the recorded run. No timing is asserted (tests
// assert correctness; the bench measures cost). Plus the path
// discretisation, the timing windows and the throughput bench's paired
// ratios as library functions.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench.hpp"
#include "bench/drive.hpp"
#include "bench/paths.hpp"
#include "bench/throughput.hpp"
#include "validation/checks.hpp"

using namespace mortar;
using namespace mortar::harness;

namespace {

const std::string kDir = MJ_BENCH_QUICK_DIR;

std::string file_text(const std::string& name) {
  std::ifstream in(kDir + "/" + name, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A CSV of the bench: header and rows of text fields (no field holds a comma).
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  int column(const std::string& name) const {
    for (size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return static_cast<int>(i);
    FAIL("no column " << name);
    return -1;
  }
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::string f;
  std::istringstream s(line);
  while (std::getline(s, f, ',')) fields.push_back(f);
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

Table read_table(const std::string& name) {
  std::ifstream in(kDir + "/" + name);
  REQUIRE(in);
  Table t;
  std::string line;
  std::getline(in, line);
  t.header = split(line);
  while (std::getline(in, line)) t.rows.push_back(split(line));
  return t;
}

double number(const std::string& s) { return s == "nan" ? NAN : std::stod(s); }

// One row of bench.csv by its columns.
struct Run {
  std::string path, scheme, outcome;
  double stol = 0, h = 0, error = 0, ns = 0, ns_min = 0, ns_max = 0;
  long drifted = 0;
  int reproduced = 0, repeats = 0;
};

std::vector<Run> runs() {
  const Table t = read_table("bench.csv");
  std::vector<Run> out;
  for (const auto& r : t.rows) {
    REQUIRE(r.size() == t.header.size());
    Run x;
    x.path = r[t.column("path")];
    x.scheme = r[t.column("scheme")];
    x.outcome = r[t.column("outcome")];
    x.stol = number(r[t.column("stol")]);
    x.h = number(r[t.column("increment_mm")]);
    x.error = number(r[t.column("error_traction")]);
    x.ns = number(r[t.column("ns_per_update")]);
    x.ns_min = number(r[t.column("ns_min")]);
    x.ns_max = number(r[t.column("ns_max")]);
    x.drifted = std::stol(r[t.column("drifted_increments")]);
    x.reproduced = std::stoi(r[t.column("reproduced")]);
    x.repeats = std::stoi(r[t.column("repeats")]);
    out.push_back(x);
  }
  return out;
}

const Run& find(const std::vector<Run>& all, const std::string& path, const std::string& scheme, double stol,
                double h) {
  for (const Run& r : all)
    if (r.path == path && r.scheme == scheme && r.stol == stol && r.h == h) return r;
  FAIL("no run " << path << " " << scheme << " " << stol << " " << h);
  return all.front();
}

// The smooth calibration paths the fixture ran (all five, or only
// vdp_sn0.5 in sanitizer builds).
std::vector<std::string> smooth_paths() {
  std::vector<std::string> present;
  const std::string csv = file_text("bench.csv");
  for (const char* p : {"vdp_sn0.1", "vdp_sn0.5", "vdp_sn1.0", "almeida_M15", "almeida_M34"})
    if (csv.find(std::string("\n") + p + ",") != std::string::npos) present.push_back(p);
  return present;
}
const std::vector<double> kQuickH = {1e-4, 1e-3, 1e-2};

}  // namespace

TEST_CASE("the quick run wrote every file, and each is well formed", "[bench]") {
  for (const char* f : {"bench.csv", "reference.csv", "stability.md", "summary.md", "work_precision.gp",
                        "work_precision_all.gp", "stability_map.gp"})
    CHECK(std::filesystem::exists(kDir + "/" + f));
  for (const char* png : {"work_precision.png", "work_precision_all.png", "stability_map.png"})
    CHECK(file_text(png).substr(0, 8) == "\x89PNG\r\n\x1a\n");
  for (const char* svg : {"work_precision.svg", "work_precision_all.svg", "stability_map.svg"})
    CHECK(file_text(svg).find("<svg") != std::string::npos);

  const std::vector<Run> all = runs();
  std::set<std::string> paths, labels;
  for (const Run& r : all) {
    paths.insert(r.path);
    labels.insert(r.scheme + std::to_string(r.stol));
  }
  // 12 paths (no Atkinson in quick; 1 in sanitizer builds), 7 schemes (FE,
  // 5 STOLs, implicit), 3 h.
  const size_t n_paths = MJ_BENCH_QUICK_PATH_COUNT;
  CHECK(paths.size() == n_paths);
  CHECK(paths.count("vdp_sn0.5") == 1);
  CHECK(labels.size() == 7);
  CHECK(all.size() == n_paths * 7 * 3);
  const std::set<std::string> outcomes = {"accurate", "inaccurate", "drifted", "failed", "non-finite"};
  for (const Run& r : all) {
    CAPTURE(r.path, r.scheme, r.stol, r.h, r.outcome, r.error);
    REQUIRE(outcomes.count(r.outcome) == 1);
    const bool completed = r.outcome != "failed" && r.outcome != "non-finite";
    CHECK(std::isfinite(r.error) == completed);
    if (!completed) continue;
    CHECK(r.error >= 0);
    // Outcomes follow from the numbers as the map's legend says.
    CHECK((r.outcome == "accurate") == (r.error < kAccurateError && r.drifted == 0));
    CHECK((r.outcome == "drifted") == (r.drifted > 0));
    // Timed, with a spread that brackets the median.
    CHECK(r.repeats >= 3);
    CHECK(r.ns > 0);
    CHECK(r.ns_min <= r.ns);
    CHECK(r.ns <= r.ns_max);
  }
  const std::string stability = file_text("stability.md");
  for (const char* s : {"## forward-euler", "## modified-euler STOL=1e-05", "## implicit"})
    CHECK(stability.find(s) != std::string::npos);
}

TEST_CASE("the timed block of staggered points reproduced the recorded run bit for bit", "[bench]") {
  // Point k of the timed block starts window k from the state the one-point
  // run recorded there; after a sweep it must hold that run's state at the
  // end of its window: the blocking and the neighbours do not matter.
  for (const Run& r : runs()) {
    if (r.repeats == 0) continue;
    CAPTURE(r.path, r.scheme, r.stol, r.h);
    CHECK(r.reproduced == 1);
  }
}

TEST_CASE("the reference is converged to the level the study states", "[bench]") {
  const Table t = read_table("reference.csv");
  REQUIRE(t.rows.size() == size_t(MJ_BENCH_QUICK_PATH_COUNT) * 3);
  double worst = 0;
  for (const auto& r : t.rows) {
    const std::string path = r[t.column("path")];
    const double d = number(r[t.column("difference_traction")]);
    const double e = number(r[t.column("difference_energy")]);
    CAPTURE(path, r[t.column("increment_mm")], d, e);
    worst = std::max(worst, d);
    // Tightened, the reference moves far less than the smallest error the
    // map distinguishes...
    CHECK(d < kReferenceRequired);
    CHECK(e < kReferenceRequired);
    // ...and on the smooth calibration paths by less than 1e-10.
    const std::vector<std::string> smooth = smooth_paths();
    if (std::find(smooth.begin(), smooth.end(), path) != smooth.end()) {
      CHECK(d < 1e-10);
      CHECK(e < 1e-9);
    }
  }
  // The summary states the measured number.
  CHECK(file_text("summary.md").find("it moves by at most " + format_number(worst, 2) + " (traction") !=
        std::string::npos);
}

TEST_CASE("modified Euler's error follows STOL on the smooth paths", "[bench]") {
  const std::vector<Run> all = runs();
  for (const std::string& path : smooth_paths())
    for (double h : kQuickH) {
      double previous = INFINITY;
      for (double stol : {1e-2, 1e-4, 1e-5, 1e-6, 1e-8}) {
        const Run& r = find(all, path, "modified-euler", stol, h);
        CAPTURE(path, h, stol, r.error);
        CHECK(r.error < previous);  // tighter STOL, smaller error
        previous = r.error;
        // The error controller's promise, measured: error ~ 0.1 STOL.
        if (stol <= 1e-4) {
          CHECK(r.error <= stol);
          CHECK(r.error >= 1e-3 * stol);
        }
      }
    }
}

TEST_CASE("forward Euler is first order on van der Pluijm, the implicit scheme accurate at every h", "[bench]") {
  const std::vector<Run> all = runs();
  for (const std::string& path : smooth_paths()) {
    if (path.rfind("vdp", 0) != 0) continue;
    const double fine = find(all, path, "forward-euler", 0, 1e-4).error,
                 coarse = find(all, path, "forward-euler", 0, 1e-3).error;
    const double slope = std::log10(coarse / fine);  // one decade of h
    CAPTURE(path, fine, coarse, slope);
    CHECK(slope > 0.6);
    CHECK(slope < 1.4);
    // The implicit scheme's substeps hold its error (docs/model.md 7.5): it
    // does not grow tenfold with a decade of h, and stays accurate.
    const double i_fine = find(all, path, "implicit", 0, 1e-4).error,
                 i_coarse = find(all, path, "implicit", 0, 1e-3).error;
    CAPTURE(i_fine, i_coarse);
    CHECK(i_fine < 1e-3);
    CHECK(i_coarse < 1e-3);
    CHECK(i_coarse < 5 * i_fine);
  }
}

TEST_CASE("the accurate outcomes are where they must be", "[bench]") {
  const std::vector<Run> all = runs();
  for (const std::string& path : smooth_paths()) {
    CAPTURE(path);
    // Modified Euler at STOL 1e-6 and h = 1e-4 mm (explicit-typical).
    CHECK(find(all, path, "modified-euler", 1e-6, 1e-4).outcome == "accurate");
    // The default scheme and STOL at every increment size of the study.
    for (double h : kQuickH) {
      CAPTURE(h);
      CHECK(find(all, path, "modified-euler", 1e-5, h).outcome == "accurate");
    }
  }
  // The default on every path the fixture ran, the mixed ones included
  // (rocking, cap_reversal, softened_reopened, apex_jumps): the law's answer
  // does not depend on how the path is cut (docs/model.md 6, 7.1).
  for (const Run& r : all) {
    if (r.scheme != "modified-euler" || r.stol != 1e-5) continue;
    CAPTURE(r.path, r.h, r.error);
    CHECK(r.outcome == "accurate");
  }
  // The summary's line for the error 1e-4 on van der Pluijm -0.5 MPa: modified
  // Euler reaches it.
  const std::string summary = file_text("summary.md");
  CHECK(summary.find("on vdp_sn0.5: modified-euler: ") != std::string::npos);
  CHECK(summary.find("on vdp_sn0.5: modified-euler: cannot") == std::string::npos);
}

TEST_CASE("paths: every increment is at most h and every corner is hit", "[bench]") {
  BenchPath p;
  p.legs = {{Vec3::Zero(), Vec3(0.0035, 0, 0)},
            {Vec3(0.0035, 0, 0), Vec3(0.0035, 0.002, 0.001), Vec3(0.0035, 0.004, 0.001)},
            {Vec3(0.0035, 0.004, 0.001), Vec3(0.0035, 0.004, 0.001)}};  // a held leg
  for (double h : {1e-4, 1e-3, 1e-2}) {
    CAPTURE(h);
    const std::vector<Vec3> d = discretise(p, h);
    REQUIRE(d.front() == Vec3::Zero());
    for (size_t i = 1; i < d.size(); ++i) CHECK((d[i] - d[i - 1]).norm() <= h * (1 + 1e-12));
    // Corners exactly, and the fewest parts no longer than h per leg.
    const long n1 = std::lround(std::ceil(0.0035 / h - 1e-9));
    const double l2 = std::sqrt(0.002 * 0.002 + 0.001 * 0.001) + 0.002;
    const long n2 = std::lround(std::ceil(l2 / h - 1e-9));
    REQUIRE(d.size() == static_cast<size_t>(1 + n1 + n2 + 1));
    CHECK(d[n1] == p.legs[0].back());
    CHECK(d[n1 + n2] == p.legs[1].back());
    CHECK(d.back() == p.legs[2].back());
  }
}

TEST_CASE("timing windows cover every increment once, in near-equal windows", "[bench]") {
  for (long n : {1L, 5L, 127L, 128L, 129L, 20323L}) {
    const TimingWindows w = timing_windows(n, 128);
    CAPTURE(n);
    CHECK(w.points() == std::min(n, 128L));
    CHECK(w.start.front() == 0);
    CHECK(w.start.back() == n);
    long shortest = n;
    for (int k = 0; k < w.points(); ++k) shortest = std::min(shortest, w.start[k + 1] - w.start[k]);
    CHECK(shortest >= 1);
    CHECK(w.length() - shortest <= 1);
  }
}

namespace {

// The traction the default scheme returns at the end of every leg of a bench
// path, driven at h = 1e-4 mm.
std::vector<Vec3> corner_tractions(const std::string& id) {
  const std::vector<BenchPath> chosen = bench_paths(MJ_CALIBRATION_DATA_DIR, true, {id});
  REQUIRE(chosen.size() == 1);
  const BenchPath* path = &chosen.front();
  REQUIRE(path->id == id);
  const std::vector<Vec3> history = discretise(*path, 1e-4);
  const Trajectory t =
      drive_point(path->parameters, path->cap, path->directions, SchemeControls{}, history, 1, 60, false);
  REQUIRE(t.complete(static_cast<long>(history.size()) - 1));
  std::vector<Vec3> corners;
  size_t i = 0;
  for (const auto& leg : path->legs) {
    while (history[i] != leg.back()) ++i;
    corners.push_back(t.traction[i]);
  }
  return corners;
}

}  // namespace

TEST_CASE("rocking: three times separated, closed into compression and slid", "[bench]") {
  // Legs: open, close, slide; three times (bench/paths.cpp).
  const std::vector<Vec3> c = corner_tractions("rocking");
  REQUIRE(c.size() == 9);
  for (int k = 0; k < 3; ++k) {
    CAPTURE(k, c[3 * k].transpose(), c[3 * k + 1].transpose(), c[3 * k + 2].transpose());
    CHECK(c[3 * k].norm() == 0);  // opened past complete separation: no traction at all
    CHECK(c[3 * k + 1][0] < -2);  // closed: about 5.6 MPa of compression (model.md 6)
    CHECK(c[3 * k + 2][0] < -2);
    CHECK(std::abs(c[3 * k + 2][1]) > 1);  // sliding on the friction left
  }
  CHECK(c[2][1] > 0);  // slips alternating in sign
  CHECK(c[5][1] < 0);
  CHECK(c[8][1] > 0);
}

TEST_CASE("cap_reversal: the shear reverses at every corner, on the tension cap, short of separation", "[bench]") {
  const std::vector<Vec3> c = corner_tractions("cap_reversal");
  REQUIRE(c.size() == 8);
  for (size_t k = 0; k < c.size(); ++k) {
    CAPTURE(k, c[k].transpose());
    CHECK(c[k][0] >= 0);                          // open
    CHECK(c[k][1] * (k % 2 ? -1 : 1) > 0.01);     // tau follows the slip's sign, strength left
    if (k < 4) CHECK(c[k][0] > 0.01);             // the first four on the cap
  }
}

TEST_CASE("crush: the cap on, crushed past its peak fc, opened and reclosed", "[bench]") {
  const std::vector<BenchPath> chosen = bench_paths(MJ_CALIBRATION_DATA_DIR, true, {"crush"});
  REQUIRE(chosen.size() == 1);
  const BenchPath& path = chosen.front();
  REQUIRE(path.cap.on());
  const double fc = path.cap.fc, Cs = path.cap.Cs;
  const std::vector<Vec3> history = discretise(path, 1e-4);
  const long n = static_cast<long>(history.size()) - 1;
  const Trajectory t = drive_point(path.parameters, path.cap, path.directions, SchemeControls{}, history, 1, 60,
                                   false, {n});
  REQUIRE(t.complete(n));
  // The cap's measure sqrt(sigma_n^2 + Cs tau^2) reaches fc (the peak, at a
  // slope of zero, so within the increments' sampling) and never exceeds it.
  double most = 0;
  for (const Vec3& x : t.traction) most = std::max(most, std::sqrt(x[0] * x[0] + Cs * (x[1] * x[1] + x[2] * x[2])));
  CHECK(most > 0.99 * fc);
  CHECK(most < fc * (1 + 1e-6));
  // Crushed past the peak: SDV 36 (kappa_c) beyond kappa_p at the end.
  REQUIRE(t.snapshots.size() == 1);
  CHECK(t.snapshots[0].state[cap_slot::kappa_c] > path.cap.kappa_p);
  // The corners: pressed to 0.3 fc; opened to zero traction; reclosed under
  // pressure, inside the peak.
  const std::vector<Vec3> c = corner_tractions("crush");
  REQUIRE(c.size() == 6);
  CHECK(c[0][0] == Approx(-0.3 * fc).epsilon(1e-9));
  CHECK(c[4].norm() == 0);
  CHECK(c[5][0] < 0);
  CHECK(-c[5][0] < fc);
}

TEST_CASE("throughput ratios pair the samples of one repeat", "[bench]") {
  // A host twice as slow in the second repeat: each repeat's ratio is 2, the
  // ratio of the medians (20 / 5 = 4) is not.
  const std::vector<double> elastic = {10, 40, 20}, copy = {5, 20, 10};
  CHECK(paired_ratio(elastic, copy) == 2.0);
  const std::vector<double> a = {1, 10, 3}, b = {1, 5, 1};  // ratios 1, 2, 3
  CHECK(paired_ratio(a, b) == 2.0);
  CHECK_THROWS_WITH(paired_ratio(a, {1, 2}), Catch::Contains("same, non-zero number of samples"));
  CHECK_THROWS(paired_ratio({}, {}));
}
