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

// A picture's displacement factor. Automatic: the largest relative
// displacement across a joint in the snapshot (|opening, slip| at a point,
// from the two bodies' motions) drawn as 5 % of the wall's height, so that
// a rigid motion of the whole wall does not set the scale.
struct Magnification {
  double factor = 1;
  double largest_relative = 0;  // [mm]
  bool automatic = true;        // false: the scene file's `magnification`
};
Magnification picture_magnification(const SceneOutputSpec& output, const WallModel& m, const WallSnapshot& s);

// snapshot_<k>_blocks.csv (one outline per body, displaced by `magnification`
// times its displacement, blank line between bodies) and
// snapshot_<k>_joints.csv (every point: x, y displaced, opening, slip, d_n,
// d_s, dissipated energy per unit area).
void write_snapshot_csv(const std::string& dir, int k, const WallModel& m, const WallSnapshot& s,
                        double magnification);

std::string scene_summary(const SceneSpec& spec, const WallModel& m, const WallRunSummary& r,
                          const WallSample& last);

}  // namespace mortar::harness
