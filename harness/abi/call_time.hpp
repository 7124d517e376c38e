// The counters and times the solver hands the routine with every call:
// VUINTERACTION's jFlags(1..2) and rData(1..3), UINTER's KSTEP, KINC, KIT,
// TIME(1..2) and DTIME.
#pragma once

namespace mortar::harness {

struct CallTime {
  int step = 1;               // jFlags(1), KSTEP
  int increment = 0;          // jFlags(2), KINC: a cut-back retries the same number
  int iteration = 0;          // KIT (UINTER only)
  double step_time = 0;       // rData(1), TIME(1): at the end of the increment
  double total_time = 0;      // rData(2), TIME(2)
  double time_increment = 0;  // rData(3), DTIME
};

}  // namespace mortar::harness
