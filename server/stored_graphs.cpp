// See server/stored_graphs.h.
#include "server/stored_graphs.h"

#include "server/documents.h"

namespace fsdb {
namespace {

bool current(const StoredGraph& g, const ObjectVersion& shape, const StoreVersions& versions) {
  if (g.version != shape.latestVersion) return false;
  for (const auto& [id, version] : g.reached) {
    const auto it = versions.latest.find(id);
    if (it == versions.latest.end() || it->second != version) return false;
  }
  return true;
}

}  // namespace

StoreVersions StoreVersions::read(const Store& store) {
  StoreVersions out;
  for (const char* kind : {"part", "shape"})
    for (const ObjectVersion& o : store.objectVersions(kind)) out.latest[o.id] = o.latestVersion;
  return out;
}

std::shared_ptr<const StoredGraph> buildStoredGraph(const Store& store, int64_t shape, size_t maxNodes,
                                                    const StoreVersions& versions) {
  const StoredObject object = store.get("shape", shape);
  auto out = std::make_shared<StoredGraph>();
  out->id = object.id;
  out->version = object.version;
  out->name = object.name;
  // The versions of what the resolver returns, as `versions` knows them (-1: newer than `versions`,
  // so the entry is rebuilt next time: being conservative never serves a stale graph).
  const ReferenceResolver store_ = storeResolver(store);
  const ReferenceResolver recording = [&](const std::string& kind, const nlohmann::json& key) {
    std::optional<ResolvedReference> r = store_(kind, key);
    if (r) {
      const auto it = versions.latest.find(r->id);
      out->reached.emplace_back(r->id, it == versions.latest.end() ? -1 : it->second);
    }
    return r;
  };
  out->shape = shapeGraph(nlohmann::json::parse(object.documentJson), "", maxNodes, recording);
  for (const CsgGraphLeaf& leaf : out->shape.leaves) out->leafDescriptors.push_back(describePart(leaf.part));
  out->signature = csgSignature(out->shape.graph);
  return out;
}

std::shared_ptr<const StoredGraph> StoredGraphCache::graph(const Store& store, const ObjectVersion& shape,
                                                           const StoreVersions& versions, size_t maxNodes) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = entries_.find(shape.id);
    if (it != entries_.end() && current(*it->second, shape, versions)) return it->second;
  }
  std::shared_ptr<const StoredGraph> built = buildStoredGraph(store, shape.id, maxNodes, versions);
  std::lock_guard<std::mutex> lock(mutex_);
  ++builds_;
  if (entries_.size() >= maxEntries_) entries_.clear();
  entries_[shape.id] = built;
  return built;
}

size_t StoredGraphCache::size() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return entries_.size();
}

size_t StoredGraphCache::builds() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return builds_;
}

}  // namespace fsdb
