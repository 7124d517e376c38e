// `masonry-joint bench`: the work-precision study and stability map
// (bench/bench.hpp), its files and charts.
#pragma once

#include <iosfwd>

#include "bench/bench.hpp"
#include "bench/throughput.hpp"

namespace mortar::harness {

// `masonry-joint bench`: runs the study, writes the files, prints the
// summary. Returns the exit status: 0, or 1 when a reference moved by
// kReferenceRequired or more when tightened, or a chart could not be drawn.
int run_bench_command(const BenchOptions& options, std::ostream& out, std::ostream& err);

// `masonry-joint bench --throughput`: prints the table of ns per
// point-update and the ratios (bench/throughput.hpp). Returns 0, or 1 when a
// call failed or a workload left its regime; the ratios never fail it
// (timings are the machine's, not the routine's).
int run_throughput_command(const ThroughputOptions& options, std::ostream& out, std::ostream& err);

}  // namespace mortar::harness
