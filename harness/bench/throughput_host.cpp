#include "bench/throughput_host.hpp"

#include <algorithm>
#include <chrono>
#include <thread>

namespace mortar::harness {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Eight multiply-add chains: each waits on its own last result.
void arithmetic_chains(long iterations) {
  double x[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  for (long i = 0; i < iterations; ++i)
    for (double& v : x) v = v * 0.999999999 + 1e-9;
  volatile double sink = x[0] + x[1] + x[2] + x[3] + x[4] + x[5] + x[6] + x[7];
  (void)sink;
}

// Sixteen independent additions per iteration: more than a core's adders
// finish in the latency of one, so the adders, not the chains, set the pace.
void independent_additions(long iterations) {
  double x[16];
  for (int k = 0; k < 16; ++k) x[k] = k;
  for (long i = 0; i < iterations; ++i)
    for (double& v : x) v += 1e-9;
  double sum = 0;
  for (const double v : x) sum += v;
  volatile double sink = sum;
  (void)sink;
}


namespace {

// One sample: the loop on 1 thread, then on 2 threads at once (each the same
// count), as throughput 2 threads against 1.
double host_scaling_sample(void (*loop)(long), long iterations) {
  const Clock::time_point t0 = Clock::now();
  loop(iterations);
  const Clock::time_point t1 = Clock::now();
  std::thread other(loop, iterations);
  loop(iterations);
  other.join();
  const Clock::time_point t2 = Clock::now();
  return 2.0 * std::chrono::duration<double>(t1 - t0).count() / std::chrono::duration<double>(t2 - t1).count();
}

}  // namespace

double host_thread_scaling(void (*loop)(long), int repeats, double seconds) {
  const Clock::time_point t0 = Clock::now();
  loop(100000);  // the calibration: iterations for `seconds`
  const double per_iteration = std::chrono::duration<double>(Clock::now() - t0).count() / 1e5;
  const long iterations = std::max(1000L, long(seconds / std::max(per_iteration, 1e-12)));
  std::vector<double> samples;
  for (int rep = 0; rep < repeats; ++rep) samples.push_back(host_scaling_sample(loop, iterations));
  return median(samples);
}


}  // namespace mortar::harness
