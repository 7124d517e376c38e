// Single precision against double at the increments Abaqus/Explicit takes
// (docs/model.md 3, float pairs): vuinteraction_ in single precision along
// Almeida M15 pure opening and van der Pluijm sliding under compression, at
// increments of 1e-5 .. 1e-8 mm, against the law in double precision (what
// the double routine computes). With DEPVAR = 34 (float pairs) the traction
// agrees within 1e-3 of the peak at every increment; with DEPVAR = 23 (plain
// floats) the softening stalls, and the numbers are printed for comparison.
// The fallback is named once on stderr; a low part that is not a pair is a
// state that breaks its rules.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "mortar/state_layout.hpp"
#include "one_point.hpp"
#include "paper_sets.hpp"
#include "stderr_capture.hpp"
#include "test_scale.hpp"
#include "formatted.hpp"

static_assert(sizeof(mj_real) == sizeof(float), "the precision tests drive the single-precision routine");

namespace {

using namespace mj_abi_test;

struct Agreement {
  double traction;  // max over increments |sigma_single - sigma_double|_inf / peak
  double area;      // (work_single - work_double) / G
};

Agreement agreement(const Curve& single, const Curve& law, double G) {
  double peak = 0, worst = 0;
  for (const mortar::Vec3& t : law.traction) peak = std::max(peak, t.cwiseAbs().maxCoeff());
  for (size_t i = 0; i < law.traction.size(); ++i)
    worst = std::max(worst, (single.traction[i] - law.traction[i]).cwiseAbs().maxCoeff());
  return {worst / peak, (single.work - law.work) / G};
}

// One increment size of one path: the legs, and the fracture energy the
// area is measured against.
struct Case {
  double h;
  std::vector<Leg> legs;
};

// A fine leg of `count` increments h, shortened under the sanitizers
// (tests/support/test_scale.hpp) but never below a tenth.
long fine(long count) { return std::max(long(mj_test::scaled(int(count))), count / 10); }

double peak_of(const Curve& c, int component) {
  double peak = 0;
  for (const mortar::Vec3& t : c.traction) peak = std::max(peak, std::abs(t[component]));
  return peak;
}

// The traction component `component` (0 normal, 1 slip) is the one loaded.
void compare(const char* path, const mortar::Parameters& p, double G, int component, const std::vector<Case>& cases) {
  const std::vector<Real> props = props_of<Real>(p);
  const mortar::Model model = mortar::make_model_checked(p);
  for (const Case& c : cases) {
    const Curve law = run_law(model, c.legs);
    const Curve pairs = run_routine(props, mortar::kPairedStateCount, c.legs);
    const Curve plain = run_routine(props, mortar::kStateCount, c.legs);
    const Agreement a = agreement(pairs, law, G), b = agreement(plain, law, G);
    const int i = component;
    INFO(mj_test::formatted(
        "%s, h = %.0e mm, %zu increments: max |sigma_single - sigma_double| / peak: float pairs %.2e, "
        "plain float %.2e; area excess / G: float pairs %+.2e, plain float %+.2e; final traction "
        "%.4g (double), %.4g (pairs), %.4g (plain) MPa",
        path, c.h, law.traction.size(), a.traction, b.traction, a.area, b.area, law.traction.back()[i],
        pairs.traction.back()[i], plain.traction.back()[i]));
    CAPTURE(path, c.h);
    CHECK(law.failures == 0);
    CHECK(pairs.failures == 0);
    CHECK(a.traction <= 1e-3);
    CHECK(std::abs(a.area) <= 1e-5);  // measured at most 1.6e-7
    // Every path ends softened: the finest increments run past the peak
    // (not when shortened under the sanitizers).
    if (mj_test::property_scale() == 1) CHECK(std::abs(law.traction.back()[i]) < 0.99 * peak_of(law, i));
  }
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

// First in this file: the warning is once per process.
TEST_CASE("Single precision, DEPVAR below 34: plain floats named once on stderr and DEPVAR = 34 says nothing",
          "[abi][precision]") {
  const std::vector<Real> props = props_of<Real>(mortar::testing::almeida_m15());
  mj_test::StderrCapture err;
  OnePoint pairs(props, mortar::kPairedStateCount);
  pairs.call();
  pairs.call();
  CHECK(err.text().empty());
  OnePoint plain(props, mortar::kStateCount), also_plain(props, 30);
  for (int i = 0; i < 3; ++i) {
    plain.call();
    also_plain.call();
  }
  const std::string text = err.text();
  INFO("stderr: " << text);
  CHECK(count(text, "DEPVAR = 23 is below 34") == 1);
  CHECK(count(text, "warning") == 1);
  CHECK(text.find("VUINTERACTION, interaction 'PRECISION'") == 0);
  CHECK(text.find("DEPVAR=34 keeps it as float pairs (SDV 24-34)") != std::string::npos);
  CHECK(plain.state[mortar::slot::status] == Real(0));
  CHECK(plain.state[mortar::slot::initialised] == Real(1));
}

TEST_CASE("Single precision: a low part that is not its high part's remainder is an invalid state", "[abi][precision]") {
  OnePoint pt(props_of<Real>(mortar::testing::almeida_m15()), mortar::kPairedStateCount);
  pt.call();
  pt.penetration = Real(-0.01);
  pt.call();
  const std::vector<Real> start = pt.state;
  REQUIRE(start[mortar::slot::plastic_n] > Real(0));
  pt.state[mortar::low_slot::plastic_n] = Real(1e-3);  // far beyond one spacing of SDV 1
  std::vector<Real> expected = pt.state;
  expected[mortar::slot::status] = Real(int(mortar::Failure::invalid_state));
  pt.penetration = Real(-0.011);
  mj_test::StderrCapture err;
  pt.call();
  INFO("stderr: " << err.text());
  CHECK(err.text().find("point 1 of 1 (slave node 1001)") != std::string::npos);
  CHECK(pt.state == expected);  // the start state kept, the code in SDV 21
}

TEST_CASE("Single precision, float pairs: Almeida M15 pure opening agrees with double within 1e-3 of the peak "
          "at increments of 1e-5 .. 1e-8 mm",
          "[abi][precision]") {
  const mortar::Parameters p = mortar::testing::almeida_m15();
  // The peak is at ft0/kn = 2.4e-3 mm; 1e-8 mm starts at 2.3e-3 mm (reached
  // in increments of 1e-5) and softens for 2e-3 mm.
  compare("M15 opening", p, p.GIC, 0,
          {{1e-5, {{1e-5, 0, 5000}}},
           {1e-6, {{1e-6, 0, fine(50000)}}},
           {1e-7, {{1e-7, 0, fine(500000)}}},
           {1e-8, {{1e-5, 0, 230}, {1e-8, 0, fine(200000)}}}});
}

TEST_CASE("Single precision, float pairs: van der Pluijm sliding at sigma_n = -1 MPa agrees with double within "
          "1e-3 of the peak at increments of 1e-5 .. 1e-8 mm",
          "[abi][precision]") {
  const mortar::Parameters p = mortar::testing::van_der_pluijm(-1.0);
  const Leg press{-1.0 / p.kn, 0, 1};  // sigma_n = -1 MPa, then slip at fixed opening
  // Full slide to the residual (0.2 mm) at 1e-5 and 1e-6 mm; the finer ones
  // from before the peak (2.05e-2 mm, reached in increments of 1e-5; the
  // peak is at 2.2e-2 mm) into softening.
  compare("vdp sliding", p, p.GIIC, 1,
          {{1e-5, {press, {0, 1e-5, 20000}}},
           {1e-6, {press, {0, 1e-6, fine(200000)}}},
           {1e-7, {press, {0, 1e-5, 2050}, {0, 1e-7, fine(100000)}}},
           {1e-8, {press, {0, 1e-5, 2050}, {0, 1e-8, fine(400000)}}}});
}
