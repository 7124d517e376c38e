// `masonry-joint bench --throughput`: the cost of one point-update of
// vuinteraction_ against the cost of touching its arrays.
//
// In Abaqus/Explicit the routine runs for every contact point at every
// increment, most points elastic most of the time, so its cost per
// point-update is the cost of the analysis. What can be asked of it is a
// ratio: an elastic update close to a pass that only reads and writes the
// arrays the routine touches (the memory limit), plastic updates within a
// small factor of the elastic one, and blocks on two threads twice as fast.
// Absolute times belong to a machine; the ratios measured within one run are
// the targets (README, "Speed").
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "mortar/parameters.hpp"

namespace mortar::harness {

struct ThroughputOptions {
  std::string data_dir;  // calibration_data/ (the M15 parameter set)
  bool quick = false;    // tiny sizes: checks that it runs, measures nothing
  int repeats = 11;      // timed repeats per case; medians are reported
  bool quiet = false;    // no progress on stderr
  bool wide = false;     // the table not fitted to 100 columns
};

// What each case times, per point and increment.
enum class Workload { copy, elastic, softening, sliding };
inline constexpr Workload kWorkloads[] = {Workload::copy, Workload::elastic, Workload::softening, Workload::sliding};
const char* workload_name(Workload w);

// One configuration: a precision, the points in or out of cache, 1 or 2
// threads; the median ns per point-update of each workload (wall time over
// points x increments, so that 2 threads show their throughput), and each
// repeat's sample, from which the ratios are taken pair by pair (below).
struct ThroughputRow {
  bool single = false;
  bool in_cache = true;
  int threads = 1;
  long points = 0;
  double ns[4] = {};               // by Workload
  std::vector<double> samples[4];  // by Workload, one per repeat, in the order timed
};

// The ratio of two sample series timed in the same repeats: the median over
// the repeats of a[r] / b[r]. A repeat times every workload of one precision
// and cache case on 1 and on 2 threads back to back (about 0.3 s), so each
// ratio compares samples of one moment of a shared host; the ratio of two
// medians can compare samples taken seconds apart, and the host's speed
// drifts by tens of percent within a run.
double paired_ratio(const std::vector<double>& a, const std::vector<double>& b);

// The compression cap's rows (bench/throughput_cap.cpp): sliding by 1e-5 mm
// per increment at a pressure of 0.3 fc, on the residual hyperbola without
// the cap and with it (inside the cap), and crushing along the cap.
enum class CapWorkload { sliding_no_cap, sliding_inside_cap, crushing };
inline constexpr int kCapWorkloadCount = 3;
inline constexpr int kCapBlockPoints = 256;  // two blocks
inline constexpr CapWorkload kCapWorkloads[] = {CapWorkload::sliding_no_cap, CapWorkload::sliding_inside_cap,
                                                CapWorkload::crushing};
const char* cap_workload_name(CapWorkload w);

// One precision, one thread, in cache: median ns per point-update and each
// repeat's sample, by CapWorkload.
struct CapRow {
  bool single = false;
  double ns[kCapWorkloadCount] = {};
  std::vector<double> samples[kCapWorkloadCount];
};

struct ThroughputResult {
  int block = 0, repeats = 0;
  long points_out_of_cache = 0;
  std::vector<ThroughputRow> rows;
  // What 2 threads give on this host for work that shares no memory: two
  // loops whose values stay in registers, each timed on 1 thread and on 2 at
  // once (median of the repeats). The 2-thread target is read against them.
  //   chains: eight multiply-add chains, each waiting on its own last result;
  //   ports: sixteen independent additions per iteration, more than a core's
  //     adders finish in the latency of one. On two cores both loops scale by
  //     2; where the two vCPUs are hyperthreads of one core, the second thread
  //     finds the adders taken and the port-bound loop scales by little more
  //     than 1.
  double host_chain_scaling = 0;  // chains
  double host_port_scaling = 0;   // ports
  CompressionCap cap;              // the cap's rows: its parameters,
  double cap_pressure = 0;         // the pressure [MPa],
  std::vector<CapRow> cap_rows;    // double, then single
};

// Runs the cap's rows onto r (r.repeats samples of about `seconds` each).
void run_cap_throughput(const Parameters& p, const ThroughputOptions& o, double seconds, ThroughputResult& r,
                        std::ostream& err);

// Runs every case; std::runtime_error when a routine call fails or a
// workload leaves its regime (an elastic update that dissipates, a plastic
// one that does not).
ThroughputResult run_throughput(const ThroughputOptions& options, std::ostream& err);

// The table of ns per point-update, the ratios and the targets (markdown).
std::string throughput_report(const ThroughputResult& r);

}  // namespace mortar::harness
