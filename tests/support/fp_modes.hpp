// The CPU's flush-to-zero (FTZ) and denormals-are-zero (DAZ) modes, which
// Intel-compiled programs (and so some Abaqus builds) run with: a subnormal
// result is replaced by 0, and a subnormal operand is read as 0
// (docs/robustness.md, floating-point modes). x86-64 only (the SSE control
// register MXCSR); MJ_FP_MODES is 0 elsewhere, and the tests that need the
// modes are not built there.
#pragma once

#if defined(__x86_64__) || defined(_M_X64)
#define MJ_FP_MODES 1
#include <xmmintrin.h>
#else
#define MJ_FP_MODES 0
#endif

namespace mj_test {

#if MJ_FP_MODES
// Sets FTZ and DAZ for the current thread while it lives, then restores the
// control register as it was.
class FlushDenormals {
 public:
  FlushDenormals() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | kFlushToZero | kDenormalsAreZero); }
  ~FlushDenormals() { _mm_setcsr(saved_); }
  FlushDenormals(const FlushDenormals&) = delete;
  FlushDenormals& operator=(const FlushDenormals&) = delete;

 private:
  static constexpr unsigned kFlushToZero = 0x8000;      // MXCSR bit 15
  static constexpr unsigned kDenormalsAreZero = 0x0040;  // MXCSR bit 6
  unsigned saved_;
};
#endif

// Whether the modes are in force, seen from arithmetic rather than from the
// register: a subnormal operand reads as 0 (DAZ), a product that would be
// subnormal comes out as 0 (FTZ), in double and in float. Volatile, so that
// the compiler cannot fold the products at its own (default) mode.
inline bool denormals_flushed() {
  volatile double subnormal = 1e-310, small = 1e-300, factor = 1e-10;
  volatile float subnormal_f = 1e-40f, small_f = 1e-30f, factor_f = 1e-10f;
  const bool daz = subnormal * 1.0 == 0.0 && subnormal_f * 1.0f == 0.0f;
  const bool ftz = small * factor == 0.0 && small_f * factor_f == 0.0f;
  return daz && ftz;
}

}  // namespace mj_test
