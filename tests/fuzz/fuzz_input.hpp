// The byte format of one fuzz input for vuinteraction_ (docs/robustness.md): how raw
// bytes become the arguments of a sequence of calls on one block. Read by the
// fuzz target (fuzz_vuinteraction.cpp) and written by the seed generator
// (make_seeds.cpp), so both sides live here.
//
// Everything is read front to back; a missing byte reads as 0, so every byte
// string is a valid input. Layout:
//
//   dims     6 bytes: nDir, nStates, nNodState, nBlock, nProps, nNodSlv. A
//            byte with its high bit clear gives a value Abaqus would pass
//            (nDir 2/3, nStates 23..30, nBlock 1..8, ...); with the high bit set, a value
//            from a small range around and beyond the valid one (nDir -4..11,
//            nStates -2..61, ...). Arrays are always sized as declared (the
//            caller's side of the contract); negative sizes mean empty arrays.
//   props    mode byte: 0 paper set, 1 random valid set, 2 raw doubles, 3
//            paper set scaled per parameter by 10^(i8/16); for modes 0, 1, 3
//            one byte per entry from props(15) on (controls, shear sign,
//            extra entries: a table of interesting values, or a raw double);
//            then up to 3 overrides (index byte, raw double). The target
//            lowers the substep budget props(18) to 10^3 where it is 0 (the
//            default, 10^5) or a larger valid count (up to 10^9): with a
//            tolerance no substep meets (STOL 1e-309) one increment spends
//            the whole budget, hours at 10^9; below the budget the same code
//            runs, and the rule [1, 1e9] itself is a unit test
//            (test_parameters.cpp). With nProps < 18 the law's default
//            applies, which the libFuzzer build lowers to 10^3 too
//            (src/mortar/parameters.hpp).
//   start    one flag byte: incoming stress and sed all 0, or one value each.
//   calls    1 + (byte % 8) calls. Per call: up to 3 state corruptions (point,
//            slot, value: garbage a corrupted restart could hold), then per
//            point the penetration (small kinds add to the previous one) and
//            nDir drDisp components. The target skips an input's remaining
//            calls once its points have spent 2 000 substeps (SDV 19 + 20)
//            in all: tight tolerances legitimately cost up to the budget of
//            substeps per point and increment (10^3 in the libFuzzer build;
//            the fallback chain four times that), and repeating that teaches
//            nothing; such inputs took most of a long run's time
//            (docs/robustness.md).
//
// A value is a kind byte and its payload (see Value): 0, small, tiny (down to
// denormals), huge (up to 1e308), NaN, +-infinity, raw IEEE bits, -1e36 (the
// "no opposite surface" marker).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <vector>

namespace mj_fuzz {

// Reads the input front to back; missing bytes are zeros.
class Reader {
 public:
  Reader(const uint8_t* data, size_t size) : p_(data), n_(size) {}
  uint8_t u8() { return i_ < n_ ? p_[i_++] : 0; }
  int16_t i16() {
    const uint16_t lo = u8(), hi = u8();
    return int16_t(uint16_t(lo | (hi << 8)));
  }
  uint16_t u16() { return uint16_t(i16()); }
  double f64() {
    uint64_t bits = 0;
    for (int k = 0; k < 8; ++k) bits |= uint64_t(u8()) << (8 * k);
    double x;
    std::memcpy(&x, &bits, sizeof x);
    return x;
  }

 private:
  const uint8_t* p_;
  size_t n_, i_ = 0;
};

// Writes the same format (seed generator).
class Writer {
 public:
  void u8(int b) { bytes.push_back(uint8_t(b)); }
  void i16(int v) {
    const uint16_t u = uint16_t(int16_t(v));
    u8(u & 0xff);
    u8(u >> 8);
  }
  void f64(double x) {
    uint64_t bits;
    std::memcpy(&bits, &x, sizeof x);
    for (int k = 0; k < 8; ++k) u8(int((bits >> (8 * k)) & 0xff));
  }
  std::vector<uint8_t> bytes;
};

// Dimension bytes.
inline int decode_n_dir(uint8_t b) { return (b & 0x80) ? (b & 0x0f) - 4 : 2 + (b & 1); }
inline int decode_n_states(uint8_t b) { return (b & 0x80) ? (b & 0x3f) - 2 : 23 + (b & 0x07); }
inline int decode_n_node_states(uint8_t b) { return (b & 0x80) ? (b & 0x03) - 1 : ((b & 0x40) ? 2 : 1); }
inline int decode_n_block(uint8_t b) { return (b & 0x80) ? (b & 0x03) - 2 : 1 + (b % 8); }
inline int decode_n_props(uint8_t b) { return (b & 0x80) ? (b & 0x1f) - 1 : 14 + (b % 7); }
inline int decode_n_node_slv(uint8_t b) { return b & 0x03; }

// Kinds of values (the low 7 bits of the kind byte modulo kKinds; the high
// bit makes tiny, huge and infinite values negative).
enum ValueKind : int {
  kZero = 0,
  kSmall = 1,    // i16/32768 * 1e-2 mm: the scale of joint openings
  kSmaller = 2,  // i16/32768 * 1e-4 mm: elastic range
  kTiny = 3,     // 10^-(u8 % 324): down into the denormals
  kHuge = 4,     // 10^(u8 % 309)
  kNaN = 5,
  kInfinity = 6,
  kRaw = 7,      // any IEEE double
  kUnpaired = 8, // -1e36: no opposite surface
  kLarge = 9,    // i16/32768 * 1 mm
  kKinds = 10
};
inline bool kind_is_small(int kind) { return kind == kSmall || kind == kSmaller || kind == kLarge; }

// A value; `relative_to` is added for the small kinds when `relative` (the
// penetration of a continuing path).
inline double read_value(Reader& r, bool relative = false, double relative_to = 0) {
  const uint8_t tag = r.u8();
  const int kind = (tag & 0x7f) % kKinds;
  const double sign = (tag & 0x80) ? -1.0 : 1.0;
  double v = 0;
  switch (kind) {
    case kZero: v = 0; break;
    case kSmall: v = r.i16() / 32768.0 * 1e-2; break;
    case kSmaller: v = r.i16() / 32768.0 * 1e-4; break;
    case kTiny: v = sign * std::pow(10.0, -double(r.u8() % 324)); break;
    case kHuge: v = sign * std::pow(10.0, double(r.u8() % 309)); break;
    case kNaN: v = std::numeric_limits<double>::quiet_NaN(); break;
    case kInfinity: v = sign * std::numeric_limits<double>::infinity(); break;
    case kRaw: v = r.f64(); break;
    case kUnpaired: v = -1e36; break;
    default: v = r.i16() / 32768.0; break;  // kLarge
  }
  if (relative && kind_is_small(kind)) v += relative_to;
  return v;
}

// Writers of each kind (seed generator).
inline void write_small(Writer& w, double mm) {  // nearest kSmall value
  w.u8(kSmall);
  w.i16(int(std::lround(std::max(-32768.0, std::min(32767.0, mm / 1e-2 * 32768.0)))));
}
inline void write_smaller(Writer& w, double mm) {
  w.u8(kSmaller);
  w.i16(int(std::lround(std::max(-32768.0, std::min(32767.0, mm / 1e-4 * 32768.0)))));
}
inline void write_raw(Writer& w, double x) {
  w.u8(kRaw);
  w.f64(x);
}
inline void write_kind(Writer& w, int kind, bool negative = false, int payload = 0) {
  w.u8(kind | (negative ? 0x80 : 0));
  if (kind == kTiny || kind == kHuge) w.u8(payload);
  if (kind == kSmall || kind == kSmaller || kind == kLarge) w.i16(payload);
  if (kind == kRaw) w.f64(0.0);
}

// Table-driven values of props(15..20) and beyond (props modes 0, 1, 3): a
// byte with its high bit set reads a raw double instead.
inline double control_value(int index0, uint8_t b, Reader& r) {
  if (b & 0x80) return r.f64();
  static const double scheme[] = {0, 1, 2, 3, -1, 1.5};
  static const double tol[] = {0, 1e-12, 1e-8, 1e-5, 1e-3, 0.5, 1, -1, 2, 1e-300};
  static const double substeps[] = {0, 1, 10, 1000, 1e9, 1.5, -1, 2e9, -1e300, 1e6};
  static const double min_substep[] = {0, 1e-300, 1e-12, 1e-4, 0.5, 1, 1.5, -1, 1e-8};
  static const double sign[] = {0, 1, -1, 0.5, 2};
  static const double other[] = {0, 1, -1, 1e300};
  auto pick = [b](const double* t, size_t n) { return t[b % n]; };
  switch (index0) {
    case 14: return pick(scheme, std::size(scheme));
    case 15: case 16: return pick(tol, std::size(tol));
    case 17: return pick(substeps, std::size(substeps));
    case 18: return pick(min_substep, std::size(min_substep));
    case 19: return pick(sign, std::size(sign));
    default: return pick(other, std::size(other));
  }
}

}  // namespace mj_fuzz
