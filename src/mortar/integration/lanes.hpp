// Two doubles in one vector register (SSE2, every x86-64), for the elastic
// shortcut's lanes (elastic_lanes.hpp), and the two functions its tests
// (elastic_shortcut.hpp) call with std::abs's and std::max's results, lane
// by lane. Declared before those tests, which then take either a double or
// a lanes::D. GCC and Clang only (vector extensions): MORTAR_ELASTIC_LANES
// says whether the lanes are there.
#pragma once

#include <cstdint>
#include <cstring>

#if defined(__GNUC__)
#define MORTAR_ELASTIC_LANES 1
#else
#define MORTAR_ELASTIC_LANES 0
#endif

namespace mortar {

#if MORTAR_ELASTIC_LANES
namespace lanes {
// Two lanes rather than four: four doubles fill two registers each without
// AVX, and the spills cost more than the wider lanes save (measured in a
// first version: 619 against 530 instructions per single-precision elastic
// update, docs/bench/throughput.md).
constexpr int kWidth = 2;
typedef double D __attribute__((vector_size(8 * kWidth)));
typedef std::int64_t Mask __attribute__((vector_size(8 * kWidth)));  // all bits set: true
}  // namespace lanes

inline lanes::D magnitude(lanes::D x) {
  lanes::Mask bits;
  std::memcpy(&bits, &x, sizeof bits);
  bits &= 0x7fffffffffffffffLL;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}
// std::max(a, b) lane by lane: a < b ? b : a.
inline lanes::D larger(lanes::D a, double b) { return a < b ? lanes::D{} + b : a; }
inline lanes::D larger(lanes::D a, lanes::D b) { return a < b ? b : a; }
#endif

}  // namespace mortar
