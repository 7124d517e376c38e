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
