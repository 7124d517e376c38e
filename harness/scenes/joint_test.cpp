#include "scenes/joint_test.hpp"

namespace mortar::harness {

long Scene::total_increments() const {
  long n = 0;
  for (int s = 0; s < steps(); ++s) n += increments(s);
  return n;
}

IncrementClock clock_of(const Scene& scene, int step, long i) {
  const double n = double(scene.increments(step));
  IncrementClock c;
  c.time_increment = 1.0 / n;
  c.step_time = double(i) / n;
  c.total_time = double(step) + c.step_time;
  return c;
}

JointTest::JointTest(const Protocol& protocol, int points, const std::function<double(int)>& target_scale)
    : protocol_(protocol), scale_(static_cast<size_t>(points), 1.0), start_(static_cast<size_t>(points)) {
  if (target_scale)
    for (int k = 0; k < points; ++k) scale_[static_cast<size_t>(k)] = target_scale(k);
}

void JointTest::begin_step(int, int point, const Eigen::Vector3d& separation, const Eigen::Vector3d& traction) {
  start_[static_cast<size_t>(point)] = StepStart{separation, traction};
}

PointTargets JointTest::targets(int step, long i, int point) const {
  const ProgramStep& s = protocol_.steps[static_cast<size_t>(step)];
  const ProgramStep* before = step > 0 ? &protocol_.steps[static_cast<size_t>(step - 1)] : nullptr;
  const double f = double(i) / double(s.increments), scale = scale_[static_cast<size_t>(point)];
  const StepStart& at = start_[static_cast<size_t>(point)];
  PointTargets t;
  for (int j = 0; j < 3; ++j) {
    const ComponentProgram& c = s.component[j];
    const double end = scale * c.target;
    double from = c.kind == Control::displacement ? at.separation[j] : at.traction[j];
    if (c.kind == Control::traction && before && before->component[j].kind == Control::traction)
      from = scale * before->component[j].target;
    t.kind[j] = c.kind;
    t.value[j] = i == s.increments ? end : from + (end - from) * f;
  }
  return t;
}

std::string JointTest::origin(int step) const {
  const ProgramStep& s = protocol_.steps[static_cast<size_t>(step)];
  const std::string number = std::to_string(step + 1);
  const std::string name = s.name == "step " + number ? "" : " ('" + s.name + "')";
  return "; step " + number + name + " is defined at " + protocol_.file + ":" + std::to_string(s.line);
}

}  // namespace mortar::harness
