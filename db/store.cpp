// See db/store.h. Layout: the connection pool, the writes, the reads, the descriptor index. The
// rows of one object (reference resolution, cycle check, versions, edges, cache invalidation) are
// db/object_rows.cpp.
#include "db/store.h"

#include <algorithm>
#include <condition_variable>
#include <filesystem>
#include <mutex>

#include "db/descriptor_index.h"
#include "db/migrations.h"
#include "db/object_rows.h"
#include "db/sqlite.h"
#include "geometry/core/error.h"

namespace fsdb {

using sqlite::Connection;
using sqlite::Transaction;
using namespace object_rows;

// --- Impl: the connection pool ------------------------------------------------------------------

class Store::Impl {
 public:
  std::string path;
  int schemaVersion = 0;
  std::mutex mutex;
  std::condition_variable available;
  std::vector<std::unique_ptr<Connection>> connections;
  std::vector<Connection*> idle;

  // A connection on loan for one public call; returned to the pool on destruction.
  class Lease {
   public:
    explicit Lease(Impl& impl) : impl_(impl) {
      std::unique_lock<std::mutex> lock(impl_.mutex);
      impl_.available.wait(lock, [&] { return !impl_.idle.empty(); });
      connection_ = impl_.idle.back();
      impl_.idle.pop_back();
    }
    ~Lease() {
      {
        std::lock_guard<std::mutex> lock(impl_.mutex);
        impl_.idle.push_back(connection_);
      }
      impl_.available.notify_one();
    }
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    Connection& operator*() const { return *connection_; }

   private:
    Impl& impl_;
    Connection* connection_ = nullptr;
  };
};

Store::Store(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Store::~Store() = default;

std::unique_ptr<Store> Store::open(const std::string& path, const StoreOptions& options) {
  if (path.empty() || path == ":memory:" || path.rfind("file:", 0) == 0)
    throw Error(errc::kStorage, "store path '" + path + "' is not a file path");
  std::error_code error;
  auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, error);
  if (error)
    throw Error(errc::kStorage, "cannot create the directory of '" + path + "': " + error.message());
  auto impl = std::make_unique<Impl>();
  impl->path = path;
  sqlite::ConnectionOptions connectionOptions{options.busyTimeoutMs, options.synchronousFull};
  // The first connection migrates before the others open, so none of them sees an old schema.
  for (int i = 0; i < std::max(1, options.poolSize); ++i) {
    impl->connections.push_back(std::make_unique<Connection>(path, connectionOptions));
    if (i == 0) impl->schemaVersion = applyMigrations(*impl->connections[0], embeddedMigrations());
    impl->idle.push_back(impl->connections.back().get());
  }
  return std::unique_ptr<Store>(new Store(std::move(impl)));
}

const std::string& Store::path() const { return impl_->path; }
int Store::schemaVersion() const { return impl_->schemaVersion; }

// --- Writes -------------------------------------------------------------------------------------

StoredObject Store::create(const NewObject& object) {
  Impl::Lease connection(*impl_);
  Transaction transaction(*connection);
  auto result = createIn(*connection, object);
  transaction.commit();
  return result;
}

StoredObject Store::put(int64_t id, const NewObject& object) {
  Impl::Lease connection(*impl_);
  Transaction transaction(*connection);
  auto result = putIn(*connection, id, object);
  transaction.commit();
  return result;
}

std::vector<int64_t> Store::remove(const std::string& kind, int64_t id, bool cascade) {
  Impl::Lease connection(*impl_);
  Transaction transaction(*connection);
  auto row = objectRow(*connection, id);
  if (!row || row->kind != kind) throw Error(errc::kNotFound, kind + " " + std::to_string(id) + " not found");
  if (!cascade) {
    auto statement = (*connection).prepare(
        "SELECT o.id, o.kind, o.name, (SELECT COUNT(*) FROM refs WHERE child_id = ?1)"
        " FROM refs JOIN objects o ON o.id = refs.parent_id WHERE refs.child_id = ?1"
        " ORDER BY o.id LIMIT 5");
    statement->bind(1, id);
    std::string users;
    int64_t total = 0;
    while (statement->step()) {
      users += (users.empty() ? "" : ", ") +
               describe(statement->columnText(1), statement->columnText(2), statement->columnInt(0));
      total = statement->columnInt(3);
    }
    if (total > 0) {
      if (total > 5) users += " and " + std::to_string(total - 5) + " more";
      throw Error(errc::kInUse, describe(row->kind, row->name, id) + " is used by " + users);
    }
  }
  // One statement for all: refs.child_id has no ON DELETE, and SQLite checks foreign keys at the
  // end of a statement, when the parents are gone with their children. Versions, normalised rows
  // and cache rows go by ON DELETE CASCADE. RETURNING names what went, so the walk runs once.
  auto statement = (*connection).prepare("DELETE FROM objects WHERE id = ?1 OR id IN (" FSDB_REACHING_SQL
                                         ") RETURNING id");
  statement->bind(1, id);
  std::vector<int64_t> removed;
  while (statement->step())
    if (statement->columnInt(0) != id) removed.push_back(statement->columnInt(0));
  std::sort(removed.begin(), removed.end());
  removed.insert(removed.begin(), id);
  transaction.commit();
  return removed;
}

std::vector<BulkItemResult> Store::createBatch(const std::vector<NewObject>& items, BulkMode mode) {
  Impl::Lease connection(*impl_);
  Transaction transaction(*connection);
  std::vector<BulkItemResult> results;
  results.reserve(items.size());
  for (const auto& item : items) {
    BulkItemResult result;
    sqlite::Savepoint savepoint(*connection, "bulk_item");
    try {
      auto stored = mode == BulkMode::kCreate ? createIn(*connection, item) : upsertIn(*connection, item);
      savepoint.release();
      result.id = stored.id;
      result.version = stored.version;
    } catch (const Error& e) {
      // An I/O or disk-full error may have ended the whole transaction: then nothing of the batch
      // can commit, and the batch fails as a whole.
      if (!(*connection).inTransaction()) throw;
      savepoint.rollback();
      result.errorCode = e.code();
      result.errorMessage = e.what();
      result.errorPath = e.path();
    }
    results.push_back(std::move(result));
  }
  transaction.commit();
  return results;
}

void Store::storeEvaluation(int64_t objectId, const std::string& key, const CachedEvaluation& value) {
  Impl::Lease connection(*impl_);
  Transaction transaction(*connection);
  if (!objectRow(*connection, objectId))
    throw Error(errc::kNotFound, "object " + std::to_string(objectId) + " not found");
  auto statement = (*connection).prepare(
      "INSERT OR REPLACE INTO eval_cache (key, object_id, result, vdb) VALUES (?1, ?2, ?3, ?4)");
  statement->bind(1, key).bind(2, objectId).bind(3, value.resultJson);
  if (value.vdb.empty()) statement->bindNull(4); else statement->bindBlob(4, value.vdb);
  statement->run();
  transaction.commit();
}

void Store::checkpoint() {
  Impl::Lease connection(*impl_);
  auto statement = (*connection).prepare("PRAGMA wal_checkpoint(TRUNCATE)");
  statement->run();
}

// --- Reads --------------------------------------------------------------------------------------
// Each read that runs more than one statement does so in one deferred transaction, so it sees
// one snapshot even while a writer commits beside it.

StoredObject Store::get(const std::string& kind, int64_t id, std::optional<int> version) const {
  Impl::Lease connection(*impl_);
  Transaction transaction(*connection, Transaction::Mode::kDeferred);
  if (auto object = loadObject(*connection, kind, id, "", version)) return *object;
  auto row = objectRow(*connection, id);
  if (row && row->kind == kind && version)
    throw Error(errc::kNotFound, describe(kind, row->name, id) + " has no version " +
                                     std::to_string(*version) + " (latest is " +
                                     std::to_string(row->latestVersion) + ")");
  throw Error(errc::kNotFound, kind + " " + std::to_string(id) + " not found");
}

std::optional<StoredObject> Store::find(const ObjectReference& reference) const {
  Impl::Lease connection(*impl_);
  Transaction transaction(*connection, Transaction::Mode::kDeferred);
  return loadObject(*connection, reference.kind, reference.id, reference.name, std::nullopt);
}

std::vector<StoredObject> Store::list(const ListQuery& query) const {
  Impl::Lease connection(*impl_);
  Transaction transaction(*connection, Transaction::Mode::kDeferred);
  std::vector<StoredObject> objects;
  {
    auto statement = (*connection).prepare(
        std::string(kObjectColumns) +
        " AND v.version = COALESCE(?3, o.latest_version)"
        " WHERE o.kind = ?1 AND (?2 IS NULL OR o.name = ?2) AND o.id > ?4 ORDER BY o.id LIMIT ?5");
    statement->bind(1, query.kind);
    if (query.name) statement->bind(2, *query.name); else statement->bindNull(2);
    // A version only selects with a name (one object); otherwise every object's latest.
    if (query.name && query.version) statement->bind(3, *query.version); else statement->bindNull(3);
    statement->bind(4, query.afterId).bind(5, std::max(0, query.limit));
    while (statement->step()) objects.push_back(readObject(*statement));
  }
  for (auto& object : objects)
    if (object.version == object.latestVersion) object.references = referencesOf(*connection, object.id);
  return objects;
}

std::map<std::string, int64_t> Store::counts() const {
  Impl::Lease connection(*impl_);
  auto statement = (*connection).prepare("SELECT kind, COUNT(*) FROM objects GROUP BY kind");
  std::map<std::string, int64_t> counts;
  while (statement->step()) counts[statement->columnText(0)] = statement->columnInt(1);
  return counts;
}

std::vector<int64_t> Store::dependents(int64_t id) const {
  Impl::Lease connection(*impl_);
  return dependentsOf(*connection, id);
}

// --- The descriptor index -----------------------------------------------------------------------

std::vector<DescriptorCandidate> Store::descriptorCandidates(const std::string& kind,
                                                            const DescriptorOverlap& test) const {
  Impl::Lease connection(*impl_);
  Transaction transaction(*connection, Transaction::Mode::kDeferred);
  return descriptorCandidatesIn(*connection, kind, test);
}

std::vector<DescriptorRange> Store::descriptorRanges(const DescriptorOverlap& test) const {
  Impl::Lease connection(*impl_);
  return descriptorRangesIn(*connection, test);
}

std::vector<DescriptorCandidate> Store::descriptorRangeRows(const std::string& kind, const DescriptorRange& range) const {
  Impl::Lease connection(*impl_);
  std::vector<DescriptorCandidate> rows;
  descriptorRangeRowsIn(*connection, kind, range, rows);
  return rows;
}

std::vector<int64_t> Store::pendingDescriptorIds(const std::string& kind) const {
  Impl::Lease connection(*impl_);
  return pendingDescriptorIdsIn(*connection, kind);
}

std::vector<int64_t> Store::objectIds(const std::string& kind) const {
  Impl::Lease connection(*impl_);
  auto statement = (*connection).prepare("SELECT id FROM objects WHERE kind = ?1 ORDER BY id");
  statement->bind(1, kind);
  std::vector<int64_t> ids;
  while (statement->step()) ids.push_back(statement->columnInt(0));
  return ids;
}

std::vector<ObjectVersion> Store::objectVersions(const std::string& kind) const {
  Impl::Lease connection(*impl_);
  auto statement = (*connection).prepare("SELECT id, name, latest_version FROM objects WHERE kind = ?1 ORDER BY id");
  statement->bind(1, kind);
  std::vector<ObjectVersion> out;
  while (statement->step())
    out.push_back({statement->columnInt(0), statement->columnText(1), static_cast<int>(statement->columnInt(2))});
  return out;
}

std::vector<IndexedObject> Store::indexedObjects(const std::string& kind, const std::vector<int64_t>& ids) const {
  Impl::Lease connection(*impl_);
  Transaction transaction(*connection, Transaction::Mode::kDeferred);
  auto statement = (*connection).prepare(
      "SELECT o.name, p.object_id IS NOT NULL, v.component, v.descriptor_values FROM objects o"
      " LEFT JOIN descriptor_pending p ON p.object_id = o.id LEFT JOIN descriptor_values v ON v.object_id = o.id"
      " WHERE o.id = ?1 AND o.kind = ?2 ORDER BY v.component");
  std::vector<IndexedObject> objects;
  objects.reserve(ids.size());
  for (int64_t id : ids) {
    statement->reset();
    statement->bind(1, id).bind(2, kind);
    IndexedObject object;
    object.id = id;
    bool found = false;
    while (statement->step()) {
      if (!found) {
        object.name = statement->columnText(0);
        object.pending = statement->columnInt(1) != 0;
        found = true;
      }
      if (!statement->isNull(2))
        object.components.emplace_back(static_cast<int>(statement->columnInt(2)), statement->columnBlob(3));
    }
    if (found) objects.push_back(std::move(object));
  }
  return objects;
}

std::vector<DescriptorComponent> Store::descriptorRows(int64_t id) const {
  Impl::Lease connection(*impl_);
  Transaction transaction(*connection, Transaction::Mode::kDeferred);
  std::vector<DescriptorComponent> components;
  {
    auto statement = (*connection).prepare(
        "SELECT component, descriptor_values FROM descriptor_values WHERE object_id = ?1 ORDER BY component");
    statement->bind(1, id);
    while (statement->step()) {
      DescriptorComponent component;
      component.component = static_cast<int>(statement->columnInt(0));
      component.values = statement->columnBlob(1);
      components.push_back(std::move(component));
    }
  }
  auto statement = (*connection).prepare(
      "SELECT component, descriptor, support_lo, core_lo, core_hi, support_hi FROM descriptor_index"
      " WHERE object_id = ?1 ORDER BY component, descriptor");
  statement->bind(1, id);
  while (statement->step()) {
    const int c = static_cast<int>(statement->columnInt(0));
    auto it = std::find_if(components.begin(), components.end(),
                           [c](const DescriptorComponent& d) { return d.component == c; });
    if (it == components.end()) it = components.insert(components.end(), DescriptorComponent{c, {}, {}});
    it->spans.push_back({statement->columnText(1), statement->columnDouble(2), statement->columnDouble(3),
                         statement->columnDouble(4), statement->columnDouble(5)});
  }
  return components;
}

std::vector<PendingDescriptors> Store::pendingDescriptors(int64_t afterId, int limit) const {
  Impl::Lease connection(*impl_);
  auto statement = (*connection).prepare(
      "SELECT p.object_id, o.kind, p.generation FROM descriptor_pending p JOIN objects o ON o.id = p.object_id"
      " WHERE p.object_id > ?1 ORDER BY p.object_id LIMIT ?2");
  statement->bind(1, afterId).bind(2, std::max(0, limit));
  std::vector<PendingDescriptors> pending;
  while (statement->step())
    pending.push_back({statement->columnInt(0), statement->columnText(1), statement->columnInt(2)});
  return pending;
}

size_t Store::replaceDescriptors(
    const std::vector<std::pair<PendingDescriptors, std::vector<DescriptorComponent>>>& refreshed) {
  Impl::Lease connection(*impl_);
  Transaction transaction(*connection);
  size_t replaced = 0;
  for (const auto& [pending, components] : refreshed) {
    {
      auto statement = (*connection).prepare("SELECT generation FROM descriptor_pending WHERE object_id = ?1");
      statement->bind(1, pending.id);
      if (!statement->step() || statement->columnInt(0) != pending.generation) continue;
    }
    auto row = objectRow(*connection, pending.id);
    if (!row) continue;
    writeDescriptorRows(*connection, pending.id, row->kind, components);
    clearDescriptorsPending(*connection, pending.id);
    ++replaced;
  }
  transaction.commit();
  return replaced;
}

std::optional<CachedEvaluation> Store::cachedEvaluation(const std::string& key) const {
  Impl::Lease connection(*impl_);
  auto statement = (*connection).prepare("SELECT result, vdb FROM eval_cache WHERE key = ?1");
  statement->bind(1, key);
  if (!statement->step()) return std::nullopt;
  return CachedEvaluation{statement->columnText(0), statement->columnBlob(1)};
}

std::string Store::integrityCheck() const {
  Impl::Lease connection(*impl_);
  auto statement = (*connection).prepare("PRAGMA integrity_check");
  return statement->step() ? statement->columnText(0) : "no result";
}

}  // namespace fsdb
