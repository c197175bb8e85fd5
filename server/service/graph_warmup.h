#pragma once
// Warm-up of the stored graphs when `fsdb serve` starts (server/service/stored_graphs.h;
// docs/design/structural-search.md): a background thread builds the graph of every live shape with StoredGraphCache::graphs,
// so the first POST /query/csg of the process does not wait for them (about 10 s at 10k trees built
// one at a time).
//
// Contract:
// - The server answers at once. A search that arrives during the warm-up waits for its build
//   (graphs() runs one build at a time, within the search's --max-query-ms) and then builds only
//   what is still missing: no graph is built twice and answers are those of a cold search.
// - Logs one line at the start and one at the end (graphs built, seconds); a failure (a shape that
//   no longer fits --max-nodes, a storage error) is logged as a warning, never fatal: searches
//   build what the warm-up did not.
// - The destructor stops the build before the next graph and joins the thread.
#include <atomic>
#include <cstddef>
#include <memory>
#include <thread>

#include "db/store.h"
#include "server/service/stored_graphs.h"

namespace fsdb {

class GraphWarmup {
 public:
  GraphWarmup(const Store& store, std::shared_ptr<StoredGraphCache> cache, size_t maxNodes);
  ~GraphWarmup();
  GraphWarmup(const GraphWarmup&) = delete;
  GraphWarmup& operator=(const GraphWarmup&) = delete;
  void wait();  // until the build ended (tests)

 private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace fsdb
