// The length of a 2-vector as std::hypot gives it, without the call where one
// side is small against the other:
//  - hypot(x, +-0) is fabs(x) exactly (C11 Annex F.10.4.3), and hypot is
//    symmetric. A 2D joint has no second shear component, and the fully
//    softened surface has alpha = 0 (Eq. 3 with s = 0).
// The rest: docs/numerics.md, section 16.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

namespace mortar {

// sqrt(2) 2^-27 rounded down, just below 2^-26.5. With b <= a c (a > 0, the
// product rounded), b^2 <= a^2 2^-53 (1 + 2^-54) < a ulp(a), as a 2^-53 <
// ulp(a) (1 - 2^-53) for a in [2^e, 2^(e+1)), ulp(a) = 2^(e-52). So
// a^2 + b^2 < (a + ulp(a)/2)^2: the exact length lies below the midpoint
// between a and the next double up, and rounds to a. (For a subnormal a,
// ulp(a) = 2^-1074 and a c rounds to a multiple of it: to 0, leaving b = 0,
// or to at most 2 a c, which is enough while a < 2^-1023, and above that
// within 2^-25 of a c: b^2 < a ulp(a) in each case.)
inline constexpr double kNegligibleSide = 0x1.6a09e667f3bccp-27;

// The largest double c with c (1 + 2^-53) <= 1.5^0.5 2^-26. With b <= a c
// (the product rounded) and a normal, b^2 <= 1.5 a^2 2^-52 < 3 a ulp(a), as
// ulp(a) / a > 2^-53. So a^2 + b^2 < (a + 1.5 ulp(a))^2: the length rounds
// to a or to a + ulp(a) (exact: a is a multiple of ulp(a)), the latter when
// b^2 - a ulp(a) > ulp(a)^2 / 4, past the midpoint a + ulp(a)/2.
inline constexpr double kOneUlpSide = 0x1.3988e1409212dp-26;
// Within this many ulp(a)^2 of that midpoint the decision is left to hypot.
// The C library's hypot may round the wrong way up to 1.75 ulp(a)^2 from it,
// its first square root of a^2 + b^2 being rounded (docs/numerics.md,
// section 16). Outside the band the decision
// is exact: b^2 - a ulp(a) is rounded once by the fused multiply-add, the
// bounds (0.25 +- kOneUlpBand) ulp(a)^2 are doubles, and rounding is monotonic.
inline constexpr double kOneUlpBand = 8;

// ulp(a) for a normal a >= 2^-970: the power of two 52 binades below a's.
inline double ulp_of_normal(double a) {
  std::uint64_t bits;
  std::memcpy(&bits, &a, sizeof bits);
  bits = (bits & 0x7ff0000000000000ull) - (std::uint64_t(52) << 52);
  double u;
  std::memcpy(&u, &bits, sizeof u);
  return u;
}

inline double hypot_of(double x, double y) {
  if (y == 0) return std::abs(x);
  if (x == 0) return std::abs(y);
  // NaN fails both tests and goes to hypot, which answers it as C11 asks
  // (an infinite side wins over NaN); an infinite side passes and is the answer.
  const double ax = std::abs(x), ay = std::abs(y);
  if (ay <= ax * kNegligibleSide) return ax;
  if (ax <= ay * kNegligibleSide) return ay;
  const double a = ax < ay ? ay : ax, b = ax < ay ? ax : ay;
  // Within 2^+-400, a ulp(a) and ulp(a)^2 are normal and exact.
  if (b <= a * kOneUlpSide && a >= 0x1p-400 && a <= 0x1p400) {
    const double u = ulp_of_normal(a), u2 = u * u;
    const double excess = std::fma(b, b, -a * u);
    if (excess > (0.25 + kOneUlpBand) * u2) return a + u;
    if (excess < (0.25 - kOneUlpBand) * u2) return a;
  }
  return std::hypot(x, y);
}

}  // namespace mortar
