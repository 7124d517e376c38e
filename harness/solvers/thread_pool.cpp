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

ThreadPool::ThreadPool(int threads) : threads_(threads < 1 ? 1 : threads) {
  for (int t = 1; t < threads_; ++t) workers_.emplace_back(&ThreadPool::worker, this);
}

ThreadPool::~ThreadPool() {
  if (workers_.empty()) return;
  stop_.store(true, std::memory_order_seq_cst);
  claim_.store(static_cast<std::uint64_t>(generation_ + 1) << 32, std::memory_order_seq_cst);
  { std::lock_guard<std::mutex> lock(sleep_mutex_); }
  wake_.notify_all();
  for (std::thread& w : workers_) w.join();
}

// A worker starts from generation 0, the pool's before its first job: a job
// or the stop published before the worker first runs is not missed.
void ThreadPool::worker() {
  std::uint32_t seen = 0;
  for (;;) {
    const auto start = std::chrono::steady_clock::now();
    std::uint32_t generation;
    for (unsigned turn = 1; (generation = generation_of(claim_.load(std::memory_order_acquire))) == seen; ++turn) {
      relax(turn);
      if (turn % 64 != 0 || std::chrono::steady_clock::now() - start < kSpin) continue;
      sleepers_.fetch_add(1, std::memory_order_seq_cst);
      {
        std::unique_lock<std::mutex> lock(sleep_mutex_);
        wake_.wait(lock, [&] { return generation_of(claim_.load(std::memory_order_seq_cst)) != seen; });
      }
      sleepers_.fetch_sub(1, std::memory_order_relaxed);
    }
    if (stop_.load(std::memory_order_seq_cst)) return;
    seen = generation;
    take_part(generation);
  }
}

void ThreadPool::take_part(std::uint32_t generation) {
  bool counted = false;
  for (;;) {
    std::uint64_t claim = claim_.load(std::memory_order_acquire);
    do {
      if (generation_of(claim) != generation || unclaimed_of(claim) == 0) return;
    } while (!claim_.compare_exchange_weak(claim, claim - 1, std::memory_order_acq_rel, std::memory_order_acquire));
    // A claim made: the job stays the caller's current one until this item is done.
    const int item = total_ - static_cast<int>(unclaimed_of(claim));
    if (!counted) participants_.fetch_add(1, std::memory_order_relaxed), counted = true;
    int phase = 0;
    while (item >= phase_end_[phase]) ++phase;
    if (phase > 0)
      for (unsigned turn = 0; done_.load(std::memory_order_acquire) < phase_end_[phase - 1]; ++turn) relax(turn);
    if (!failed_.load(std::memory_order_acquire)) {
      try {
        (*work_)(phase, phase > 0 ? item - phase_end_[phase - 1] : item);
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex_);
        if (!error_ || item < error_item_) error_ = std::current_exception(), error_item_ = item;
        failed_.store(true, std::memory_order_release);
      }
    }
    done_.fetch_add(1, std::memory_order_acq_rel);
  }
}

void ThreadPool::run(const std::vector<int>& items, const std::function<void(int, int)>& work) {
  phase_end_.resize(items.size());
  total_ = 0;
  for (size_t p = 0; p < items.size(); ++p) phase_end_[p] = total_ += items[p];
  if (total_ == 0) return;
  work_ = &work;
  error_ = nullptr;
  failed_.store(false, std::memory_order_relaxed);
  done_.store(0, std::memory_order_relaxed);
  participants_.store(0, std::memory_order_relaxed);
  ++generation_;
  claim_.store(static_cast<std::uint64_t>(generation_) << 32 | static_cast<std::uint32_t>(total_),
               std::memory_order_seq_cst);
  if (sleepers_.load(std::memory_order_seq_cst) > 0) {
    { std::lock_guard<std::mutex> lock(sleep_mutex_); }
    wake_.notify_all();
  }
  take_part(generation_);
  for (unsigned turn = 0; done_.load(std::memory_order_acquire) < total_; ++turn) relax(turn);
  if (error_) std::rethrow_exception(error_);
}

}  // namespace mortar::harness
