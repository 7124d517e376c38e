// The files of `masonry-joint scene`: the history (one row every few
// increments), the wall at chosen instants (bodies displaced, joint points
// with damage and opening) and the summary text.
#pragma once

#include <string>
#include <vector>

#include "input/scene_file.hpp"
#include "solvers/block_solver.hpp"

namespace mortar::harness {

// Streams history rows into a CSV (header on construction).
class HistoryCsv {
 public:
  explicit HistoryCsv(const std::string& path);
  ~HistoryCsv();
  void row(const WallSample& s);

 private:
  struct Impl;
  Impl* impl_;
};

// snapshot_<k>_blocks.csv (one outline per body, displaced by `magnification`
// times its displacement, blank line between bodies) and
// snapshot_<k>_joints.csv (x, y displaced, damage, opening of every point).
void write_snapshot_csv(const std::string& dir, int k, const WallModel& m, const WallSnapshot& s,
                        double magnification);

std::string scene_summary(const SceneSpec& spec, const WallModel& m, const WallRunSummary& r,
                          const WallSample& last);

}  // namespace mortar::harness
