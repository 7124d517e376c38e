// The joint test: one loading program (input/protocol.hpp) applied to N
// identical interface points, the way a laboratory test loads a joint.
//
// Targets ramp linearly over a step from where the point was at the step's
// start to the step's end value, reaching the end value exactly. A traction
// that was already controlled in the step before ramps from that step's
// target (so a held traction is held exactly), otherwise from the traction
// the point carried. `target_scale` (optional) multiplies point k's targets,
// which lets tests give every point a different history.
#pragma once

#include <functional>
#include <vector>

#include "input/protocol.hpp"
#include "scenes/scene.hpp"

namespace mortar::harness {

class JointTest : public Scene {
 public:
  JointTest(const Protocol& protocol, int points, const std::function<double(int)>& target_scale = {});

  int points() const override { return static_cast<int>(scale_.size()); }
  int directions() const override { return protocol_.directions; }
  int steps() const override { return static_cast<int>(protocol_.steps.size()); }
  long increments(int step) const override { return protocol_.steps[static_cast<size_t>(step)].increments; }
  void begin_step(int step, int point, const Eigen::Vector3d& separation, const Eigen::Vector3d& traction) override;
  PointTargets targets(int step, long i, int point) const override;
  std::string origin(int step) const override;

 private:
  struct StepStart {
    Eigen::Vector3d separation = Eigen::Vector3d::Zero();
    Eigen::Vector3d traction = Eigen::Vector3d::Zero();
  };
  const Protocol& protocol_;
  std::vector<double> scale_;
  std::vector<StepStart> start_;
};

}  // namespace mortar::harness
