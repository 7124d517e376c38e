// Parameter sets of the paper's Table 1 (docs/model.md 2), and the model of a
// set under a scheme, for tests.
#pragma once

#include "mortar/parameters.hpp"

namespace mortar::testing {

// van der Pluijm monotonic shear; m and n depend on the normal stress level.
inline Parameters van_der_pluijm(double sigma_n) {
  double m = 1217.7, n = 1828.3;
  if (sigma_n == -0.1) { m = 10547.4; n = 15836.0; }
  if (sigma_n == -1.0) { m = 398.3; n = 598.1; }
  return {209.9, 87.4, 0.62, 0.88, 0.00458, 0.058, 40.97, 36.87, m, 27.7, 0, n, 10, 3};
}
inline Parameters atkinson() {
  return {471.4, 196.4, 0.085, 0.128, 0.0242, 0.1933, 35.26, 34.72, 50.4, 0.544, 0, 367.96, 10, 3};
}
inline Parameters almeida_m15() {
  return {741.1, 308.8, 1.78, 2.67, 0.01209, 0.121, 40, 32, 511.9, 8, 0, 856.1, 10, 3};
}
inline Parameters almeida_m34() {
  return {750.5, 312.7, 0.91, 1.37, 0.00293, 0.02925, 40, 32, 2944.5, 8, 0, 4923.8, 10, 3};
}

// The model of set p integrated by `scheme` at STOL `stol` (docs/model.md 7.4),
// every other control at its default.
inline Model model_with(const Parameters& p, Scheme scheme, double stol = 1e-5) {
  Controls c;
  c.scheme = scheme;
  c.stol = stol;
  return make_model_checked(p, c);
}

}  // namespace mortar::testing
