#include "output/flag_tally.hpp"

namespace mortar::harness {

void FlagTally::add(int point, int flags) {
  if (point >= static_cast<int>(last_.size())) last_.resize(static_cast<size_t>(point) + 1, 0);
  const int raised = flags & ~last_[static_cast<size_t>(point)];
  for (int b = 0; b < integration_flag::kCount; ++b)
    if (raised & (1 << b)) ++raised_[static_cast<size_t>(b)];
  last_[static_cast<size_t>(point)] |= flags;
}

std::array<int, integration_flag::kCount> FlagTally::points() const {
  std::array<int, integration_flag::kCount> n{};
  for (int flags : last_)
    for (int b = 0; b < integration_flag::kCount; ++b)
      if (flags & (1 << b)) ++n[static_cast<size_t>(b)];
  return n;
}

void FlagTally::add_unpaired(int point, long increments) {
  if (increments <= 0) return;
  if (point >= static_cast<int>(unpaired_.size())) unpaired_.resize(static_cast<size_t>(point) + 1, 0);
  unpaired_[static_cast<size_t>(point)] += increments;
}

std::string FlagTally::unpaired_warning() const {
  long increments = 0, points = 0;
  for (long n : unpaired_) increments += n, points += n > 0;
  if (increments == 0) return "";
  return "warning: " + std::to_string(increments) + " point-increment(s) at " + std::to_string(points) +
         " point(s) opened by 1e30 mm or more: the routine takes such a point as unpaired (no opposite "
         "surface, penetration <= -1e30), returns zero traction and leaves its state as it was; those results "
         "are not the law's (docs/abaqus.md, Unpaired slave nodes)";
}

std::string FlagTally::summary(bool increments) const {
  const std::array<int, integration_flag::kCount> n = points();
  std::string s = "integration flags (SDV 35):";
  bool any = false;
  for (int b = 0; b < integration_flag::kCount; ++b) {
    const size_t i = static_cast<size_t>(b);
    if (n[i] == 0) continue;
    s += std::string(any ? "; " : " ") + integration_flag::kNames[b] + ": " + std::to_string(n[i]) + " point(s)";
    if (increments) s += ", " + std::to_string(raised_[i]) + " increment(s) raising it";
    any = true;
  }
  return any ? s : s + " none";
}

}  // namespace mortar::harness
