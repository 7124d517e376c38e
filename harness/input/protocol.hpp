// Loading programs ("protocols"): what the mock solver imposes on a joint.
//
// A protocol is a list of steps. In each step every component of the
// separation (n, s1, s2) is either displacement-controlled or
// traction-controlled, with a target reached at the end of the step, linear
// in between. Cycle steps (fully reversed displacement cycles of growing
// amplitude) are written compactly and expanded here into one step per leg.
// The file format is documented in harness/README.md.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "scenes/targets.hpp"

namespace mortar::harness {

struct ComponentProgram {
  Control kind = Control::displacement;
  double target = 0;  // separation [mm] or traction [MPa] at the end of the step, law signs
};

struct ProgramStep {
  std::string name;  // for messages and progress ("step 2", or the name given in the file)
  int line = 0;      // line of the [[step]] that defined it
  long increments = 1;
  std::array<ComponentProgram, 3> component;
};

struct Protocol {
  std::string file;
  std::string title;
  int directions = 3;              // nDir of the calls: 2 (one slip) or 3
  std::vector<ProgramStep> steps;  // cycle steps already expanded into legs
  long total_increments() const;
};

inline constexpr long kMaxIncrementsPerStep = 10'000'000;
inline constexpr long kMaxIncrementsTotal = 50'000'000;
// A traction target beyond this is refused (exit 2): no joint comes near it.
inline constexpr double kMaxTractionTarget = 1e4;  // MPa
// The largest displacement target or cycle amplitude [mm]: an opening this
// large is already far past any joint (the routine takes it as unpaired);
// beyond it the law's arithmetic leaves its tested range.
inline constexpr double kMaxDisplacementTarget = 1e30;

Protocol read_protocol_file(const std::string& path);

}  // namespace mortar::harness
