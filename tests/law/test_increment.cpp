// One increment's loop of segments (src/mortar/integration/increment.*,
// docs/model.md 9): what bounds it, and which failure each bound reports.
#include <catch2/catch.hpp>


#include "mortar/integration/increment.hpp"
#include "formatted.hpp"

using namespace mortar;

TEST_CASE("Segments: restarts in one regime are not regime segments, and have their own honest bound",
          "[increment][failure]") {
  // An increment whose substepper hands the rest back 40 times (the point
  // left the surface and yields again further on) across 3 regime switches
  // has 4 regime segments: no code 3 (more than 32 regime segments).
  const Controls c;
  SegmentCount n;
  Failure first = Failure::none;
  int segments_asked = 0;
  for (int i = 0; i < 43; ++i) {
    const Failure f = n.check(c);
    ++segments_asked;
    if (f != Failure::none) {
      first = f;
      break;
    }
    if (i % 11 == 10) {
      ++n.switches;
    } else {
      ++n.restarts;
    }
  }
  INFO(mj_test::formatted("[increment] %ld restarts, %d switches: %s after %d segments asked", n.restarts, n.switches,
                          failure_name(first), segments_asked));
  CHECK(first == Failure::none);
  CHECK(n.restarts == 40);
  CHECK(n.switches == 3);
  // The regime segments: 32 are allowed, the 33rd (after 32 switches) is code 3.
  n.switches = kMaxSegments - 1;
  CHECK(n.check(c) == Failure::none);
  n.switches = kMaxSegments;
  CHECK(n.check(c) == Failure::too_many_switches);
  // Restarts: each follows at least one accepted substep, so the substep
  // budget bounds them; beyond it the loop stops with code 1, whatever the
  // switches.
  SegmentCount r;
  r.restarts = c.max_substeps;
  CHECK(r.check(c) == Failure::none);
  r.restarts = long(c.max_substeps) + 1;
  CHECK(r.check(c) == Failure::too_many_substeps);
}
