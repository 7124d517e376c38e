// Tests of the Abaqus/Standard adapter UINTER through its C ABI (always double
// precision): DDSDDR against central differences of STRESS with respect to
// RDISP, calls that Abaqus repeats within an increment, the defaults, linear
// perturbation, unpaired points, the cut-back request and the error reports.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "abi_support.hpp"
#include "uinter_point.hpp"
#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"
#include "paper_sets.hpp"
#include "stderr_capture.hpp"
#include "vuinteraction.h"

namespace {

using mj_abi_test::drive;
using mj_abi_test::Name80;
using mj_abi_test::Point;
using mj_test::StderrCapture;

namespace slot = mortar::slot;

std::vector<double> paper_props(const mortar::Parameters& p, int n_props = 14) {
  return mj_abi_test::props_of<double>(p, n_props);
}

// Central differences of STRESS with respect to RDISP(j) (DRDISP moving with
// it) from the same start state; relative Frobenius error of DDSDDR.
double ddsddr_fd_error(Point pt, const double* r0, const double* r1, double h) {
  pt.to(r0, r1);
  const int n = pt.n_dir;
  std::vector<double> analytic(pt.ddsddr, pt.ddsddr + n * n), fd(n * n);
  for (int j = 0; j < n; ++j) {
    double rp[3], rm[3];
    std::copy(r1, r1 + 3, rp);
    std::copy(r1, r1 + 3, rm);
    rp[j] += h;
    rm[j] -= h;
    pt.to(r0, rp);
    double sp[3];
    std::copy(pt.stress, pt.stress + 3, sp);
    pt.to(r0, rm);
    for (int i = 0; i < n; ++i) fd[i + j * n] = (sp[i] - pt.stress[i]) / (2 * h);
  }
  double num = 0, den = 0;
  for (int k = 0; k < n * n; ++k) {
    num += (analytic[k] - fd[k]) * (analytic[k] - fd[k]);
    den += analytic[k] * analytic[k];
  }
  return std::sqrt(num / den);
}

}  // namespace

TEST_CASE("UINTER: DDSDDR is d STRESS / d RDISP (central differences)", "[uinter]") {
  SECTION("closed: shear at compression on the softening branch (3D)") {
    Point pt(3, paper_props(mortar::testing::van_der_pluijm(-0.5)));
    double r[3] = {1e-4, 0, 0};  // initial overclosure: the reference
    const double pressed[3] = {1e-4 + 0.5 / 209.9, 0, 0};
    drive(pt, r, pressed, 2);
    const double sheared[3] = {pressed[0], 0.02, 0.0};
    drive(pt, r, sheared, 10);
    REQUIRE(pt.statev[slot::work_II] > 0);
    const double r1[3] = {r[0] + 1e-4, r[1] + 2e-3, r[2] + 5e-4};
    CHECK(ddsddr_fd_error(pt, r, r1, 1e-8) < 1e-6);
    // Pressure positive; the shear stress and its stiffness follow the slip (+1).
    pt.to(r, r1);
    CHECK(pt.stress[0] > 0);
    CHECK(pt.stress[1] > 0);
  }
  SECTION("open: tension softening (2D)") {
    Point pt(2, paper_props(mortar::testing::almeida_m15()));
    double r[3] = {0, 0, 0};
    const double opened[3] = {-0.004, 0, 0};  // a gap: RDISP(1) < 0
    drive(pt, r, opened, 40);
    REQUIRE(pt.statev[slot::damage_n] > 0.3);
    const double r1[3] = {r[0] - 1e-3, 0, 0};
    CHECK(ddsddr_fd_error(pt, r, r1, 1e-8) < 1e-6);
    pt.to(r, r1);
    CHECK(pt.stress[0] < 0);      // tension: negative pressure
    CHECK(pt.D(0, 0) < 0);        // softening
  }
  SECTION("mixed: opening and sliding (3D)") {
    Point pt(3, paper_props(mortar::testing::almeida_m34()));
    double r[3] = {0, 0, 0};
    const double target[3] = {-0.001, 0.003, 0};
    drive(pt, r, target, 10);
    // Half the increment that completes the normal damage in a substep (its
    // tangent is flagged approximate there, docs/model.md 7.5).
    const double r1[3] = {r[0] - 1e-4, r[1] + 1e-3, r[2] - 5e-4};
    CHECK(ddsddr_fd_error(pt, r, r1, 1e-8) < 1e-6);
  }
}

TEST_CASE("UINTER: a call Abaqus repeats commits nothing", "[uinter]") {
  Point pt(3, paper_props(mortar::testing::van_der_pluijm(-0.5)));
  double r[3] = {0, 0, 0};
  const double target[3] = {0.5 / 209.9, 0.01, 0};
  drive(pt, r, target, 5);
  const std::vector<double> start = pt.statev;
  const double r1[3] = {r[0], r[1] + 0.004, r[2] + 0.001};
  pt.to(r, r1);
  const std::vector<double> end1 = pt.out_statev;
  double s1[3], d1[9];
  std::copy(pt.stress, pt.stress + 3, s1);
  std::copy(pt.ddsddr, pt.ddsddr + 9, d1);
  // An overshooting iteration in between, then the same call again.
  const double r2[3] = {r[0], r[1] + 0.008, r[2]};
  pt.to(r, r2);
  CHECK(pt.statev == start);  // the caller's copy is never written
  pt.to(r, r1);
  CHECK(pt.out_statev == end1);
  for (int i = 0; i < 3; ++i) CHECK(pt.stress[i] == s1[i]);
  for (int i = 0; i < 9; ++i) CHECK(pt.ddsddr[i] == d1[i]);
  // Abaqus's first iteration of an increment (DRDISP = 0) returns the start traction.
  pt.to(r, r);
  mortar::State s;
  mortar::load_state(start.data(), s);
  mortar::Controls c;
  c.scheme = mortar::Scheme::implicit;
  const mortar::Model M = mortar::make_model(mortar::testing::van_der_pluijm(-0.5), c);
  const mortar::Vec3 t = mortar::traction_of(M, s);
  CHECK(pt.stress[0] == Approx(-t[0]).epsilon(1e-14));
  CHECK(pt.stress[1] == Approx(t[1]).epsilon(1e-14));
}

TEST_CASE("UINTER: the first call sets the reference at the start of its increment", "[uinter]") {
  Point pt(2, paper_props(mortar::testing::almeida_m15()));
  pt.rdisp[0] = 2e-4 + 1e-5;  // overclosure at the end of the first increment
  pt.drdisp[0] = 1e-5;        // of which 1e-5 in this increment
  pt.call();
  CHECK(pt.out_statev[slot::initialised] == 1);
  CHECK(pt.out_statev[slot::reference_penetration] == Approx(2e-4).epsilon(1e-14));
  CHECK(pt.out_statev[slot::separation_n] == Approx(-1e-5).epsilon(1e-10));
  CHECK(pt.stress[0] == Approx(741.1 * 1e-5).epsilon(1e-10));  // pressure
  // Defaults: elastic tangent diag(kn, ks) with the +1 shear sign.
  CHECK(pt.D(0, 0) == Approx(741.1));
  CHECK(pt.D(1, 1) == Approx(308.8));
  CHECK(pt.D(0, 1) == 0);
  CHECK(pt.flux[0] == 0);
  CHECK(pt.ddsddt[0] == 0);
  CHECK(pt.sfd == 0);
}

TEST_CASE("UINTER: linear perturbation uses the base state's stiffness and keeps the state", "[uinter]") {
  Point pt(3, paper_props(mortar::testing::almeida_m15()));
  double r[3] = {0, 0, 0};
  const double opened[3] = {-0.004, 0.0005, 0};
  drive(pt, r, opened, 20);
  pt.linper = 1;
  pt.rdisp[0] = -1e-6;  // perturbations
  pt.rdisp[1] = 2e-6;
  pt.rdisp[2] = 0;
  std::copy(pt.rdisp, pt.rdisp + 3, pt.drdisp);
  pt.call();
  CHECK(pt.out_statev == pt.statev);
  const double dn = pt.statev[slot::damage_n], ds = pt.statev[slot::damage_s];
  CHECK(pt.D(0, 0) == Approx(741.1 * (1 - dn)));
  CHECK(pt.D(1, 1) == Approx(308.8 * (1 - ds)));
  CHECK(pt.stress[0] == Approx(pt.D(0, 0) * -1e-6));
  CHECK(pt.stress[1] == Approx(pt.D(1, 1) * 2e-6));
}

TEST_CASE("UINTER: an unpaired point carries nothing and keeps its state", "[uinter]") {
  Point pt(3, paper_props(mortar::testing::almeida_m15()));
  pt.statev[slot::work_I] = 1e-3;
  pt.rdisp[0] = -1e36;
  pt.call();
  CHECK(pt.out_statev == pt.statev);
  for (int i = 0; i < 3; ++i) CHECK(pt.stress[i] == 0);
  for (int i = 0; i < 9; ++i) CHECK(pt.ddsddr[i] == 0);
}

TEST_CASE("UINTER: a rejected increment asks for a smaller one and leaves finite outputs", "[uinter]") {
  Point pt(3, paper_props(mortar::testing::almeida_m15()));
  double r[3] = {0, 0, 0};
  const double target[3] = {-0.002, 0.001, 0};
  drive(pt, r, target, 5);
  pt.rdisp[0] = r[0];
  pt.rdisp[1] = std::numeric_limits<double>::infinity();
  pt.rdisp[2] = 0;
  StderrCapture err;
  pt.call();
  const std::string message = err.text();
  INFO("stderr: " << message);
  CHECK(pt.pnewdt == 0.5);
  CHECK(message.find("UINTER, interaction 'MORTAR-STD': node 4711") != std::string::npos);
  CHECK(message.find("PNEWDT = 0.5") != std::string::npos);
  CHECK(pt.out_statev[slot::status] == int(mortar::Failure::non_finite_increment));
  CHECK(pt.out_statev[slot::plastic_n] == pt.statev[slot::plastic_n]);
  for (int i = 0; i < 3; ++i) CHECK(std::isfinite(pt.stress[i]));
  for (int i = 0; i < 9; ++i) CHECK(std::isfinite(pt.ddsddr[i]));
  CHECK(std::isfinite(pt.sed));
}

TEST_CASE("UINTER: a state whose adapter slots break their rules is rejected, as in the Explicit routines",
          "[uinter][errors]") {
  // The open and initialised flags (SDV 15, 23) 0 or 1, SDV 35 (NSTATV 35) a
  // whole number from 0 to 15 (docs/model.md 3): otherwise the state is kept,
  // SDV 21 = invalid_state, a smaller increment asked for.
  struct Bad {
    int slot;
    double value;
  };
  const int flags = mortar::flag_slot::integration_flags;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Bad bad = GENERATE_COPY(Bad{slot::open, 0.5}, Bad{slot::initialised, 2}, Bad{flags, 2.5}, Bad{flags, 16},
                                Bad{flags, -1}, Bad{flags, nan});
  CAPTURE(bad.slot, bad.value);
  Point pt(3, paper_props(mortar::testing::almeida_m15()));
  pt.n_states = mortar::kFlaggedStateCount;
  pt.statev.assign(size_t(pt.n_states), 0.0);
  double r[3] = {0, 0, 0};
  const double target[3] = {-0.0002, 0.0001, 0};
  drive(pt, r, target, 3);
  pt.statev[size_t(bad.slot)] = bad.value;
  StderrCapture err;
  pt.call();
  CHECK(pt.pnewdt == 0.5);
  CHECK(err.text().find("invalid state") != std::string::npos);
  CHECK(pt.out_statev[slot::status] == int(mortar::Failure::invalid_state));
  for (int i = 0; i < pt.n_states; ++i)
    if (i != slot::status) CHECK((pt.out_statev[size_t(i)] == pt.statev[size_t(i)] || i == bad.slot));
  for (int i = 0; i < 3; ++i) CHECK(std::isfinite(pt.stress[i]));
  // The same slots valid: integrated.
  pt.statev[size_t(bad.slot)] = bad.slot == flags ? 3.0 : 1.0;
  pt.call();
  CHECK(pt.out_statev[slot::status] == 0);
}

TEST_CASE("UINTER: bad arguments and properties are reported and coded in SDV 21", "[uinter][errors]") {
  SECTION("a property") {
    std::vector<double> props = paper_props(mortar::testing::almeida_m15(), 20);
    props[3] = 0.5;
    Point pt(3, props);
    pt.stress[1] = std::numeric_limits<double>::quiet_NaN();
    StderrCapture err;
    pt.call();
    const std::string message = err.text();
    CHECK(message.find("UINTER, interaction 'MORTAR-STD': property 'c0' (props(4)) = 0.5") != std::string::npos);
    CHECK(pt.out_statev[slot::status] == -4);
    for (int i = 0; i < 3; ++i) CHECK(std::isfinite(pt.stress[i]));
    for (int i = 0; i < 9; ++i) CHECK(pt.ddsddr[i] == 0);
  }
  SECTION("the shear sign") {
    std::vector<double> props = paper_props(mortar::testing::almeida_m15(), 20);
    props[19] = 0.5;
    Point pt(3, props);
    StderrCapture err;
    pt.call();
    CHECK(err.text().find("props(20) is 0 (default, = +1), -1 or +1") != std::string::npos);
    CHECK(pt.out_statev[slot::status] == -4);
  }
  SECTION("the array sizes") {
    struct Case {
      const char* message;
      int code;
      void (*spoil)(Point&);
    };
    const Case cases[] = {
        {"argument NSTATV = 21", -2, [](Point& pt) { pt.n_states = 21; }},
        {"argument NDIR = 4", -1, [](Point& pt) { pt.n_dir = 4; }},
        {"argument NPROPS = 13", -3, [](Point& pt) { pt.props.resize(13); }},
    };
    for (const Case& c : cases) {
      Point pt(3, paper_props(mortar::testing::almeida_m15()));
      c.spoil(pt);
      StderrCapture err;
      pt.call();
      INFO(c.message);
      CHECK(err.text().find(c.message) != std::string::npos);
      CHECK(pt.out_statev[slot::status] == c.code);
    }
  }
}

TEST_CASE("UINTER: props(15) selects the scheme, the implicit one by default", "[uinter]") {
  // Same increment with the default (implicit) and with props(15) = 3: identical.
  auto run = [](std::vector<double> props) {
    Point pt(3, std::move(props));
    double r[3] = {0, 0, 0};
    const double target[3] = {0.5 / 209.9, 0.02, 0.0};
    drive(pt, r, target, 8);
    return pt.statev;
  };
  const std::vector<double> by_default = run(paper_props(mortar::testing::van_der_pluijm(-0.5)));
  std::vector<double> props = paper_props(mortar::testing::van_der_pluijm(-0.5), 15);
  props[14] = 3;
  CHECK(run(props) == by_default);
  props[14] = 1;
  CHECK(run(props) != by_default);
}
