// The float pairs of the single-precision routines (src/mortar/state.hpp,
// docs/model.md 3): the high parts are exactly the plain float layout users
// read, the pair carries a double to about 48 bits, a low part that is not
// its high part's remainder is recognised, and rounding the state into pairs
// keeps a state on the yield surface within FTOL·ft0 of it, where plain
// floats do not (the start of every plastic increment, docs/model.md 7.1).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"
#include "mortar/physics/elasticity.hpp"
#include "mortar/physics/yield_surface.hpp"
#include "mortar/state_pairs.hpp"
#include "paper_sets.hpp"
#include "formatted.hpp"

using namespace mortar;

namespace {

// Every paired variable of `s`, in the order of kPairedSlots.
std::vector<double> paired_values(const State& s) {
  return {s.plastic[0], s.plastic[1], s.plastic[2], s.wI, s.wII, s.wIII, s.dn, s.ds,
          s.separation[0], s.separation[1], s.separation[2]};
}

State random_state(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0, 1), exponent(-9, 1);
  auto magnitude = [&] { return std::pow(10.0, exponent(rng)) * (unit(rng) < 0.5 ? -1 : 1); };
  State s;
  s.plastic = Vec3(magnitude(), magnitude(), magnitude());
  s.crack = Vec3(magnitude(), magnitude(), magnitude());
  s.wI = std::abs(magnitude());
  s.wII = std::abs(magnitude());
  s.wIII = std::abs(magnitude());
  s.dn = unit(rng);
  s.ds = unit(rng);
  s.separation = Vec3(magnitude(), magnitude(), magnitude());
  s.open = unit(rng) < 0.5;
  return s;
}

State round_trip_pairs(const State& s) {
  float a[kPairedStateCount] = {};
  store_state_pairs(s, a);
  State back;
  load_state_pairs(a, back);
  return back;
}

State round_trip_float(const State& s) {
  float a[kStateCount] = {};
  store_state(s, a);
  State back;
  load_state(a, back);
  return back;
}

}  // namespace

TEST_CASE("State pairs: the low parts are SDV 24-34, one per accumulating variable", "[state][pairs]") {
  CHECK(kPairedStateCount == 34);
  CHECK(low_slot::plastic_n == 23);  // SDV 24
  CHECK(low_slot::separation_s2 == 33);  // SDV 34
  const int highs[] = {slot::plastic_n, slot::plastic_s1, slot::plastic_s2, slot::work_I, slot::work_II,
                       slot::work_III, slot::damage_n, slot::damage_s, slot::separation_n, slot::separation_s1,
                       slot::separation_s2};
  int i = 0;
  for (const SlotPair& p : kPairedSlots) {
    CHECK(p.high == highs[i]);
    CHECK(p.low == kStateCount + i);
    ++i;
  }
  CHECK(std::string(kLowStateNames[0]) == "dp_n_lo");
  CHECK(std::string(kLowStateNames[kPairedStateCount - kStateCount - 1]) == "delta_s2_lo");
}

TEST_CASE("State pairs: SDV 1-23 are the plain float layout and the pair gives the double back to 48 bits",
          "[state][pairs]") {
  std::mt19937 rng(20261111);
  double worst = 0;
  for (int n = 0; n < 2000; ++n) {
    const State s = random_state(rng);
    float plain[kStateCount] = {}, paired[kPairedStateCount] = {};
    store_state(s, plain);
    store_state_pairs(s, paired);
    for (int i = 0; i < kStateCount; ++i) REQUIRE(paired[i] == plain[i]);
    for (const SlotPair& p : kPairedSlots) REQUIRE(pair_consistent(paired[p.high], paired[p.low]));
    const std::vector<double> in = paired_values(s), out = paired_values(round_trip_pairs(s));
    for (size_t i = 0; i < in.size(); ++i) worst = std::max(worst, std::abs(out[i] - in[i]) / std::abs(in[i]));
    const State back = round_trip_pairs(s);
    CHECK(back.dn <= 1);
    CHECK(back.ds <= 1);
    CHECK(back.wI >= 0);
  }
  INFO(mj_test::formatted("float pair round trip: worst relative error %.3g (2^-48 = %.3g)", worst,
                          std::ldexp(1.0, -48)));
  CHECK(worst <= std::ldexp(1.0, -47));
}

TEST_CASE("State pairs: a low part beyond one float spacing of its high part is not a pair", "[state][pairs]") {
  const float high = 0.05f;
  const float spacing = std::nextafter(high, 1.0f) - high;
  CHECK(pair_consistent(high, 0.0f));
  CHECK(pair_consistent(high, 0.5f * spacing));
  CHECK(pair_consistent(high, -spacing));
  CHECK_FALSE(pair_consistent(high, 2.0f * spacing));
  CHECK_FALSE(pair_consistent(high, 1e-3f));
  CHECK(pair_consistent(0.0f, 0.0f));
  CHECK(pair_consistent(0.0f, std::numeric_limits<float>::denorm_min()));
  CHECK_FALSE(pair_consistent(0.0f, 1e-30f));
  CHECK_FALSE(pair_consistent(high, std::numeric_limits<float>::quiet_NaN()));
  CHECK_FALSE(pair_consistent(std::numeric_limits<float>::infinity(), 0.0f));
}

namespace {

std::uint32_t bits_of(float x) {
  std::uint32_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// The pair store_state_pairs writes for x, computed so that no compiler can
// fold the extension of the truncation (the volatile).
void reference_pair(double x, float& high, float& low) {
  volatile float h = float(x);
  high = h;
  low = float(x - double(high));
}

// store_state_pairs applied to the pair's own value (the full path's rewrite).
void rewrite(float& high, float& low) { reference_pair(pair_value(high, low), high, low); }

}  // namespace

TEST_CASE("State pairs: a stored pair is canonical, so storing its value again leaves it as it is, but for the "
          "ties and the signed zeros, canonical within two rewrites",
          "[state][pairs]") {
  std::mt19937_64 rng(20261203);
  std::uniform_int_distribution<std::uint64_t> any_bits;
  std::uniform_real_distribution<double> unit(-1, 1), exponent(-160, 128);
  long canonical = 0, exceptions = 0, ties = 0;
  for (int n = 0; n < 400000; ++n) {
    // Doubles over float's range and beyond its least spacing, half of them
    // with random low bits, a quarter near float values.
    double x = std::ldexp(unit(rng), int(exponent(rng)));
    if (n % 4 == 1) x = double(float(x)) + std::ldexp(unit(rng), int(exponent(rng)) - 30);
    if (n % 4 == 2) x = std::nextafter(double(float(x)), any_bits(rng) % 2 ? 1e300 : -1e300);
    float high, low;
    reference_pair(x, high, low);
    if (!std::isfinite(high)) continue;
    const double v = pair_value(high, low);
    const bool is_canonical = pair_canonical(high, low, v);
    float h2 = high, l2 = low;
    rewrite(h2, l2);
    // Canonical means exactly that the rewrite changes nothing.
    REQUIRE(is_canonical == (bits_of(h2) == bits_of(high) && bits_of(l2) == bits_of(low)));
    REQUIRE(pair_consistent(high, low));
    if (is_canonical) {
      ++canonical;
      continue;
    }
    ++exceptions;
    // Only the exceptions of pair_canonical's comment; (-0, -0) becomes
    // (-0, +0), then (+0, +0), every other one canonical at once.
    const bool signed_zero = bits_of(low) == 0x80000000u || bits_of(high) == 0x80000000u;
    const float spacing = std::nextafter(std::abs(high), std::numeric_limits<float>::infinity()) - std::abs(high);
    const bool tie = std::abs(double(low)) == 0.5 * double(spacing) || std::abs(double(low)) == 0.25 * double(spacing);
    CHECK((signed_zero || tie));
    ties += !signed_zero;
    if (!pair_canonical(h2, l2, pair_value(h2, l2))) {
      CHECK((bits_of(high) == 0x80000000u && bits_of(low) == 0x80000000u));
      rewrite(h2, l2);
    }
    CHECK(pair_canonical(h2, l2, pair_value(h2, l2)));
    CHECK(pair_value(h2, l2) == v);
  }
  INFO(mj_test::formatted(
      "stored pairs: %ld canonical, %ld exceptions (%ld ties, the rest signed zeros of values below 2^-97)", canonical,
      exceptions, ties));
  CHECK(ties * 100 < canonical);  // rare (here 0.1 %: the draws crowd near float values); signed zeros: tiny values

  // The three exceptions, constructed: a tie (the remainder rounding up to
  // half an odd high part's spacing), a low part -0, a high part -0.
  const float odd = 1.0f + std::ldexp(1.0f, -23);
  const double tie = double(odd) + std::ldexp(1.0, -24) - std::ldexp(1.0, -52);
  for (const double x : {tie, -std::ldexp(1.0, -160), -0.0, double(odd)}) {
    float high, low;
    reference_pair(x, high, low);
    const bool exception = x != double(odd);
    CHECK(pair_canonical(high, low, pair_value(high, low)) == !exception);
    rewrite(high, low);
    if (x != -std::ldexp(1.0, -160)) CHECK(pair_canonical(high, low, pair_value(high, low)));
    rewrite(high, low);
    CHECK(pair_canonical(high, low, pair_value(high, low)));
  }
}

TEST_CASE("State pairs: a canonical pair with a finite high part is consistent", "[state][pairs]") {
  // What lets the elastic path's canonical test stand for pair_consistent:
  // high parts of every magnitude (denormals and FLT_MAX included), low
  // parts from 0 to a few spacings, either sign, signed zeros.
  std::mt19937_64 rng(31);
  std::uniform_int_distribution<std::uint32_t> finite_bits(0, 0x7f7fffffu), any(0, 0xffffffffu);
  long canonical = 0, bad = 0;
  for (int n = 0; n < 1000000; ++n) {
    std::uint32_t hb = finite_bits(rng) | (any(rng) & 0x80000000u);
    if (n % 8 == 0) hb = any(rng) & 0x80000001u;  // zeros and the least denormal
    float high;
    std::memcpy(&high, &hb, sizeof high);
    const float spacing = std::nextafter(std::abs(high), std::numeric_limits<float>::infinity()) - std::abs(high);
    const std::uint32_t r = any(rng);
    float low = std::ldexp(float(r % 4096) - 2048.0f, -int(r >> 12) % 40) * spacing / 512.0f;
    if (n % 16 == 1) low = -0.0f;
    if (n % 16 == 2) low = 0.5f * spacing;
    if (!std::isfinite(low)) continue;
    if (!pair_canonical(high, low, pair_value(high, low))) continue;
    ++canonical;
    bad += !pair_consistent(high, low);
  }
  INFO(mj_test::formatted("canonical pairs drawn: %ld", canonical));
  CHECK(canonical > 100000);
  CHECK(bad == 0);
}

TEST_CASE("State pairs: split_into_pair, inline and over consecutive lanes, is store_state_pairs' rounding", "[state][pairs]") {
  // Three lanes side by side, as the elastic path stores the separation: the
  // shape GCC 12.2's vectoriser miscompiles without split_into_pair's barrier.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1, 1), exponent(-40, 10);
  int differences = 0;
  for (int n = 0; n < 20000; ++n) {
    State s;
    for (int i = 0; i < 3; ++i) s.separation[i] = std::ldexp(1.0 + unit(rng) * 1e-3, int(exponent(rng)));
    s.separation[0] = 1.0 + std::ldexp(1.0, -30);
    float a[kPairedStateCount] = {}, b[6];
    store_state_pairs(s, a);
    for (int i = 0; i < 3; ++i) split_into_pair(s.separation[i], b[i], b[3 + i]);
    for (int i = 0; i < 3; ++i) {
      differences += bits_of(b[i]) != bits_of(a[slot::separation_n + i]);
      differences += bits_of(b[3 + i]) != bits_of(a[low_slot::separation_n + i]);
    }
  }
  CHECK(differences == 0);
}

namespace {

// Worst |F(rounded) - F(exact)| / (FTOL ft0) over the plastic increments of a
// double-precision run, the state rounded as `round` does.
template <class Round>
double worst_drift(const Model& M, const std::vector<State>& on_surface, Round round) {
  double worst = 0;
  for (const State& s : on_surface) {
    const State r = round(s);
    const double F = yield_function(traction_of(M, s), surface_of(M, s));
    const double Fr = yield_function(traction_of(M, r), surface_of(M, r));
    worst = std::max(worst, std::abs(Fr - F) / (M.controls.ftol * M.p.ft0));
  }
  return worst;
}

// The end states of the plastic increments (on the surface within FTOL) of
// `n` increments `d` from `s`.
void collect_on_surface(const Model& M, State s, const Vec3& d, int n, std::vector<State>& out) {
  for (int i = 0; i < n; ++i) {
    REQUIRE(integrate_increment(M, s, d).status.ok());
    const Vec3 sigma = traction_of(M, s);
    if (std::abs(yield_function(sigma, surface_of(M, s))) <= yield_tolerance(M, sigma)) out.push_back(s);
  }
}

}  // namespace

TEST_CASE("State pairs: rounding to pairs keeps a state on the surface within FTOL*ft0 where plain floats do not",
          "[state][pairs]") {
  // Almeida M15 opened to 0.05 mm, van der Pluijm sheared to 0.2 mm at
  // sigma_n = -1 MPa, both at 1e-5 mm: the start state of every next plastic
  // increment is this end state as the routine stores and reloads it.
  struct Run {
    const char* name;
    Model model;
    State start;
    Vec3 d;
    int n;
  };
  State pressed;
  const Model vdp = testing::model_with(testing::van_der_pluijm(-1.0), Scheme::modified_euler);
  REQUIRE(integrate_increment(vdp, pressed, Vec3(-1.0 / vdp.p.kn, 0, 0)).status.ok());
  const Run runs[] = {
      {"M15 opening", testing::model_with(testing::almeida_m15(), Scheme::modified_euler), State(),
       Vec3(1e-5, 0, 0), 5000},
      {"vdp shear", vdp, pressed, Vec3(0, 1e-5, 0), 20000},
  };
  for (const Run& run : runs) {
    std::vector<State> on_surface;
    collect_on_surface(run.model, run.start, run.d, run.n, on_surface);
    REQUIRE(on_surface.size() > size_t(run.n) / 2);
    const double pairs = worst_drift(run.model, on_surface, round_trip_pairs);
    const double plain = worst_drift(run.model, on_surface, round_trip_float);
    INFO(mj_test::formatted("%s: %zu states on the surface; worst |dF|/(FTOL ft0): float pairs %.3g, plain float %.3g",
                            run.name, on_surface.size(), pairs, plain));
    CHECK(pairs <= 1e-3);
    CHECK(plain > 1);  // why the pairs: plain floats put the start state off the surface
  }
}

TEST_CASE("State pairs: canonical_pairs_into sets each paired member as load_state_pairs does and tells canonical "
          "arrays from the others",
          "[state][pairs]") {
  // The vectorised load of the elastic path against its scalar definition:
  // every member from its own pair (pair_value), and the verdict the and of
  // pair_canonical over the 11 pairs, on stored states and on arrays with
  // one pair made non-canonical.
  std::mt19937_64 rng(47);
  std::uniform_real_distribution<double> value(-2.0, 2.0);
  long canonical = 0, not_canonical = 0;
  for (int n = 0; n < 20000; ++n) {
    State s;
    for_each_pair(s, [&](int, int, double& x) { x = value(rng) * std::ldexp(1.0, int(rng() % 40) - 30); });
    float a[kPairedStateCount] = {};
    store_state_pairs(s, a);
    if (n % 2 == 1) {  // one pair made non-canonical: a low part -0, or a whole spacing
      const SlotPair p = kPairedSlots[rng() % kPairCount];
      const float high = a[p.high];
      a[p.low] = n % 4 == 1 ? -0.0f : std::nextafter(high, 2 * high + 1) - high;
    }
    State expected, got;
    load_state_pairs(a, expected);
    const bool verdict = canonical_pairs_into(a, got);
    // Both states' paired members in kPairedSlots' order (for_each_pair's).
    double want[kPairCount], have[kPairCount];
    int i = 0;
    for_each_pair(expected, [&](int, int, double& x) { want[i++] = x; });
    i = 0;
    for_each_pair(got, [&](int, int, double& x) { have[i++] = x; });
    bool all = true;
    for (int k = 0; k < kPairCount; ++k)
      all = all && pair_canonical(a[kPairedSlots[k].high], a[kPairedSlots[k].low], want[k]);
    CHECK(verdict == all);
    (all ? canonical : not_canonical) += 1;
    CHECK(std::memcmp(want, have, sizeof want) == 0);
  }
  INFO(mj_test::formatted("canonical arrays: %ld, not canonical: %ld", canonical, not_canonical));
  CHECK(canonical > 5000);
  CHECK(not_canonical > 5000);
}

TEST_CASE("State pairs: pairs_consistent is pair_consistent over the 11 pairs, whatever the other slots hold",
          "[state][pairs]") {
  // The vectorised test of the single-precision full path against its scalar
  // definition, on stored states with one pair spoilt, or one slot of SDV
  // 1-23 that belongs to no pair: NaN, infinity, a low part beyond its
  // spacing.
  std::mt19937_64 rng(53);
  std::uniform_real_distribution<double> value(-2.0, 2.0);
  const float spoilt[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(), 1e-3f,
                          -1e30f};
  long consistent = 0, inconsistent = 0;
  for (int n = 0; n < 20000; ++n) {
    State s;
    for_each_pair(s, [&](int, int, double& x) { x = value(rng) * std::ldexp(1.0, int(rng() % 40) - 30); });
    float a[kPairedStateCount] = {};
    store_state_pairs(s, a);
    const float bad = spoilt[rng() % 4];
    if (n % 3 == 1) {  // a pair's high or low part
      const SlotPair p = kPairedSlots[rng() % kPairCount];
      a[rng() % 2 ? p.high : p.low] = bad;
    } else if (n % 3 == 2) {  // a slot of no pair (the vector lanes read SDV 4 beside the pairs)
      int i;
      do i = int(rng() % kStateCount);
      while (std::any_of(std::begin(kPairedSlots), std::end(kPairedSlots), [&](const SlotPair& p) { return p.high == i; }));
      a[i] = bad;
    }
    bool all = true;
    for (const SlotPair& p : kPairedSlots) all = all && pair_consistent(a[p.high], a[p.low]);
    CHECK(pairs_consistent(a) == all);
    (all ? consistent : inconsistent) += 1;
  }
  INFO(mj_test::formatted("consistent arrays: %ld, not consistent: %ld", consistent, inconsistent));
  CHECK(consistent > 10000);
  CHECK(inconsistent > 3000);
}
