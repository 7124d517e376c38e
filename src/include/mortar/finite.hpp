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

// all_finite() of twelve floats the caller computes, tested as three vectors
// built in registers. The same test through an array would store them one by
// one and load them four at a time, and a load that spans several pending
// stores waits for them (no store forwarding): about a sixth of the
// single-precision elastic update (adapter/state_storage.hpp).
#if defined(__GNUC__)
inline bool all_finite_values(const float (&v)[12]) {
  typedef float F4 __attribute__((vector_size(16)));
  typedef std::uint32_t U4 __attribute__((vector_size(16)));
  const F4 a = {v[0], v[1], v[2], v[3]}, b = {v[4], v[5], v[6], v[7]}, c = {v[8], v[9], v[10], v[11]};
  const F4 zeros[] = {a * 0.0f, b * 0.0f, c * 0.0f};
  U4 bits[3];
  std::memcpy(bits, zeros, sizeof bits);
  const U4 any = (bits[0] | bits[1] | bits[2]) << 1;
  return (any[0] | any[1] | any[2] | any[3]) == 0;
}
#else
inline bool all_finite_values(const float (&v)[12]) { return all_finite(v, 12); }
#endif

}  // namespace mortar
