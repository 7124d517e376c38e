// What the Catch2 tests of the entry points (abi_tests.cpp: VUINTERACTION and
// VUINTER, uinter_tests.cpp: UINTER) share: names and props as Abaqus passes
// them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "mortar/parameters.hpp"

namespace mj_abi_test {

// A CHARACTER*80 name as Fortran passes it: blank padded, no terminator.
struct Name80 {
  char text[80];
  explicit Name80(const char* s) {
    std::memset(text, ' ', sizeof text);
    std::memcpy(text, s, std::min(std::strlen(s), sizeof text));
  }
};

// props(1..n_props) in the routine's precision: the parameter set as
// props(1..14), then zeros (the routine's defaults for controls and the shear
// sign) up to n_props.
template <class Real>
std::vector<Real> props_of(const mortar::Parameters& p, int n_props = mortar::kParameterCount) {
  const auto all = mortar::to_props(p);
  std::vector<Real> props(n_props, Real(0));
  for (int i = 0; i < std::min(n_props, mortar::kParameterCount); ++i) props[i] = Real(all[i]);
  return props;
}

// Every value finite, in either precision.
template <class Real>
bool all_finite(const std::vector<Real>& v) {
  return std::all_of(v.begin(), v.end(), [](Real x) { return std::isfinite(double(x)); });
}

}  // namespace mj_abi_test
