#include "output/progress.hpp"

#include <cstdio>

#include <unistd.h>

namespace mortar::harness {

Progress::Progress(std::string label, bool quiet) : label_(std::move(label)), active_(!quiet && isatty(2)) {}

Progress::~Progress() { finish(); }

void Progress::update(long done, long total) {
  if (!active_ || total <= 0) return;
  const int percent = static_cast<int>(100 * done / total);
  if (percent == shown_) return;
  shown_ = percent;
  std::fprintf(stderr, "\r%s %3d %%", label_.c_str(), percent);
  std::fflush(stderr);
}

void Progress::finish() {
  if (!active_ || shown_ < 0) return;
  std::fprintf(stderr, "\r%*s\r", static_cast<int>(label_.size()) + 8, "");
  std::fflush(stderr);
  shown_ = -1;
}

}  // namespace mortar::harness
