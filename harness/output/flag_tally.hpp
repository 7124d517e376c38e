// The integration flags (SDV 35, docs/model.md 9) of a run's points, as the
// summaries of `run`, `validate` and `scene` report them: for each flag, the
// points that hold it at the end and the increments that raised it at a
// point for the first time (the flags are OR'd over a point's history).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mortar/result.hpp"

namespace mortar::harness {

class FlagTally {
 public:
  // Point `point`'s SDV 35 after an increment.
  void add(int point, int flags);
  // "integration flags (SDV 35): none" or, for each flag raised, "name: P
  // point(s), I increment(s) raising it" (without the increments when the
  // points were added once, at the end).
  std::string summary(bool increments = true) const;
  std::array<int, integration_flag::kCount> points() const;

  // Point `point` went through `increments` increment(s) opened so far that
  // the routine took it as unpaired (abi_signs::unpaired): not integrated.
  void add_unpaired(int point, long increments = 1);
  // "" when none; else a warning naming the increments and points (the
  // routine's answer there, zero traction, is not the law's).
  std::string unpaired_warning() const;

 private:
  std::vector<int> last_;
  std::vector<long> unpaired_;
  std::array<long, integration_flag::kCount> raised_{};
};

}  // namespace mortar::harness
