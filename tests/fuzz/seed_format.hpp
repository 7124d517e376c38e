// The seed generator's side of the input format (fuzz_input.hpp): one seed
// as its dimensions, props and start values (Case), then its calls, each a
// few state corruptions and the per-point increments (Seed::call).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "fuzz_input.hpp"

namespace mj_fuzz {

// Dimension bytes (inverse of the decode_* functions).
inline int enc_dir(int v) { return (v == 2 || v == 3) ? v - 2 : 0x80 | (v + 4); }
inline int enc_states(int v) { return (v >= 23 && v <= 30) ? v - 23 : 0x80 | (v + 2); }
inline int enc_node_states(int v) { return v == 1 ? 0 : v == 2 ? 0x40 : 0x80 | (v + 1); }
inline int enc_block(int v) { return (v >= 1 && v <= 8) ? v - 1 : 0x80 | (v + 2); }
inline int enc_props(int v) { return (v >= 14 && v <= 20) ? v - 14 : 0x80 | (v + 1); }

// A value, exactly: special kinds where they apply, else the raw double.
inline void value(Writer& w, double x) {
  if (x == 0) {
    w.u8(mj_fuzz::kZero);
  } else if (std::isnan(x)) {
    w.u8(mj_fuzz::kNaN);
  } else if (std::isinf(x)) {
    w.u8(mj_fuzz::kInfinity | (x < 0 ? 0x80 : 0));
  } else if (x == -1e36) {
    w.u8(mj_fuzz::kUnpaired);
  } else {
    mj_fuzz::write_raw(w, x);
  }
}
// A small increment (mm), in the kind that keeps mutations at the joint's scale.
inline void small(Writer& w, double mm) {
  if (std::abs(mm) <= 1e-4) mj_fuzz::write_smaller(w, mm);
  else mj_fuzz::write_small(w, mm);
}

struct Case {
  int n_dir = 3, n_states = 23, n_node_states = 1, n_block = 1, n_props = 14, n_nod_slv = 1;
  int props_mode = 0, paper = 0;                  // modes 0 and 3
  std::vector<int> control_bytes;                 // props(15..nProps), modes 0, 1, 3
  std::vector<double> raw_props;                  // mode 2
  std::vector<int> payload;                       // mode 1 (u16 each) or mode 3 (i8 each)
  std::vector<std::pair<int, double>> overrides;  // up to 3
  bool start_values = false;
  double start_stress = 0, start_sed = 0;
};

// One call: corruptions (point, slot, value), then per point the penetration
// (written by `pen`) and the drDisp components (written by `dd`).
struct Corruption {
  int point, slot;
  double value;
};

class Seed {
 public:
  explicit Seed(const Case& c) : c_(c) {
    w_.u8(enc_dir(c.n_dir));
    w_.u8(enc_states(c.n_states));
    w_.u8(enc_node_states(c.n_node_states));
    w_.u8(enc_block(c.n_block));
    w_.u8(enc_props(c.n_props));
    w_.u8(c.n_nod_slv);
    w_.u8(c.props_mode);
    if (c.props_mode == 2) {
      for (int i = 0; i < c.n_props; ++i) w_.f64(i < int(c.raw_props.size()) ? c.raw_props[i] : 0.0);
    } else {
      if (c.props_mode == 1) {
        // 14 two-byte fractions in Table 1 order, with the switch bytes
        // of m and n (nonzero: decay present) where random_valid_set reads them.
        const int order[14] = {0, 1, 2, 6, 7, 3, 4, 5, 8, 9, 10, 11, 12, 13};
        for (int j = 0; j < 14; ++j) {
          if (order[j] == 8 || order[j] == 11) w_.u8(1);
          w_.i16(c.payload[order[j]]);
        }
      } else {
        w_.u8(c.paper);
        if (c.props_mode == 3)
          for (int v : c.payload) w_.u8(v);
      }
      for (int i = 14; i < c.n_props; ++i) {
        const int b = i - 14 < int(c.control_bytes.size()) ? c.control_bytes[i - 14] : 0;
        w_.u8(b);
      }
    }
    w_.u8(int(c.overrides.size()));
    for (const auto& [index, v] : c.overrides) {
      w_.u8(index);
      w_.f64(v);
    }
    w_.u8(c.start_values ? 1 : 0);
    if (c.start_values) {
      for (int i = 0; i < c.n_dir * c.n_block; ++i) value(w_, c.start_stress);
      for (int i = 0; i < c.n_block; ++i) value(w_, c.start_sed);
    }
  }
  // Calls are appended by `call`; the count byte is written by `bytes`.
  template <class Points>
  void call(const std::vector<Corruption>& corruptions, Points points) {
    Writer w;
    w.u8(int(corruptions.size()));
    for (const Corruption& x : corruptions) {
      w.u8(x.point);
      w.u8(x.slot);
      value(w, x.value);
    }
    for (int k = 0; k < std::max(c_.n_block, 0); ++k) points(w, k);
    calls_.push_back(w.bytes);
  }
  std::vector<uint8_t> bytes() const {
    std::vector<uint8_t> out = w_.bytes;
    out.push_back(uint8_t(calls_.size() - 1));
    for (const auto& c : calls_) out.insert(out.end(), c.begin(), c.end());
    return out;
  }

 private:
  Case c_;
  Writer w_;
  std::vector<std::vector<uint8_t>> calls_;
};

}  // namespace mj_fuzz
