#pragma once
// SqlStore: the one implementation of Store (db/store.h) over db/sql.h, holding a pool of
// connections of one engine. Every query of the store is written here (and in object_rows.h,
// descriptor_index.h) once; SqliteStore and PostgresStore only open the connections, apply their
// engine's migrations and answer the few engine-specific calls (checkpoint, integrityCheck).
// Internal to db/: callers use Store::open.
#include <atomic>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "db/sql.h"
#include "db/store.h"

namespace fsdb {

class SqlStore : public Store {
 public:
  const std::string& path() const override { return location_; }
  int schemaVersion() const override { return schemaVersion_; }

  StoredObject create(const NewObject& object) override;
  StoredObject put(int64_t id, const NewObject& object, std::optional<int> ifVersion) override;
  StoredObject get(const std::string& kind, int64_t id, std::optional<int> version) const override;
  std::optional<StoredObject> find(const ObjectReference& reference) const override;
  std::vector<StoredObject> list(const ListQuery& query) const override;
  std::vector<StoredObject> named(const std::vector<std::string>& names,
                                  const std::vector<std::string>& kinds) const override;
  std::vector<StoredObject> described(const std::vector<std::string>& words, const std::vector<std::string>& kinds,
                                      int limit) const override;
  std::vector<int64_t> remove(const std::string& kind, int64_t id, bool cascade, std::optional<int> ifVersion) override;
  std::vector<BulkItemResult> createBatch(const std::vector<NewObject>& items, BulkMode mode) override;
  std::map<std::string, int64_t> counts() const override;
  std::vector<int64_t> dependents(int64_t id) const override;
  int64_t changeSeq() const override;
  ChangeFeed changesSince(int64_t seq) const override;
  std::vector<DescriptorCandidate> descriptorCandidates(const std::string& kind,
                                                        const DescriptorOverlap& test) const override;
  std::vector<DescriptorRange> descriptorRanges(const DescriptorOverlap& test) const override;
  std::vector<DescriptorCandidate> descriptorRangeRows(const std::string& kind, const DescriptorRange& range,
                                                       const DescriptorRangeRead& read) const override;
  std::vector<DescriptorCandidate> descriptorSupports(const std::string& descriptor,
                                                      const std::vector<int64_t>& ids) const override;
  int64_t lastObjectId() const override;
  std::vector<int64_t> pendingDescriptorIds(const std::string& kind) const override;
  std::vector<int64_t> objectIds(const std::string& kind) const override;
  std::vector<ObjectVersion> objectVersions(const std::string& kind) const override;
  std::vector<IndexedObject> indexedObjects(const std::string& kind, const std::vector<int64_t>& ids) const override;
  std::vector<DescriptorComponent> descriptorRows(int64_t id) const override;
  std::vector<PendingDescriptors> pendingDescriptors(int64_t afterId, int limit) const override;
  size_t replaceDescriptors(
      const std::vector<std::pair<PendingDescriptors, std::vector<DescriptorComponent>>>& refreshed) override;
  StoreStats stats() const override;
  std::optional<CachedEvaluation> cachedEvaluation(const std::string& key) const override;
  void storeEvaluation(int64_t objectId, const std::string& key, const CachedEvaluation& value) override;
  void readSnapshot(const std::function<void()>& body) const override;

 protected:
  // A connection on loan for one public call; returned to the pool on destruction. A read
  // (kRead) inside readSnapshot on this thread takes the snapshot's connection instead and gives
  // nothing back; kOwn (writes, and the snapshot itself) always takes a connection of its own.
  class Lease {
   public:
    enum class Use { kRead, kOwn };
    explicit Lease(const SqlStore& store, Use use = Use::kRead);
    ~Lease();
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    sql::Connection& operator*() const { return *connection_; }

   private:
    const SqlStore& store_;
    sql::Connection* connection_ = nullptr;
    bool shared_ = false;  // the snapshot's connection
  };

  explicit SqlStore(std::string location) : location_(std::move(location)) {}
  // Adds a pooled connection (open() adds poolSize of them; the first migrates).
  void addConnection(std::unique_ptr<sql::Connection> connection);
  void setSchemaVersion(int version) { schemaVersion_ = version; }
  void setMaxCacheBytes(std::uint64_t bytes) { maxCacheBytes_ = bytes; }
  // Called on a connection before it is lent (PostgreSQL: reconnect when the server dropped it).
  virtual void beforeUse(sql::Connection& connection) const {}

 private:
  std::string location_;
  int schemaVersion_ = 0;
  std::uint64_t maxCacheBytes_ = 0;  // StoreOptions::maxCacheBytes
  std::atomic<std::uint64_t> evictions_{0};
  mutable std::atomic<int> waiting_{0};  // Lease constructors waiting for a connection
  mutable std::mutex mutex_;
  mutable std::condition_variable available_;
  std::vector<std::unique_ptr<sql::Connection>> connections_;
  mutable std::vector<sql::Connection*> idle_;
};

}  // namespace fsdb
