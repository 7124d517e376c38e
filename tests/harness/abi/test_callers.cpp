// The two callers of the ABI behind one interface (abi/caller.hpp): the same
// trial gives the same traction in the law's signs through vuinteraction_
// and uinter_, every call starts from the committed start, and UINTER's
// tangent comes back as d traction / d separation.
#include <catch2/catch.hpp>

#include <memory>

#include "abi/props.hpp"
#include "abi/uinter_caller.hpp"
#include "abi/vuinteraction_caller.hpp"
#include "mortar/state_layout.hpp"

using namespace mortar;
using namespace mortar::harness;

namespace {
const Parameters kVdp{209.9, 87.4, 0.62, 0.88, 0.00458, 0.058, 40.97, 36.87, 1217.7, 27.7, 0, 1828.3, 10, 3};

std::unique_ptr<Caller> make_caller(bool uinter) {
  const std::vector<double> props = props_for(kVdp, Scheme::modified_euler, 0);
  if (uinter) return std::make_unique<UinterCaller>(UinterSetup{3, kStateCount, props});
  AbiSetup setup;
  setup.n_dir = 3;
  setup.n_states = kStateCount;
  setup.props = props;
  setup.stiffness_default = kVdp.kn;
  auto caller = std::make_unique<VuinteractionCaller>(setup, 1, 0);
  // VUINTERACTION takes its first call as the reference state.
  caller->set_trial(0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  caller->call(CallTime{});
  caller->accept(0);
  caller->commit();
  return caller;
}

Eigen::Vector3d traction_at(Caller& c, const Eigen::Vector3d& end) {
  c.set_trial(0, end, end);
  CallTime time;
  time.increment = 1;
  time.time_increment = time.step_time = time.total_time = 1;
  c.call(time);
  return c.traction(0);
}
}  // namespace

TEST_CASE("Callers: one trial, one traction in the law's signs, from either entry point", "[abi]") {
  const bool uinter = GENERATE(false, true);
  CAPTURE(uinter);
  auto caller = make_caller(uinter);
  // Closed and elastic: sigma = (kn dn, ks ds1, ks ds2).
  const Eigen::Vector3d end(-1e-4, 2e-4, -1e-4);
  const Eigen::Vector3d t = traction_at(*caller, end);
  CHECK(caller->status(0) == 0.0);
  CHECK(t[0] == Approx(kVdp.kn * end[0]).epsilon(1e-12));
  CHECK(t[1] == Approx(kVdp.ks * end[1]).epsilon(1e-12));
  CHECK(t[2] == Approx(kVdp.ks * end[2]).epsilon(1e-12));
}

TEST_CASE("Callers: a call does not commit but accept and commit do", "[abi]") {
  const bool uinter = GENERATE(false, true);
  CAPTURE(uinter);
  auto caller = make_caller(uinter);
  const Eigen::Vector3d a(0.0, 0.05, 0.0), b(0.0, 1e-4, 0.0);  // a far into softening, b elastic
  const Eigen::Vector3d first = traction_at(*caller, b);
  traction_at(*caller, a);
  CHECK(traction_at(*caller, b) == first);  // the start is untouched by the call at a
  traction_at(*caller, a);
  caller->accept(0);
  caller->commit();
  CHECK(caller->state(0)[slot::work_II] > 0.0);  // the committed start has slipped plastically
  CHECK(caller->dissipation_increment(0) > 0.0);
}

TEST_CASE("Callers: UINTER's DDSDDR comes back as d traction / d separation", "[abi]") {
  auto uinter = make_caller(true);
  auto vuinteraction = make_caller(false);
  Eigen::Matrix3d T;
  CHECK_FALSE(vuinteraction->tangent(0, T));  // VUINTERACTION returns no tangent
  traction_at(*uinter, Eigen::Vector3d(-1e-4, 1e-4, 0.0));
  REQUIRE(uinter->tangent(0, T));
  CHECK(T(0, 0) == Approx(kVdp.kn));
  CHECK(T(1, 1) == Approx(kVdp.ks));
  CHECK(T(2, 2) == Approx(kVdp.ks));
  CHECK(std::abs(T(0, 1)) + std::abs(T(1, 0)) == Approx(0.0).margin(1e-9));
}
