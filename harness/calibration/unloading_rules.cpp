#include "calibration/unloading_rules.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "calibration/curve_reading.hpp"

namespace mortar::harness {

namespace {

UnloadingBranch read_branch(const TestCurve& c, size_t start, size_t end, double k) {
  UnloadingBranch br;
  br.curve = c.name;
  br.first_row = int(start) + 1;
  std::vector<double> x, y;
  for (size_t i = start; i < end; ++i)
    if (c.y[i] > 0) x.push_back(c.x[i]), y.push_back(c.y[i]);
  br.points = int(x.size());
  if (x.size() < 3) return br.why_not = "fewer than 3 open points (traction > 0)", br;
  const Line l = line_through(x, y);
  if (!(l.b > 0)) return br.why_not = "the branch's traction does not fall with the separation", br;
  br.delta_p = -l.a / l.b;
  br.delta_in = c.x[start] - (l.a + l.b * c.x[start]) / k;
  if (!(br.delta_p > 0) || !(br.delta_in > br.delta_p))
    return br.why_not = "its zero-traction point is not between 0 and the inelastic separation", br;
  br.ratio = br.delta_in / br.delta_p - 1;
  return br;
}

}  // namespace

std::vector<UnloadingBranch> unloading_branches(const TestCurve& c, double k) {
  std::vector<UnloadingBranch> out;
  double reached = -INFINITY;
  size_t start = 0;
  bool inside = false;
  for (size_t i = 0; i <= c.x.size(); ++i) {
    const bool below = i < c.x.size() && c.x[i] < reached;
    if (below && !inside) inside = true, start = i - 1;
    if (!below && inside) inside = false, out.push_back(read_branch(c, start, i, k));
    if (i < c.x.size() && !below) reached = c.x[i];
  }
  return out;
}

void unloading_rules(const std::vector<TestCurve>& curves, Calibration& cal) {
  struct Ratio {
    const char* name;
    double k;
    double sum = 0;
    int n = 0;
  };
  Ratio bn{"bn", cal["kn"].value}, bs{"bs", cal["ks"].value};
  bool closed_shear_branches = false;
  for (const TestCurve& c : curves) {
    if (!c.cycles()) continue;
    const char* shows = c.unloading_shows();
    if (!shows) {
      closed_shear_branches = closed_shear_branches || !unloading_branches(c, bs.k).empty();
      continue;
    }
    Ratio& r = shows == std::string("bn") ? bn : bs;
    for (const UnloadingBranch& b : unloading_branches(c, r.k)) {
      char line[240];
      if (std::isnan(b.ratio))
        std::snprintf(line, sizeof line, "%s: the unloading branch from data row %d gives no %s: %s", b.curve.c_str(),
                      b.first_row, r.name, b.why_not.c_str());
      else
        std::snprintf(line, sizeof line,
                      "%s: the unloading branch from data row %d (%d open points): delta_in = %.4g mm, zero traction "
                      "at %.4g mm, %s = %.3g", b.curve.c_str(), b.first_row, b.points, b.delta_in, b.delta_p, r.name, b.ratio);
      cal.notes.push_back(line);
      if (!std::isnan(b.ratio)) r.sum += b.ratio, ++r.n;
    }
  }
  for (Ratio* r : {&bn, &bs}) {
    if (r->n == 0) continue;
    const double mean = r->sum / r->n;
    char how[200];
    std::snprintf(how, sizeof how, "starting value: %d unloading branch(es), delta_in/delta_p - 1 (secant rule, model.md 6)",
                  r->n);
    cal[r->name] = {mean, Stage::fit, how};
  }
  if (closed_shear_branches && bs.n == 0)
    cal.notes.push_back("bs: the shear curves' unloading branches are under compression, where the joint is closed and "
                        "unloads through its plastic slip alone (model.md 6): they show no crack slip. A cyclic shear "
                        "test at constant tension (sigma_n > 0) gives bs");
}

}  // namespace mortar::harness
