// Two doubles in one vector register (SSE2, every x86-64) for the elastic
// kernel's lanes (mortar/batch.hpp), and abs_of and max_of over them, so that
// the kernel's templates (mortar/elastic.hpp) take a double or a lanes::D.
// GCC and Clang only (vector extensions): MORTAR_ELASTIC_LANES says whether
// the lanes are there.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__GNUC__)
#define MORTAR_ELASTIC_LANES 1
#else
#define MORTAR_ELASTIC_LANES 0
#endif

// The elastic kernel's templates inline into each caller, so that its inputs
// and results stay in registers; GCC's size limits would keep one copy out
// of line, called through memory.
#if defined(__GNUC__)
#define MORTAR_KERNEL_INLINE inline __attribute__((always_inline))
#else
#define MORTAR_KERNEL_INLINE inline
#endif

namespace mortar {

inline double abs_of(double x) { return std::abs(x); }
// std::max(a, b): a < b ? b : a.
inline double max_of(double a, double b) { return a < b ? b : a; }

#if MORTAR_ELASTIC_LANES
namespace lanes {
// Two lanes rather than four: without AVX four doubles take two registers
// each, and the spills cost more than the wider lanes save.
constexpr int kWidth = 2;
typedef double D __attribute__((vector_size(8 * kWidth)));
typedef std::int64_t Mask __attribute__((vector_size(8 * kWidth)));  // all bits set: true
}  // namespace lanes

inline lanes::D abs_of(lanes::D x) {
  lanes::Mask bits;
  std::memcpy(&bits, &x, sizeof bits);
  bits &= 0x7fffffffffffffffLL;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}
inline lanes::D max_of(lanes::D a, double b) { return a < b ? lanes::D{} + b : a; }
inline lanes::D max_of(lanes::D a, lanes::D b) { return a < b ? b : a; }
#endif

}  // namespace mortar
