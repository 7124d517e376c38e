#include "bench/throughput.hpp"

#include <algorithm>
#include <alloca.h>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "bench/drive.hpp"
#include "bench/throughput_call.hpp"
#include "bench/throughput_host.hpp"
#include "input/parameter_file.hpp"
#include "mortar/state_layout.hpp"
#include "vuinteraction.h"

namespace mortar::harness {

VuinteractionRoutine<double> double_precision_routine() { return &vuinteraction_; }

const char* workload_name(Workload w) {
  switch (w) {
    case Workload::copy: return "copy";
    case Workload::elastic: return "elastic";
    case Workload::softening: return "softening";
    case Workload::sliding: return "sliding";
  }
  return "?";
}

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kBlock = 128;  // points per call, as in Abaqus/Explicit's blocks
constexpr long kThreadGap = 1024;  // points between two threads' shares (Cases::ranges)
// Law signs: the joint is pressed to sigma_n = -0.5 MPa (the penetration that
// gives it on the undamaged joint) and holds that penetration.
constexpr double kPressure = 0.5;        // MPa
constexpr double kElasticStep = 1e-7;    // mm, alternating in sign
constexpr double kPlasticStep = 1e-5;    // mm of slip per increment
constexpr double kPreStep = 1e-4;        // mm: the pre-drive to the start states
constexpr double kSofteningSlip = 0.03;  // mm: past the peak, s about 0.06 (w_II = 0.114 of G_IIC = 0.121 N/mm)
constexpr double kResidualSlip = 1.0;    // mm: s about 2e-9, tan(phi) within 0.1 % of tan(phir)

// The copy pass: what every point-update costs at least. Per point it reads
// the arrays the routine reads (penetration, drDisp, dRot, the state as far
// as the routine's layout goes, sed) and writes the ones it writes (state,
// stress, the energies, the fluxes); the state goes through a local copy the
// compiler must keep, as the routine's does.
template <class Real>
void copy_pass(Real* stress, Real* flux_slv, Real* flux_mst, Real* state, Real* sed, Real* sfd, Real* scd, Real* spd,
               Real* svd, const int* n_block, const int*, const int*, const int*, const int*, const int*,
               const int* n_dir, const int* n_states, const int*, const int*, const int*, const int*, const Real*,
               const char*, const char*, const char*, const int*, const int*, const Real*, const Real* penetration,
               const Real* dr_disp, const Real* d_rot, const Real*, const Real*, const Real*, const Real*,
               const Real*, const Real*, const Real*, const Real*, const Real*, const Real*, const Real*,
               const Real*, const Real*, const Real*, const Real*, int, int, int) {
  const int nd = *n_dir, ns = *n_states;
  const int used = std::min(ns, sizeof(Real) == 4 ? kPairedStateCount : kStateCount);
  for (int k = 0; k < *n_block; ++k) {
    Real local[kPairedStateCount];
    Real* st = state + long(k) * ns;
    std::copy(st, st + used, local);
    const Real* dd = dr_disp + long(k) * nd;
    const Real* rot = d_rot + 4L * k;
    local[slot::separation_s1] += dd[1] * rot[0];
    local[slot::separation_s2] += dd[2] * rot[3];
    asm volatile("" : : "r"(local) : "memory");
    std::copy(local, local + used, st);
    stress[long(k) * nd] = -penetration[k];
    for (int i = 1; i < nd; ++i) stress[long(k) * nd + i] = dd[i];
    sed[k] = sed[k] + penetration[k];
    spd[k] = sfd[k] = scd[k] = svd[k] = flux_slv[k] = flux_mst[k] = Real(0);
  }
}

// Where the frames of the timed loop start on the stack, in bytes below
// where they would. At some places of the main thread's stack (which ASLR
// moves from run to run in steps of 16 bytes, the arrays only in whole
// pages) what the loop keeps on the stack shares its offset within a 4 KiB
// page with the arrays it streams through, and a load waits on a store to
// the other address (4K aliasing): the copy pass took 1.5-2.5 x its time
// in every sample of such a run (docs/decisions.md). The copy pass
// is timed from four places a quarter of a page apart and the fastest is its
// sample: the limit it stands for is the fastest pass over the arrays.
constexpr int kCopyPlacements[] = {0, 1024, 2048, 3072};

// One precision's points: the arrays, the routine, and the start state of
// each workload (one point driven there, then copied to every point).
template <class Real>
class Cases {
 public:
  Cases(VuinteractionRoutine<Real> routine, const std::vector<double>& props, long points)
      : routine_(routine), props_(props), a_(int(points), n_states(), props, 2) {
    start_[0] = start_[1] = drive(0);  // copy, elastic
    start_[2] = drive(kSofteningSlip);
    start_[3] = drive(kResidualSlip);
    // The elastic increments alternate: variant 0 (restore()) presses further
    // and slips forward by 1e-7 mm, variant 1 goes back.
    for (long k = 0; k < a_.points; ++k) {
      a_.penetration[1][k] = Real(pressed());
      a_.dr_disp[1][k * 3 + 1] = a_.dr_disp[1][k * 3 + 2] = Real(-kElasticStep);
    }
  }

  // Median-ready sample: wall ns per point-update of `w` over `increments`
  // increments of the first `points` points, on `threads` threads (each its
  // own contiguous share of the blocks), from the workload's start state;
  // the copy pass's the fastest of its placements.
  double time(Workload w, long points, int threads, long increments) {
    if (w != Workload::copy) return time_once(w, points, threads, increments, 0);
    double fastest = 1e300;
    for (const int shift : kCopyPlacements) fastest = std::min(fastest, time_once(w, points, threads, increments, shift));
    return fastest;
  }

  // Points needed for `points` on up to 2 threads.
  // (A gap after the last share too: the next allocation's first bytes may
  // share its last cache line.)
  static long capacity(long points) { return points + 2 * kThreadGap; }

 private:
  double time_once(Workload w, long points, int threads, long increments, int shift) {
    const std::vector<Range> shares = ranges(points, threads);
    for (const Range& r : shares) restore(w, r);
    const bool plastic = w == Workload::softening || w == Workload::sliding;
    // By value, and copied into each thread: the loop reads its bounds again
    // after every call of the (opaque) routine, and should not read them
    // from a line of the first thread's stack. Its frames start `shift`
    // bytes further down that thread's stack (kCopyPlacements).
    auto work = [this, w, plastic, increments, shift](Range r) {
      volatile char* below = static_cast<volatile char*>(alloca(std::size_t(shift) + 1));
      below[0] = 0;
      run_share(w, plastic, increments, r);
    };
    // The clock starts when every thread is running: a thread just created
    // may wait for its CPU to be woken and scheduled, which an analysis's
    // threads, alive from increment to increment, do not (on this KVM guest,
    // samples of 1-8 ms: 2 threads against 1 gave 0.80-1.78 with the
    // creation timed, 1.17-1.94 without; docs/decisions.md).
    std::atomic<int> ready{0};
    auto all_running = [&] {
      ready.fetch_add(1);
      while (ready.load() < threads) {
      }
    };
    std::atomic<int> finished{0};
    std::vector<std::thread> pool;
    for (size_t t = 1; t < shares.size(); ++t)
      pool.emplace_back([&, t, work] {
        all_running();
        work(shares[t]);
        finished.fetch_add(1);
      });
    all_running();
    const Clock::time_point t0 = Clock::now();
    work(shares[0]);
    // The clock stops when the last share is done, seen by spinning: a join
    // that blocks lets this vCPU halt, and the host's wake-up of it was timed
    // with the work (double elastic in cache, 2 threads against 1: 1.73-1.83
    // over five runs with the join timed, 1.84-1.90 over three without;
    // docs/decisions.md).
    while (finished.load() < threads - 1) {
    }
    const double ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count();
    for (std::thread& th : pool) th.join();
    for (const Range& r : shares) check(w, r);
    return ns / (double(points) * double(increments));
  }

  static int n_states() { return sizeof(Real) == 4 ? kPairedStateCount : kStateCount; }
  double pressed() const { return kPressure / props_[0]; }

  void call(Workload w, long first, int count, int variant) {
    if (w == Workload::copy) {
      a_.call(&copy_pass<Real>, first, count, variant);
    } else {
      a_.call(routine_, first, count, variant);
    }
  }

  // Each thread's contiguous share of whole blocks, kThreadGap points apart:
  // in Abaqus each thread's blocks are its own arrays, and neighbouring
  // shares would write the same cache lines at their boundary (measured: 2
  // threads slower than 1 on the copy pass of 2 x 128 points). A gap of 64
  // points was not enough: 256 bytes of a float array, which a core's
  // prefetcher streaming through its share reads past, so that the lines
  // the other core writes moved between them (single precision in cache,
  // 2 threads against 1: 1.71-1.75 on the elastic update with 64, 1.94-1.98
  // with 1024; docs/decisions.md).
  struct Range {
    long first, last;
  };
  static std::vector<Range> ranges(long points, int threads) {
    const long blocks = (points + kBlock - 1) / kBlock;
    std::vector<Range> r;
    for (int t = 0; t < threads; ++t) {
      const long first = blocks * t / threads * kBlock, last = std::min(points, blocks * (t + 1) / threads * kBlock);
      r.push_back({first + t * kThreadGap, last + t * kThreadGap});
    }
    return r;
  }

  // The timed loop over one thread's share, out of line so that its frame
  // lies below the caller's alloca (time_once).
  __attribute__((noinline)) void run_share(Workload w, bool plastic, long increments, Range r) {
    for (long i = 0; i < increments; ++i) {
      const int variant = plastic ? 0 : int(i % 2);
      for (long b = r.first; b < r.last; b += kBlock) call(w, b, int(std::min<long>(kBlock, r.last - b)), variant);
    }
  }

  struct Start {
    std::vector<Real> state, stress;
    Real sed = 0;
  };

  // One point from the reference state: pressed, then slipped to `slip` in
  // steps of kPreStep.
  Start drive(double slip) {
    PointArrays<Real> one(1, n_states(), props_, 1);
    one.call(routine_, 0, 1, 0);  // the reference call
    one.penetration[0][0] = Real(pressed());
    one.call(routine_, 0, 1, 0);
    const long steps = std::lround(slip / kPreStep);
    one.dr_disp[0][1] = Real(kPreStep);
    for (long i = 0; i < steps; ++i) one.call(routine_, 0, 1, 0);
    if (one.state[slot::status] != Real(0)) throw std::runtime_error("bench --throughput: the pre-drive failed");
    return {one.state, one.stress, one.sed[0]};
  }

  // Every point back at the workload's start, and variant 0 the workload's
  // inputs: the elastic forward step, or 1e-5 mm of slip at the pressed
  // penetration (every increment of the plastic workloads).
  void restore(Workload w, Range r) {
    const Start& s = start_[int(w)];
    const bool plastic = w == Workload::softening || w == Workload::sliding;
    for (long k = r.first; k < r.last; ++k) {
      std::copy(s.state.begin(), s.state.end(), &a_.state[k * n_states()]);
      std::copy(s.stress.begin(), s.stress.end(), &a_.stress[k * 3]);
      a_.sed[k] = s.sed;
      a_.penetration[0][k] = Real(pressed() + (plastic ? 0.0 : kElasticStep));
      a_.dr_disp[0][k * 3 + 1] = Real(plastic ? kPlasticStep : kElasticStep);
      a_.dr_disp[0][k * 3 + 2] = Real(plastic ? 0.0 : kElasticStep);
    }
  }

  // Every point integrated, and in the regime its workload names.
  void check(Workload w, Range r) const {
    if (w == Workload::copy) return;
    for (long k = r.first; k < r.last; ++k) {
      const bool dissipated = a_.spd[k] != Real(0);
      const bool plastic = w != Workload::elastic;
      if (a_.state[k * n_states() + slot::status] != Real(0) || dissipated != plastic)
        throw std::runtime_error(std::string("bench --throughput: point ") + std::to_string(k + 1) + " of the " +
                                 workload_name(w) + " workload left its regime or failed");
    }
  }

  VuinteractionRoutine<Real> routine_;
  std::vector<double> props_;
  PointArrays<Real> a_;
  Start start_[4];
};

// One precision and cache case: its rows (1 and 2 threads), the increments
// that make each of its samples last about `seconds`, and its timer.
struct CaseRows {
  ThroughputRow rows[2];
  long increments[2][4] = {};
  std::function<double(Workload, long points, int threads, long increments)> time;
};

// One precision's in- or out-of-cache case, on `cases`, warmed up and sized.
template <class Real>
void add_case(Cases<Real>& cases, bool in_cache, long out_points, double seconds, std::vector<CaseRows>& out) {
  CaseRows c;
  c.time = [&cases](Workload w, long points, int threads, long increments) {
    return cases.time(w, points, threads, increments);
  };
  for (int t = 0; t < 2; ++t) {
    ThroughputRow& row = c.rows[t];
    row.single = sizeof(Real) == 4;
    row.in_cache = in_cache;
    row.threads = t + 1;
    row.points = in_cache ? long(kBlock) * row.threads : out_points;
    for (const Workload w : kWorkloads) {  // warm-up, and the number of increments
      const double ns = cases.time(w, row.points, row.threads, 2);
      c.increments[t][int(w)] = std::max(2L, long(seconds * 1e9 / (ns * double(row.points))) & ~1L);
    }
  }
  out.push_back(std::move(c));
}

// Every case, repeat by repeat. Within a repeat each case times every
// workload on 1 and on 2 threads back to back, so that a slow moment of a
// shared machine falls on all the samples of that case alike and the ratios
// (paired_ratio) compare samples of one moment; and each repeat goes through
// all four cases, so that a slow spell of a second or two falls on a few
// repeats of every case rather than on all the repeats of one (their median
// then leaves it out). Each sample lasts about `seconds`.
void run_cases(std::vector<CaseRows>& cases, const ThroughputOptions& o, ThroughputResult& r, std::ostream& err) {
  for (int rep = 0; rep < r.repeats; ++rep) {
    for (CaseRows& c : cases)
      for (const Workload w : kWorkloads)
        for (ThroughputRow& row : c.rows)
          row.samples[int(w)].push_back(c.time(w, row.points, row.threads, c.increments[row.threads - 1][int(w)]));
    if (!o.quiet) err << "bench --throughput: repeat " << rep + 1 << " of " << r.repeats << " done\n";
  }
  for (CaseRows& c : cases)
    for (ThroughputRow& row : c.rows) {
      for (const Workload w : kWorkloads) row.ns[int(w)] = median(row.samples[int(w)]);
      r.rows.push_back(row);
    }
}

}  // namespace

ThroughputResult run_throughput(const ThroughputOptions& o, std::ostream& err) {
  const Parameters p = read_parameter_file(o.data_dir + "/almeida_tension/params_M15.toml").values;
  const std::vector<double> props = bench_props(p, SchemeControls{});
  ThroughputResult r;
  r.block = kBlock;
  r.repeats = o.quick ? 1 : std::max(1, o.repeats);
  // Out of cache: about 40 MB of the arrays the routine touches (double),
  // ten times the 4 MB second-level cache of the machine in README "Speed".
  r.points_out_of_cache = o.quick ? 4L * kBlock : 1024L * kBlock;
  const double seconds = o.quick ? 2e-4 : 0.04;
  // Each case its own arrays, sized to it: the points in cache in arrays of
  // their own size, not at the start of the out-of-cache case's arrays, which
  // the allocator maps page-aligned, every array's first point at the same
  // offset in a page, so that the first points of the twenty arrays fall in
  // one set of the first-level cache, which slowed the in-cache case and
  // its two-thread scaling.
  const long in_capacity = Cases<double>::capacity(2 * kBlock);
  const long out_capacity = Cases<double>::capacity(r.points_out_of_cache);
  Cases<double> doubles_in(double_precision_routine(), props, in_capacity);
  Cases<double> doubles_out(double_precision_routine(), props, out_capacity);
  Cases<float> singles_in(single_precision_routine(), props, in_capacity);
  Cases<float> singles_out(single_precision_routine(), props, out_capacity);
  std::vector<CaseRows> cases;
  add_case(doubles_in, true, r.points_out_of_cache, seconds, cases);
  add_case(doubles_out, false, r.points_out_of_cache, seconds, cases);
  add_case(singles_in, true, r.points_out_of_cache, seconds, cases);
  add_case(singles_out, false, r.points_out_of_cache, seconds, cases);
  run_cases(cases, o, r, err);
  r.host_chain_scaling = host_thread_scaling(&arithmetic_chains, r.repeats, seconds);
  r.host_port_scaling = host_thread_scaling(&independent_additions, r.repeats, seconds);
  run_cap_throughput(p, o, seconds, r, err);
  return r;
}

}  // namespace mortar::harness
