// The length of a 2-vector as std::hypot gives it, without the call where one
// side is negligible:
//  - hypot(x, +-0) is fabs(x) exactly (C11 Annex F.10.4.3), and hypot is
//    symmetric. A 2D joint has no second shear component, and the fully
//    softened surface has alpha = 0 (Eq. 3 with s = 0).
//  - A side at most 2^-26.5 of the other: the correctly rounded length is the
//    longer side (kNegligibleSide, below), and glibc's hypot returns it
//    (tests/law/test_norms.cpp). On the residual surface alpha = s a can be
//    that small against |tau| (Eq. 3, docs/model.md 4): for the Almeida M15
//    set near 1 MPa, with s below about 2.5e-9 (docs/bench/throughput.md).
// hypot itself rescales against overflow and corrects its square root with a
// division: about fifty instructions, most of them on the dependency chain
// of the rate statement (about 15 ns a call on the AMD EPYC host of
// docs/bench/throughput.md).
#pragma once

#include <cmath>

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

inline double hypot_of(double x, double y) {
  if (y == 0) return std::abs(x);
  if (x == 0) return std::abs(y);
  // NaN fails both tests and goes to hypot, which answers it as C11 asks
  // (an infinite side wins over NaN); an infinite side passes and is the answer.
  const double ax = std::abs(x), ay = std::abs(y);
  if (ay <= ax * kNegligibleSide) return ax;
  if (ax <= ay * kNegligibleSide) return ay;
  return std::hypot(x, y);
}

}  // namespace mortar
