// The throughput bench's sample statistics and the host's own references
// for the thread rows (ThroughputResult::host_chain_scaling, _port_scaling).
#pragma once

#include <vector>

namespace mortar::harness {

double median(std::vector<double> v);

// Loops on values that stay in registers, whose result goes to a volatile so
// that they are not removed: eight multiply-add chains, each waiting on its
// own last result; sixteen independent additions per iteration, where the
// adders, not the chains, set the pace.
void arithmetic_chains(long iterations);
void independent_additions(long iterations);

// 2 threads against 1 (throughput) of `loop`, the median of `repeats`
// samples of about `seconds` each.
double host_thread_scaling(void (*loop)(long), int repeats, double seconds);

}  // namespace mortar::harness
