// See server/service/graph_warmup.h.
#include "server/service/graph_warmup.h"

#include <spdlog/spdlog.h>

#include <chrono>
#include <exception>

namespace fsdb {
namespace {
struct Stopped {};  // thrown by the build's check when the server stops
}  // namespace

GraphWarmup::GraphWarmup(const Store& store, std::shared_ptr<StoredGraphCache> cache, size_t maxNodes) {
  thread_ = std::thread([this, &store, cache, maxNodes]() {
    const auto start = std::chrono::steady_clock::now();
    try {
      const std::shared_ptr<const StoreVersions> current = cache->versions(store);
      const StoreVersions& versions = *current;
      spdlog::info("structural search: warming the graphs of {} shapes", versions.shapes.size());
      const size_t before = cache->builds();
      cache->graphs(store, versions, maxNodes, [this]() {
        if (stop_.load()) throw Stopped{};
      });
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      spdlog::info("structural search: warm-up built {} graphs in {:.2f} s", cache->builds() - before, seconds);
    } catch (const Stopped&) {
      spdlog::info("structural search: warm-up stopped");
    } catch (const std::exception& e) {
      spdlog::warn("structural search: warm-up failed: {}", e.what());
    }
  });
}

void GraphWarmup::wait() {
  if (thread_.joinable()) thread_.join();
}

GraphWarmup::~GraphWarmup() {
  stop_.store(true);
  wait();
}

}  // namespace fsdb
