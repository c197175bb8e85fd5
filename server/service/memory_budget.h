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
// - After a release of at least kTrimBytes the C library is asked to return its free memory to
//   the system (malloc_trim), so that the RSS falls during and after a load: without it, two
//   rounds of 16 evaluations at 384 under 1 GiB kept 1.35 GB after the load, and trimmed only
//   once the load was over they peaked at 1.33 GB instead of 0.92-0.94 GB. The trim runs on the
//   budget's own thread, at most once per kTrimInterval, one for all the releases in between:
//   malloc_trim holds each allocator arena's lock while it hands back the free pages (85-235 ms
//   after an evaluation at 384 on a 2-core machine), which stalls every thread that allocates,
//   the connection front and cheap requests included. Trimmed after each of 8 evaluations that
//   ended together, back to back, a /health probe once waited 1.5 s.
// - limit 0: no limit (reservations are still counted).
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <set>
#include <functional>
#include <string>
#include <thread>

namespace fsdb {

// The Retry-After of an `overloaded` answer: about as long as an evaluation that holds memory.
inline constexpr int kOverloadedRetrySeconds = 5;

class MemoryBudget {
 public:
  static constexpr std::uint64_t kTrimBytes = std::uint64_t(64) << 20;
  static constexpr std::chrono::milliseconds kWaitForRelease{10000};

  static constexpr std::chrono::milliseconds kTrimInterval{1000};

  // `trim` is what gives the free memory back (malloc_trim(0) when empty; tests count calls);
  // `interval` the least time from the end of one trim to the start of the next.
  explicit MemoryBudget(std::uint64_t limitBytes, std::function<void()> trim = {},
                        std::chrono::milliseconds interval = kTrimInterval);
  ~MemoryBudget();
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
  void trimmerLoop();

  const std::uint64_t limit_;
  std::atomic<std::uint64_t> reserved_{0};
  std::atomic<std::uint64_t> refusals_{0};
  std::atomic<std::uint64_t> nextOrder_{0};
  std::atomic<int> waiting_{0};
  std::mutex mutex_;
  std::condition_variable released_;
  std::set<Reservation*, ByOrder> live_;  // every reservation not yet destroyed

  // The trimmer: trimWanted_ after a large release, lastTrim_ when the last trim ended.
  const std::function<void()> trim_;
  const std::chrono::milliseconds interval_;
  std::mutex trimMutex_;
  std::condition_variable trimWake_;
  bool trimWanted_ = false;
  bool stopping_ = false;
  std::chrono::steady_clock::time_point lastTrim_;
  std::thread trimmer_;  // last: started once every member above exists
};

}  // namespace fsdb
