// Random valid parameter sets for the randomised tests (docs/model.md 10,
// invariant 10, the property tests): over and beyond the ranges of Table 1, including
// sets whose mode-I softening snaps back (ft0^2/GIC > kn). One generator, so
// that every randomised test draws from the same population; the draw order
// is part of each test's fixed-seed reproducibility.
#pragma once

#include <cmath>
#include <random>

#include "mortar/parameters.hpp"

namespace mj_test {

inline double log_uniform(std::mt19937& rng, double lo, double hi) {
  return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(rng));
}
inline double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// Valid by construction: c0 > ft0 tan(phi0), phir <= phi0, psir <= psi0.
inline mortar::Parameters random_parameters(std::mt19937& rng) {
  mortar::Parameters p;
  p.kn = log_uniform(rng, 20, 5000);
  p.ks = p.kn * uniform(rng, 0.2, 0.8);
  p.ft0 = log_uniform(rng, 0.05, 3);
  p.phi0 = uniform(rng, 20, 50);
  p.phir = p.phi0 * uniform(rng, 0.6, 1.0);
  p.c0 = p.ft0 * std::tan(p.phi0 * M_PI / 180) * uniform(rng, 1.05, 4);
  p.GIC = log_uniform(rng, 1e-4, 0.05);
  p.GIIC = p.GIC * uniform(rng, 2, 25);
  p.m = uniform(rng, 0, 1) < 0.2 ? 0.0 : log_uniform(rng, 10, 2e4);
  p.psi0 = uniform(rng, 0, 35);
  p.psir = p.psi0 * uniform(rng, 0, 1);
  p.n = uniform(rng, 0, 1) < 0.2 ? 0.0 : log_uniform(rng, 10, 2e4);
  p.bn = uniform(rng, 0, 15);
  p.bs = uniform(rng, 0, 6);
  return p;
}

}  // namespace mj_test
