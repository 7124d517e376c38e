// Mixed control through the ABI: every controlled traction is held within the
// stated tolerance at every increment, displacements are imposed exactly, and
// the harness reads the routine's signs and energies as documented.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

#include "abi/props.hpp"
#include "abi/uinter_caller.hpp"
#include "abi/vuinteraction_caller.hpp"
#include "mortar/state_layout.hpp"
#include "scenes/joint_test.hpp"
#include "solvers/mixed_control_solver.hpp"
#include "support.hpp"

using namespace mortar;
using namespace mortar::harness;
using namespace mortar::harness::testing;

namespace {
// Worst |sigma_j - target_j| over the traction-controlled components, and
// worst |delta_j - target_j| over the displacement-controlled ones.
struct Misfit {
  double traction = 0, separation = 0;
  long controlled = 0;
};
Misfit misfit(const std::vector<Sample>& curve) {
  Misfit m;
  for (const Sample& s : curve) {
    if (s.increment == 0) continue;
    for (int j = 0; j < 3; ++j) {
      if (s.traction_controlled[j]) {
        ++m.controlled;
        m.traction = std::max(m.traction, std::abs(s.traction[j] - s.target[j]));
      } else {
        m.separation = std::max(m.separation, std::abs(s.separation[j] - s.target[j]));
      }
    }
  }
  return m;
}
}  // namespace

TEST_CASE("Controlled tractions are held within the tolerance at every increment", "[mixed]") {
  const double tolerance = GENERATE(1e-9, 1e-12);
  const std::string program = GENERATE(std::string("short_shear.toml"), std::string("three_components.toml"));
  CAPTURE(tolerance, program);
  // Arrange
  const ParameterSet params = read_parameter_file(data_file("vdp_sn0.5.toml"));
  const Protocol protocol = read_protocol_file(data_file(program));
  RunSettings settings;
  settings.mixed.traction_tolerance = tolerance;
  // Act
  const std::vector<Sample> curve = run_one_point(params.values, protocol, settings);
  // Assert
  REQUIRE(curve.size() == static_cast<size_t>(protocol.total_increments()) + 1);
  const Misfit m = misfit(curve);
  CHECK(m.controlled > 0);
  CHECK(m.traction <= tolerance);
  CHECK(m.separation <= 1e-15);
  double worst_reported = 0;
  for (const Sample& s : curve) worst_reported = std::max(worst_reported, s.traction_residual);
  CHECK(worst_reported <= tolerance);
}

TEST_CASE("A held traction is the step's target, not a ramp, after the step that set it", "[mixed]") {
  const ParameterSet params = read_parameter_file(data_file("vdp_sn0.5.toml"));
  const Protocol protocol = read_protocol_file(data_file("three_components.toml"));
  const std::vector<Sample> curve = run_one_point(params.values, protocol, RunSettings{});
  long off_target = 0;
  for (const Sample& s : curve) {
    if (s.step < 2) continue;
    off_target += s.target[0] != -0.8;
    if (s.step == 2) off_target += s.target[2] != 0.3;
  }
  CHECK(off_target == 0);
  // The s2 traction of step 3 ramps from 0.3 to 0 over its 100 increments.
  CHECK(curve.back().target[2] == 0.0);
  CHECK(curve[440 + 50].target[2] == Approx(0.15).margin(1e-12));
}

TEST_CASE("Signs: compression closes, positive slip gives positive shear (law signs)", "[mixed]") {
  // Arrange
  const ParameterSet params = read_parameter_file(data_file("vdp_sn0.5.toml"));
  const Parameters& p = params.values;
  const Protocol protocol = read_protocol_file(data_file("short_shear.toml"));
  // Act
  const std::vector<Sample> curve = run_one_point(p, protocol, RunSettings{});
  // Assert: after the normal step the joint is closed elastically by sigma_n / kn.
  const Sample& loaded = curve[20];
  CHECK(loaded.traction[0] == Approx(-0.5).margin(1e-9));
  CHECK(loaded.separation[0] == Approx(-0.5 / p.kn).epsilon(1e-8));
  CHECK(loaded.elastic_energy == Approx(0.5 * 0.5 * 0.5 / p.kn).epsilon(1e-8));
  // First slip increment (elastic): tau = ks * slip, positive, in the law's convention.
  const Sample& first_slip = curve[21];
  CHECK(first_slip.separation[1] == Approx(0.0001));
  CHECK(first_slip.traction[1] == Approx(p.ks * 0.0001).epsilon(1e-10));
  // The routine's state agrees with the separation the harness imposed.
  double worst = 0;
  for (const Sample& s : curve)
    for (int j = 0; j < 3; ++j) worst = std::max(worst, std::abs(s.state[slot::separation_n + j] - s.separation[j]));
  CHECK(worst <= 1e-15);
}

TEST_CASE("A failure the routine reports in SDV21 stops the run with the code and its meaning", "[mixed]") {
  // Arrange: max substeps = 1 (props(18)) makes the law give up on a plastic increment.
  const ParameterSet params = read_parameter_file(data_file("vdp_sn0.5.toml"));
  AbiSetup setup;
  setup.n_dir = 3;
  setup.n_states = kStateCount;
  setup.props = props_for(params.values, Scheme::modified_euler, 0, 1);
  setup.stiffness_default = params.values.kn;
  MixedControlSolver block(setup, 0, 3, MixedControlOptions{});
  CallTime info;
  block.reference_call(info);
  PointTargets far[3];
  for (PointTargets& t : far) t.value = {0.0, 0.05, 0.0};  // far past the peak in one increment
  // Act / Assert
  info.increment = 1;
  CHECK_THROWS_WITH(block.advance(far, info),
                    Catch::Contains("point 1, step 1, increment 1: the call failed") &&
                        Catch::Contains("status 1 in SDV21: too many substeps"));
}

TEST_CASE("The Newton system is solved on the free components only", "[mixed]") {
  PointTargets t;
  t.kind = {Control::traction, Control::displacement, Control::traction};
  Eigen::Matrix3d K;
  K << 4, 1, 2,  //
      7, 9, 8,   // the displacement-controlled row and column must not matter
      1, 5, 3;
  const Eigen::Vector3d rhs(1.0, 100.0, 2.0);
  const Eigen::Vector3d x = solve_on_free(t, K, rhs);
  CHECK(x[1] == 0.0);
  CHECK(4 * x[0] + 2 * x[2] == Approx(1.0));
  CHECK(1 * x[0] + 3 * x[2] == Approx(2.0));
  // Two directions: the third component is never an unknown.
  const Eigen::Vector3d x2 = solve_on_free(t, K, rhs, 2);
  CHECK(x2[0] == Approx(0.25));
  CHECK(x2[2] == 0.0);
  CHECK(failure_location(2, 3, 17) == "point 3, step 3, increment 17: ");
}

TEST_CASE("One mixed-control solver, either caller: the same curve through vuinteraction_ and uinter_", "[mixed]") {
  // Arrange: the short shear program (normal traction held, slip imposed).
  const ParameterSet params = read_parameter_file(data_file("vdp_sn0.5.toml"));
  const Protocol protocol = read_protocol_file(data_file("short_shear.toml"));
  const Parameters& p = params.values;
  const std::vector<double> props = props_for(p, Scheme::modified_euler, 0);
  AbiSetup setup;
  setup.n_dir = protocol.directions;
  setup.n_states = kStateCount;
  setup.props = props;
  setup.stiffness_default = p.kn;
  const Eigen::Vector3d elastic(p.kn, p.ks, p.ks);
  MixedControlSolver through_vuinteraction(std::make_unique<VuinteractionCaller>(setup, 1, 0), 0, elastic, {});
  MixedControlSolver through_uinter(
      std::make_unique<UinterCaller>(UinterSetup{protocol.directions, kStateCount, props}), 0, elastic, {});
  JointTest scene(protocol, 1);
  // Act
  double worst = 0;
  long increments = 0;
  for (MixedControlSolver* b : {&through_vuinteraction, &through_uinter}) b->reference_call(CallTime{});
  for (int s = 0; s < scene.steps(); ++s) {
    const PointResult& r = through_vuinteraction.result(0);
    scene.begin_step(s, 0, r.separation, r.traction);
    for (long i = 1; i <= scene.increments(s); ++i) {
      const PointTargets t = scene.targets(s, i, 0);
      CallTime time;
      time.step = s + 1;
      time.increment = static_cast<int>(i);
      for (MixedControlSolver* b : {&through_vuinteraction, &through_uinter}) b->advance(&t, time);
      const PointResult &a = through_vuinteraction.result(0), &u = through_uinter.result(0);
      worst = std::max({worst, (a.traction - u.traction).cwiseAbs().maxCoeff(),
                        (a.separation - u.separation).cwiseAbs().maxCoeff()});
      ++increments;
    }
  }
  // Assert: both routines integrate the same law in double precision (measured: identical).
  CHECK(increments == protocol.total_increments());
  CHECK(worst <= 1e-12);
  CHECK(through_uinter.result(0).traction[1] > 0.1);  // sheared through the peak, softened but loaded
}
