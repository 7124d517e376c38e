// The pool of threads of the wall solver (solvers/thread_pool.hpp): every
// item once, phases in order, the pool reused job after job, errors carried
// to the caller, items taken from a thread that does not come.
#include <catch2/catch.hpp>

#include <atomic>
#include <thread>
#include <stdexcept>
#include <string>
#include <vector>

#include "solvers/thread_pool.hpp"

using namespace mortar::harness;

TEST_CASE("thread pool: every item of every phase runs once, a phase after the one before", "[threads]") {
  for (int threads : {1, 2, 3}) {
    ThreadPool pool(threads);
    REQUIRE(pool.size() == threads);
    std::vector<std::atomic<int>> first(37), second(5);
    std::atomic<int> first_done{0};
    bool ordered = true;
    std::atomic<int> early{0};
    for (int job = 0; job < 2000; ++job) {
      for (auto& c : first) c = 0;
      for (auto& c : second) c = 0;
      first_done = 0;
      pool.run_dealt({37, 5}, [&](int phase, int item) {
        if (phase == 0) {
          ++first[item];
          ++first_done;
        } else {
          if (first_done.load() != 37) ++early;
          ++second[item];
        }
      });
      for (auto& c : first) ordered = ordered && c.load() == 1;
      for (auto& c : second) ordered = ordered && c.load() == 1;
    }
    INFO(threads << " threads");
    CHECK(ordered);
    CHECK(early.load() == 0);
    CHECK(pool.participants() >= 1);
    CHECK(pool.participants() <= threads);
  }
}

TEST_CASE("thread pool: the results of a job are the caller's when run returns", "[threads]") {
  ThreadPool pool(2);
  std::vector<double> out(64);
  double total = 0;
  for (int job = 1; job <= 500; ++job) {
    pool.run_dealt({64}, [&](int, int item) { out[item] = job * item; });
    for (double x : out) total += x;
  }
  CHECK(total == 64.0 * 63 / 2 * (500.0 * 501 / 2));
}

TEST_CASE("thread pool: an exception reaches the caller, the later phases are skipped, the pool goes on",
          "[threads]") {
  for (int threads : {1, 2, 3}) {
    ThreadPool pool(threads);
    std::atomic<int> later{0};
    const auto job = [&](int phase, int item) {
      if (phase == 1) ++later;
      if (phase == 0 && item == 3) throw std::runtime_error("item " + std::to_string(item));
    };
    try {
      pool.run_dealt({8, 4}, job);
      FAIL("no exception");
    } catch (const std::runtime_error& e) {
      INFO(threads << " threads: " << e.what());
      CHECK(std::string(e.what()) == "item 3");
    }
    CHECK(later.load() == 0);
    std::atomic<int> count{0};
    pool.run_dealt({10}, [&](int, int) { ++count; });
    CHECK(count.load() == 10);
  }
}

TEST_CASE("thread pool: an empty job returns at once", "[threads]") {
  ThreadPool pool(2);
  int calls = 0;
  pool.run_dealt({0, 0}, [&](int, int) { ++calls; });
  CHECK(calls == 0);
}

TEST_CASE("thread pool: a thread takes the items of a thread that is busy", "[threads]") {
  ThreadPool pool(2);
  // Item 3, the worker's first, waits until every other item is done: its
  // items 4 and 5 must be taken by the caller (or, had the caller taken
  // item 3, by the worker).
  ThreadPool::Job job(1, std::vector<std::vector<int>>(2));
  job[0][0] = {0, 1, 2};
  job[0][1] = {3, 4, 5};
  for (int round = 0; round < 100; ++round) {
    std::atomic<int> others{0};
    std::vector<int> ran(6, 0);
    pool.run(job, [&](int, int item) {
      ++ran[item];
      if (item == 3) {
        while (others.load() < 5) std::this_thread::yield();
      } else {
        ++others;
      }
    });
    REQUIRE(ran == std::vector<int>(6, 1));
  }
}
