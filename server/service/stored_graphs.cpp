// See server/service/stored_graphs.h.
#include "server/service/stored_graphs.h"

#include <atomic>
#include <chrono>
#include <cstring>
#include <exception>
#include <map>

#include <tbb/parallel_for.h>

#include "geometry/core/error.h"
#include "server/service/documents.h"

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

// Every fuzzy value of a part, in one order.
std::vector<const FuzzyNumber*> values(const FuzzyPart& p) {
  return {&p.eps1, &p.eps2, &p.a1, &p.a2, &p.a3, &p.kx, &p.ky, &p.kv, &p.t, &p.tx, &p.ty, &p.tz, &p.deg, &p.scale};
}

}  // namespace

uint64_t partKey(const FuzzyPart& part) {
  uint64_t h = 1469598103934665603ull;  // FNV-1a over the bytes of every breakpoint and the axis
  const auto mix = [&h](double x) {
    uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    for (int i = 0; i < 8; ++i) h = (h ^ ((bits >> (8 * i)) & 0xff)) * 1099511628211ull;
  };
  for (const FuzzyNumber* v : values(part)) {
    for (const Breakpoint& b : v->breakpoints()) {
      mix(b.x);
      mix(b.mu);
    }
    mix(-1.0);  // separates the values
  }
  for (double a : {part.axis.x, part.axis.y, part.axis.z}) mix(a);
  return h;
}

bool samePart(const FuzzyPart& a, const FuzzyPart& b) {
  const std::vector<const FuzzyNumber*> va = values(a), vb = values(b);
  for (size_t i = 0; i < va.size(); ++i)
    if (!(*va[i] == *vb[i])) return false;
  return a.axis.x == b.axis.x && a.axis.y == b.axis.y && a.axis.z == b.axis.z;
}

StoreVersions StoreVersions::read(const Store& store) { return StoreVersions{}.updated(store.changesSince(0)); }

StoreVersions StoreVersions::updated(const ChangeFeed& feed) const {
  StoreVersions out;
  if (!feed.reset) out = *this;
  out.seq = feed.seq;
  if (feed.changes.empty()) return out;
  std::map<int64_t, ObjectVersion> shapes;
  for (const ObjectVersion& s : out.shapes) shapes.emplace(s.id, s);
  for (const ObjectChange& c : feed.changes) {
    const bool live = c.latestVersion > 0 && (c.kind == "part" || c.kind == "shape");
    if (live) out.latest[c.id] = c.latestVersion;
    else out.latest.erase(c.id);
    if (live && c.kind == "shape") shapes[c.id] = ObjectVersion{c.id, c.name, c.latestVersion};
    else shapes.erase(c.id);
  }
  out.shapes.clear();
  out.shapes.reserve(shapes.size());
  for (auto& [id, s] : shapes) out.shapes.push_back(std::move(s));
  return out;
}

std::shared_ptr<const StoreVersions> StoredGraphCache::versions(const Store& store) {
  const int64_t seq = store.changeSeq();
  std::lock_guard<std::mutex> lock(versionsMutex_);
  if (versions_ && versions_->seq == seq) return versions_;
  const ChangeFeed feed = store.changesSince(versions_ ? versions_->seq : 0);
  versions_ = std::make_shared<const StoreVersions>(versions_ ? versions_->updated(feed) : StoreVersions{}.updated(feed));
  return versions_;
}

std::shared_ptr<StoredGraph> buildStoredGraph(const Store& store, int64_t shape, size_t maxNodes,
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
  std::shared_ptr<StoredGraph> built = buildStoredGraph(store, shape.id, maxNodes, versions);
  std::lock_guard<std::mutex> lock(mutex_);
  insert(built);
  return built;
}

void StoredGraphCache::insert(const std::shared_ptr<StoredGraph>& built) {
  ++builds_;
  if (entries_.size() >= maxEntries_) {
    entries_.clear();
    parts_.clear();
  }
  for (const CsgGraphLeaf& leaf : built->shape.leaves) built->leafParts.push_back(intern(leaf.part));
  std::shared_ptr<const StoredGraph>& entry = entries_[built->id];
  // Interned first, released after: a part the old and the new graph share keeps its id.
  if (entry) release(*entry);
  entry = built;
}

void StoredGraphCache::release(const StoredGraph& graph) {
  for (size_t i = 0; i < graph.leafParts.size(); ++i) {
    const auto bucket = parts_.find(partKey(graph.shape.leaves[i].part));
    if (bucket == parts_.end()) continue;  // cleared since
    std::vector<InternedPart>& known = bucket->second;
    for (size_t k = 0; k < known.size(); ++k) {
      if (known[k].id != graph.leafParts[i]) continue;
      if (--known[k].uses == 0) known.erase(known.begin() + static_cast<std::ptrdiff_t>(k));
      break;
    }
    if (known.empty()) parts_.erase(bucket);
  }
}

void StoredGraphCache::dropDeleted(const StoreVersions& versions) {
  if (versions.seq == sweptSeq_) return;
  sweptSeq_ = versions.seq;
  for (auto it = entries_.begin(); it != entries_.end();) {
    if (versions.latest.count(it->first)) {
      ++it;
      continue;
    }
    release(*it->second);
    it = entries_.erase(it);
  }
}

std::vector<std::shared_ptr<const StoredGraph>> StoredGraphCache::graphs(const Store& store,
                                                                         const StoreVersions& versions,
                                                                         size_t maxNodes,
                                                                         const std::function<void()>& check) {
  const std::vector<ObjectVersion>& shapes = versions.shapes;
  std::vector<std::shared_ptr<const StoredGraph>> out(shapes.size());
  // The indexes of `shapes` without a current entry; the others are filled in.
  const auto lookUp = [&]() {
    std::vector<size_t> missing;
    std::lock_guard<std::mutex> lock(mutex_);
    dropDeleted(versions);
    for (size_t i = 0; i < shapes.size(); ++i) {
      if (out[i]) continue;
      const auto it = entries_.find(shapes[i].id);
      if (it != entries_.end() && current(*it->second, shapes[i], versions)) out[i] = it->second;
      else missing.push_back(i);
    }
    return missing;
  };
  if (lookUp().empty()) return out;
  std::unique_lock<std::timed_mutex> building(buildMutex_, std::defer_lock);
  while (!building.try_lock_for(std::chrono::milliseconds(20)))
    if (check) check();
  const std::vector<size_t> missing = lookUp();  // what the build we waited for left
  std::vector<std::shared_ptr<StoredGraph>> built(missing.size());
  std::vector<std::exception_ptr> errors(missing.size());
  std::atomic<bool> stopped{false};  // check() threw: build nothing more
  std::exception_ptr stopError;
  std::mutex stopMutex;
  tbb::parallel_for(size_t(0), missing.size(), [&](size_t k) {
    if (stopped.load()) return;
    try {
      if (check) check();
    } catch (...) {
      std::lock_guard<std::mutex> lock(stopMutex);
      if (!stopped.exchange(true)) stopError = std::current_exception();
      return;
    }
    try {
      built[k] = buildStoredGraph(store, shapes[missing[k]].id, maxNodes, versions);
    } catch (const Error& e) {
      if (e.code() != std::string(errc::kNotFound)) errors[k] = std::current_exception();  // not_found: deleted
    } catch (...) {
      errors[k] = std::current_exception();
    }
  });
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (size_t k = 0; k < missing.size(); ++k) {  // in shape order: the interned ids of serial graph() calls
      if (!built[k]) continue;
      insert(built[k]);
      out[missing[k]] = built[k];
    }
  }
  if (stopError) std::rethrow_exception(stopError);
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
  return out;
}

int64_t StoredGraphCache::intern(const FuzzyPart& part) {
  std::vector<InternedPart>& bucket = parts_[partKey(part)];
  for (InternedPart& known : bucket) {
    if (samePart(known.part, part)) {
      ++known.uses;
      return known.id;
    }
  }
  bucket.push_back(InternedPart{part, nextPart_, 1});
  return nextPart_++;
}

size_t StoredGraphCache::internedParts() const {
  std::lock_guard<std::mutex> lock(mutex_);
  size_t n = 0;
  for (const auto& [key, bucket] : parts_) n += bucket.size();
  return n;
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
