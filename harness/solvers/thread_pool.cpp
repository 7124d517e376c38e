#include "solvers/thread_pool.hpp"

#include <chrono>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace mortar::harness {

namespace {

// How long an idle worker spins before it sleeps.
constexpr auto kSpin = std::chrono::microseconds(50);

std::uint32_t generation_of(std::uint64_t claim) { return static_cast<std::uint32_t>(claim >> 32); }
std::uint32_t unclaimed_of(std::uint64_t claim) { return static_cast<std::uint32_t>(claim); }

// One turn of a wait loop: a pause, and now and then the core to another
// thread (the one being waited for may be waiting for it).
void relax(unsigned turn) {
#if defined(__x86_64__) || defined(__i386__)
  if (turn % 256 != 255) {
    _mm_pause();
    return;
  }
#else
  (void)turn;
#endif
  std::this_thread::yield();
}

}  // namespace

ThreadPool::ThreadPool(int threads)
    : threads_(threads < 1 ? 1 : threads), queues_(static_cast<size_t>(kMaxPhases) * threads_) {
  for (int t = 1; t < threads_; ++t) workers_.emplace_back(&ThreadPool::worker, this, t);
}

ThreadPool::~ThreadPool() {
  if (workers_.empty()) return;
  stop_.store(true, std::memory_order_seq_cst);
  generation_.fetch_add(1, std::memory_order_seq_cst);
  { std::lock_guard<std::mutex> lock(sleep_mutex_); }
  wake_.notify_all();
  for (std::thread& w : workers_) w.join();
}

// A worker starts from generation 0, the pool's before its first job: a job
// or the stop published before the worker first runs is not missed.
void ThreadPool::worker(int thread) {
  std::uint32_t seen = 0;
  for (;;) {
    const auto start = std::chrono::steady_clock::now();
    std::uint32_t generation;
    for (unsigned turn = 1; (generation = generation_.load(std::memory_order_acquire)) == seen; ++turn) {
      relax(turn);
      if (turn % 64 != 0 || std::chrono::steady_clock::now() - start < kSpin) continue;
      sleepers_.fetch_add(1, std::memory_order_seq_cst);
      {
        std::unique_lock<std::mutex> lock(sleep_mutex_);
        wake_.wait(lock, [&] { return generation_.load(std::memory_order_seq_cst) != seen; });
      }
      sleepers_.fetch_sub(1, std::memory_order_relaxed);
    }
    if (stop_.load(std::memory_order_seq_cst)) return;
    seen = generation;
    take_part(thread, generation);
  }
}

int ThreadPool::claim(int phase, int owner, std::uint32_t generation) {
  std::atomic<std::uint64_t>& word = queues_[static_cast<size_t>(phase) * threads_ + owner].claim;
  std::uint64_t c = word.load(std::memory_order_acquire);
  do {
    if (generation_of(c) != generation || unclaimed_of(c) == 0) return -1;
  } while (!word.compare_exchange_weak(c, c - 1, std::memory_order_acq_rel, std::memory_order_acquire));
  // A claim made: the job stays the caller's current one until this item is done.
  const std::vector<int>& list = (*job_)[phase][owner];
  return list[list.size() - unclaimed_of(c)];
}

void ThreadPool::run_item(int phase, int item) {
  if (!failed_.load(std::memory_order_acquire)) {
    try {
      (*work_)(phase, item);
    } catch (...) {
      const int order = (phase > 0 ? phase_end_[phase - 1].load(std::memory_order_relaxed) : 0) + item;
      std::lock_guard<std::mutex> lock(error_mutex_);
      if (!error_ || order < error_item_) error_ = std::current_exception(), error_item_ = order;
      failed_.store(true, std::memory_order_release);
    }
  }
  done_.fetch_add(1, std::memory_order_acq_rel);
}

void ThreadPool::take_part(int thread, std::uint32_t generation) {
  bool counted = false;
  const int phases = phases_.load(std::memory_order_acquire);
  for (int phase = 0; phase < phases; ++phase) {
    if (phase > 0) {
      const int end = phase_end_[phase - 1].load(std::memory_order_acquire);
      for (unsigned turn = 0; done_.load(std::memory_order_acquire) < end; ++turn) {
        if (generation_.load(std::memory_order_acquire) != generation) return;
        relax(turn);
      }
    }
    // Its own items first, then the others'.
    for (int k = 0; k < threads_; ++k) {
      const int owner = (thread + k) % threads_;
      for (int item; (item = claim(phase, owner, generation)) >= 0;) {
        if (!counted) participants_.fetch_add(1, std::memory_order_relaxed), counted = true;
        run_item(phase, item);
      }
    }
  }
}

void ThreadPool::run(const Job& items, const std::function<void(int, int)>& work) {
  const int phases = static_cast<int>(items.size() < kMaxPhases ? items.size() : kMaxPhases);
  int total = 0;
  for (int p = 0; p < phases; ++p) {
    for (int t = 0; t < threads_; ++t) total += t < static_cast<int>(items[p].size()) ? items[p][t].size() : 0;
    phase_end_[p].store(total, std::memory_order_relaxed);
  }
  if (total == 0) return;
  job_ = &items, work_ = &work;
  error_ = nullptr;
  failed_.store(false, std::memory_order_relaxed);
  done_.store(0, std::memory_order_relaxed);
  participants_.store(0, std::memory_order_relaxed);
  phases_.store(phases, std::memory_order_relaxed);
  const std::uint32_t generation = generation_.load(std::memory_order_relaxed) + 1;
  for (int p = 0; p < phases; ++p)
    for (int t = 0; t < threads_; ++t) {
      const std::uint64_t n = t < static_cast<int>(items[p].size()) ? items[p][t].size() : 0;
      queues_[static_cast<size_t>(p) * threads_ + t].claim.store(static_cast<std::uint64_t>(generation) << 32 | n,
                                                                  std::memory_order_relaxed);
    }
  generation_.store(generation, std::memory_order_seq_cst);
  if (sleepers_.load(std::memory_order_seq_cst) > 0) {
    { std::lock_guard<std::mutex> lock(sleep_mutex_); }
    wake_.notify_all();
  }
  take_part(0, generation);
  for (unsigned turn = 0; done_.load(std::memory_order_acquire) < total; ++turn) relax(turn);
  if (error_) std::rethrow_exception(error_);
}

void ThreadPool::run_dealt(const std::vector<int>& items, const std::function<void(int, int)>& work) {
  dealt_.assign(items.size(), std::vector<std::vector<int>>(threads_));
  for (size_t p = 0; p < items.size(); ++p)
    for (int i = 0; i < items[p]; ++i) dealt_[p][i % threads_].push_back(i);
  run(dealt_, work);
}

}  // namespace mortar::harness
