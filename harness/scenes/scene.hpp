// A scene: the interface points a mock solver drives and the way their
// targets are produced. The solvers (solvers/) know nothing of protocols or
// geometry: they ask the scene, step by step and increment by increment, what
// every point must reach, solve it and commit it, and tell the scene where the
// points are at the start of each step.
//
// Today's scene is the joint test (scenes/joint_test.hpp): one loading
// program applied to N points. A wall of rigid blocks plugs in the same way:
// many points whose separation targets come from the blocks' motions (and
// whose begin_step sees the points' tractions, from which block forces follow).
#pragma once

#include <string>

#include <Eigen/Core>

#include "scenes/targets.hpp"

namespace mortar::harness {

class Scene {
 public:
  virtual ~Scene() = default;

  virtual int points() const = 0;
  virtual int directions() const = 0;  // nDir of every call: 2 (one slip) or 3
  virtual int steps() const = 0;
  virtual long increments(int step) const = 0;  // of step 0..steps()-1
  long total_increments() const;

  // The committed separation and traction (law signs) of `point` at the
  // start of `step`, before the step's first targets are asked for.
  virtual void begin_step(int step, int point, const Eigen::Vector3d& separation,
                          const Eigen::Vector3d& traction) = 0;
  // What `point` must reach after increment i (0 = the step's start,
  // increments(step) = its end) of `step`.
  virtual PointTargets targets(int step, long i, int point) const = 0;
  // Where `step` comes from, appended to a failure message
  // ("; step 2 ('shear') is defined at file.toml:7").
  virtual std::string origin(int step) const = 0;
};

// The program's clock of increment i of step s: each step lasts 1, in
// increments of equal length (jFlags/rData of VUINTERACTION, TIME/DTIME of
// UINTER).
struct IncrementClock {
  double time_increment = 0, step_time = 0, total_time = 0;
};
IncrementClock clock_of(const Scene& scene, int step, long i);

}  // namespace mortar::harness
