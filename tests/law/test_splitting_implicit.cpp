// One law in every scheme (docs/model.md 7.5): the implicit scheme at the
// default controls, one call per increment, against the default scheme's
// tight reference (STOL 1e-9, FTOL 1e-12, each increment cut into 100 calls),
// on every family of the splitting study, within 1e-3 of the path's peak.
// Decisions it shares with the substepped scheme (complete separation,
// closure, the slip reversing on the tension cap, the apex, the step to the
// regime boundary) would show here as errors that do not shrink with h.
// The table: splitting_table --implicit (docs/robustness.md).
#include "splitting_check.hpp"

using namespace mj_test::splitting;

namespace {
void check_implicit(const std::string& family, const std::vector<Cell>& cells) {
  for (const Cell& c : first_scaled(cells)) {
    const Measured m = measure(family, set_named(c.set), c, {}, {}, true);
    INFO(family << ", set " << c.set << ", h = " << c.h << " mm, " << m.increments << " increments");
    REQUIRE(m.peak > 0);
    CHECK(m.reference_failures + m.implicit_failures == 0);
    CHECK(m.implicit <= 1e-3);
  }
}
}  // namespace

TEST_CASE("Splitting: the implicit scheme against the default scheme's tight reference, h = 1e-3 mm",
          "[splitting][implicit]") {
  for (const std::string& family : families()) check_implicit(family, all_cells(1e-3));
}

TEST_CASE("Splitting: the implicit scheme against the default scheme's tight reference, h = 1e-4, 1e-5 mm",
          "[splitting][implicit]") {
  for (const std::string& family : families()) {
    check_implicit(family, fine_cells(family, 1e-4));
    check_implicit(family, fine_cells(family, 1e-5));
  }
}
