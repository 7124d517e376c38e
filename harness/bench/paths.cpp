#include "bench/paths.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "input/input_error.hpp"
#include "input/parameter_file.hpp"
#include "input/protocol.hpp"
#include "solvers/explicit_run.hpp"
#include "validation/calibration_data.hpp"

namespace mortar::harness {

namespace {

double polyline_length(const std::vector<Vec3>& leg) {
  double L = 0;
  for (size_t i = 1; i < leg.size(); ++i) L += (leg[i] - leg[i - 1]).norm();
  return L;
}

// Appends the n points at arc lengths L*j/n, j = 1..n, of the polyline.
void sample_leg(const std::vector<Vec3>& leg, int n, std::vector<Vec3>& out) {
  const double L = polyline_length(leg);
  size_t seg = 1;
  double seg_start = 0;  // arc length at leg[seg - 1]
  for (int j = 1; j <= n; ++j) {
    if (j == n) {  // the corner itself, exactly
      out.push_back(leg.back());
      continue;
    }
    const double s = L * double(j) / double(n);
    while (seg + 1 < leg.size() && seg_start + (leg[seg] - leg[seg - 1]).norm() < s) {
      seg_start += (leg[seg] - leg[seg - 1]).norm();
      ++seg;
    }
    const double len = (leg[seg] - leg[seg - 1]).norm();
    const double f = len > 0 ? std::clamp((s - seg_start) / len, 0.0, 1.0) : 1.0;
    out.push_back(leg[seg - 1] + f * (leg[seg] - leg[seg - 1]));
  }
}

// The separation history a mixed-control run went through, one leg per
// program step.
std::vector<std::vector<Vec3>> history_of_run(const Parameters& p, const Protocol& protocol, Scheme scheme,
                                              double stol) {
  RunSettings settings;
  settings.scheme = scheme;
  settings.stol = stol;
  std::vector<std::vector<Vec3>> legs;
  Vec3 last = Vec3::Zero();
  int step = 0;
  run_protocol(p, protocol, settings, [&](int, const Sample& s) {
    if (s.increment == 0) return;
    if (s.step != step) {
      legs.push_back({last});
      step = s.step;
    }
    legs.back().push_back(s.separation);
    last = s.separation;
  });
  return legs;
}

// Legs of straight lines between corner points (the origin first).
std::vector<std::vector<Vec3>> straight_legs(const std::vector<Vec3>& corners) {
  std::vector<std::vector<Vec3>> legs;
  Vec3 last = Vec3::Zero();
  for (const Vec3& c : corners) {
    legs.push_back({last, c});
    last = c;
  }
  return legs;
}

ComponentProgram displacement(double target) { return {Control::displacement, target}; }
ComponentProgram traction(double target) { return {Control::traction, target}; }

// Cyclic shear with sign reversals at sigma_n = -0.1, -0.5 and -1.0 MPa in
// turn, on one joint: +/-0.04 mm about zero at each (beyond the peak slip of
// 0.011-0.021 mm of the van der Pluijm tests, so every level reaches the
// surface and the later ones start from a softened joint). Increments of
// 1e-5 mm, the finest of the study.
Protocol cyclic_at_three_normal_stresses() {
  Protocol p;
  p.file = "(bench: cyclic shear at three normal stresses)";
  p.title = "cyclic shear, +/-0.04 mm at sigma_n = -0.1, -0.5, -1.0 MPa";
  const double amplitude = 0.04, max_increment = 1e-5;
  double slip = 0;
  for (double sigma_n : {-0.1, -0.5, -1.0}) {
    ProgramStep normal;
    normal.name = "normal stress " + std::to_string(sigma_n);
    normal.increments = 50;
    normal.component = {traction(sigma_n), displacement(slip), displacement(0)};
    p.steps.push_back(normal);
    for (double target : {amplitude, -amplitude, amplitude, 0.0}) {
      ProgramStep leg;
      leg.name = "slip to " + std::to_string(target);
      leg.increments = std::lround(std::ceil(std::abs(target - slip) / max_increment));
      leg.component = {traction(sigma_n), displacement(target), displacement(0)};
      p.steps.push_back(leg);
      slip = target;
    }
  }
  return p;
}

// The cyclic program up to the end of its first amplitude's cycles: the
// later, larger cycles slide at the residual friction (the same smooth
// response for 24 more mm of travel) and would dominate the run time.
void keep_first_amplitude(std::vector<std::vector<Vec3>>& legs) {
  double first = 0;
  for (size_t i = 0; i < legs.size(); ++i) {
    const double slip = std::abs(legs[i].back()[1]);
    if (first == 0 && slip > 0.1) first = slip;  // the end of the first cycle leg
    if (first > 0 && slip > first * (1 + 1e-9)) {
      legs.resize(i);
      return;
    }
  }
}

// A bench path by its id, built only when chosen: most paths are the
// history of a mixed-control run, which takes seconds (minutes under the
// sanitizers), so a study of one path builds that path alone.
struct PathEntry {
  std::string id;
  std::function<BenchPath()> build;
};

void add_calibration_paths(const std::string& data_dir, bool quick, std::vector<PathEntry>& paths) {
  for (const SeriesSpec& series : read_calibration_data(data_dir, {})) {
    if (quick && series.kind == SeriesKind::cyclic_shear) continue;
    for (const CaseSpec& c : series.cases) {
      paths.push_back({c.name, [series, c] {
                         BenchPath b;
                         b.id = c.name;
                         const Protocol protocol = read_protocol_file(c.protocol_file);
                         b.title = protocol.title.empty() ? c.name : protocol.title;
                         b.parameters = read_parameter_file(c.params_file).values;
                         b.directions = protocol.directions;
                         b.legs = history_of_run(b.parameters, protocol, series.scheme, series.stol);
                         if (series.kind == SeriesKind::cyclic_shear) {
                           keep_first_amplitude(b.legs);
                           b.title += " (to the end of the first amplitude's cycles)";
                         }
                         return b;
                       }});
    }
  }
}

// What a bed joint at the toe or heel of a rocking wall goes through, three
// times with different amplitudes: the joint opens to well past complete
// separation (15 to 40 softening lengths u = GIC/ft0; separation, s_raw <=
// s_sep, comes after about 16: model.md 6, Decision -- complete separation),
// closes to delta_n = 0 (contact is regained at delta_n = delta_p_n, the
// largest opening over 1 + bn, about 0.027 mm: model.md 6, Decision --
// opening past complete normal damage; so about 5.6 MPa of compression),
// and slides under that
// compression (slips of 0.04, -0.06 and 0.05 mm, past the elastic slip of
// about 0.02 mm), then reopens to zero traction. Every closing must find the
// same contact point however the path is cut into increments.
std::vector<std::vector<Vec3>> rocking_legs(const Parameters& p) {
  const double u = p.GIC / p.ft0;  // mode-I softening length [mm]
  std::vector<Vec3> corners;
  double slip = 0;
  for (const auto& [opening, next_slip] : {std::pair{40.0, 0.04}, {15.0, -0.02}, {30.0, 0.03}}) {
    corners.push_back({opening * u, slip, 0});
    corners.push_back({0, slip, 0});
    corners.push_back({0, next_slip, 0});
    slip = next_slip;
  }
  return straight_legs(corners);
}

// Shear reversing while the joint opens and softens on the tension cap: the
// slip zig-zags with an amplitude of a tenth of the opening reached, eight
// legs up to 6 softening lengths. The first four legs soften on the cap
// (sigma_n from ft0 down to 0.02 MPa, normal damage to 0.996); in the last
// four the normal damage is complete and the shear works down the cohesion
// left at sigma_n = 0, short of separation. Every reversal is a slip against
// the elastic slip, which unloads on the shear secant (model.md 6, Decision --
// open-regime branches), and the traction crosses tau = 0 near the apex.
std::vector<std::vector<Vec3>> cap_reversal_legs(const Parameters& p) {
  const double u = p.GIC / p.ft0;
  constexpr int kLegs = 8;
  std::vector<Vec3> corners;
  for (int k = 1; k <= kLegs; ++k) {
    const double opening = 6.0 * u * k / kLegs;
    corners.push_back({opening, (k % 2 ? 0.1 : -0.1) * opening, 0});
  }
  return straight_legs(corners);
}

// Crushing (docs/model.md 12), the splitting tests' crush family
// (tests/support/splitting_paths.hpp) with its cap (crush_cap). Pressed to
// 0.3 fc, slid onto the cap and along it (its flow closes the joint, so the
// pressure falls) through the corner onto the hyperbola; crushed past the
// peak with the slip held, the slip turned and reversed, opened, then closed
// and pressed onto the softened cap.
BenchPath crush_path(const Parameters& p) {
  const CompressionCap c = crush_cap(p);
  const double e0 = p.ft0 / p.kn, a = -0.3 * c.fc / p.kn, soft = c.kappa_p + 2 * c.Gfc / c.fc;
  const double s = 3 * c.fc / p.ks, b = -(c.fc / p.kn + soft);
  BenchPath path{"crush", "crushing: slid along the cap, through the corner, crushed, reversed, opened, reclosed", p,
                 3, straight_legs({{a, 0, 0}, {a, s, 0}, {b, s, 0}, {b, -s, s}, {2 * e0, -s, s}, {b - 0.5 * soft, 0, 0}}),
                 c};
  return path;
}

void add_mixed_paths(const std::string& data_dir, std::vector<PathEntry>& paths) {
  const Parameters p = read_parameter_file(data_dir + "/vdp_monotonic_shear/params_sn0.5.toml").values;
  // A path given directly as its legs, on these parameters.
  auto given = [&p](const char* id, const char* title, std::vector<std::vector<Vec3>> legs) {
    return PathEntry{id, [=] { return BenchPath{id, title, p, 3, legs, CompressionCap{}}; }};
  };
  // Opening past the tensile peak (ft0/kn = 0.003 mm), shear in both
  // tangential directions while open, closing into compression, then shear
  // reversed under compression: every regime switch of the law in one path.
  paths.push_back(given("open_shear_close", "opening, shear (s1, s2) while open, closing, reversed shear closed",
                        straight_legs({{0.004, 0, 0}, {0.004, 0.02, 0.01}, {-0.004, 0.02, 0.01}, {-0.004, -0.02, 0.01}})));
  paths.push_back({"cyclic_three_sigma_n", [p] {
                     BenchPath b;
                     b.id = "cyclic_three_sigma_n";
                     const Protocol protocol = cyclic_at_three_normal_stresses();
                     b.title = protocol.title;
                     b.parameters = p;
                     b.legs = history_of_run(p, protocol, Scheme::modified_euler, 1e-8);
                     return b;
                   }});
  // Zig-zag slip while opening past ft0/kn: the traction path crosses
  // tau = 0 on the tension cap, so large increments jump from one side of
  // the apex of the hyperbola to the other.
  paths.push_back(given("apex_jumps", "opening with the slip zig-zagging through zero: jumps across the apex",
                        straight_legs({{0.0025, 0.002, 0}, {0.006, -0.002, 0}, {0.010, 0.003, 0}, {0.020, -0.003, 0}})));
  // Opening to separation (wI -> GIC: s = 0, the surface a cone through the
  // origin), friction on the softened joint under compression, reopening
  // (zero traction), sliding back open, and closing again.
  paths.push_back(given("softened_reopened", "full separation, closed friction, reopened, closed again",
                        straight_legs({{0.1, 0, 0},
                                       {-0.004, 0, 0},
                                       {-0.004, 0.05, 0},
                                       {0.05, 0.05, 0},
                                       {0.05, 0, 0},
                                       {-0.002, 0, 0},
                                       {-0.002, 0.03, 0}})));
  paths.push_back(given("rocking", "rocking toe: separated, closed, slid, reopened, three times", rocking_legs(p)));
  paths.push_back(given("cap_reversal", "opening and softening on the tension cap with slip reversals",
                        cap_reversal_legs(p)));
  paths.push_back({"crush", [p] { return crush_path(p); }});
}

}  // namespace

CompressionCap crush_cap(const Parameters& p) {
  const double Cs = 9, fc = 4 * std::sqrt(p.ft0 * p.ft0 + Cs * p.c0 * p.c0);
  const double Gfc = 2 * 481 * fc * fc / (588 * std::min(p.kn, Cs * p.ks));
  return {fc, Cs, Gfc, fc / p.kn};
}

std::vector<Vec3> discretise(const BenchPath& path, double h) {
  std::vector<Vec3> points{Vec3::Zero()};
  for (const auto& leg : path.legs) {
    const double L = polyline_length(leg);
    // The 1e-9 keeps a leg of exactly k*h from getting k+1 parts by round-off.
    const int n = std::max(1, static_cast<int>(std::ceil(L / h * (1 - 1e-9))));
    sample_leg(leg, n, points);
  }
  return points;
}

double path_length(const BenchPath& path) {
  double L = 0;
  for (const auto& leg : path.legs) L += polyline_length(leg);
  return L;
}

std::vector<BenchPath> bench_paths(const std::string& data_dir, bool quick, const std::vector<std::string>& ids) {
  std::vector<PathEntry> entries;
  add_calibration_paths(data_dir, quick, entries);
  add_mixed_paths(data_dir, entries);
  std::vector<BenchPath> paths;
  if (ids.empty()) {
    for (const PathEntry& e : entries) paths.push_back(e.build());
    return paths;
  }
  for (const std::string& id : ids) {
    auto it = std::find_if(entries.begin(), entries.end(), [&](const PathEntry& e) { return e.id == id; });
    if (it == entries.end()) {
      std::string known;
      for (const PathEntry& e : entries) known += (known.empty() ? "" : ", ") + e.id;
      throw InputError("--path " + id + ": no such bench path (the paths are: " + known + ")");
    }
    paths.push_back(it->build());
  }
  return paths;
}

}  // namespace mortar::harness
