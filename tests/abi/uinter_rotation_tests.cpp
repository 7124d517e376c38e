// Tests of the rotation of the tangent directions through UINTER (DROT,
// adapter/rotation.hpp; docs/abaqus.md, "Rotating tangent directions"): Abaqus
// hands the accumulated slips RDISP(2..3) already turned into the current
// tangent directions, so the stored slips must turn with them; a joint sliding
// on its residual surface keeps its traction and its tangent in space while
// its tangent directions turn by 90 degrees. A bad DROT is reported.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "abi_support.hpp"
#include "adapter/status_codes.hpp"
#include "mortar/state_layout.hpp"
#include "paper_sets.hpp"
#include "stderr_capture.hpp"
#include "uinter_point.hpp"
#include "formatted.hpp"

namespace {

using mj_abi_test::Point;
using mj_test::StderrCapture;
namespace slot = mortar::slot;
constexpr double kPi = 3.14159265358979323846;

// The tangent directions turn by `angle` (t1 towards t2): DROT, column-major,
// takes the components of a fixed in-plane vector from v to DROT v.
std::array<double, 4> turn(double angle) {
  return {std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle)};
}

// One converged increment to penetration `pen` and accumulated global slip
// (ux, 0), the tangent directions turned to `theta` from `theta_before`: RDISP
// in the new directions, DRDISP its change from the turned start (what Abaqus
// passes), the call repeated as in a second iteration (it must commit nothing).
void increment(Point& pt, double pen, double ux, double theta, double theta_before) {
  const std::array<double, 4> r = turn(theta - theta_before);
  const double s1 = pt.rdisp[1], s2 = pt.rdisp[2];
  const double start[3] = {pt.rdisp[0], r[0] * s1 + r[2] * s2, r[1] * s1 + r[3] * s2};
  const double end[3] = {pen, std::cos(theta) * ux, -std::sin(theta) * ux};
  std::copy(r.begin(), r.end(), pt.drot);
  pt.to(start, end);
  const std::vector<double> first = pt.out_statev;
  pt.to(start, end);
  REQUIRE(pt.out_statev == first);
  REQUIRE(pt.pnewdt >= 1);
  pt.commit();
}

// DDSDDR in global components: P D P^T, P = diag(1, R(theta)).
std::array<double, 9> global_tangent(const Point& pt, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  const double P[3][3] = {{1, 0, 0}, {0, c, -s}, {0, s, c}};
  std::array<double, 9> g{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) g[i + 3 * j] += P[i][a] * pt.D(a, b) * P[j][b];
  return g;
}

struct Deviation {
  double shear = 0, tangent = 0, friction = 0;
};

// A turning point and a fixed one under the same motion in space: pressed to
// sigma_n = -0.5 MPa, slid 0.6 mm along x to the residual surface, slid on
// (4e-4 mm per increment, less than the elastic slip) while the tangent
// directions of the first turn by 90 degrees in 2-degree steps, then on.
// Before the turn: |tau| / pressure; from the turn on: the largest relative
// deviation of the turning point's shear traction and DDSDDR, in global
// components, from the fixed point's.
Deviation run_sliding_turn() {
  const std::vector<double> props = mj_abi_test::props_of<double>(mortar::testing::almeida_m15());
  Point turning(3, props), fixed(3, props);
  const double pressed = 0.5 / 741.1, du = 2e-3;
  double ux = 0, theta = 0;
  Deviation dev;
  auto step = [&](double pen, double dux, double to_theta) {
    ux += dux;
    increment(turning, pen, ux, to_theta, theta);
    increment(fixed, pen, ux, 0, 0);
    theta = to_theta;
    if (theta == 0) {
      dev.friction = std::hypot(fixed.stress[1], fixed.stress[2]) / fixed.stress[0];
      return;
    }
    const double c = std::cos(theta), s = std::sin(theta);
    const double gx = c * turning.stress[1] - s * turning.stress[2], gy = s * turning.stress[1] + c * turning.stress[2];
    const double ref = std::hypot(fixed.stress[1], fixed.stress[2]);
    dev.shear = std::fmax(dev.shear, std::hypot(gx - fixed.stress[1], gy - fixed.stress[2]) / ref);
    const std::array<double, 9> g = global_tangent(turning, theta);
    double num = 0, den = 0;
    for (int k = 0; k < 9; ++k) {
      num += (g[k] - fixed.ddsddr[k]) * (g[k] - fixed.ddsddr[k]);
      den += fixed.ddsddr[k] * fixed.ddsddr[k];
    }
    dev.tangent = std::fmax(dev.tangent, std::sqrt(num / den));
  };
  for (int i = 1; i <= 10; ++i) step(pressed * i / 10, 0, 0);
  for (int i = 0; i < 300; ++i) step(pressed, du, 0);
  for (int i = 1; i <= 45; ++i) step(pressed, du / 5, i * kPi / 90);
  for (int i = 0; i < 20; ++i) step(pressed, du / 5, kPi / 2);
  return dev;
}

}  // namespace

TEST_CASE("UINTER: a sliding joint keeps its traction and tangent in space while its tangents turn 90 degrees",
          "[uinter][rotation]") {
  const Deviation dev = run_sliding_turn();
  INFO(
      mj_test::formatted("[rotation] UINTER: |tau|/pressure %.6g before the turn, turn: shear deviation %.3g, DDSDDR "
                         "deviation %.3g",
                         dev.friction, dev.shear, dev.tangent));
  CHECK(dev.friction == Approx(std::tan(32 * kPi / 180)).epsilon(0.005));
  CHECK(dev.shear < 1e-9);
  CHECK(dev.tangent < 1e-6);
}

TEST_CASE("UINTER: a bad DROT is reported with its value and the rule, where DROT is read", "[uinter][rotation]") {
  const std::vector<double> props = mj_abi_test::props_of<double>(mortar::testing::almeida_m15());
  SECTION("3D: reported, coded in SDV 21") {
    Point pt(3, props);
    pt.drot[1] = std::numeric_limits<double>::quiet_NaN();
    StderrCapture err;
    pt.call();
    CHECK_THAT(err.text(), Catch::Contains("UINTER, interaction 'MORTAR-STD': argument DROT(2,1) = nan (node 4711) "
                                           "violates the rule: every entry finite"));
    CHECK(pt.out_statev[slot::status] == mj_adapter::kBadRotation);
    for (int i = 0; i < 3; ++i) CHECK(std::isfinite(pt.stress[i]));
  }
  SECTION("3D: not a rotation") {
    Point pt(3, props);
    pt.drot[2] = 0.1;
    StderrCapture err;
    pt.call();
    CHECK_THAT(err.text(), Catch::Contains("argument DROT(:,:) = [1 0.1; 0 1] (node 4711) violates the rule: a "
                                           "rotation, |DROT^T DROT - I| <= 0.001 and det > 0 (here 0.1 and det 1)"));
    CHECK(pt.out_statev[slot::status] == mj_adapter::kBadRotation);
  }
  SECTION("not read: 2D, linear perturbation, an unpaired point") {
    Point flat(2, props), perturbed(3, props), unpaired(3, props);
    perturbed.linper = 1;
    unpaired.rdisp[0] = -1e36;
    StderrCapture err;
    for (Point* pt : {&flat, &perturbed, &unpaired}) {
      std::fill(pt->drot, pt->drot + 4, 0.0);
      pt->call();
      CHECK(pt->out_statev[slot::status] == 0);
    }
    CHECK(err.text().empty());
  }
}
