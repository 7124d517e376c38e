// Load paths and independent measurements of their results, for the law tests.
// Everything measured here is computed from the returned curve (tractions and
// separations), not taken from the law's own bookkeeping, unless named so.
#pragma once

#include <cmath>
#include <vector>

#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"
#include "paper_sets.hpp"

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

// One increment at a prescribed normal traction: the shear increments are
// imposed and the normal separation increment is solved for, as a solver
// would (Newton with forward-difference slopes and a halving line search,
// each trial from a copy of the start state), then committed to `s`. False,
// with `s` unchanged, when the traction is not reached within 1e-12 MPa in
// 50 iterations.
inline bool step_at_normal_traction(const Model& M, State& s, double sigma_n, double d_slip1, double d_slip2,
                                    IncrementResult& result) {
  constexpr double kTolerance = 1e-12;
  Vec3 d(0, d_slip1, d_slip2);
  auto trial = [&](const Vec3& dd, State& end) {
    end = s;
    return integrate_increment(M, end, dd);
  };
  State end;
  IncrementResult r = trial(d, end);
  double res = r.traction[0] - sigma_n;
  for (int it = 0; it < 50 && !(std::abs(res) <= kTolerance); ++it) {
    const double h = 1e-7 * (std::abs(d[0]) + 1e-4);
    Vec3 dh = d;
    dh[0] += h;
    State probe;
    const double slope = (trial(dh, probe).traction[0] - sigma_n - res) / h;
    const double dx = -res / slope;
    if (!std::isfinite(dx)) return false;
    double lambda = 1;
    for (int ls = 0; ls < 30; ++ls) {
      Vec3 dn = d;
      dn[0] += lambda * dx;
      State sn;
      const IncrementResult rn = trial(dn, sn);
      const double resn = rn.traction[0] - sigma_n;
      if (std::abs(resn) < std::abs(res) || ls == 29) {
        d = dn;
        r = rn;
        end = sn;
        res = resn;
        break;
      }
      lambda *= 0.5;
    }
  }
  if (!(std::abs(res) <= kTolerance)) return false;
  s = end;
  result = r;
  return true;
}

// Shear at constant normal traction sigma_n (mixed control), as in the van
// der Pluijm tests: first the normal traction is applied, then the slip.
inline Curve shear_at_constant_normal(const Model& M, double sigma_n, double slip, int increments,
                                      double direction_angle = 0.0) {
  State s;
  Curve c;
  c.samples.push_back(sample_of(M, s, IncrementResult{}));
  auto step = [&](double d1, double d2) {
    IncrementResult r;
    if (!step_at_normal_traction(M, s, sigma_n, d1, d2, r) || !r.status.ok()) c.all_ok = false;
    c.samples.push_back(Sample{s.separation, r.traction, s, r});
  };
  step(0, 0);
  const double ds = slip / increments;
  for (int i = 0; i < increments; ++i) step(ds * std::cos(direction_angle), ds * std::sin(direction_angle));
  return c;
}

}  // namespace mortar::testing
