// MemoryBudget (server/service/memory_budget.h): reservations within the limit succeed, one that
// would pass it is refused with `overloaded` and takes nothing, what is given back can be taken
// again, and threads racing for it never hold more than the limit together.
#include "server/service/memory_budget.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <memory>
#include <mutex>
#include <vector>

#include "geometry/core/error.h"

namespace fsdb {
namespace {

TEST(MemoryBudget, ReservesWithinTheLimitAndRefusesBeyond) {
  MemoryBudget budget(10 << 20);
  auto a = budget.reserve(6 << 20, "a");
  EXPECT_EQ(budget.reserved(), std::uint64_t(6) << 20);
  try {
    budget.reserve(5 << 20, "the grid at resolution 512");
    ADD_FAILURE() << "no overloaded";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kOverloaded);
    EXPECT_NE(std::string(e.what()).find("max_memory_mb=10"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("the grid at resolution 512 needs 5 MiB"), std::string::npos) << e.what();
  }
  EXPECT_EQ(budget.reserved(), std::uint64_t(6) << 20);  // the refused one took nothing
  EXPECT_EQ(budget.refusals(), 1u);
  a->grow(4 << 20, "a");
  EXPECT_EQ(a->bytes(), std::uint64_t(10) << 20);
  EXPECT_THROW(a->grow(1, "a"), Error);
  a.reset();
  EXPECT_EQ(budget.reserved(), 0u);
  auto b = budget.reserve(10 << 20, "b");  // all of it, once given back
  EXPECT_EQ(budget.reserved(), std::uint64_t(10) << 20);
}

// Older reservations go first: an older one that does not fit makes the youngest younger one
// give way (its next grow is refused) and goes on once that one has given its memory back.
TEST(MemoryBudget, TheYoungestGivesWayToAnOlderOne) {
  MemoryBudget budget(10 << 20);
  auto older = budget.reserve(6 << 20, "older");
  auto younger = budget.reserve(3 << 20, "younger");
  std::atomic<bool> grown{false};
  std::thread t([&] {
    older->grow(3 << 20, "older");  // 12 > 10: waits for the younger one
    grown = true;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_FALSE(grown.load());
  EXPECT_THROW(younger->grow(1, "younger"), Error);  // told to give way
  younger.reset();                                   // its memory goes back
  t.join();
  EXPECT_TRUE(grown.load());
  EXPECT_EQ(budget.reserved(), std::uint64_t(9) << 20);
  // A new reservation that does not fit is refused at once: nothing younger can give way.
  EXPECT_THROW(budget.reserve(2 << 20, "new"), Error);
  EXPECT_EQ(budget.reserved(), std::uint64_t(9) << 20);
}

TEST(MemoryBudget, NoLimitCountsOnly) {
  MemoryBudget budget(0);
  auto a = budget.reserve(std::uint64_t(1) << 40, "a");
  EXPECT_EQ(budget.reserved(), std::uint64_t(1) << 40);
}

TEST(MemoryBudget, RacingThreadsNeverHoldMoreThanTheLimit) {
  MemoryBudget budget(4 << 20);
  std::atomic<std::uint64_t> most{0};
  std::atomic<int> refused{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&] {
      for (int i = 0; i < 2000; ++i) {
        try {
          auto r = budget.reserve(0, "r");
          r->grow(1 << 20, "r");
          std::uint64_t now = budget.reserved(), seen = most.load();
          while (now > seen && !most.compare_exchange_weak(seen, now)) {
          }
        } catch (const Error&) {
          ++refused;
        }
      }
    });
  for (auto& t : threads) t.join();
  EXPECT_LE(most.load(), std::uint64_t(4) << 20);
  EXPECT_EQ(budget.reserved(), 0u);
  EXPECT_EQ(budget.refusals(), static_cast<std::uint64_t>(refused.load()));
}

// The free memory is handed back after a large release, on the budget's thread, at most once per
// interval: releases that come together share one trim (malloc_trim holds the allocator's locks
// and stalls every thread; eight back to back held a /health probe 1.5 s); a small release trims
// nothing.
TEST(MemoryBudget, TrimsAfterLargeReleasesAtMostOncePerInterval) {
  using Clock = std::chrono::steady_clock;
  std::mutex mutex;
  std::vector<Clock::time_point> trims;
  auto count = [&] {
    std::lock_guard<std::mutex> lock(mutex);
    return trims.size();
  };
  auto waitForTrims = [&](size_t n) {
    for (int i = 0; i < 1000 && count() < n; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return count();
  };
  const auto interval = std::chrono::milliseconds(300);
  MemoryBudget budget(0, [&] {
    std::lock_guard<std::mutex> lock(mutex);
    trims.push_back(Clock::now());
  }, interval);

  budget.reserve(1 << 20, "small").reset();
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_EQ(count(), 0u) << "a small release trims nothing";

  budget.reserve(MemoryBudget::kTrimBytes, "first").reset();
  EXPECT_EQ(waitForTrims(1), 1u) << "a large release is trimmed without waiting for the interval";

  // Eight large releases together, right after that trim: one more trim, an interval later.
  std::vector<std::shared_ptr<MemoryBudget::Reservation>> load;
  for (int i = 0; i < 8; ++i) load.push_back(budget.reserve(MemoryBudget::kTrimBytes, "load"));
  load.clear();
  EXPECT_EQ(waitForTrims(2), 2u);
  std::this_thread::sleep_for(interval * 2);
  ASSERT_EQ(count(), 2u) << "eight releases together share one trim";
  EXPECT_GE(trims[1] - trims[0], interval);
}

// The budget's trimmer thread stops with it, also while it waits out an interval.
TEST(MemoryBudget, DestroyedWhileATrimWaits) {
  std::atomic<int> trims{0};
  auto budget = std::make_unique<MemoryBudget>(0, [&] { ++trims; }, std::chrono::hours(1));
  budget->reserve(MemoryBudget::kTrimBytes, "a").reset();
  for (int i = 0; i < 500 && trims.load() < 1; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_EQ(trims.load(), 1);
  budget->reserve(MemoryBudget::kTrimBytes, "b").reset();  // its trim waits an hour
  const auto start = std::chrono::steady_clock::now();
  budget.reset();
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  EXPECT_EQ(trims.load(), 1);
}

}  // namespace
}  // namespace fsdb
