// A pool of threads for a whole run: the workers are started once, woken
// for each job, and joined when the pool is destroyed.
//
// A job is a few phases of items; the items of a phase start only once
// every item of the phase before is done. Each thread first runs the items
// the job gives it (the same ones job after job, so their data stay in its
// core's caches), then takes what is left of the other threads' items. The
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

  // items[phase][thread]: the items that thread runs first. Runs
  // work(phase, item) for every item of every phase (at most kMaxPhases)
  // and returns when all are done. An exception from an item skips the
  // items not yet started and is rethrown here (the lowest item's, when
  // several threw).
  using Job = std::vector<std::vector<std::vector<int>>>;
  static constexpr int kMaxPhases = 4;
  void run(const Job& items, const std::function<void(int phase, int item)>& work);
  // items[phase] items per phase, dealt to the threads in turn.
  void run_dealt(const std::vector<int>& items, const std::function<void(int phase, int item)>& work);

  // Threads that ran at least one item of the last job (1 to size()).
  int participants() const { return participants_.load(std::memory_order_relaxed); }

 private:
  struct alignas(64) Queue {
    std::atomic<std::uint64_t> claim{0};  // generation << 32 | items not yet claimed
  };
  void worker(int thread);
  // Runs the phases of job `generation` as thread `thread`.
  void take_part(int thread, std::uint32_t generation);
  // Claims the next item of queue (phase, owner); -1 when none is left.
  int claim(int phase, int owner, std::uint32_t generation);
  void run_item(int phase, int item);

  int threads_;
  std::vector<std::thread> workers_;
  std::vector<Queue> queues_;  // kMaxPhases x threads
  // The job, written by the caller before it publishes the job's generation.
  const Job* job_ = nullptr;
  const std::function<void(int, int)>* work_ = nullptr;
  std::atomic<int> phases_{0};
  std::atomic<int> phase_end_[kMaxPhases] = {};  // items before the end of each phase
  std::exception_ptr error_;
  int error_item_ = 0;
  std::mutex error_mutex_;
  std::atomic<std::uint32_t> generation_{0};
  std::atomic<int> done_{0}, participants_{0};
  std::atomic<bool> failed_{false}, stop_{false};
  std::atomic<int> sleepers_{0};
  std::mutex sleep_mutex_;
  std::condition_variable wake_;
  Job dealt_;  // run_dealt's job
};

}  // namespace mortar::harness
