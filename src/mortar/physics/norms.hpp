// The length of a 2-vector as std::hypot gives it, without the call where one
// side is zero: hypot(x, +-0) is fabs(x) exactly (C11 Annex F.10.4.3) and
// hypot is symmetric, so the value is hypot's, bit for bit. A 2D joint has
// no second shear component, and the fully softened surface has alpha = 0
// (Eq. 3 with s = 0); hypot itself rescales against overflow and costs about
// forty instructions.
#pragma once

#include <cmath>

namespace mortar {

inline double hypot_of(double x, double y) {
  if (y == 0) return std::abs(x);
  if (x == 0) return std::abs(y);
  return std::hypot(x, y);
}

}  // namespace mortar
