// The compression cap through the Explicit routines' C ABI, compiled once per
// precision (docs/abaqus.md, props 21-24 and SDV 36-37): bad cap props
// reported with name, value and rule; the DEPVAR a capped deck needs; a deck
// without a cap (20 props, or 24 with fc = 0) gives today's results bit for
// bit and never touches SDV 36-37; kappa_c round-trips through SDV 36 (a
// float pair in SDV 36-37 in single precision) and a corrupted one is an
// invalid state.
#include <algorithm>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "adapter/status_codes.hpp"
#include "explicit_calls.hpp"
#include "mortar/integrator.hpp"
#include "mortar/state_pairs.hpp"
#include "paper_sets.hpp"
#include "stderr_capture.hpp"

namespace {

using namespace mj_abi_test;
using mj_test::StderrCapture;
namespace slot = mortar::slot;
namespace cap_slot = mortar::cap_slot;
constexpr bool kSingle = sizeof(Real) == sizeof(float);
constexpr int kCapped = kSingle ? mortar::kCappedStateCountSingle : mortar::kCappedStateCountDouble;
constexpr Real kSentinel = Real(-7.5);

// A cap that keeps its rules on Almeida M15: fc/3 = 10 > sqrt(ft0^2 +
// Cs c0^2) = 3.21; 481 fc^2 / (588 Gfc) = 147 < min(kn, Cs ks) = 308.8.
mortar::CompressionCap m15_cap() { return {30.0, 1.0, 5.0, 0.01}; }

// Almeida M15 as props(1..20) (controls and shear sign at their defaults)
// and props(21..24) = `cap`.
std::vector<Real> capped_props(const mortar::CompressionCap& cap) {
  std::vector<Real> props = paper_props(mortar::kCapFirstProp + mortar::kCapCount);
  for (int i = 0; i < mortar::kCapCount; ++i) props[mortar::kCapFirstProp + i] = Real(mortar::cap_parameter_at(cap, i));
  return props;
}

bool same_bits(const std::vector<Real>& a, const std::vector<Real>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(Real) * a.size()) == 0;
}

// A block's first call (the reference), then `n` elastic increments of
// closure (penetration 1e-6 mm each, far below the cap) at every point.
void press_elastic(GeneralContact& gc, int n) {
  for (int i = 0; i < n; ++i) {
    for (Real& p : gc.penetration) p += Real(1e-6);
    gc.call();
  }
}

}  // namespace

TEST_CASE("Cap: a bad props(21..24) is reported with its name, value and rule", "[abi][cap][errors]") {
  REQUIRE(mortar::validate(m15_cap(), mortar::testing::almeida_m15()).ok());
  struct Case {
    int index;
    double value;
    std::vector<std::string> parts;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Case> cases = {
      {0, -1.0, {"'fc' (props(21)) = -1", "fc = 0 (no cap) or 1e-3 <= fc <= 1000 MPa"}},
      {1, nan, {"'Cs' (props(22)) = nan", "must be a finite number"}},
      {2, 0.0, {"'Gfc' (props(23)) = 0", "1e-6 <= Gfc <= 1e4 N/mm"}},
      {0, 9.0, {"'fc' (props(21)) = 9", "fc/3 > sqrt(ft0^2 + Cs c0^2)"}},
      {3, -0.5, {"'kappa_p' (props(24)) = -0.5", "0 <= kappa_p <= 100 mm"}},
  };
  for (const Case& c : cases) {
    mortar::CompressionCap cap = m15_cap();
    mortar::cap_parameter_at(cap, c.index) = c.value;
    GeneralContact gc(3, 3, capped_props(cap), kCapped);
    std::fill(gc.stress.begin(), gc.stress.end(), Real(0.25));
    const std::vector<Real> stress_in = gc.stress;
    StderrCapture err;
    gc.call();
    const std::string message = err.text();
    INFO("stderr: " << message);
    CHECK(message.find("VUINTERACTION, interaction 'JOINT-A'") != std::string::npos);
    for (const std::string& part : c.parts) CHECK(message.find(part) != std::string::npos);
    for (int k = 0; k < gc.n_block; ++k) CHECK(gc.state_of(k)[slot::status] == Real(mj_adapter::kBadProperty));
    CHECK(gc.stress == stress_in);
    CHECK(all_finite(gc.sed));
  }
}

TEST_CASE("Cap: DEPVAR below 36 (double) or 37 (single) is reported as a bad state count", "[abi][cap][errors]") {
  // The routine's own precision: one below what it needs.
  {
    GeneralContact gc(2, 3, capped_props(m15_cap()), kCapped - 1);
    StderrCapture err;
    gc.call();
    const std::string message = err.text();
    INFO("stderr: " << message);
    CHECK(message.find("nStates = " + std::to_string(kCapped - 1)) != std::string::npos);
    CHECK(message.find(kSingle ? "DEPVAR=37" : "DEPVAR=36") != std::string::npos);
    CHECK(message.find("compression cap") != std::string::npos);
    for (int k = 0; k < gc.n_block; ++k) CHECK(gc.state_of(k)[slot::status] == Real(mj_adapter::kBadStateCount));
  }
  // Double precision with DEPVAR = 35 and single with 36, whichever this is.
  {
    GeneralContact gc(2, 3, capped_props(m15_cap()), kSingle ? 36 : 35);
    StderrCapture err;
    gc.call();
    CHECK(gc.state_of(0)[slot::status] == Real(mj_adapter::kBadStateCount));
    CHECK(err.text().find("DEPVAR") != std::string::npos);
  }
  // VUINTER spells it nStateVar.
  {
    ContactPair cp(2, 3, capped_props(m15_cap()), kCapped - 1);
    StderrCapture err;
    cp.call();
    CHECK(err.text().find("VUINTER, interaction 'PAIR-B': argument nStateVar = " + std::to_string(kCapped - 1)) !=
          std::string::npos);
    CHECK(cp.statev[slot::status] == Real(mj_adapter::kBadStateCount));
  }
  // The props read once per thread: the same props but fc, after a call
  // without a cap with DEPVAR 35, must not come back from the cache.
  {
    std::vector<Real> off = capped_props(m15_cap());
    off[mortar::kCapFirstProp] = Real(0);
    GeneralContact uncapped(2, 3, off, mortar::kFlaggedStateCount);
    uncapped.call();
    CHECK(uncapped.state_of(0)[slot::status] == Real(0));
    GeneralContact capped(2, 3, capped_props(m15_cap()), mortar::kFlaggedStateCount);
    StderrCapture err;
    capped.call();
    CHECK(capped.state_of(0)[slot::status] == Real(mj_adapter::kBadStateCount));
  }
}

TEST_CASE("Cap: a deck with 20 props and with 24 props and fc = 0 give the same outputs bit for bit, and leave "
          "SDV 36-37 alone",
          "[abi][cap]") {
  const int points = 6, depvar = 40, increments = 600;
  std::vector<Real> twenty = paper_props(20), off = capped_props(m15_cap());
  off[mortar::kCapFirstProp] = Real(0);
  GeneralContact a(points, 3, twenty, depvar), b(points, 3, off, depvar);
  for (GeneralContact* gc : {&a, &b})
    for (int k = 0; k < points; ++k)
      gc->state_of(k)[cap_slot::kappa_c] = gc->state_of(k)[cap_slot::kappa_c_low] = kSentinel;
  // A random path per point: opening and closing, slips both ways, at
  // increments that reach the surface, soften and unload.
  std::mt19937 rng(35);
  std::uniform_real_distribution<double> step(-1.0, 1.0);
  int differences = 0, plastic = 0;
  for (int i = 0; i < increments; ++i) {
    for (int k = 0; k < points; ++k) {
      const Real dp = Real(2e-4 * step(rng) - 1e-5), d1 = Real(1e-3 * step(rng)), d2 = Real(5e-4 * step(rng));
      for (GeneralContact* gc : {&a, &b}) {
        gc->penetration[k] += dp;
        gc->dr_disp[3 * k + 1] = d1;
        gc->dr_disp[3 * k + 2] = d2;
      }
    }
    a.call();
    b.call();
    differences += !same_bits(a.state, b.state) + !same_bits(a.stress, b.stress) + !same_bits(a.sed, b.sed) +
                   !same_bits(a.spd, b.spd);
    for (int k = 0; k < points; ++k) plastic += a.state_of(k)[slot::substeps_accepted] > Real(0);
  }
  CHECK(differences == 0);
  CHECK(plastic > 0);  // the path is not elastic throughout
  for (int k = 0; k < points; ++k) {
    CHECK(b.state_of(k)[cap_slot::kappa_c] == kSentinel);
    CHECK(b.state_of(k)[cap_slot::kappa_c_low] == kSentinel);
  }
}

TEST_CASE("Cap: kappa_c round-trips through SDV 36 (a float pair in SDV 36-37 in single precision)",
          "[abi][cap][state]") {
  // 0.1 mm as a float pair (float(0.1), float(0.1 - float(0.1))): a double
  // of 48 significant bits, no float, whose pair is canonical.
  float high = 0, low = 0;
  mortar::split_into_pair(0.1, high, low);
  const double kappa = mortar::pair_value(high, low);
  REQUIRE(double(high) != kappa);
  REQUIRE(double(float(kappa)) != kappa);
  REQUIRE(mortar::pair_canonical(high, low, kappa));
  const int points = 4;
  GeneralContact gc(points, 3, capped_props(m15_cap()), kCapped);
  gc.call();  // the reference
  for (int k = 0; k < points; ++k) {
    Real* st = gc.state_of(k);
    if constexpr (kSingle) {
      st[cap_slot::kappa_c] = high;
      st[cap_slot::kappa_c_low] = low;
    } else {
      st[cap_slot::kappa_c] = kappa;
    }
  }
  // Points 2 and 4 go the full path (a plastic last increment, SDV 19 > 0:
  // no shortcut), which loads kappa_c and stores it again; 1 and 3 the
  // elastic store, which does not write it.
  gc.state_of(1)[slot::substeps_accepted] = Real(1);
  gc.state_of(3)[slot::substeps_accepted] = Real(1);
  press_elastic(gc, 1);
  press_elastic(gc, 5);
  for (int k = 0; k < points; ++k) {
    const Real* st = gc.state_of(k);
    INFO("point " << k + 1);
    CHECK(st[slot::status] == Real(0));
    CHECK(st[slot::substeps_accepted] == Real(0));  // elastic
    if constexpr (kSingle) {
      CHECK(st[cap_slot::kappa_c] == high);
      CHECK(st[cap_slot::kappa_c_low] == low);
    } else {
      CHECK(st[cap_slot::kappa_c] == kappa);
    }
  }
  CHECK(gc.stress[0] > Real(0));  // pressed
}

TEST_CASE("Cap: a kappa_c that is not one the routine wrote is an invalid state", "[abi][cap][state]") {
  const Real inf = std::numeric_limits<Real>::infinity(), nan = std::numeric_limits<Real>::quiet_NaN();
  std::vector<std::pair<Real, Real>> bad = {{inf, Real(0)}, {nan, Real(0)}, {Real(-1e-3), Real(0)}};
  if constexpr (kSingle) bad.push_back({Real(0.1), Real(1e-3)});  // a low part far beyond its high part's spacing
  for (const auto& [high, low] : bad) {
    GeneralContact gc(2, 3, capped_props(m15_cap()), kCapped);
    gc.call();
    gc.state_of(0)[cap_slot::kappa_c] = high;
    if constexpr (kSingle) gc.state_of(0)[cap_slot::kappa_c_low] = low;
    const std::vector<Real> before(gc.state_of(0), gc.state_of(0) + kCapped);
    StderrCapture err;
    press_elastic(gc, 1);
    INFO("SDV 36 = " << high << ", SDV 37 = " << low);
    CHECK(gc.state_of(0)[slot::status] == Real(int(mortar::Failure::invalid_state)));
    CHECK(gc.state_of(0)[slot::separation_n] == before[slot::separation_n]);  // start state kept
    CHECK(gc.state_of(1)[slot::status] == Real(0));
    CHECK(err.text().find("point 1 of 2") != std::string::npos);
  }
}
