// The Abaqus/Explicit adapters' error reports through their C ABI, compiled
// once per precision: bad arguments and props reported with name, value and
// rule, SDV 21's codes, rejected points kept at their start state
// (docs/abaqus.md, docs/model.md 9).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "abi_support.hpp"
#include "explicit_calls.hpp"
#include "adapter/arguments.hpp"
#include "adapter/report.hpp"
#include "adapter/status_codes.hpp"
#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"
#include "paper_sets.hpp"
#include "stderr_capture.hpp"
#include "vuinteraction.h"

namespace {

using namespace mj_abi_test;
using mj_test::StderrCapture;
using Real = mj_real;
namespace slot = mortar::slot;
constexpr int kStates = mortar::kStateCount;

// A rejected block: the message names the routine, the interaction, the
// argument and the rule; every point carries `code` in SDV 21; the outputs
// are finite and the stress is what came in.
void check_rejected(const std::string& message, const std::vector<std::string>& parts, GeneralContact& gc,
                    int code, const std::vector<Real>& stress_in) {
  INFO("stderr: " << message);
  for (const std::string& part : parts) CHECK(message.find(part) != std::string::npos);
  for (int k = 0; k < gc.n_block; ++k) CHECK(gc.state_of(k)[slot::status] == Real(code));
  CHECK(gc.stress == stress_in);
  CHECK(all_finite(gc.sed));
  CHECK(all_finite(gc.spd));
  CHECK(std::all_of(gc.spd.begin(), gc.spd.end(), [](Real x) { return x == Real(0); }));
}

GeneralContact initialised_block(std::vector<Real> props, int states = kStates) {
  GeneralContact gc(3, 3, std::move(props), states);
  std::fill(gc.stress.begin(), gc.stress.end(), Real(0.25));
  return gc;
}

}  // namespace

TEST_CASE("bad arguments are reported and leave finite outputs", "[abi][errors]") {
  SECTION("nDir") {
    GeneralContact gc = initialised_block(paper_props());
    gc.n_dir = 1;  // fewer rows than allocated: still within the arrays
    const std::vector<Real> stress_in = gc.stress;
    StderrCapture err;
    gc.call();
    check_rejected(err.text(), {"VUINTERACTION", "interaction 'JOINT-A'", "nDir = 1", "2 (2D) or 3 (3D)"}, gc, -1,
                   stress_in);
  }
  SECTION("nStates below the layout") {
    GeneralContact gc(3, 3, paper_props(), 22);
    std::fill(gc.stress.begin(), gc.stress.end(), Real(0.25));
    const std::vector<Real> stress_in = gc.stress;
    StderrCapture err;
    gc.call();
    check_rejected(err.text(), {"nStates = 22", "at least 23 state variables"}, gc, -2, stress_in);
  }
  SECTION("nStates too small to hold the status: nothing outside the array is touched") {
    GeneralContact gc(3, 3, paper_props(), 10, 8);
    std::fill(gc.state.begin(), gc.state.end(), Real(-3));
    StderrCapture err;
    gc.call();
    const std::string message = err.text();
    CHECK(message.find("nStates = 10") != std::string::npos);
    CHECK(std::all_of(gc.state.begin(), gc.state.end(), [](Real x) { return x == Real(-3); }));
    CHECK(all_finite(gc.stress));
  }
  SECTION("nProps") {
    GeneralContact gc = initialised_block(paper_props(13));
    const std::vector<Real> stress_in = gc.stress;
    StderrCapture err;
    gc.call();
    check_rejected(err.text(), {"nProps = 13", "14 parameters"}, gc, -3, stress_in);
  }
  SECTION("nNodState") {
    GeneralContact gc = initialised_block(paper_props());
    gc.n_node_states = 0;
    StderrCapture err;
    gc.call();
    CHECK(err.text().find("nNodState = 0") != std::string::npos);
    CHECK(all_finite(gc.stress));
  }
  SECTION("non-finite incoming stress is not passed back") {
    GeneralContact gc = initialised_block(paper_props(13));
    gc.stress[1] = std::numeric_limits<Real>::quiet_NaN();
    gc.sed[2] = std::numeric_limits<Real>::infinity();
    StderrCapture err;
    gc.call();
    CHECK(all_finite(gc.stress));
    CHECK(all_finite(gc.sed));
  }
}

TEST_CASE("invalid properties and controls are reported with name, value and rule", "[abi][errors]") {
  struct Case {
    int index;
    double value;
    std::vector<std::string> parts;
  };
  const std::vector<Case> cases = {
      {3, 0.5, {"'c0' (props(4))", "= 0.5", "c0 > ft0*tan(phi0)"}},
      {0, -1.0, {"'kn' (props(1))", "0.01 <= kn <= 1e6 N/mm^3"}},
      {0, 1e7, {"'kn' (props(1))", "= 10000000", "kn <= 1e6 N/mm^3"}},
      {7, 45.0, {"'phir' (props(8))", "phir <= phi0"}},
      {14, 4.0, {"props(15)", "scheme is 1"}},
      {15, 2.0, {"props(16)", "STOL"}},
      {19, 0.5, {"props(20)", "0 (default, = -1), -1 or +1"}},
  };
  for (const Case& c : cases) {
    std::vector<Real> props = paper_props(20);
    props[c.index] = Real(c.value);
    GeneralContact gc = initialised_block(props);
    const std::vector<Real> stress_in = gc.stress;
    StderrCapture err;
    gc.call();
    std::vector<std::string> parts = c.parts;
    parts.push_back("interaction 'JOINT-A'");
    check_rejected(err.text(), parts, gc, -4, stress_in);
  }
}

TEST_CASE("SDV 21 reads back: the law's names for its codes, the adapter's for its own", "[abi][errors]") {
  using namespace mj_adapter;
  // The numbers docs/abaqus.md documents and the harness reads.
  CHECK(kBadDirections == -1);
  CHECK(kBadStateCount == -2);
  CHECK(kBadPropCount == -3);
  CHECK(kBadProperty == -4);
  CHECK(kBadNodeStates == -5);
  CHECK(kBadRotation == -6);
  CHECK(kInternalError == -9);
  for (int code = 0; code <= int(mortar::Failure::local_solve_failed); ++code)
    CHECK(std::string(status_meaning(code)) == mortar::failure_name(static_cast<mortar::Failure>(code)));
  CHECK(std::string(status_meaning(kBadDirections)) == "nDir is not 2 or 3");
  CHECK(std::string(status_meaning(kBadStateCount)) ==
        "fewer than 23 state variables (with a compression cap: 36, single precision 37)");
  CHECK(std::string(status_meaning(kBadPropCount)) == "fewer than 14 properties");
  CHECK(std::string(status_meaning(kBadProperty)).find("a property breaks its rule") == 0);
  CHECK(std::string(status_meaning(kBadNodeStates)) == "nNodState < 1");
  CHECK(std::string(status_meaning(kBadRotation)).find("dRot of a point is not a rotation") == 0);
  CHECK(std::string(status_meaning(kInternalError)) == "the routine's internal error");
}

TEST_CASE("messages name the interaction: trailing blanks cut, a hidden length beyond 1..80 read as 80", "[abi][errors]") {
  using mj_adapter::make_caller;
  const Name80 name("JOINT-A");
  auto named = [](const mj_adapter::Caller& c) { return std::string(c.name, c.name_length); };
  CHECK(named(make_caller("VUINTER", name.text, 80)) == "JOINT-A");
  CHECK(named(make_caller("VUINTER", name.text, 0)) == "JOINT-A");
  CHECK(named(make_caller("VUINTER", name.text, 1 << 20)) == "JOINT-A");
  CHECK(named(make_caller("VUINTER", name.text, 3)) == "JOI");
  CHECK(named(make_caller("VUINTER", Name80("").text, 80)).empty());
  CHECK(named(make_caller("VUINTER", nullptr, 80)) == "?");
}

TEST_CASE("the first array size that breaks its rule is the one reported", "[abi][errors]") {
  const mj_adapter::ArgumentNames names = {"nDir", "nDir is 2 (2D) or 3 (3D)", "nStates", "nProps", "dRot"};
  using mj_adapter::check_counts;
  CHECK(check_counts({1, 0, 0, 0}, names).code == mj_adapter::kBadDirections);
  CHECK(check_counts({3, 0, 0, 0}, names).code == mj_adapter::kBadNodeStates);
  CHECK(check_counts({3, 1, 22, 0}, names).code == mj_adapter::kBadStateCount);
  CHECK(std::string(check_counts({3, 1, 22, 0}, names).argument) == "nStates");
  CHECK(check_counts({2, 1, 23, 13}, names).code == mj_adapter::kBadPropCount);
  CHECK(check_counts({2, 1, 23, 14}, names).code == 0);
}

TEST_CASE("VUINTER reports bad arguments too", "[abi][errors]") {
  ContactPair cp(2, 3, paper_props(), 22);
  StderrCapture err;
  cp.call();
  const std::string message = err.text();
  CHECK(message.find("VUINTER, interaction 'PAIR-B'") != std::string::npos);
  CHECK(message.find("nStateVar = 22") != std::string::npos);
  CHECK(cp.statev[slot::status] == Real(-2));
  CHECK(cp.statev[22 + slot::status] == Real(-2));
}

TEST_CASE("a point the law rejects keeps its start state and is reported", "[abi][errors]") {
  GeneralContact gc(3, 3, paper_props());
  gc.call();
  gc.dr_disp[3 * 1 + 1] = std::numeric_limits<Real>::infinity();  // point 2: slip increment not finite
  gc.penetration = {Real(-1e-4), Real(-1e-4), Real(-1e-4)};
  StderrCapture err;
  gc.call();
  const std::string message = err.text();
  INFO("stderr: " << message);
  CHECK(message.find("point 2 of 3 (slave node 1002)") != std::string::npos);
  CHECK(message.find("separation increment is not finite") != std::string::npos);
  CHECK(gc.state_of(0)[slot::status] == Real(0));
  CHECK(gc.state_of(1)[slot::status] == Real(int(mortar::Failure::non_finite_increment)));
  CHECK(gc.state_of(2)[slot::status] == Real(0));
  CHECK(gc.state_of(1)[slot::separation_n] == Real(0));  // start state kept
  CHECK(gc.state_of(0)[slot::separation_n] != Real(0));
  CHECK(all_finite(gc.stress));
  CHECK(all_finite(gc.sed));
}

TEST_CASE("a non-finite penetration at the first call does not become the reference", "[abi][errors]") {
  GeneralContact gc(2, 2, paper_props());
  gc.penetration = {std::numeric_limits<Real>::quiet_NaN(), Real(0)};
  StderrCapture err;
  gc.call();
  CHECK(err.text().find("point 1 of 2") != std::string::npos);
  CHECK(gc.state_of(0)[slot::initialised] == Real(0));
  CHECK(gc.state_of(0)[slot::status] == Real(int(mortar::Failure::non_finite_increment)));
  CHECK(gc.state_of(1)[slot::initialised] == Real(1));
  CHECK(all_finite(gc.stress));
}
