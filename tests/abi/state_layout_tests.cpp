// The state array of the Explicit routines in both precisions (docs/model.md
// 3, vuinteraction/adapter/state_storage.hpp): with DEPVAR = 23 the routine is
// the law over the plain layout in its precision, bit for bit (single: the
// fallback; double: always); in double precision SDV 24-34 and 36 onwards are
// never touched and DEPVAR = 34 or 40 gives the DEPVAR = 23 results bit for
// bit; in single precision DEPVAR >= 34 keeps SDV 1-23 as the plain layout
// reads them and the low parts in SDV 24-34; with DEPVAR >= 35 both keep the
// integration flags in SDV 35 (docs/model.md 9).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <catch2/catch.hpp>

#include "adapter/rotation.hpp"
#include "adapter/state_storage.hpp"
#include "one_point.hpp"
#include "paper_sets.hpp"

namespace {

using namespace mj_abi_test;
namespace slot = mortar::slot;
constexpr bool kDouble = sizeof(Real) == sizeof(double);
constexpr Real kSentinel = Real(-7.5);

// A path that is elastic, then plastic in shear and opening, then softening:
// penetration and slips at increment i of n.
struct Inputs {
  Real penetration, dr_disp[3];
};
Inputs inputs(int i, int n) {
  const double t = double(i) / n, before = double(std::max(i - 1, 0)) / n;
  const Real p = Real(1e-4 - 3e-3 * t);
  return {p, {Real(0), Real(0.03 * (t - before)), Real(-0.01 * (t - before))}};
}

// The full path of the adapter (adapter/explicit_block.hpp, integrate_point):
// the whole state loaded from this precision's layout for the declared state
// count (adapter/state_storage.hpp), its tangential vectors turned by dRot,
// the law, the whole state stored (with DEPVAR = 23: the law between
// mortar::load_state and store_state). The routine stores by its elastic
// store (which writes only what an elastic increment changes) wherever the
// elastic shortcut holds.
struct FullPath {
  mj_adapter::StateStorage<Real> storage;
  std::vector<Real> state;
  Real stress[3] = {};
  explicit FullPath(int states) : storage(mj_adapter::StateStorage<Real>::of(states)), state(states, Real(0)) {}

  void call(const mortar::Model& M, const Inputs& in, const Real* d_rot) {
    mortar::State s;
    storage.load(state.data(), s);
    mj_adapter::rotate_tangential_state(d_rot, s);
    const bool first = state[slot::initialised] == Real(0);
    const double reference = double(state[slot::reference_penetration]);
    const mortar::Vec3 d = first ? mortar::Vec3::Zero()
                                 : mortar::Vec3((reference - double(in.penetration)) - s.separation[0],
                                                double(in.dr_disp[1]), double(in.dr_disp[2]));
    const mortar::IncrementResult r = mortar::integrate_increment(M, s, d);
    storage.store(s, state.data());
    if (first) {
      state[slot::reference_penetration] = in.penetration;
      state[slot::initialised] = Real(1);
    }
    stress[0] = Real(-r.traction[0]);
    stress[1] = Real(-1.0 * r.traction[1]);
    stress[2] = Real(-1.0 * r.traction[2]);
  }
};

bool same_bits(const Real* a, const Real* b, int n) { return std::memcmp(a, b, sizeof(Real) * size_t(n)) == 0; }

void apply(OnePoint& pt, const Inputs& in) {
  pt.penetration = in.penetration;
  std::copy(in.dr_disp, in.dr_disp + 3, pt.dr_disp);
}

std::vector<Real> m15_props() { return props_of<Real>(mortar::testing::almeida_m15()); }

// The model the routine reads from props in its precision.
mortar::Model model_of(const std::vector<Real>& props) {
  double p[mortar::kParameterCount];
  for (int i = 0; i < mortar::kParameterCount; ++i) p[i] = double(props[i]);
  mortar::Parameters parameters;
  mortar::Controls controls;
  REQUIRE(mortar::read_props(p, mortar::kParameterCount, parameters, controls).ok());
  return mortar::make_model(parameters, controls);
}

}  // namespace

TEST_CASE("State array: with DEPVAR = 23 the routine is the law over the plain layout, bit for bit",
          "[abi][state]") {
  const mortar::Model model = model_of(m15_props());
  OnePoint pt(m15_props(), mortar::kStateCount);
  FullPath plain(mortar::kStateCount);  // DEPVAR = 23: mortar::load_state and store_state
  const Real unit[4] = {1, 0, 0, 1};
  const int n = 400;
  int differences = 0;
  for (int i = 0; i <= n; ++i) {
    apply(pt, inputs(i, n));
    pt.call();
    plain.call(model, inputs(i, n), unit);
    differences += !std::equal(plain.state.begin(), plain.state.end(), pt.state.begin());
    differences += !std::equal(plain.stress, plain.stress + 3, pt.stress);
  }
  CHECK(differences == 0);
  CHECK(pt.state[slot::damage_n] > Real(0.5));  // the path softens
}

TEST_CASE("State array: slots beyond the routine's layout are never touched and in double precision "
          "DEPVAR = 40 gives the DEPVAR = 23 results bit for bit",
          "[abi][state]") {
  const int declared = 40;
  const int used = kDouble ? mortar::kStateCount : mortar::kPairedStateCount;
  const int flags = mortar::flag_slot::integration_flags;
  OnePoint wide(m15_props(), declared), narrow(m15_props(), mortar::kStateCount);
  std::fill(wide.state.begin() + used, wide.state.end(), kSentinel);
  wide.state[flags] = Real(0);  // SDV 35 holds flags, 0 to 15 (a sentinel there is rejected)
  const int n = 400;
  int untouched = 0, differences = 0;
  for (int i = 0; i <= n; ++i) {
    apply(wide, inputs(i, n));
    apply(narrow, inputs(i, n));
    wide.call();
    narrow.call();
    // Every slot beyond the layout but SDV 35, the integration flags.
    bool beyond = true;
    for (int j = used; j < declared; ++j) beyond = beyond && (j == flags || wide.state[j] == kSentinel);
    untouched += beyond;
    differences += !std::equal(narrow.state.begin(), narrow.state.end(), wide.state.begin());
    differences += !std::equal(narrow.stress, narrow.stress + 3, wide.stress);
  }
  CHECK(untouched == n + 1);
  // No fallback, no substep accepted at the floor on this path: SDV 35
  // stays 0.
  CHECK(wide.state[flags] == Real(0));
  if (kDouble) CHECK(differences == 0);
  if (!kDouble) CHECK(differences > 0);  // the pairs carry what plain floats lose
}

TEST_CASE("State array: single precision with DEPVAR >= 34 keeps SDV 1-23 as the plain layout reads them and "
          "the low parts in SDV 24-34",
          "[abi][state]") {
  if (kDouble) return;  // the double routine has no pairs (previous test)
  OnePoint pt(m15_props(), mortar::kPairedStateCount);
  const int n = 400;
  int inconsistent = 0, nonzero_low = 0;
  for (int i = 0; i <= n; ++i) {
    apply(pt, inputs(i, n));
    pt.call();
    for (const mortar::SlotPair& p : mortar::kPairedSlots) {
      const float high = float(pt.state[p.high]), low = float(pt.state[p.low]);
      inconsistent += !mortar::pair_consistent(high, low) || float(mortar::pair_value(high, low)) != high;
      nonzero_low += low != 0.0f;
    }
  }
  CHECK(inconsistent == 0);
  CHECK(nonzero_low > 0);
}

TEST_CASE("State array: elastic increments under turning tangents write what the full path writes, bit for bit",
          "[abi][state]") {
  // After plastic slip and opening (nonzero plastic and crack separation), the
  // path unloads and reloads elastically while dRot turns the tangents a
  // little at every call: the routine's elastic path must store exactly what
  // loading, turning, integrating and storing the whole state gives, in both
  // layouts of this precision. The first unloading increment follows a
  // plastic one (SDV 19 > 0), which sends it down the routine's full path;
  // the rest take the elastic path.
  const mortar::Model model = model_of(m15_props());
  for (const int states : {mortar::kStateCount, mortar::kPairedStateCount}) {
    OnePoint pt(m15_props(), states);
    FullPath full(states);
    const int n = 400;
    int differences = 0, elastic = 0;
    for (int i = 0; i <= 2 * n; ++i) {
      Inputs in = inputs(std::min(i, n), n);
      if (i > n) {  // unloaded by 2e-6 mm, then back and forth between 2e-6 and 1e-6 mm from the reached point
        const double back = i % 2 ? 2e-6 : 1e-6, before = i == n + 1 ? 0.0 : (i % 2 ? 1e-6 : 2e-6);
        in.penetration = Real(double(inputs(n, n).penetration) + back);
        in.dr_disp[1] = Real(before - back);
        in.dr_disp[2] = Real(back - before);
      }
      const double angle = i > 0 ? 1e-3 * std::sin(0.1 * i) : 0.0;
      const Real d_rot[4] = {Real(std::cos(angle)), Real(-std::sin(angle)), Real(std::sin(angle)),
                             Real(std::cos(angle))};
      apply(pt, in);
      std::copy(d_rot, d_rot + 4, pt.d_rot);
      pt.call();
      full.call(model, in, d_rot);
      differences += !std::equal(full.state.begin(), full.state.end(), pt.state.begin());
      differences += !std::equal(full.stress, full.stress + 3, pt.stress);
      elastic += i > n && pt.spd == Real(0);
    }
    CHECK(differences == 0);
    CHECK(elastic == n);  // every increment of the second half took the elastic path
    CHECK(pt.state[slot::plastic_s1] != Real(0));
    CHECK(pt.state[slot::crack_s2] != Real(0));
  }
}

TEST_CASE("State array: with float pairs the elastic store leaves unchanged pairs as they are, and a point with a "
          "pair that is not canonical goes the full path: both as loading and storing the whole state, bit for bit",
          "[abi][state]") {
  if (kDouble) return;  // no pairs
  // After plastic slip and opening, elastic back and forth, dRot the identity
  // at even calls and turning at odd ones; before every third call one pair
  // (in turn each of the 11) is replaced, in the routine's array and the
  // full path's alike, by one that is consistent but not canonical: a low
  // part with bits below the double sum's reach, a tie (half an odd high
  // part's spacing), a low part -0, or a -0 high part for a value 0.
  const mortar::Model model = model_of(m15_props());
  const int states = mortar::kPairedStateCount;
  OnePoint pt(m15_props(), states);
  FullPath full(states);
  const int n = 400;
  int differences = 0, elastic = 0, injected = 0, unchanged_kept = 0, unchanged = 0;
  for (int i = 0; i <= 2 * n; ++i) {
    Inputs in = inputs(std::min(i, n), n);
    double angle = 0;
    if (i > n) {
      const double back = i % 2 ? 2e-6 : 1e-6, before = i == n + 1 ? 0.0 : (i % 2 ? 1e-6 : 2e-6);
      in.penetration = Real(double(inputs(n, n).penetration) + back);
      in.dr_disp[1] = Real(before - back);
      in.dr_disp[2] = Real(back - before);
      angle = i % 2 ? 1e-3 * std::sin(0.1 * i) : 0.0;
    }
    const Real d_rot[4] = {Real(std::cos(angle)), Real(-std::sin(angle)), Real(std::sin(angle)),
                           Real(std::cos(angle))};
    if (i > n && i % 3 == 0) {
      // Not the damages: a value of 1 moved up leaves the range, and the
      // routine rejects the state (keeping it) where FullPath stores it.
      const int kinds[] = {0, 1, 2, 3, 4, 5, 8, 9, 10};
      const mortar::SlotPair p = mortar::kPairedSlots[kinds[(i / 3) % 9]];
      float high = pt.state[p.high], low = pt.state[p.low];
      const float spacing = std::nextafter(std::abs(high), std::numeric_limits<float>::infinity()) - std::abs(high);
      switch ((i / 33) % 4) {
        case 0: low = spacing * std::ldexp(1.0f + std::ldexp(1.0f, -23), -20); break;  // sum inexact
        case 1:  // a tie: an odd high part and half its spacing
          if (high != 0) {
            std::uint32_t b;
            std::memcpy(&b, &high, sizeof b);
            b |= 1u;
            std::memcpy(&high, &b, sizeof b);
          }
          low = 0.5f * (std::nextafter(std::abs(high), std::numeric_limits<float>::infinity()) - std::abs(high));
          break;
        case 2: low = -0.0f; break;
        default: if (high == 0) high = -0.0f; else low = -0.0f; break;
      }
      REQUIRE(mortar::pair_consistent(high, low));
      if (!mortar::pair_canonical(high, low, mortar::pair_value(high, low))) ++injected;
      pt.state[p.high] = full.state[p.high] = high;
      pt.state[p.low] = full.state[p.low] = low;
    }
    const std::vector<Real> start = pt.state;
    apply(pt, in);
    std::copy(d_rot, d_rot + 4, pt.d_rot);
    pt.call();
    full.call(model, in, d_rot);
    differences += !same_bits(full.state.data(), pt.state.data(), states);
    differences += !same_bits(full.stress, pt.stress, 3);
    if (i > n && pt.spd == Real(0)) {
      ++elastic;
      // The pairs an elastic increment without a turn does not change.
      if (angle == 0 && i % 3 != 0) {
        ++unchanged;
        bool kept = true;
        for (const mortar::SlotPair& p : mortar::kPairedSlots) {
          if (p.high >= slot::separation_n) continue;
          kept &= same_bits(&start[p.high], &pt.state[p.high], 1) && same_bits(&start[p.low], &pt.state[p.low], 1);
        }
        unchanged_kept += kept;
      }
    }
  }
  CHECK(differences == 0);
  CHECK(injected > 100);
  CHECK(elastic == n);
  CHECK(unchanged > 100);
  CHECK(unchanged_kept == unchanged);
}

TEST_CASE("State array: a first call replaces SDV 22 whatever it holds, on the elastic path as on the full path",
          "[abi][state]") {
  // Before the first call SDV 22 holds no reference yet (SDV 23 = 0), so its
  // content is no rule of the state (docs/model.md 3): a NaN or infinity
  // left there is overwritten with the penetration, in every layout.
  for (const int states : {mortar::kStateCount, mortar::kPairedStateCount}) {
    for (const Real garbage : {std::numeric_limits<Real>::quiet_NaN(), std::numeric_limits<Real>::infinity()}) {
      for (const double slip : {0.0, 0.05}) {  // a first call's slip is no increment: both elastic
        OnePoint pt(m15_props(), states);
        pt.state[slot::reference_penetration] = garbage;
        pt.penetration = Real(1e-4);
        pt.dr_disp[1] = Real(slip);
        pt.call();
        INFO("DEPVAR " << states << ", SDV 22 = " << garbage << ", slip " << slip);
        CHECK(pt.state[slot::status] == Real(0));
        CHECK(pt.state[slot::reference_penetration] == Real(1e-4));
        CHECK(pt.state[slot::initialised] == Real(1));
      }
    }
  }
}

TEST_CASE("State array: with DEPVAR = 35 SDV 35 holds the integration flags, and SDV 1-34 are those of the "
          "layout without it",
          "[abi][state][flags]") {
  // A floor of half the increment (props(19) = 0.5): the first plastic
  // increment accepts a substep at it above STOL (docs/model.md 9, flag 8).
  std::vector<Real> props = m15_props();
  props.resize(mortar::kPropsWithControls, Real(0));
  props[18] = Real(0.5);
  const int layout = kDouble ? mortar::kStateCount : mortar::kPairedStateCount;
  OnePoint flagged(props, mortar::kFlaggedStateCount), plain(props, layout);
  const int n = 40;
  int differences = 0;
  for (int i = 0; i <= n; ++i) {
    apply(flagged, inputs(i, n));
    apply(plain, inputs(i, n));
    flagged.call();
    plain.call();
    differences += !same_bits(plain.state.data(), flagged.state.data(), layout);
    differences += !same_bits(plain.stress, flagged.stress, 3);
  }
  CHECK(differences == 0);
  CHECK(flagged.state[mortar::slot::status] == Real(0));  // a flag is no failure
  CHECK(flagged.state[mortar::flag_slot::integration_flags] == Real(mortar::integration_flag::floor_above_stol));
}
