// See server/service/memory_budget.h.
#include "server/service/memory_budget.h"

#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <utility>

#include "geometry/core/error.h"

namespace fsdb {

MemoryBudget::MemoryBudget(std::uint64_t limitBytes, std::function<void()> trim, std::chrono::milliseconds interval)
    : limit_(limitBytes),
      trim_(trim ? std::move(trim) : std::function<void()>([] { malloc_trim(0); })),
      interval_(interval),
      trimmer_([this] { trimmerLoop(); }) {}

MemoryBudget::~MemoryBudget() {
  {
    std::lock_guard<std::mutex> lock(trimMutex_);
    stopping_ = true;
  }
  trimWake_.notify_all();
  trimmer_.join();
}

void MemoryBudget::trimmerLoop() {
  std::unique_lock<std::mutex> lock(trimMutex_);
  for (;;) {
    trimWake_.wait(lock, [this] { return stopping_ || trimWanted_; });
    if (stopping_) return;
    const auto next = lastTrim_ + interval_;
    if (std::chrono::steady_clock::now() < next) {
      trimWake_.wait_until(lock, next, [this] { return stopping_; });
      continue;
    }
    trimWanted_ = false;  // releases from here on want the next trim
    lock.unlock();
    trim_();
    lock.lock();
    lastTrim_ = std::chrono::steady_clock::now();
  }
}

bool MemoryBudget::fits(std::uint64_t bytes) {
  std::uint64_t now = reserved_.load(std::memory_order_relaxed);
  for (;;) {
    if (limit_ > 0 && (bytes > limit_ || now > limit_ - bytes)) return false;
    if (reserved_.compare_exchange_weak(now, now + bytes, std::memory_order_relaxed)) return true;
  }
}

void MemoryBudget::refuse(std::uint64_t bytes, const std::string& what) {
  refusals_.fetch_add(1, std::memory_order_relaxed);
  throw Error(errc::kOverloaded,
              "the server is at its memory budget (max_memory_mb=" + std::to_string(limit_ >> 20) + ", " +
                  std::to_string(reserved() >> 20) + " MiB held by other evaluations) and " + what + " needs " +
                  std::to_string((bytes + (1 << 20) - 1) >> 20) + " MiB more; retry in a few seconds, " +
                  "lower the resolution, or raise --max-memory-mb",
              "");
}

void MemoryBudget::take(Reservation& r, std::uint64_t bytes, const std::string& what) {
  if (bytes == 0) return;
  if (r.stop_.load(std::memory_order_relaxed)) refuse(bytes, what);  // giving way to an older one
  // Counted as this reservation's before the total takes them: a waiter (take, below) that finds
  // the total full must find who holds it, or it finds nobody to wait for and is refused.
  r.bytes_.fetch_add(bytes, std::memory_order_relaxed);
  if (fits(bytes)) return;
  r.bytes_.fetch_sub(bytes, std::memory_order_relaxed);
  const auto giveUp = std::chrono::steady_clock::now() + kWaitForRelease;
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    if (fits(bytes)) {
      r.bytes_.fetch_add(bytes, std::memory_order_relaxed);
      return;
    }
    if (r.stop_.load(std::memory_order_relaxed)) refuse(bytes, what);
    // The youngest younger reservation that holds memory gives way; none: this one is refused.
    Reservation* younger = nullptr;
    for (auto it = live_.rbegin(); it != live_.rend() && (*it)->order_ > r.order_; ++it)
      if ((*it)->bytes() > 0 && !(*it)->stop_.load(std::memory_order_relaxed)) {
        younger = *it;
        break;
      }
    const bool waiting = younger != nullptr || std::any_of(live_.begin(), live_.end(), [&](const Reservation* x) {
                           return x->order_ > r.order_ && x->bytes() > 0;  // already told: wait for it
                         });
    if (younger) younger->stop_.store(true, std::memory_order_relaxed);
    if (!waiting || std::chrono::steady_clock::now() >= giveUp) refuse(bytes, what);
    ++waiting_;
    released_.wait_for(lock, std::chrono::milliseconds(50));
    --waiting_;
  }
}

void MemoryBudget::release(Reservation& r) {
  std::uint64_t bytes = 0;
  {
    // Its bytes leave the reservation and the total together, under the lock: an older one
    // waiting in take() saw them leave the younger one first and the total later, found nothing
    // to wait for and was refused (MemoryBudget.TheYoungestGivesWayToAnOlderOne, now and then).
    std::lock_guard<std::mutex> lock(mutex_);
    bytes = r.bytes_.exchange(0);
    live_.erase(&r);
    reserved_.fetch_sub(bytes, std::memory_order_relaxed);
  }
  released_.notify_all();
  // The allocator keeps freed pages for reuse; after a large result is freed, the trimmer hands
  // them back (see the header for why not on this thread).
  if (bytes < kTrimBytes) return;
  {
    std::lock_guard<std::mutex> lock(trimMutex_);
    trimWanted_ = true;
  }
  trimWake_.notify_all();
}

std::shared_ptr<MemoryBudget::Reservation> MemoryBudget::reserve(std::uint64_t bytes, const std::string& what) {
  auto r = std::make_shared<Reservation>(*this, nextOrder_.fetch_add(1, std::memory_order_relaxed));
  {
    std::lock_guard<std::mutex> lock(mutex_);
    live_.insert(r.get());
  }
  r->grow(bytes, what);
  return r;
}

std::uint64_t MemoryBudget::defaultLimitBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || pageSize <= 0) return std::uint64_t(4) << 30;
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(pageSize) / 2;
}

}  // namespace fsdb
