// The cells of the splitting study (docs/robustness.md, Splitting
// invariance): which sets run at which increment size, on how long a path,
// and the measurement of one cell. Shared by tests/law/test_splitting*.cpp and
// the table program tests/law/splitting_table.cpp, so that the table shows
// what the tests assert.
#pragma once

#include <string>
#include <vector>

#include "splitting_paths.hpp"

namespace mj_test::splitting {

// One cell: a set, an increment size and the reach of the path
// (path_of: 1 = full length).
struct Cell {
  std::string set;
  double h;
  double reach = 1;
};

// The finer increments make the paths long (a path of 0.1 mm is 10^4
// increments of 1e-5 mm, each 100 calls in the reference): there a shorter
// path, which still passes each family's features.
inline double reach_at(double h) { return h >= 1e-3 ? 1.0 : h >= 1e-4 ? 0.5 : 0.2; }

// Every set at h (the table's --all-sets; the tests at 1e-3 mm).
inline std::vector<Cell> all_cells(double h) {
  std::vector<Cell> v;
  for (const NamedSet& s : sets()) v.push_back({s.name, h, reach_at(h)});
  return v;
}

// The subset of sets a family runs at the finer increments: three at
// 1e-4 mm, two at 1e-5 mm, Table 1 and random ones, sets with short and with
// long softening lengths. Random paths with jumps, short paths of few
// increments, run on all nine.
inline std::vector<Cell> fine_cells(const std::string& family, double h) {
  struct Subset {
    const char* family;
    std::vector<std::string> at_1e4, at_1e5;
  };
  static const std::vector<Subset> subsets = {
      {"separation", {"vdP-0.5", "M34", "rnd2"}, {"M34", "rnd0"}},
      {"cap", {"vdP-0.1", "M15", "rnd1"}, {"M34", "rnd2"}},
      {"open-shear-close", {"vdP-0.5", "Atk", "rnd1"}, {"M15", "rnd0"}},
      {"slip3d", {"vdP-1.0", "M34", "rnd1"}, {"vdP-0.1", "rnd2"}},
      {"crush", {"vdP-0.5", "Atk", "rnd0"}, {"M15", "rnd1"}},
      {"random-jumps",
       {"vdP-0.1", "vdP-0.5", "vdP-1.0", "M15", "M34", "Atk", "rnd0", "rnd1", "rnd2"},
       {"vdP-0.1", "vdP-0.5", "vdP-1.0", "M15", "M34", "Atk", "rnd0", "rnd1", "rnd2"}},
  };
  std::vector<Cell> v;
  for (const Subset& s : subsets)
    if (family == s.family)
      for (const std::string& n : h >= 1e-4 ? s.at_1e4 : s.at_1e5) v.push_back({n, h, reach_at(h)});
  return v;
}

// Cells outside families(): the bench's cap_reversal at 1e-2 mm, one leg an
// increment (test_splitting_cap_reversal.cpp).
inline std::vector<Cell> bench_cells() { return {{"vdP-0.5", 1e-2, 1}}; }

// The seed of a set's random path: its place in sets().
inline unsigned seed_of(const std::string& name) {
  const std::vector<NamedSet> all = sets();
  for (size_t i = 0; i < all.size(); ++i)
    if (all[i].name == name) return unsigned(i);
  return 0;
}

// One cell measured: (a) the tight cuts against the tight reference, (b) the
// default controls' cuts against it. Errors are relative to the reference's
// peak traction.
struct Measured {
  size_t increments = 0;
  double peak = 0;
  std::vector<double> tight_by_calls, default_by_calls;
  double tight = 0, defaults = 0;  // the worst of each
  long reference_failures = 0, tight_failures = 0, default_failures = 0;
  // The most substeps one call took (Run::worst_work): over the tight runs,
  // the reference included, and over the default runs.
  long tight_work = 0, default_work = 0;
  // The implicit scheme (docs/model.md 7.5) at the default controls, 1 call
  // per increment, against the same reference (measured on request).
  double implicit = -1;
  long implicit_failures = 0, implicit_work = 0;
  // Increments, over every run compared, in which one run dropped at fixed
  // separation and the reference did not, or the other way round (worst,
  // splitting_paths.hpp: compared with the reference either side too).
  long drops_apart = 0;
  bool any_failure() const { return reference_failures + tight_failures + default_failures > 0; }
};

inline Measured measure(const std::string& family, const NamedSet& ns, const Cell& c,
                        const std::vector<int>& tight_calls = {1, 20}, const std::vector<int>& default_calls = {1},
                        bool implicit = false) {
  const Path w = path_of(family, ns.p, seed_of(ns.name), c.reach);
  const mortar::CompressionCap cap = cap_for(family, ns.p);
  const mortar::Model Mt = mortar::make_model(ns.p, tight(), cap), Md = mortar::make_model(ns.p, mortar::Controls{}, cap);
  const Run ref = drive(Mt, w, c.h, kReferenceCalls);
  Measured m;
  m.increments = ref.traction.size();
  m.peak = peak(ref.traction);
  m.reference_failures = ref.failures;
  m.tight_work = ref.worst_work;
  for (int n : tight_calls) {
    const Run r = drive(Mt, w, c.h, n);
    m.tight_failures += r.failures;
    m.tight_work = std::max(m.tight_work, r.worst_work);
    m.tight_by_calls.push_back(worst(r, ref, m.peak));
    m.drops_apart += count_drops_apart(r, ref);
    m.tight = std::max(m.tight, m.tight_by_calls.back());
  }
  for (int n : default_calls) {
    const Run r = drive(Md, w, c.h, n);
    m.default_failures += r.failures;
    m.default_work = std::max(m.default_work, r.worst_work);
    m.default_by_calls.push_back(worst(r, ref, m.peak));
    m.drops_apart += count_drops_apart(r, ref);
    m.defaults = std::max(m.defaults, m.default_by_calls.back());
  }
  if (implicit) {
    mortar::Controls ci;
    ci.scheme = mortar::Scheme::implicit;
    const Run r = drive(mortar::make_model(ns.p, ci, cap), w, c.h, 1);
    m.implicit_failures = r.failures;
    m.implicit_work = r.worst_work;
    m.implicit = worst(r, ref, m.peak);
    m.drops_apart += count_drops_apart(r, ref);
  }
  return m;
}

}  // namespace mj_test::splitting
