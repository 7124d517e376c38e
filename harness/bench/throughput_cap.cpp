// `bench --throughput`, the compression cap's rows (throughput.hpp,
// CapWorkload): what a sliding update costs with the cap on against the same
// parameter set without it, at a pressure where the capped point crushes.
//
// The Almeida M15 set, and with it the cap of the splitting tests' crush
// family (tests/support/splitting_paths.hpp, crush_cap): Cs = 9,
// fc = 4 sqrt(ft0^2 + Cs c0^2) = 32.8 MPa (the rule: fc/3 above that root), Gfc twice its
// snap-back bound, kappa_p = fc/kn. Every point is pressed to 0.3 fc
// (9.8 MPa on the undamaged joint) and slides by 1e-5 mm per increment:
// - no cap: on the residual hyperbola, after 1 mm of slip;
// - cap, inside it: the same drive with the cap on; the point crushed on the
//   way (kappa_c 0.014 mm), then left the cap for the hyperbola, and slides
//   inside the cap (what the cap costs a point it does not hold);
// - cap, crushing: the capped point after 0.01 mm of slip, on the cap (first
//   reached at 0.0055 mm) and sliding along it, kappa_c growing every update
//   (the corner with the hyperbola comes at about 0.06 mm).
// One thread, the points in cache (two blocks); the three are timed back to
// back in every repeat, so that their ratios pair samples of one moment.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ostream>
#include <stdexcept>
#include <string>

#include "bench/drive.hpp"
#include "bench/paths.hpp"
#include "bench/throughput.hpp"
#include "bench/throughput_call.hpp"
#include "bench/throughput_host.hpp"
#include "mortar/state_layout.hpp"

namespace mortar::harness {

const char* cap_workload_name(CapWorkload w) {
  switch (w) {
    case CapWorkload::sliding_no_cap: return "sliding, no cap";
    case CapWorkload::sliding_inside_cap: return "sliding, inside the cap";
    case CapWorkload::crushing: return "sliding, crushing on the cap";
  }
  return "?";
}

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kBlock = 128;
constexpr long kPoints = kCapBlockPoints;
constexpr double kPressureOfFc = 0.3;  // the pressure, a share of fc
constexpr double kStep = 1e-5;         // mm of slip per timed increment
constexpr double kPreStep = 1e-4;      // mm: the pre-drive
constexpr double kResidualSlip = 1.0;  // mm: on the residual hyperbola
constexpr double kCrushSlip = 0.01;    // mm: on the cap, short of the corner


// One precision's three workloads, each its own arrays (their props differ).
template <class Real>
class CapCases {
 public:
  static constexpr int kStates = sizeof(Real) == 4 ? kCappedStateCountSingle : kCappedStateCountDouble;

  CapCases(VuinteractionRoutine<Real> routine, const Parameters& p, const CompressionCap& cap)
      : routine_(routine), pressed_(kPressureOfFc * cap.fc / p.kn) {
    const std::vector<double> without = bench_props(p, SchemeControls{}), with = bench_props(p, SchemeControls{}, cap);
    cases_.push_back(make(without, kResidualSlip));
    cases_.push_back(make(with, kResidualSlip));
    cases_.push_back(make(with, kCrushSlip));
  }

  // ns per point-update of `increments` increments over every point, from
  // the workload's start state; throws if a point leaves its regime.
  double time(CapWorkload w, long increments) {
    Case& c = cases_[size_t(w)];
    for (long k = 0; k < kPoints; ++k) {
      std::copy(c.start.begin(), c.start.end(), &c.a.state[k * kStates]);
      std::copy(c.stress.begin(), c.stress.end(), &c.a.stress[k * 3]);
      c.a.sed[k] = c.sed;
    }
    const Clock::time_point t0 = Clock::now();
    for (long i = 0; i < increments; ++i)
      for (long b = 0; b < kPoints; b += kBlock) c.a.call(routine_, b, kBlock, 0);
    const double ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count();
    check(w, c);
    return ns / (double(kPoints) * double(increments));
  }

 private:
  struct Case {
    PointArrays<Real> a;
    std::vector<Real> start, stress;
    Real sed = 0;
  };

  // One point pressed and slid to `slip`, copied as every point's start;
  // then every increment 1e-5 mm of slip at that penetration.
  Case make(const std::vector<double>& props, double slip) {
    PointArrays<Real> one(1, kStates, props, 1);
    one.call(routine_, 0, 1, 0);  // the reference call
    one.penetration[0][0] = Real(pressed_);
    one.call(routine_, 0, 1, 0);
    one.dr_disp[0][1] = Real(kPreStep);
    for (long i = 0, n = std::lround(slip / kPreStep); i < n; ++i) one.call(routine_, 0, 1, 0);
    if (one.state[slot::status] != Real(0)) throw std::runtime_error("bench --throughput: the cap's pre-drive failed");
    Case c{PointArrays<Real>(int(kPoints), kStates, props, 1), one.state, one.stress, one.sed[0]};
    for (long k = 0; k < kPoints; ++k) {
      c.a.penetration[0][k] = Real(pressed_);
      c.a.dr_disp[0][k * 3 + 1] = Real(kStep);
    }
    return c;
  }

  // Every point integrated and plastic; kappa_c grew when crushing, else
  // kept its start value.
  void check(CapWorkload w, const Case& c) const {
    const Real kappa0 = c.start[cap_slot::kappa_c];
    for (long k = 0; k < kPoints; ++k) {
      const Real* s = &c.a.state[k * kStates];
      const bool crushed = s[cap_slot::kappa_c] > kappa0;
      if (s[slot::status] != Real(0) || c.a.spd[k] == Real(0) || crushed != (w == CapWorkload::crushing))
        throw std::runtime_error(std::string("bench --throughput: point ") + std::to_string(k + 1) + " of '" +
                                 cap_workload_name(w) + "' left its regime or failed");
    }
  }

  VuinteractionRoutine<Real> routine_;
  double pressed_;
  std::vector<Case> cases_;
};

template <class Real>
CapRow run_cap_rows(CapCases<Real>& cases, double seconds, int repeats) {
  CapRow row;
  row.single = sizeof(Real) == 4;
  long increments[kCapWorkloadCount];
  for (const CapWorkload w : kCapWorkloads) {  // warm-up, and the number of increments
    const double ns = cases.time(w, 2);
    increments[int(w)] = std::max(2L, long(seconds * 1e9 / (ns * double(kPoints))));
  }
  for (int rep = 0; rep < repeats; ++rep)
    for (const CapWorkload w : kCapWorkloads) row.samples[int(w)].push_back(cases.time(w, increments[int(w)]));
  for (const CapWorkload w : kCapWorkloads) row.ns[int(w)] = median(row.samples[int(w)]);
  return row;
}

}  // namespace

void run_cap_throughput(const Parameters& p, const ThroughputOptions& o, double seconds, ThroughputResult& r,
                        std::ostream& err) {
  const CompressionCap cap = crush_cap(p);
  r.cap = cap;
  r.cap_pressure = kPressureOfFc * cap.fc;
  CapCases<double> doubles(double_precision_routine(), p, cap);
  CapCases<float> singles(single_precision_routine(), p, cap);
  r.cap_rows.push_back(run_cap_rows(doubles, seconds, r.repeats));
  r.cap_rows.push_back(run_cap_rows(singles, seconds, r.repeats));
  if (!o.quiet) err << "bench --throughput: the cap's rows done\n";
}

}  // namespace mortar::harness
