// Load paths and independent measurements of their results, for the law tests.
// Everything measured here is computed from the returned curve (tractions and
// separations), not taken from the law's own bookkeeping, unless named so.
#pragma once

#include <cmath>
#include <vector>

#include "mortar/integrator.hpp"
#include "point_driver.hpp"

namespace mortar::testing {

struct Sample {
  Vec3 separation;
  Vec3 traction;
  State state;
  IncrementResult result;
};

// A recorded path: the start sample plus one per increment.
struct Curve {
  std::vector<Sample> samples;
  bool all_ok = true;

  // External work sum of 1/2 (sigma_i + sigma_i+1) . (delta_i+1 - delta_i).
  double external_work() const {
    double w = 0;
    for (size_t i = 1; i < samples.size(); ++i)
      w += 0.5 * (samples[i - 1].traction + samples[i].traction)
                     .dot(samples[i].separation - samples[i - 1].separation);
    return w;
  }
  // Elastic energy + dissipation booked by the law at the end of the path.
  double stored_plus_dissipated(const Model& M) const {
    const State& s = samples.back().state;
    return elastic_energy(M, s) + s.dissipation_plastic + s.dissipation_damage + s.energy_unilateral;
  }
  double max_traction(int i) const {
    double m = -1e300;
    for (const Sample& s : samples) m = std::max(m, s.traction[i]);
    return m;
  }
};

inline Sample sample_of(const Model& M, const State& s, const IncrementResult& r) {
  return Sample{s.separation, traction_of(M, s), s, r};
}

// Drives a point through separation increments (all components imposed).
class DisplacementDriver {
 public:
  explicit DisplacementDriver(const Model& M, State start = State{}) : M_(M), s_(start) {
    curve_.samples.push_back(sample_of(M_, s_, IncrementResult{}));
  }
  // `count` equal increments adding up to `total`.
  void ramp(const Vec3& total, int count) {
    for (int i = 0; i < count; ++i) step(total / count);
  }
  // Ramp to an absolute separation target.
  void ramp_to(const Vec3& target, int count) { ramp(target - s_.separation, count); }
  void step(const Vec3& d) {
    IncrementResult r = integrate_increment(M_, s_, d);
    if (!r.status.ok()) curve_.all_ok = false;
    curve_.samples.push_back(Sample{s_.separation, r.traction, s_, r});
  }
  const Curve& curve() const { return curve_; }
  const State& state() const { return s_; }

 private:
  const Model& M_;
  State s_;
  Curve curve_;
};

// Shear at constant normal traction sigma_n (mixed control), as in the van
// der Pluijm tests: first the normal traction is applied, then the slip.
inline Curve shear_at_constant_normal(const Model& M, double sigma_n, double slip, int increments,
                                      double direction_angle = 0.0) {
  harness::PointStepper step = harness::law_stepper(M);
  State s;
  Curve c;
  c.samples.push_back(sample_of(M, s, IncrementResult{}));
  harness::MixedIncrement pre;
  pre.c[0] = {true, sigma_n};
  harness::MixedResult r0 = harness::solve_mixed(step, s, pre, {1e-12, 50, 0});
  c.samples.push_back(Sample{s.separation, r0.result.traction, s, r0.result});
  const double ds = slip / increments;
  for (int i = 0; i < increments; ++i) {
    harness::MixedIncrement inc;
    inc.c[0] = {true, sigma_n};
    inc.c[1] = {false, ds * std::cos(direction_angle)};
    inc.c[2] = {false, ds * std::sin(direction_angle)};
    harness::MixedResult r = harness::solve_mixed(step, s, inc, {1e-12, 50, 0});
    if (!r.result.status.ok()) c.all_ok = false;
    c.samples.push_back(Sample{s.separation, r.result.traction, s, r.result});
  }
  return c;
}

inline Model model_with(const Parameters& p, Scheme scheme, double stol = 1e-5) {
  Controls c;
  c.scheme = scheme;
  c.stol = stol;
  return make_model_checked(p, c);
}

}  // namespace mortar::testing
