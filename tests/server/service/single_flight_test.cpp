#include "server/service/single_flight.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <stdexcept>
#include <thread>

namespace fsdb {
namespace {

// Work that starts, says so, and waits until released.
struct Gate {
  std::mutex m;
  std::condition_variable cv;
  bool started = false, released = false;
  std::atomic<int> runs{0};
  int work(int value) {
    ++runs;
    std::unique_lock<std::mutex> lock(m);
    started = true;
    cv.notify_all();
    cv.wait(lock, [&] { return released; });
    return value;
  }
  void waitStarted() {
    std::unique_lock<std::mutex> lock(m);
    cv.wait(lock, [&] { return started; });
  }
  void release() {
    std::lock_guard<std::mutex> lock(m);
    released = true;
    cv.notify_all();
  }
};

TEST(SingleFlight, CallersOfOneKeyWhileItRunsShareOneRun) {
  SingleFlight<int> flights;
  Gate gate;
  int first = 0, second = 0, third = 0;
  std::thread a([&] { first = flights.run("k", [&] { return gate.work(7); }); });
  gate.waitStarted();
  std::thread b([&] { second = flights.run("k", [&] { return gate.work(8); }); });
  std::thread c([&] { third = flights.run("k", [&] { return gate.work(9); }); });
  // b and c reach run() while a's work waits at the gate (they only take a lock and a future).
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  gate.release();
  a.join();
  b.join();
  c.join();
  EXPECT_EQ(gate.runs.load(), 1);
  EXPECT_EQ(first, 7);
  EXPECT_EQ(second, 7);
  EXPECT_EQ(third, 7);
  // The key is forgotten once the work ended: a later call runs its own work.
  EXPECT_EQ(flights.run("k", [] { return 11; }), 11);
}

TEST(SingleFlight, OtherKeysRunApart) {
  SingleFlight<int> flights;
  Gate gate;
  int held = 0;
  std::thread a([&] { held = flights.run("a", [&] { return gate.work(1); }); });
  gate.waitStarted();
  EXPECT_EQ(flights.run("b", [] { return 2; }), 2);  // not blocked behind "a"
  gate.release();
  a.join();
  EXPECT_EQ(held, 1);
}

TEST(SingleFlight, AnExceptionReachesEveryWaitingCallerAndIsNotKept) {
  SingleFlight<int> flights;
  Gate gate;
  std::atomic<int> failures{0};
  std::thread a([&] {
    try {
      flights.run("k", [&]() -> int {
        gate.work(0);
        throw std::runtime_error("limit");
      });
    } catch (const std::runtime_error&) {
      ++failures;
    }
  });
  gate.waitStarted();
  std::thread b([&] {
    try {
      flights.run("k", [] { return 5; });
    } catch (const std::runtime_error&) {
      ++failures;
    }
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  gate.release();
  a.join();
  b.join();
  EXPECT_EQ(failures.load(), 2);
  EXPECT_EQ(flights.run("k", [] { return 3; }), 3);
}

}  // namespace
}  // namespace fsdb
