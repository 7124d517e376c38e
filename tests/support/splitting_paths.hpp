// Splitting invariance (docs/model.md 6, Decision - complete separation at
// s_sep; 7.1, Decisions - s relative, loading from the surface): the path
// families, the parameter sets and the drive shared by the law's splitting
// tests (tests/law/test_splitting*.cpp), the single-precision splitting test
// (tests/abi/precision_splitting_tests.cpp) and the measurement program
// (tests/law/splitting_table.cpp). No Catch2 here: the program links the law
// only, and builds against older versions of it.
//
// A path is a list of legs in separation space (law signs: opening and the
// two slips). A leg is cut into increments of about h, except a jump, which
// is one increment whatever h (a solver's sudden large step). Each increment
// is handed to integrate_increment as `calls` equal calls; the traction is
// compared after each increment, relative to the path's peak traction.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"
#include "paper_sets.hpp"
#include "random_parameters.hpp"

namespace mj_test::splitting {

using mortar::Parameters;
using mortar::Vec3;

struct NamedSet {
  std::string name;
  Parameters p;
};

// Table 1's six sets, then three random valid ones (seed 11). Mode-I
// snap-back (ft0^2/GIC > kn/2) is a different path, the return at fixed
// separation (docs/model.md 6, Snap-back); a long softening length only makes
// the paths longer.
inline std::vector<NamedSet> sets() {
  namespace t = mortar::testing;
  std::vector<NamedSet> v = {{"vdP-0.1", t::van_der_pluijm(-0.1)}, {"vdP-0.5", t::van_der_pluijm(-0.5)},
                             {"vdP-1.0", t::van_der_pluijm(-1.0)}, {"M15", t::almeida_m15()},
                             {"M34", t::almeida_m34()},            {"Atk", t::atkinson()}};
  std::mt19937 rng(11);
  for (int k = 0; k < 3;) {
    const Parameters p = random_parameters(rng);
    if (p.ft0 * p.ft0 / p.GIC > 0.5 * p.kn || p.GIC / p.ft0 > 0.02) continue;
    v.push_back({"rnd" + std::to_string(k++), p});
  }
  return v;
}

inline NamedSet set_named(const std::string& name) {
  for (const NamedSet& s : sets())
    if (s.name == name) return s;
  return {"", Parameters{}};
}

struct Leg {
  Vec3 to;            // the waypoint the leg ends at
  bool jump = false;  // one increment, whatever h
};
using Path = std::vector<Leg>;

inline const std::vector<std::string>& families() {
  static const std::vector<std::string> f = {"separation", "cap", "open-shear-close", "slip3d", "random-jumps",
                                             "crush"};
  return f;
}

// The compression cap of the "crush" family for set p (docs/model.md 12):
// Cs = 9 (Lourenco's), fc four times the bound of its rule (fc/3 >
// sqrt(ft0^2 + Cs c0^2)), Gfc twice the bound of its snap-back rule, the
// peak at a plastic closure kappa_p = fc/kn. Every other family has none.
inline mortar::CompressionCap crush_cap(const Parameters& p) {
  const double Cs = 9, fc = 4 * std::sqrt(p.ft0 * p.ft0 + Cs * p.c0 * p.c0);
  const double Gfc = 2 * 481 * fc * fc / (588 * std::min(p.kn, Cs * p.ks));
  return {fc, Cs, Gfc, fc / p.kn};
}
inline mortar::CompressionCap cap_for(const std::string& family, const Parameters& p) {
  return family == "crush" ? crush_cap(p) : mortar::CompressionCap{};
}

// The joint's own lengths: elastic limits in tension and shear, softening
// lengths in mode I and II.
struct Lengths {
  double e0, es, un, us;
  explicit Lengths(const Parameters& p) : e0(p.ft0 / p.kn), es(p.c0 / p.ks), un(p.GIC / p.ft0), us(p.GIIC / p.c0) {}
};

// Random waypoints with jumps: each leg moves by a fraction of the softening
// lengths, reverses (part of) the previous leg, or jumps by a few elastic
// limits in one increment. The opening is kept above -4 e0 (a few ft0 of
// pressure). Deterministic: the seed is the set's.
inline Path random_jumps(const Parameters& p, unsigned seed, int legs) {
  const Lengths L(p);
  std::mt19937 rng(seed);
  auto u = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  Path w;
  Vec3 x = Vec3::Zero(), last = Vec3::Zero();
  for (int k = 0; k < legs; ++k) {
    const double r = u(0, 1);
    Vec3 dx;
    bool jump = false;
    if (r < 0.3) {  // a jump of 2-5 elastic limits
      Vec3 dir(u(-1, 1.2), u(-1, 1), u(-1, 1));
      dir /= std::max(dir.norm(), 1e-3);
      dx = u(2, 5) * Vec3(dir[0] * L.e0, dir[1] * L.es, dir[2] * L.es);
      jump = true;
    } else if (r < 0.5 && k > 0) {  // a reversal
      dx = -u(0.3, 1.0) * last;
    } else {
      // A long softening length (Atkinson's us = 1.5 mm) only makes the
      // path longer: a leg moves by at most 0.02 mm normal, 0.05 mm in slip.
      const double un = std::min(L.un, 0.02), us = std::min(L.us, 0.05);
      dx = Vec3(u(-0.5, 1.0) * un, u(-0.6, 0.6) * us, u(-0.6, 0.6) * us);
    }
    Vec3 next = x + dx;
    next[0] = std::max(next[0], -4 * L.e0);
    last = next - x;
    x = next;
    w.push_back({x, jump});
  }
  return w;
}

// The waypoints of a family for set p, seed the set's index. `reach` (<= 1)
// shortens the long legs, which are multiples of the softening lengths, for
// the finer increments; the features of a family (complete separation,
// reversals, closure, direction changes) stay on the path.
inline Path path_of(const std::string& family, const Parameters& p, unsigned seed, double reach = 1) {
  const Lengths J(p);
  const double u = J.un, e0 = J.e0;
  Path w;
  auto add = [&](std::initializer_list<Vec3> xs) {
    for (const Vec3& x : xs) w.push_back({x});
  };
  if (family == "separation") {
    // Open past complete separation (s_sep = 1e-7 at about 16 u), press shut
    // to about 3 ft0, slide, reopen, press shut, slide back past zero, reopen.
    const double L = std::min(std::max(30 * reach, 18.0) * u, 0.3) + e0, Lt = reach * std::min(4 * u, 0.05);
    const double dc = L / (1 + p.bn) - 3 * e0;
    add({Vec3(L, 0, 0), Vec3(dc, 0, 0), Vec3(dc, Lt, 0), Vec3(1.5 * L, Lt, 0), Vec3(dc, Lt, 0), Vec3(dc, -Lt, 0),
         Vec3(2 * L, -Lt, 0)});
  } else if (family == "cap") {
    // Opening while softening on the tension cap, the slip reversing at
    // every waypoint.
    const double Lo = reach * std::min(6 * u, 0.1), A = Lo / 16;
    for (int k = 1; k <= 8; ++k) w.push_back({Vec3(e0 + Lo * k / 8, k % 2 ? A : -A, 0)});
  } else if (family == "cap-reversal") {
    // The bench's cap_reversal (harness/bench/paths.cpp): from the origin the
    // slip zig-zags with a tenth of the opening while the joint opens to 6 u
    // in eight legs. Its reversals unload inside the surface and reload
    // within one leg (docs/model.md 7.1, Decision - unloading, then reloading).
    for (int k = 1; k <= 8; ++k) w.push_back({Vec3(reach * 6 * u * k / 8, (k % 2 ? 0.1 : -0.1) * reach * 6 * u * k / 8, 0)});
  } else if (family == "open-shear-close") {
    const double L = reach * std::min(2 * u, 0.04);
    add({Vec3(L, 0, 0), Vec3(L, L, 0), Vec3(-2 * e0, L, 0), Vec3(-2 * e0, 2 * L, 0)});
  } else if (family == "crush") {
    // With the cap of crush_cap: pressed to 0.3 fc, slid onto the cap, along
    // it (its flow closes the joint plastically, so the pressure falls) and
    // through the corner onto the hyperbola; crushed past the peak with the
    // slip held, the slip turned and reversed, the joint opened, then closed
    // and pressed onto the softened cap again.
    const mortar::CompressionCap c = crush_cap(p);
    const double a = -0.3 * c.fc / p.kn, soft = reach * (c.kappa_p + 2 * c.Gfc / c.fc);
    const double s = reach * 3 * c.fc / p.ks, b = -(c.fc / p.kn + soft);
    add({Vec3(a, 0, 0), Vec3(a, s, 0), Vec3(b, s, 0), Vec3(b, -s, s), Vec3(2 * e0, -s, s), Vec3(b - 0.5 * soft, 0, 0)});
  } else if (family == "slip3d") {
    // Under compression (sigma_n about -ft0), the slip turning by 90 degrees
    // and reversing.
    const double dc = -e0, L = reach * std::min(4 * J.us, 0.1);
    add({Vec3(dc, 0, 0), Vec3(dc, L, 0), Vec3(dc, L, L), Vec3(dc, 0, L), Vec3(dc, 0.5 * L, -0.5 * L), Vec3(dc, -L, 0)});
  } else {
    // Fewer legs at a shorter reach: the first legs of the same path.
    w = random_jumps(p, 1000 + seed, 12);
    if (reach < 1) w.resize(std::max<size_t>(4, size_t(std::lround(12 * reach))));
  }
  return w;
}

// The tractions after each increment, whether the increment dropped at
// fixed separation (a return of docs/model.md 6: snap-back, closure onto a
// surface the traction lies beyond), the calls that failed, and the most
// substeps (accepted, rejected and relaxation steps: what max_substeps
// bounds) one call took.
struct Run {
  std::vector<Vec3> traction;
  std::vector<char> dropped;
  long failures = 0;
  long calls = 0;
  long worst_work = 0;
};

// Each leg cut into increments of about h (a jump: one), each increment
// into `calls` equal calls.
inline Run drive(const mortar::Model& M, const Path& w, double h, int calls) {
  Run out;
  mortar::State s;
  Vec3 from = Vec3::Zero();
  for (const Leg& leg : w) {
    const Vec3 d = leg.to - from;
    from = leg.to;
    const int n = leg.jump ? 1 : std::max(1, int(std::ceil(d.norm() / h - 1e-9)));
    for (int i = 0; i < n; ++i) {
      mortar::IncrementResult r;
      bool dropped = false;
      for (int c = 0; c < calls; ++c) {
        r = mortar::integrate_increment(M, s, d / n / calls);
        out.failures += !r.status.ok();
        out.worst_work = std::max(out.worst_work, r.status.work());
        dropped = dropped || r.status.relaxations > 0;
        ++out.calls;
      }
      out.traction.push_back(r.traction);
      out.dropped.push_back(dropped);
    }
  }
  return out;
}

inline double peak(const std::vector<Vec3>& t) {
  double p = 0;
  for (const Vec3& x : t) p = std::max(p, x.norm());
  return p;
}

// max over increments |a - b| / peak (Euclidean norm of the traction).
inline double worst(const std::vector<Vec3>& a, const std::vector<Vec3>& b, double pk) {
  if (a.size() != b.size()) return INFINITY;
  double e = 0;
  for (size_t i = 0; i < a.size(); ++i) e = std::max(e, (a[i] - b[i]).norm() / pk);
  return e;
}

// Whether one of the runs drops at fixed separation in increment i and the
// other does not.
inline bool drop_apart(const Run& a, const Run& b, size_t i) {
  return a.dropped.size() == b.dropped.size() && i < a.dropped.size() && a.dropped[i] != b.dropped[i];
}

// The same between two runs of the law (b the reference). A drop is a jump
// of the traction along the path, and which increment holds it turns on
// where the point reaches the surface: an error of 1e-7 mm there moves it by
// one increment, and the difference in that increment is then the jump, not
// an error of the integration. So in an increment where the runs disagree
// about a drop, a is compared with the nearest of b's tractions one
// increment either side as well (docs/robustness.md, Splitting invariance);
// a run that drops two or more increments apart still shows.
inline double worst(const Run& a, const Run& b, double pk) {
  if (a.traction.size() != b.traction.size()) return INFINITY;
  double e = 0;
  for (size_t i = 0; i < a.traction.size(); ++i) {
    double d = (a.traction[i] - b.traction[i]).norm();
    if (drop_apart(a, b, i)) {
      if (i > 0) d = std::min(d, (a.traction[i] - b.traction[i - 1]).norm());
      if (i + 1 < b.traction.size()) d = std::min(d, (a.traction[i] - b.traction[i + 1]).norm());
    }
    e = std::max(e, d / pk);
  }
  return e;
}
inline long count_drops_apart(const Run& a, const Run& b) {
  long n = 0;
  for (size_t i = 0; i < a.dropped.size(); ++i) n += drop_apart(a, b, i);
  return n;
}

// The tight controls of requirement (a): STOL 1e-9, FTOL 1e-12 and a
// smallest substep of 1e-6 of the call, the rest at their defaults
// (docs/model.md 7.4). At the default floor (1e-4 of the call) a jump of
// several elastic limits taken as one call ends substeps at the floor above
// STOL 1e-9, while the same jump cut into 100 calls resolves 100 times finer:
// the floor, not the law, would then set the difference.
inline mortar::Controls tight() {
  mortar::Controls c;
  c.stol = 1e-9;
  c.ftol = 1e-12;
  c.min_substep = 1e-6;
  return c;
}

// The calls per increment of the tight reference: never the candidate's cut.
inline constexpr int kReferenceCalls = 100;

}  // namespace mj_test::splitting
