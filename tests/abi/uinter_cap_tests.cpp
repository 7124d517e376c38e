// The compression cap through UINTER (docs/abaqus.md, props 21-24 and SDV
// 36): a bad cap prop and NSTATV below 36 reported and coded in SDV 21; a
// deck with 20 props and with 24 and fc = 0 the same bit for bit, SDV 36
// untouched; kappa_c round-trips through SDV 36 and a corrupted one is an
// invalid state.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "abi_support.hpp"
#include "mortar/state_layout.hpp"
#include "paper_sets.hpp"
#include "stderr_capture.hpp"
#include "uinter_point.hpp"

namespace {

using mj_abi_test::drive;
using mj_abi_test::Point;
using mj_test::StderrCapture;
namespace slot = mortar::slot;
namespace cap_slot = mortar::cap_slot;

// Almeida M15 as props(1..20) and a cap that keeps its rules as
// props(21..24) (fc = 0 for none).
std::vector<double> capped_props(double fc) {
  std::vector<double> props = mj_abi_test::props_of<double>(mortar::testing::almeida_m15(), 24);
  props[20] = fc;
  props[21] = 1.0;   // Cs
  props[22] = 5.0;   // Gfc
  props[23] = 0.01;  // kappa_p
  return props;
}

Point capped_point(double fc, int n_states) {
  Point pt(3, capped_props(fc));
  pt.n_states = n_states;
  pt.statev.assign(size_t(n_states), 0.0);
  return pt;
}

}  // namespace

TEST_CASE("UINTER cap: a bad cap prop and NSTATV below 36 are reported and coded in SDV 21", "[uinter][cap]") {
  SECTION("fc") {
    Point pt = capped_point(-1.0, mortar::kCappedStateCountDouble);
    StderrCapture err;
    pt.call();
    CHECK(err.text().find("UINTER, interaction 'MORTAR-STD': property 'fc' (props(21)) = -1 violates the rule: "
                          "fc = 0 (no cap) or 1e-3 <= fc <= 1000 MPa") != std::string::npos);
    CHECK(pt.out_statev[slot::status] == -4);
  }
  SECTION("NSTATV") {
    Point pt = capped_point(30.0, mortar::kFlaggedStateCount);
    StderrCapture err;
    pt.call();
    const std::string message = err.text();
    INFO(message);
    CHECK(message.find("argument NSTATV = 35") != std::string::npos);
    CHECK(message.find("DEPVAR=36") != std::string::npos);
    CHECK(pt.out_statev[slot::status] == -2);
  }
}

TEST_CASE("UINTER cap: 20 props and 24 with fc = 0 give the same results bit for bit, SDV 36 untouched",
          "[uinter][cap]") {
  Point twenty(3, mj_abi_test::props_of<double>(mortar::testing::almeida_m15(), 20));
  twenty.n_states = 40;
  twenty.statev.assign(40, 0.0);
  Point off = capped_point(0.0, 40);
  twenty.statev[cap_slot::kappa_c] = off.statev[cap_slot::kappa_c] = -7.5;
  double ra[3] = {0, 0, 0}, rb[3] = {0, 0, 0};
  const double targets[][3] = {{-2e-4, 1e-4, 0}, {1e-3, 2e-2, -5e-3}, {-3e-3, -1e-2, 5e-3}};
  for (const auto& target : targets) {
    drive(twenty, ra, target, 20);
    drive(off, rb, target, 20);
    CHECK(twenty.statev == off.statev);
    for (int i = 0; i < 3; ++i) CHECK(twenty.stress[i] == off.stress[i]);
    for (int i = 0; i < 9; ++i) CHECK(twenty.ddsddr[i] == off.ddsddr[i]);
  }
  CHECK(off.statev[slot::dissipation_plastic] > 0);  // the path is not elastic throughout
  CHECK(off.statev[cap_slot::kappa_c] == -7.5);
}

TEST_CASE("UINTER cap: kappa_c round-trips through SDV 36, and a corrupted one is an invalid state", "[uinter][cap]") {
  Point pt = capped_point(30.0, mortar::kCappedStateCountDouble);
  double r[3] = {0, 0, 0};
  const double pressed[3] = {1e-4, 0, 0};
  drive(pt, r, pressed, 1);
  pt.statev[cap_slot::kappa_c] = 0.1;
  const double further[3] = {2e-4, 1e-5, 0};
  drive(pt, r, further, 3);
  CHECK(pt.statev[slot::status] == 0);
  CHECK(pt.statev[cap_slot::kappa_c] == 0.1);
  CHECK(pt.stress[0] > 0);  // pressed

  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const double bad : {-1e-3, nan, inf}) {
    CAPTURE(bad);
    Point p = pt;
    p.statev[cap_slot::kappa_c] = bad;
    StderrCapture err;
    p.call();
    CHECK(p.pnewdt == 0.5);
    CHECK(err.text().find("invalid state") != std::string::npos);
    CHECK(p.out_statev[slot::status] == int(mortar::Failure::invalid_state));
  }
}
