// A pool of threads for a whole run: the workers are started once, woken
// for each job, and joined when the pool is destroyed.
//
// A job is a list of phases, each a number of items; the caller and the
// workers claim items one at a time from a shared counter, and the items of
// a phase start only once every item of the phase before is done. The
// caller never waits for a worker that has not claimed an item: on a
// machine whose other cores are busy it does the whole job alone instead of
// waiting for a worker to be scheduled. Idle workers spin a short while
// (longer than the serial work between two jobs of a run), then sleep.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace mortar::harness {

class ThreadPool {
 public:
  // `threads` >= 1 threads in all: the caller and threads - 1 workers.
  explicit ThreadPool(int threads);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int size() const { return threads_; }

  // Runs work(phase, item) for every item of every phase (items[phase] of
  // them) and returns when all are done. An exception from an item skips
  // the items not yet started and is rethrown here (the lowest item's,
  // when several threw).
  void run(const std::vector<int>& items, const std::function<void(int phase, int item)>& work);

  // Threads that ran at least one item of the last job (1 to size()).
  int participants() const { return participants_.load(std::memory_order_relaxed); }

 private:
  void worker();
  // Claims and runs items of job `generation` until none is left.
  void take_part(std::uint32_t generation);

  int threads_;
  std::vector<std::thread> workers_;
  // The job, written by the caller before it publishes the job's generation.
  std::vector<int> phase_end_;  // items before the end of each phase
  const std::function<void(int, int)>* work_ = nullptr;
  int total_ = 0;
  std::exception_ptr error_;
  int error_item_ = 0;
  std::mutex error_mutex_;
  // generation << 32 | items of the job not yet claimed
  std::atomic<std::uint64_t> claim_{0};
  std::atomic<int> done_{0}, participants_{0};
  std::atomic<bool> failed_{false}, stop_{false};
  std::uint32_t generation_ = 0;  // the caller's
  std::atomic<int> sleepers_{0};
  std::mutex sleep_mutex_;
  std::condition_variable wake_;
};

}  // namespace mortar::harness
