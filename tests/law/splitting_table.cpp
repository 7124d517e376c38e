// Measurement, not a test: the splitting-invariance table of
// docs/robustness.md (Splitting invariance). For each path family, parameter
// set and increment size h (tests/support/splitting_paths.hpp) it prints the
// worst traction error after an increment, relative to the path's peak:
//   tight   = 1 and 20 calls per increment, each against 100 calls, all at
//             STOL 1e-9, FTOL 1e-12 (requirement (a), bound 1e-6);
//   default = 1 call per increment at the default controls (STOL 1e-5,
//             FTOL 1e-8) against that tight reference (requirement (b),
//             bound 1e-3).
// "fail n" counts calls that failed (the row is then not comparable). The
// substeps columns give the most substeps one call took (accepted, rejected
// and relaxation steps), over the tight runs (reference included) and over
// the default run. "drops apart" counts the increments in which one run
// dropped at fixed separation and the reference did not, or the other way
// round; there the reference one increment either side counts too (worst,
// splitting_paths.hpp).
//
// Usage: splitting_table [--h 1e-3,1e-4,1e-5] [--family NAME] [--set NAME]
//                        [--all-sets] [--implicit]
// --implicit: instead, the implicit scheme at the default controls, 1 call
// per increment, against the same tight reference of the default scheme.
// Without --all-sets, h < 1e-3 runs the sets and shortened paths the tests
// run there (fine_cells in splitting_cells.hpp). Then the bench's
// cap_reversal at 1e-2 mm (bench_cells; --family cap-reversal alone).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "splitting_cells.hpp"

using namespace mj_test::splitting;

namespace {

struct Options {
  std::vector<double> hs = {1e-3, 1e-4, 1e-5};
  std::string family, set;
  bool all_sets = false;
  bool implicit = false;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const char* v = i + 1 < argc ? argv[i + 1] : "";
    if (a == "--h") {
      o.hs.clear();
      std::stringstream ss(v);
      for (std::string x; std::getline(ss, x, ',');) o.hs.push_back(std::atof(x.c_str()));
      ++i;
    } else if (a == "--family") {
      o.family = v;
      ++i;
    } else if (a == "--set") {
      o.set = v;
      ++i;
    } else if (a == "--all-sets") {
      o.all_sets = true;
    } else if (a == "--implicit") {
      o.implicit = true;
    } else {
      std::fprintf(stderr, "usage: %s [--h 1e-3,1e-4,1e-5] [--family NAME] [--set NAME] [--all-sets] [--implicit]\n", argv[0]);
      std::exit(2);
    }
  }
  return o;
}

std::string cell_text(double e, long failures) {
  char b[64];
  if (failures) std::snprintf(b, sizeof b, "fail %ld", failures);
  else std::snprintf(b, sizeof b, "%.1e", e);
  return b;
}

void row(const std::string& family, const NamedSet& ns, const Cell& c, bool implicit) {
  if (implicit) {  // the implicit scheme's columns only
    const Measured m = measure(family, ns, c, {}, {}, true);
    std::printf("| %s | %s | %.0e | %zu | %s | %ld | %ld |\n", family.c_str(), ns.name.c_str(), c.h, m.increments,
                cell_text(m.implicit, m.implicit_failures + m.reference_failures).c_str(), m.implicit_work,
                m.drops_apart);
    std::fflush(stdout);
    return;
  }
  const Measured m = measure(family, ns, c);
  const long tf = m.tight_failures + m.reference_failures;
  std::printf("| %s | %s | %.0e | %zu | %s | %s | %s | %ld | %ld | %ld | %s |\n", family.c_str(), ns.name.c_str(),
              c.h, m.increments, cell_text(m.tight_by_calls[0], tf).c_str(), cell_text(m.tight_by_calls[1], tf).c_str(),
              cell_text(m.defaults, m.default_failures + m.reference_failures).c_str(), m.tight_work,
              m.default_work, m.drops_apart, (m.tight <= 1e-6 && m.defaults <= 1e-3 && !m.any_failure()) ? "yes" : "**no**");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  if (o.implicit)
    std::printf("| family | set | h (mm) | increments | implicit, 1 call | substeps per call, implicit "
                "| drops apart |\n|---|---|---|---|---|---|---|\n");
  else
    std::printf("| family | set | h (mm) | increments | tight, 1 call | tight, 20 calls | default, 1 call "
              "| substeps per call, tight | substeps per call, default | drops apart | within 1e-6 / 1e-3 |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& family : families()) {
    if (!o.family.empty() && family != o.family) continue;
    for (double h : o.hs) {
      for (const Cell& c : o.all_sets || h >= 1e-3 ? all_cells(h) : fine_cells(family, h)) {
        if (!o.set.empty() && c.set != o.set) continue;
        row(family, set_named(c.set), c, o.implicit);
      }
    }
  }
  if (o.family.empty() || o.family == "cap-reversal")
    for (const Cell& c : bench_cells())
      if (o.set.empty() || c.set == o.set) row("cap-reversal", set_named(c.set), c, o.implicit);
  return 0;
}
