// The joint test scene: targets ramp from the step's start to its end value
// and reach it exactly; a held traction ramps from the last target, not from
// the traction carried; point k's targets scale with target_scale(k).
#include <catch2/catch.hpp>

#include "scenes/joint_test.hpp"

using namespace mortar::harness;

namespace {
ProgramStep step_of(long increments, ComponentProgram n, ComponentProgram s1) {
  ProgramStep s;
  s.increments = increments;
  s.component = {n, s1, ComponentProgram{}};
  return s;
}

Protocol two_steps() {
  Protocol p;
  p.file = "program.toml";
  p.steps.push_back(step_of(4, {Control::traction, -0.5}, {Control::displacement, 0.0}));
  p.steps[0].name = "step 1";
  p.steps.push_back(step_of(3, {Control::traction, -0.2}, {Control::displacement, 0.3}));
  p.steps[1].name = "shear";
  p.steps[1].line = 7;
  return p;
}
}  // namespace

TEST_CASE("Scene: targets ramp linearly from where the point was and end exactly", "[scenes]") {
  const Protocol p = two_steps();
  JointTest scene(p, 1);
  scene.begin_step(0, 0, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.1, 0.0, 0.0));
  CHECK(scene.targets(0, 0, 0).value[0] == 0.1);  // the traction carried
  CHECK(scene.targets(0, 2, 0).value[0] == Approx(0.1 + (-0.5 - 0.1) * 0.5));
  CHECK(scene.targets(0, 4, 0).value[0] == -0.5);
  CHECK(scene.targets(0, 4, 0).kind[0] == Control::traction);
  CHECK(scene.targets(0, 4, 0).kind[1] == Control::displacement);
}

TEST_CASE("Scene: a traction held from the step before ramps from that step's target", "[scenes]") {
  const Protocol p = two_steps();
  JointTest scene(p, 1);
  // The point carries -0.4999 MPa (within the solver's tolerance) and has slipped 0.01 mm.
  scene.begin_step(1, 0, Eigen::Vector3d(0.0, 0.01, 0.0), Eigen::Vector3d(-0.4999, 0.2, 0.0));
  CHECK(scene.targets(1, 0, 0).value[0] == -0.5);
  CHECK(scene.targets(1, 0, 0).value[1] == 0.01);
  CHECK(scene.targets(1, 3, 0).value[1] == 0.3);
}

TEST_CASE("Scene: every point's targets scale with target_scale", "[scenes]") {
  const Protocol p = two_steps();
  JointTest scene(p, 3, [](int k) { return 1.0 + k; });
  REQUIRE(scene.points() == 3);
  for (int k = 0; k < 3; ++k) scene.begin_step(0, k, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  CHECK(scene.targets(0, 4, 0).value[0] == -0.5);
  CHECK(scene.targets(0, 4, 2).value[0] == -1.5);
}

TEST_CASE("Scene: the clock and the origin of a step", "[scenes]") {
  const Protocol p = two_steps();
  JointTest scene(p, 1);
  CHECK(scene.total_increments() == 7);
  const IncrementClock c = clock_of(scene, 1, 2);
  CHECK(c.time_increment == 1.0 / 3.0);
  CHECK(c.step_time == 2.0 / 3.0);
  CHECK(c.total_time == 1.0 + 2.0 / 3.0);
  CHECK(scene.origin(1) == "; step 2 ('shear') is defined at program.toml:7");
  CHECK(scene.origin(0) == "; step 1 is defined at program.toml:0");  // no name of its own
}
