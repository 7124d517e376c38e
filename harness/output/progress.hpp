// Progress of long runs on the terminal: a percentage rewritten in place on
// stderr when stderr is a terminal, nothing otherwise (logs stay clean), and
// nothing at all when quiet.
#pragma once

#include <string>

namespace mortar::harness {

class Progress {
 public:
  Progress(std::string label, bool quiet);
  ~Progress();
  void update(long done, long total);
  void finish();  // clears the line

 private:
  std::string label_;
  bool active_;
  int shown_ = -1;
};

}  // namespace mortar::harness
