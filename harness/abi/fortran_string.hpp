// CHARACTER*80 as Fortran passes it: blank-padded, no terminator.
#pragma once

#include <algorithm>
#include <array>
#include <cstring>

namespace mortar::harness {

inline void fortran_string(std::array<char, 80>& out, const char* text) {
  out.fill(' ');
  std::memcpy(out.data(), text, std::min(std::strlen(text), out.size()));
}

}  // namespace mortar::harness
