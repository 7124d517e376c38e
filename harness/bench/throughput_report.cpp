// The throughput bench's table (throughput_report): ns per point-update,
// the ratios within a repeat (paired_ratio), the targets and the host's own
// 2-thread scaling.
#include <algorithm>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "bench/throughput.hpp"
#include "bench/throughput_host.hpp"

namespace mortar::harness {

namespace {

std::string fixed(double x, int digits) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(digits) << x;
  return o.str();
}

}  // namespace

double paired_ratio(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size() || a.empty())
    throw std::invalid_argument("paired_ratio: the two series must have the same, non-zero number of samples");
  std::vector<double> r(a.size());
  for (size_t i = 0; i < a.size(); ++i) r[i] = a[i] / b[i];
  return median(r);
}

std::string throughput_report(const ThroughputResult& r) {
  auto ns = [](const ThroughputRow& row, Workload w) { return row.ns[int(w)]; };
  // Within one row: workload a against workload b, repeat by repeat.
  auto ratio = [](const ThroughputRow& row, Workload a, Workload b) {
    return paired_ratio(row.samples[int(a)], row.samples[int(b)]);
  };
  std::ostringstream o;
  o << "ns per point-update (median of " << r.repeats << "), blocks of " << r.block
    << " points, nDir = 3, Almeida M15 at sigma_n = -0.5 MPa: elastic +-1e-7 mm, softening and sliding "
       "(residual surface) at 1e-5 mm of slip per increment; each ratio is the median over the repeats of "
       "the ratio within a repeat\n\n"
    << "| precision | points | threads | copy | elastic | softening | sliding | elastic / copy | softening / "
       "elastic | sliding / elastic |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const ThroughputRow& row : r.rows) {
    o << "| " << (row.single ? "single" : "double") << " | " << row.points << (row.in_cache ? " (in cache)" : "")
      << " | " << row.threads << " | " << fixed(ns(row, Workload::copy), 1) << " | "
      << fixed(ns(row, Workload::elastic), 1) << " | " << fixed(ns(row, Workload::softening), 1) << " | "
      << fixed(ns(row, Workload::sliding), 1) << " | "
      << fixed(ratio(row, Workload::elastic, Workload::copy), 2) << " | "
      << fixed(ratio(row, Workload::softening, Workload::elastic), 2) << " | "
      << fixed(ratio(row, Workload::sliding, Workload::elastic), 2) << " |\n";
  }
  o << "\n2 threads against 1 (throughput):\n\n| precision | points | copy | elastic | softening | sliding |\n"
       "|---|---|---|---|---|---|\n";
  double worst_copy = 0, worst_sliding = 0, worst_threads = 1e300;
  for (size_t i = 0; i + 1 < r.rows.size(); i += 2) {
    const ThroughputRow &one = r.rows[i], &two = r.rows[i + 1];
    auto scaling = [&](Workload w) { return paired_ratio(one.samples[int(w)], two.samples[int(w)]); };
    o << "| " << (one.single ? "single" : "double") << " | " << (one.in_cache ? "in cache" : "out of cache");
    for (const Workload w : kWorkloads) o << " | " << fixed(scaling(w), 2);
    o << " |\n";
    for (const ThroughputRow* row : {&one, &two}) {
      worst_copy = std::max(worst_copy, ratio(*row, Workload::elastic, Workload::copy));
      worst_sliding = std::max(worst_sliding, ratio(*row, Workload::sliding, Workload::elastic));
    }
    for (const Workload w : {Workload::elastic, Workload::softening, Workload::sliding})
      worst_threads = std::min(worst_threads, scaling(w));
  }
  auto verdict = [](bool met) { return met ? "met" : "NOT met"; };
  o << "\ntargets, worst case over the rows:\n"
    << "- elastic / copy <= 2: " << fixed(worst_copy, 2) << ", " << verdict(worst_copy <= 2) << "\n"
    << "- sliding / elastic <= 10: " << fixed(worst_sliding, 2) << ", " << verdict(worst_sliding <= 10) << "\n"
    << "- 2 threads >= 1.8 x 1 thread (law workloads): " << fixed(worst_threads, 2) << ", "
    << verdict(worst_threads >= 1.8) << "; this host's own 2-thread scaling (arithmetic sharing nothing, "
    << "median of " << r.repeats << "): " << fixed(r.host_chain_scaling, 2) << " for dependent multiply-add chains, "
    << fixed(r.host_port_scaling, 2) << " for independent additions (port-bound)\n";
  if (r.cap_rows.empty()) return o.str();
  // The cap's rows: each capped workload against the uncapped sliding, paired.
  auto cap_ratio = [](const CapRow& row, CapWorkload a) {
    return paired_ratio(row.samples[int(a)], row.samples[int(CapWorkload::sliding_no_cap)]);
  };
  o << "\nthe compression cap (fc = " << fixed(r.cap.fc, 1) << " MPa, Cs = " << fixed(r.cap.Cs, 0)
    << "): sliding at 1e-5 mm per increment, pressed to " << fixed(r.cap_pressure, 1)
    << " MPa, 1 thread, " << kCapBlockPoints << " points in cache\n\n| precision";
  for (const CapWorkload w : kCapWorkloads) o << " | " << cap_workload_name(w);
  o << " | inside the cap / no cap | crushing / no cap |\n|---|---|---|---|---|---|\n";
  for (const CapRow& row : r.cap_rows) {
    o << "| " << (row.single ? "single" : "double");
    for (const CapWorkload w : kCapWorkloads) o << " | " << fixed(row.ns[int(w)], 1);
    o << " | " << fixed(cap_ratio(row, CapWorkload::sliding_inside_cap), 2) << " | "
      << fixed(cap_ratio(row, CapWorkload::crushing), 2) << " |\n";
  }
  return o.str();
}

}  // namespace mortar::harness
