#pragma once
// MemoryBudget: the memory the server's evaluations and meshes may hold together
// (fsdb serve --max-memory-mb; default half the machine's memory). Each reserves what it is
// about to allocate before it allocates it, and gives it back when its result is freed; past the
// budget a reservation fails with 503 `overloaded` and Retry-After, so that 16 evaluations at
// 512 at once are refused one by one instead of taking the machine (they reached 8.2 GB and were
// still rising) or the server being killed for memory.
//
// Contract:
// - A Reservation (reserve()) grows by grow(bytes); it gives back all it holds when destroyed,
//   and must not outlive its budget. Thread-safe.
// - Older reservations go first. When a grow does not fit, the youngest reservation that holds
//   memory and is younger than the one asking is told to stop: its next grow throws
//   Error(errc::kOverloaded), it gives its memory back, and the older one, which waits for that
//   (at most kWaitForRelease), goes on. When no younger one holds memory, the one asking is
//   refused. So under a load the oldest evaluations finish and the newest are refused, instead
//   of every one being refused half-way (16 evaluations at 512 under a 2 GiB budget: 16 × 503).
// - A refused grow reserves nothing. refusals() counts them.
// - When a release of at least kTrimBytes brings the total back down, the C library is asked to
//   return its free memory to the system (malloc_trim), so that the RSS falls after a load.
// - limit 0: no limit (reservations are still counted).
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <set>
#include <string>

namespace fsdb {

// The Retry-After of an `overloaded` answer: about as long as an evaluation that holds memory.
inline constexpr int kOverloadedRetrySeconds = 5;

class MemoryBudget {
 public:
  static constexpr std::uint64_t kTrimBytes = std::uint64_t(64) << 20;
  static constexpr std::chrono::milliseconds kWaitForRelease{10000};

  explicit MemoryBudget(std::uint64_t limitBytes) : limit_(limitBytes) {}
  MemoryBudget(const MemoryBudget&) = delete;
  MemoryBudget& operator=(const MemoryBudget&) = delete;

  class Reservation {
   public:
    Reservation(MemoryBudget& budget, std::uint64_t order) : budget_(budget), order_(order) {}
    Reservation(const Reservation&) = delete;
    Reservation& operator=(const Reservation&) = delete;
    ~Reservation() { budget_.release(*this); }
    // Throws Error(errc::kOverloaded) naming `what` when the budget cannot take `bytes` more.
    void grow(std::uint64_t bytes, const std::string& what) { budget_.take(*this, bytes, what); }
    std::uint64_t bytes() const { return bytes_.load(std::memory_order_relaxed); }

   private:
    friend class MemoryBudget;
    MemoryBudget& budget_;
    const std::uint64_t order_;                // creation order: smaller is older
    std::atomic<std::uint64_t> bytes_{0};
    std::atomic<bool> stop_{false};            // told to give way to an older one
  };

  // A new (youngest) reservation of `bytes` (may be 0, to grow later); throws as grow().
  std::shared_ptr<Reservation> reserve(std::uint64_t bytes, const std::string& what);

  std::uint64_t reserved() const { return reserved_.load(std::memory_order_relaxed); }
  std::uint64_t limit() const { return limit_; }
  // Grows refused since the start (those told to give way included).
  std::uint64_t refusals() const { return refusals_.load(std::memory_order_relaxed); }
  // Grows waiting now for a younger reservation to give its memory back.
  int waiting() const { return waiting_.load(std::memory_order_relaxed); }

  // Half of the machine's physical memory (the default of --max-memory-mb).
  static std::uint64_t defaultLimitBytes();

 private:
  struct ByOrder {
    bool operator()(const Reservation* a, const Reservation* b) const { return a->order_ < b->order_; }
  };
  void take(Reservation& r, std::uint64_t bytes, const std::string& what);
  void release(Reservation& r);
  [[noreturn]] void refuse(std::uint64_t bytes, const std::string& what);
  bool fits(std::uint64_t bytes);  // takes them when they fit (one atomic step)

  const std::uint64_t limit_;
  std::atomic<std::uint64_t> reserved_{0};
  std::atomic<std::uint64_t> refusals_{0};
  std::atomic<std::uint64_t> nextOrder_{0};
  std::atomic<int> waiting_{0};
  std::mutex mutex_;
  std::condition_variable released_;
  std::set<Reservation*, ByOrder> live_;  // every reservation not yet destroyed
};

}  // namespace fsdb
