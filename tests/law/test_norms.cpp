// hypot_of (physics/norms.hpp): the length of a 2-vector with std::hypot's
// value, bit for bit, and without the call where one side is small against
// the other (docs/model.md 4: R = sqrt(alpha^2 + tau^2) on the residual
// surface). The correctly rounded length is computed here independently, in
// binary128, where every product and sum below is exact; where hypot_of
// calls hypot, the test asks only that it does.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#include "mortar/physics/norms.hpp"

using mortar::hypot_of;
using mortar::kNegligibleSide;
using mortar::kOneUlpBand;
using mortar::kOneUlpSide;

namespace {

std::uint64_t bits_of(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

bool same_bits(double a, double b) { return bits_of(a) == bits_of(b) || (std::isnan(a) && std::isnan(b)); }

// A pair (a, b), a > 0, with b at the edge of the shortcut: b = a c (1 - t)
// for a small t >= 0, and a's significand near 1 half of the time (where
// ulp(a) / a is smallest and the bound is tightest).
struct Pair {
  double a, b;
};
Pair near_threshold(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0, 1);
  const double significand = rng() % 2 ? 1 + 1e-6 * unit(rng) : 1 + unit(rng);
  const double a = std::ldexp(significand, int(rng() % 1600) - 800);
  const double b = a * kNegligibleSide * (1 - (rng() % 4 == 0 ? 0.0 : 1e-12 * unit(rng)));
  return {a, b};
}

double ulp_above(double a) { return std::nextafter(a, std::numeric_limits<double>::infinity()) - a; }

// A pair in the one-ulp regime, a within 2^+-399 (its significand near 1 or
// near 2, where ulp(a) / a is largest or smallest, or anywhere), b up to
// a kOneUlpSide: on its edge, anywhere below it, or a few doubles from the
// midpoint b^2 = a ulp(a) + ulp(a)^2 / 4.
Pair one_ulp_pair(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0, 1);
  const int shape = int(rng() % 3);
  const double significand = shape == 0 ? 1 + 1e-6 * unit(rng) : shape == 1 ? 2 - 1e-6 * unit(rng) : 1 + unit(rng);
  const double a = std::ldexp(significand, int(rng() % 798) - 399);
  const double u = ulp_above(a);
  double b;
  switch (rng() % 3) {
    case 0: b = a * kOneUlpSide * (1 - 1e-9 * unit(rng)); break;
    case 1: b = a * kOneUlpSide * (0.5 + 0.5 * unit(rng)); break;
    default:
      b = std::sqrt(a * u + u * u / 4);
      for (int steps = int(rng() % 41) - 20; steps != 0; steps += steps < 0 ? 1 : -1)
        b = std::nextafter(b, steps < 0 ? 0.0 : 1.0e300);
  }
  return {a, b};
}

// The correctly rounded sqrt(x^2 + y^2) (ties to even), computed without
// the C library's hypot: a candidate from long double, then moved until the
// exact length lies within half an ulp. With a >= b >= 0 and m a midpoint
// between doubles near the length, m^2 - a^2 = (m - a)(m + a) and b^2 are
// exact in binary128 (factors of at most 56 significant bits), so every
// comparison with a^2 + b^2 is exact.
double correctly_rounded_length(double x, double y) {
  if (std::isinf(x) || std::isinf(y)) return std::numeric_limits<double>::infinity();
  if (std::isnan(x) || std::isnan(y)) return std::numeric_limits<double>::quiet_NaN();
  const double a = std::max(std::abs(x), std::abs(y)), b = std::min(std::abs(x), std::abs(y));
  if (b == 0) return a;
  const long double la = a, lb = b;
  double c = double(std::sqrt(la * la + lb * lb));
  const double most = std::numeric_limits<double>::max();
  if (c > most) c = most;  // the last double's upper midpoint decides below
  // sign of (m^2 - a^2 - b^2), exactly.
  auto compare = [&](__float128 m) {
    const __float128 lhs = (m - a) * (m + a), rhs = __float128(b) * b;
    return lhs < rhs ? -1 : lhs > rhs ? 1 : 0;
  };
  auto even = [](double v) { return (bits_of(v) & 1) == 0; };
  for (;;) {
    const double below = std::nextafter(c, 0.0);
    const double gap_up = c == most ? c - below : std::nextafter(c, most) - c;  // same binade at the top
    const __float128 upper = __float128(c) + __float128(gap_up) / 2;
    const __float128 lower = __float128(c) - (__float128(c) - below) / 2;
    const int up = compare(upper), down = compare(lower);
    if (up < 0 || (up == 0 && !even(c))) {  // the length lies above c's upper midpoint
      if (c == most) return std::numeric_limits<double>::infinity();
      c = std::nextafter(c, most);
    } else if (down > 0 || (down == 0 && !even(c))) {
      c = below;
    } else {
      return c;
    }
  }
}

// Whether hypot_of decides without calling hypot (norms.hpp): a zero side,
// a negligible side, or the one-ulp regime outside the band around the
// midpoint, the distance from it computed exactly (binary128).
bool answered_without_hypot(double x, double y) {
  const double ax = std::abs(x), ay = std::abs(y);
  if (std::isnan(x) || std::isnan(y)) return false;
  if (x == 0 || y == 0) return true;
  const double a = std::max(ax, ay), b = std::min(ax, ay);
  if (b <= a * kNegligibleSide) return true;
  if (!(b <= a * kOneUlpSide && a >= 0x1p-400 && a <= 0x1p400)) return false;
  const double u = ulp_above(a);
  const __float128 past_midpoint = __float128(b) * b - __float128(a) * u - __float128(u) * u / 4;
  const __float128 band = kOneUlpBand * (__float128(u) * u);
  return past_midpoint > band || past_midpoint < -band;
}

}  // namespace

TEST_CASE("Norms: a side at most kOneUlpSide of the other leaves the correctly rounded length at the longer side or "
          "the double after it, and hypot_of picks it",
          "[norms]") {
  std::mt19937_64 rng(71);
  long taken = 0, rounded_up = 0, in_band = 0;
  for (int n = 0; n < 300000; ++n) {
    const Pair p = one_ulp_pair(rng);
    if (!(p.b <= p.a * kOneUlpSide)) continue;
    ++taken;
    INFO(p.a << ", " << p.b);
    const double u = ulp_above(p.a);
    const __float128 b2 = __float128(p.b) * p.b, au = __float128(p.a) * u, u2 = __float128(u) * u;
    // a^2 + b^2 < (a + 1.5 u)^2: nothing beyond a + u is nearer.
    REQUIRE(b2 < 3 * au + 2.25 * u2);
    const __float128 past_midpoint = b2 - au - u2 / 4;
    if (past_midpoint == 0) continue;  // a tie: left to hypot (within the band)
    const double correctly_rounded = past_midpoint > 0 ? p.a + u : p.a;
    rounded_up += past_midpoint > 0;
    if (past_midpoint <= kOneUlpBand * u2 && past_midpoint >= -kOneUlpBand * u2) {
      ++in_band;  // hypot's answer, checked against std::hypot below
      continue;
    }
    REQUIRE(hypot_of(p.a, p.b) == correctly_rounded);
    REQUIRE(hypot_of(-p.b, p.a) == correctly_rounded);
  }
  CHECK(taken > 150000);
  CHECK(rounded_up > 50000);
  CHECK(in_band > 10000);
  // The bound is tight: a constant 1e-6 larger lets b^2 reach 3 a ulp(a)
  // where a's significand is near 2.
  const double a = std::nextafter(2.0, 0.0), b = a * (kOneUlpSide * (1 + 1e-6)), u = ulp_above(a);
  CHECK_FALSE(__float128(b) * b < __float128(3) * a * u);
}

TEST_CASE("Norms: a side at most kNegligibleSide of the other leaves the correctly rounded length at the longer side",
          "[norms]") {
  // Exactly, in binary128 (113-bit significands: b^2, a ulp(a) and ulp(a)^2/4
  // and their sum are exact): sqrt(a^2 + b^2) rounds to a when it lies below
  // the midpoint a + ulp(a)/2, i.e. b^2 < a ulp(a) + ulp(a)^2 / 4. The
  // shortcut's test is the rounded b <= a c; the pairs sit on its edge.
  std::mt19937_64 rng(61);
  long taken = 0;
  for (int n = 0; n < 200000; ++n) {
    const Pair p = near_threshold(rng);
    if (!(p.b <= p.a * kNegligibleSide)) continue;
    ++taken;
    const double ulp = ulp_above(p.a);
    const __float128 b2 = __float128(p.b) * p.b;
    const __float128 midpoint_gap = __float128(p.a) * ulp + __float128(ulp) * ulp / 4;
    REQUIRE(b2 < midpoint_gap);
    REQUIRE(hypot_of(p.a, p.b) == p.a);
  }
  CHECK(taken > 150000);
  // Twice the constant is not negligible: the bound is not loose by a factor
  // that would let a wrong constant through.
  bool beyond = false;
  for (int n = 0; n < 200000 && !beyond; ++n) {
    const double a = std::ldexp(1 + 1e-6 * double(n % 1000) / 1000, n % 400 - 200);
    const double b = 2 * a * kNegligibleSide;
    const double ulp = ulp_above(a);
    beyond = !(__float128(b) * b < __float128(a) * ulp + __float128(ulp) * ulp / 4);
  }
  CHECK(beyond);
}

TEST_CASE("Norms: hypot_of is the correctly rounded length where it answers itself, and hypot's elsewhere",
          "[norms]") {
  // Around the shortcut's edge (both orders and signs), across magnitudes and
  // ratios, and at the special values; the reference is computed here
  // (correctly_rounded_length), not taken from the C library.
  std::mt19937_64 rng(67);
  std::uniform_real_distribution<double> unit(-1, 1);
  long shortcut = 0, one_ulp = 0, decided = 0;
  for (int n = 0; n < 600000; ++n) {
    double x, y;
    if (n % 3 == 2) {
      const Pair p = one_ulp_pair(rng);
      x = rng() % 2 ? p.a : -p.a;
      y = rng() % 2 ? p.b : -p.b;
      if (rng() % 2) std::swap(x, y);
      one_ulp += p.b <= p.a * kOneUlpSide && p.b > p.a * kNegligibleSide;
    } else if (n % 3 == 0) {
      const Pair p = near_threshold(rng);
      const double scale = 1 + (rng() % 3 == 0 ? 1e-9 * unit(rng) : 0.0);  // either side of the edge
      x = rng() % 2 ? p.a : -p.a;
      y = (rng() % 2 ? p.b : -p.b) * scale;
      if (rng() % 2) std::swap(x, y);
    } else {
      x = std::ldexp(unit(rng), int(rng() % 2100) - 1075);
      y = x * std::ldexp(unit(rng), -int(rng() % 60));
    }
    const double ax = std::abs(x), ay = std::abs(y);
    shortcut += (ay <= ax * kNegligibleSide) || (ax <= ay * kNegligibleSide);
    INFO(x << ", " << y);
    if (answered_without_hypot(x, y)) {
      ++decided;
      REQUIRE(same_bits(hypot_of(x, y), correctly_rounded_length(x, y)));
    } else {
      REQUIRE(same_bits(hypot_of(x, y), std::hypot(x, y)));  // the call itself
    }
  }
  CHECK(shortcut > 100000);
  CHECK(one_ulp > 100000);
  CHECK(decided > 300000);
  // C11 Annex F.10.4.3: hypot(+-inf, y) is +inf for any y, NaN included;
  // hypot(x, +-0) is |x|; otherwise a NaN side gives NaN.
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const double big = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
  const double special[] = {0.0, -0.0, tiny, -tiny, 1e-300, 1.0, -3.5, 1e300, big, -big, inf, -inf, nan};
  for (const double x : special)
    for (const double y : special) {
      INFO(x << ", " << y);
      CHECK(same_bits(hypot_of(x, y), correctly_rounded_length(x, y)));
    }
}
