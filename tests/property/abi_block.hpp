// A caller of vuinteraction_ (standalone build, the routine's precision
// mj_real: property_tests links the double routine, property_tests_single the
// single one) for the property tests: a block of points with its arrays,
// called as Abaqus/Explicit calls it, plus random valid parameter sets and
// loading paths (fixed seeds).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"
#include "mortar/state_pairs.hpp"
#include "random_parameters.hpp"
#include "stderr_capture.hpp"
#include "test_scale.hpp"
#include "vuinteraction.h"

namespace mj_property {

using mj_test::property_scale;
using mj_test::scaled;

namespace slot = mortar::slot;
using Real = mj_real;
constexpr bool kSingle = sizeof(Real) == sizeof(float);
// The DEPVAR the blocks declare: single precision keeps its float pairs in
// SDV 24-34 (docs/model.md 3).
constexpr int kStates = kSingle ? mortar::kPairedStateCount : mortar::kStateCount;
// With a compression cap: kappa_c in SDV 36 (double) or the float pair 36-37.
constexpr int kCappedStates = kSingle ? mortar::kCappedStateCountSingle : mortar::kCappedStateCountDouble;

// One VUINTERACTION block: nBlock points, one node state each.
struct Block {
  int n_block, n_dir, n_states, n_props;
  std::vector<Real> stress, flux_slv, flux_mst, state, sed, sfd, scd, spd, svd;
  std::vector<Real> props, penetration, dr_disp;
  std::vector<int> slave_nodes;

  // `states`: DEPVAR, kStates or more (a capped deck: kCappedStates).
  Block(int block, int dir, std::vector<Real> p, int states = kStates)
      : n_block(block), n_dir(dir), n_states(states), n_props(int(p.size())), stress(size_t(dir) * block),
        flux_slv(block), flux_mst(block), state(size_t(states) * block), sed(block), sfd(block), scd(block), spd(block),
        svd(block), props(std::move(p)), penetration(block), dr_disp(size_t(dir) * block), slave_nodes(block) {
    for (int k = 0; k < block; ++k) slave_nodes[k] = 1001 + k;
  }

  Real* state_of(int k) { return &state[size_t(k) * n_states]; }
  const Real* state_of(int k) const { return &state[size_t(k) * n_states]; }
  Real* stress_of(int k) { return &stress[size_t(k) * n_dir]; }
  const Real* stress_of(int k) const { return &stress[size_t(k) * n_dir]; }

  void call() {
    const int n_nod_slv = 1, n_nod_mst = 4, n_temp = 0, n_fields = 1, n_node_states = 1;
    const int flags[3] = {1, 1, 0};
    const Real r_data[4] = {0, 0, Real(1e-6), 0};
    const size_t n = size_t(n_block), d = size_t(n_dir);
    std::vector<int> master_nodes(4 * n, 0);
    std::vector<Real> d_rot(4 * n), dircos(d * d * n), per_point(n), dircos_sl(d * n), shape_slv(n),
        shape_mst(4 * n), coord_slv(d * n), coord_mst(4 * d * n), field(n);
    for (size_t k = 0; k < n; ++k) d_rot[4 * k] = d_rot[4 * k + 3] = 1;  // the tangent directions do not turn
    char name[80], blank[80];
    std::memset(name, ' ', sizeof name);
    std::memset(blank, ' ', sizeof blank);
    std::memcpy(name, "PROPERTY", 8);
    vuinteraction_(stress.data(), flux_slv.data(), flux_mst.data(), state.data(), sed.data(), sfd.data(),
                   scd.data(), spd.data(), svd.data(), &n_block, &n_block, &n_block, &n_node_states, &n_nod_slv,
                   &n_nod_mst, &n_dir, &n_states, &n_props, &n_temp, &n_fields, flags, r_data, name, blank, blank,
                   slave_nodes.data(), master_nodes.data(), props.data(), penetration.data(), dr_disp.data(),
                   d_rot.data(), dircos.data(), per_point.data(), per_point.data(), per_point.data(),
                   dircos_sl.data(), shape_slv.data(), shape_mst.data(), coord_slv.data(), coord_mst.data(),
                   coord_slv.data(), coord_mst.data(), per_point.data(), per_point.data(), field.data(),
                   field.data(), 80, 80, 80);
  }
};

// The adapters' reports are checked by their text (tests/support).
using mj_test::StderrCapture;

// The implicit scheme's sets: n, or a single one when the tests are scaled
// down (the sanitizer builds), where its extreme increments, which spend up
// to its Newton budget (2e5 iterations), cost minutes: 3 sets took 330 s
// under ASan + UBSan.
inline int implicit_sets(int n) { return property_scale() < 1 ? 1 : n; }

// The population of tests/support/random_parameters.hpp (snap-back included:
// ft0^2/GIC up to several kn), as props(1..14).
using mj_test::log_uniform;
using mj_test::random_parameters;
using mj_test::uniform;

// props(1..14), then props(15) = scheme when not the default.
inline std::vector<Real> props_of(const mortar::Parameters& p, mortar::Scheme scheme = mortar::Scheme::modified_euler) {
  std::vector<Real> props(scheme == mortar::Scheme::modified_euler ? 14 : 15, Real(0));
  for (int i = 0; i < 14; ++i) props[i] = Real(mortar::parameter_at(p, i));
  if (props.size() > 14) props[14] = Real(static_cast<int>(scheme));
  return props;
}

// The model the routine builds from `props` (in its precision: single
// precision rounds the parameters to float, which moves F by more than FTOL).
inline mortar::Model model_of(const std::vector<Real>& props) {
  double p[15] = {};
  const int n = int(props.size());
  for (int i = 0; i < n; ++i) p[i] = double(props[i]);
  mortar::Parameters parameters;
  mortar::Controls controls;
  const mortar::ValidationError e = mortar::read_props(p, n, parameters, controls);
  if (!e.ok()) std::abort();  // props_of writes valid sets only
  return mortar::make_model(parameters, controls);
}

// One increment of a loading path in Abaqus terms: the change of the
// penetration and the slip increments drDisp(2..3).
struct Step {
  double d_penetration, slip1, slip2;
};

// Path families, scaled to the joint (un = ft0/kn, us = c0/ks: the elastic
// limits). `modest` keeps every increment within a fraction of the elastic
// limit (for the trapezoidal energy check); otherwise anything from tiny to
// many elastic limits, with reversals, opening-closing, jumps across the apex.
inline Step random_step(std::mt19937& rng, const mortar::Parameters& p, int family, bool modest) {
  const double un = p.ft0 / p.kn, us = p.c0 / p.ks;
  const double f = modest ? 0.1 : 1.0;
  switch (family % 5) {
    case 0:  // opening and closing, little shear
      return {-f * uniform(rng, -3, 3.3) * un, f * uniform(rng, -0.1, 0.1) * us, 0};
    case 1:  // shear reversals under a wandering pressure
      return {f * uniform(rng, -0.2, 0.25) * un, f * uniform(rng, -4, 4) * us, f * uniform(rng, -1, 1) * us};
    case 2:  // pressed, then sheared one way
      return {f * uniform(rng, -0.05, 0.15) * un, f * uniform(rng, 0, 2) * us, f * uniform(rng, -0.2, 0.2) * us};
    case 3:  // opening while sliding
      return {-f * uniform(rng, -0.5, 2) * un, f * uniform(rng, -2, 3) * us, f * uniform(rng, -2, 2) * us};
    default:  // anything, tiny to large
      if (modest) return {f * uniform(rng, -1, 1) * un, f * uniform(rng, -1, 1) * us, f * uniform(rng, -1, 1) * us};
      return {log_uniform(rng, 1e-12, 40) * un * (uniform(rng, 0, 1) < 0.5 ? -1 : 1),
              log_uniform(rng, 1e-12, 40) * us * (uniform(rng, 0, 1) < 0.5 ? -1 : 1),
              uniform(rng, 0, 1) < 0.5 ? 0.0 : log_uniform(rng, 1e-12, 10) * us};
  }
}

// Applies the step of point k to the block's inputs (the first call of a
// point defines its zero: it has no increment). Returns the separation
// increment the routine sees (law signs): in single precision the inputs
// are floats, so it is taken from them.
inline mortar::Vec3 apply(Block& b, int k, const Step& s) {
  const Real before = b.penetration[k];
  b.penetration[k] = Real(double(before) + s.d_penetration);
  Real* dd = &b.dr_disp[size_t(k) * b.n_dir];
  dd[0] = Real(-s.d_penetration);
  dd[1] = Real(s.slip1);
  if (b.n_dir == 3) dd[2] = Real(s.slip2);
  if (!kSingle) return mortar::Vec3(-s.d_penetration, s.slip1, b.n_dir == 3 ? s.slip2 : 0.0);
  return mortar::Vec3(double(before) - double(b.penetration[k]), double(dd[1]), b.n_dir == 3 ? double(dd[2]) : 0.0);
}

// The law's view of point k after a call: traction in law signs (sigma_n > 0
// tension; the default shear sign -1) and the state.
inline mortar::Vec3 law_traction(const Block& b, int k) {
  const Real* s = b.stress_of(k);
  return mortar::Vec3(-double(s[0]), -double(s[1]), b.n_dir == 3 ? -double(s[2]) : 0.0);
}
// The state as the routine of each precision loads it.
inline void load_point_state(const float* a, mortar::State& s) { mortar::load_state_pairs(a, s); }
inline void load_point_state(const double* a, mortar::State& s) { mortar::load_state(a, s); }
inline mortar::State law_state(const Block& b, int k) {
  mortar::State s;
  load_point_state(b.state_of(k), s);
  return s;
}

inline bool all_finite(const Real* v, size_t n) {
  return std::all_of(v, v + n, [](Real x) { return std::isfinite(double(x)); });
}

// Energy closure per point of a block. W_ext = sum 1/2 (sigma_old +
// sigma_new) . d_delta in law signs. The trapezoid is exact for a traction
// linear in the increment; for a traction monotone along each component of
// an increment its error is at most 1/2 |d_sigma_i| |d_delta_i| per
// component: `bound` sums that. A traction that drops at fixed separation
// (snap-back, closure jump) is the case the bound is made for; the law's own
// energy identity is tested at the law level (tests/law/test_energy.cpp).
struct EnergyBooks {
  std::vector<double> work, work_abs, bound;
  explicit EnergyBooks(int points) : work(size_t(points), 0.0), work_abs(size_t(points), 0.0), bound(size_t(points), 0.0) {}
  void add(int k, const mortar::Vec3& sigma_old, const mortar::Vec3& sigma, const mortar::Vec3& d_sep) {
    const double dw = 0.5 * (sigma_old + sigma).dot(d_sep);
    work[size_t(k)] += dw;
    work_abs[size_t(k)] += std::abs(dw);
    bound[size_t(k)] += 0.5 * (sigma - sigma_old).cwiseAbs().dot(d_sep.cwiseAbs());
  }
  // |W_ext - booked| with booked = sed + SDV 16 + 17 + 18.
  double error(const Block& b, int k) const {
    const Real* st = b.state_of(k);
    const double booked = double(b.sed[size_t(k)]) + double(st[slot::dissipation_plastic]) +
                          double(st[slot::dissipation_damage]) + double(st[slot::energy_unilateral]);
    return std::abs(work[size_t(k)] - booked);
  }
  // That error against sum |dW_ext|, and against the trapezoid's bound (0
  // where it is round-off: within 1e-12 of sum |dW_ext|).
  double relative(const Block& b, int k) const { return error(b, k) / std::max(work_abs[size_t(k)], 1e-300); }
  double vs_bound(const Block& b, int k) const {
    const double e = error(b, k);
    return e <= 1e-12 * work_abs[size_t(k)] ? 0.0 : e / bound[size_t(k)];
  }
};

}  // namespace mj_property
