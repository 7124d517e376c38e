// One test that a run of values is finite, for the paths every point-update
// takes (the adapters' outputs, the state's rules): no branch per value and no
// chain of dependent additions, so that the compiler can vectorise it.
#pragma once

#include <cstdint>
#include <cstring>
#include <type_traits>

namespace mortar {

// x * 0 is +0 or -0 for a finite x and NaN otherwise; or-ing the bits of the
// products, the sign bit left out, leaves 0 exactly when every x is finite.
// Integer ors may be reordered freely (floating-point sums may not), which is
// what lets the loop run in vector registers.
template <class Real>
bool all_finite(const Real* a, int n) {
  static_assert(std::is_floating_point_v<Real> && (sizeof(Real) == 4 || sizeof(Real) == 8));
  using Bits = std::conditional_t<sizeof(Real) == 4, std::uint32_t, std::uint64_t>;
  Bits any = 0;
  for (int i = 0; i < n; ++i) {
    const Real zero = a[i] * Real(0);
    Bits b;
    std::memcpy(&b, &zero, sizeof b);
    any |= b;
  }
  return Bits(any << 1) == 0;
}

}  // namespace mortar
