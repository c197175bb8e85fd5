#pragma once
// The CSG graphs of stored shapes for structural search (server/service/csg_search.h), kept in
// memory so a query does not parse 10k documents and describe their leaves each time.
//
// Contract:
// - A StoredGraph is shapeGraph (query/structural/csg_graph.h) of the latest version of a shape, references
//   resolved against the store, with describePart of every leaf (the values text leaves of a query
//   are scored on) and the node counts (query/structural/csg_bound.h).
// - The cache keys an entry by shape id and remembers the version of the shape and of every object
//   its tree reached (the parts and shapes the resolver returned). graph() returns the entry only
//   when all of them still have those versions in `versions` (versions(): the change log read once
//   per search), else builds it again: a PUT of a part changes the graphs of every tree using it,
//   even through other shapes, and so does a write by another server on the same database.
// - Memory follows the live catalogue, not the history of writes: a search whose versions moved on
//   drops the entries of deleted shapes, and an interned part is forgotten once no entry uses it
//   (rebuilt or dropped entries release theirs). Past maxEntries entries the cache is cleared.
// - Thread-safe; a graph is built outside the lock (two threads may build the same one; either
//   result is the same).
// - graphs() builds every missing or stale entry of a search at once, in parallel (tbb), and interns
//   the leaves' parts in shape order afterwards, so the entries (leafParts ids included) are those
//   of calling graph() for each shape in order. One graphs() build runs at a time: a search that
//   arrives while another (or the warm-up at serve start, server/service/graph_warmup.h) builds waits for
//   it and then builds only what is still missing, so no graph is built twice.
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <utility>
#include <vector>

#include "db/store.h"
#include "query/structural/csg_bound.h"
#include "query/structural/csg_graph.h"
#include "query/linguistic/descriptors.h"

namespace fsdb {

struct StoredGraph {
  int64_t id = 0;
  int version = 0;
  std::string name;
  ShapeGraph shape;
  std::vector<std::vector<DescriptorValue>> leafDescriptors;  // by leaf index
  // By leaf index: the cache's id of the leaf's part, equal for equal parts (StoredGraphCache), so
  // a search computes the similarities of a part used by many trees once.
  std::vector<int64_t> leafParts;
  CsgSignature signature;
  std::vector<std::pair<int64_t, int>> reached;  // (object id, version) its tree used
};

// A hash of every parameter and transform value of a part (breakpoints, rotation axis): equal parts
// have equal keys; samePart confirms a key match.
uint64_t partKey(const FuzzyPart& part);
bool samePart(const FuzzyPart& a, const FuzzyPart& b);

// Latest versions of every live part and shape, by id (ids are shared by all kinds), and the live
// shapes in id order (the candidates of a search), as of the store's change log sequence `seq`.
struct StoreVersions {
  std::unordered_map<int64_t, int> latest;
  std::vector<ObjectVersion> shapes;
  int64_t seq = 0;
  // Everything, in one snapshot (Store::changesSince(0)).
  static StoreVersions read(const Store& store);
  // These versions moved on by `feed` (from changesSince(seq)): a reset replaces them all.
  StoreVersions updated(const ChangeFeed& feed) const;
};

// Builds the graph of the latest version of `shape` (errors as shapeGraph; not_found when deleted);
// leafParts are left empty (the cache fills them).
std::shared_ptr<StoredGraph> buildStoredGraph(const Store& store, int64_t shape, size_t maxNodes,
                                                    const StoreVersions& versions);

class StoredGraphCache {
 public:
  explicit StoredGraphCache(size_t maxEntries = 200000) : maxEntries_(maxEntries) {}
  std::shared_ptr<const StoredGraph> graph(const Store& store, const ObjectVersion& shape, const StoreVersions& versions,
                                           size_t maxNodes);
  // The graphs of versions.shapes, in that order (nullptr for a shape deleted meanwhile). check()
  // (may be empty) runs while waiting for another build and before each build; what it throws
  // stops the build and is rethrown. Other build errors: the one of the first shape in order is
  // rethrown after the others were built and kept.
  std::vector<std::shared_ptr<const StoredGraph>> graphs(const Store& store, const StoreVersions& versions,
                                                         size_t maxNodes, const std::function<void()>& check = {});
  // The store's versions now, for a search: the same object while the store's change sequence
  // stands still (one indexed read per search), else the last one moved on by the changes since
  // (Store::changesSince). Writes by other servers on the same database are seen the same way.
  std::shared_ptr<const StoreVersions> versions(const Store& store);
  size_t size() const;
  size_t builds() const;  // graphs built since construction (tests and bench see hits and misses)
  size_t internedParts() const;  // distinct parts the entries use (tests see that memory follows them)

 private:
  struct InternedPart {
    FuzzyPart part;
    int64_t id;
    int uses;  // leaves of entries_ with this id
  };
  int64_t intern(const FuzzyPart& part);  // under mutex_; ids are never reused, even after a clear
  // Under mutex_: the uses of `graph`'s leaf parts end; a part left unused is forgotten.
  void release(const StoredGraph& graph);
  // Under mutex_: counts the build, interns its parts and keeps it (releasing the entry it replaces).
  void insert(const std::shared_ptr<StoredGraph>& built);
  // Under mutex_: drops the entries of shapes `versions` no longer has (deleted), once per seq.
  void dropDeleted(const StoreVersions& versions);

  std::unordered_map<uint64_t, std::vector<InternedPart>> parts_;  // by partKey
  int64_t nextPart_ = 0;
  int64_t sweptSeq_ = -1;  // the versions seq dropDeleted last ran for
  mutable std::mutex mutex_;
  std::unordered_map<int64_t, std::shared_ptr<const StoredGraph>> entries_;
  size_t builds_ = 0;
  const size_t maxEntries_;
  std::timed_mutex buildMutex_;  // held by the one graphs() build at a time
  std::mutex versionsMutex_;
  std::shared_ptr<const StoreVersions> versions_;
};

}  // namespace fsdb
