// hypot_of (physics/norms.hpp): the length of a 2-vector with std::hypot's
// value, bit for bit, and without the call where one side is small against
// the other (docs/model.md 4: R = sqrt(alpha^2 + tau^2) on the residual
// surface). The correctly rounded length is computed here independently, in
// binary128, where every product and sum below is exact.
#include <catch2/catch.hpp>

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

TEST_CASE("Norms: hypot_of is std::hypot bit for bit", "[norms]") {
  // Around the shortcut's edge (both orders and signs), across magnitudes and
  // ratios, and at the special values.
  std::mt19937_64 rng(67);
  std::uniform_real_distribution<double> unit(-1, 1);
  long shortcut = 0, one_ulp = 0;
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
    REQUIRE(same_bits(hypot_of(x, y), std::hypot(x, y)));
  }
  CHECK(shortcut > 100000);
  CHECK(one_ulp > 100000);
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const double big = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
  const double special[] = {0.0, -0.0, tiny, -tiny, 1e-300, 1.0, -3.5, 1e300, big, -big, inf, -inf, nan};
  for (const double x : special)
    for (const double y : special) {
      INFO(x << ", " << y);
      CHECK(same_bits(hypot_of(x, y), std::hypot(x, y)));
    }
}
