// See db/store.h. Layout: the connection pool, then the write path (reference resolution, cycle
// check, version rows, edges, cache invalidation) shared by create, put and createBatch, then
// the reads.
#include "db/store.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <ctime>
#include <filesystem>
#include <mutex>

#include "db/descriptor_index.h"
#include "db/migrations.h"
#include "db/sqlite.h"
#include "geometry/core/error.h"

namespace fsdb {

namespace {

using sqlite::Connection;
using sqlite::Transaction;

// ISO 8601 UTC with milliseconds: "2026-11-22T10:00:00.123Z" (sorts as text in time order).
std::string isoNow() {
  auto now = std::chrono::system_clock::now();
  auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count();
  std::time_t seconds = static_cast<std::time_t>(ms / 1000);
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char text[32];
  size_t n = std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &utc);
  std::snprintf(text + n, sizeof text - n, ".%03dZ", static_cast<int>(ms % 1000));
  return text;
}

bool knownKind(const std::string& kind) {
  return kind == "part" || kind == "shape" || kind == "curve" || kind == "surface";
}

// "part 'bolt' (id 3)": how messages name an object.
std::string describe(const std::string& kind, const std::string& name, int64_t id) {
  return kind + " '" + name + "' (id " + std::to_string(id) + ")";
}

// The ids of the objects whose latest version reaches ?1 (its ancestors in refs; ?1 itself only
// through a cycle), as a subquery. UNION (not UNION ALL) makes the walk terminate whatever the graph.
#define FSDB_REACHING_SQL                                                 \
  "WITH RECURSIVE up(id) AS (SELECT parent_id FROM refs WHERE child_id = ?1" \
  " UNION SELECT refs.parent_id FROM refs JOIN up ON refs.child_id = up.id) SELECT id FROM up"

std::vector<int64_t> dependentsOf(Connection& connection, int64_t id) {
  auto statement = connection.prepare("SELECT id FROM (" FSDB_REACHING_SQL ") WHERE id != ?1 ORDER BY id");
  statement->bind(1, id);
  std::vector<int64_t> ids;
  while (statement->step()) ids.push_back(statement->columnInt(0));
  return ids;
}

struct ObjectRow {
  int64_t id = 0;
  std::string kind, name;
  int latestVersion = 0;
};

std::optional<ObjectRow> objectRow(Connection& connection, int64_t id) {
  auto statement = connection.prepare("SELECT kind, name, latest_version FROM objects WHERE id = ?1");
  statement->bind(1, id);
  if (!statement->step()) return std::nullopt;
  return ObjectRow{id, statement->columnText(0), statement->columnText(1),
                   static_cast<int>(statement->columnInt(2))};
}

std::optional<int64_t> idByName(Connection& connection, const std::string& kind,
                                const std::string& name) {
  auto statement = connection.prepare("SELECT id FROM objects WHERE kind = ?1 AND name = ?2");
  statement->bind(1, kind).bind(2, name);
  if (!statement->step()) return std::nullopt;
  return statement->columnInt(0);
}

// The live object a reference names, or nullopt.
std::optional<int64_t> resolve(Connection& connection, const ObjectReference& reference) {
  if (!reference.id) return idByName(connection, reference.kind, reference.name);
  auto row = objectRow(connection, *reference.id);
  if (!row || row->kind != reference.kind) return std::nullopt;
  return row->id;
}

std::vector<int64_t> resolveAll(Connection& connection, const std::vector<ObjectReference>& references) {
  std::vector<int64_t> ids;
  for (const auto& reference : references) {
    auto id = resolve(connection, reference);
    if (!id) {
      std::string what = reference.id ? std::to_string(*reference.id) : "'" + reference.name + "'";
      throw Error(errc::kUnknownReference, "unknown " + reference.kind + " " + what, reference.path);
    }
    ids.push_back(*id);
  }
  return ids;
}

// Refuses edges object -> child that would let `object` reach itself: the child is the object or
// reaches it through the current refs.
void checkCycles(Connection& connection, const ObjectRow& object,
                 const std::vector<ObjectReference>& references, const std::vector<int64_t>& children) {
  auto statement = connection.prepare(
      "WITH RECURSIVE down(id) AS (SELECT ?1"
      " UNION SELECT refs.child_id FROM refs JOIN down ON refs.parent_id = down.id)"
      " SELECT 1 FROM down WHERE id = ?2 LIMIT 1");
  for (size_t i = 0; i < children.size(); ++i) {
    statement->reset();
    statement->bind(1, children[i]).bind(2, object.id);
    if (!statement->step()) continue;
    auto child = objectRow(connection, children[i]);
    std::string through = child ? describe(child->kind, child->name, child->id) : "itself";
    throw Error(errc::kReferenceCycle,
                describe(object.kind, object.name, object.id) + " would contain itself through " +
                    through,
                references[i].path);
  }
}

// What a new version of `id` changes in everything that reaches it (`dependents`, from
// dependentsOf): their cached evaluations are dropped and their descriptor components marked
// pending, as are `id`'s own cached evaluations. One reaching walk serves both.
void invalidateDependents(Connection& connection, int64_t id, const std::vector<int64_t>& dependents) {
  auto statement = connection.prepare("DELETE FROM eval_cache WHERE object_id = ?1");
  statement->bind(1, id);
  statement->run();
  for (int64_t dependent : dependents) {
    statement->reset();
    statement->bind(1, dependent);
    statement->run();
    markDescriptorsPending(connection, dependent);
  }
}

// Writes version `version` of object `row` (whose objects row exists) with its normalised rows,
// and makes its edges those of `children`.
void writeVersion(Connection& connection, const ObjectRow& row, int version, const NewObject& object,
                  const std::vector<int64_t>& children, const std::string& now) {
  {
    auto statement = connection.prepare(
        "INSERT INTO versions (object_id, version, document, content_hash, created_at)"
        " VALUES (?1, ?2, ?3, ?4, ?5)");
    statement->bind(1, row.id).bind(2, version).bind(3, object.documentJson);
    statement->bind(4, object.contentHash).bind(5, now);
    statement->run();
  }
  {
    auto statement = connection.prepare(
        "INSERT INTO part_parameters (object_id, version, name, support_lo, core_lo, core_hi,"
        " support_hi) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
    for (const auto& p : object.parameters) {
      statement->reset();
      statement->bind(1, row.id).bind(2, version).bind(3, p.name).bind(4, p.supportLo);
      statement->bind(5, p.coreLo).bind(6, p.coreHi).bind(7, p.supportHi);
      statement->run();
    }
  }
  {
    auto statement = connection.prepare(
        "INSERT INTO csg_nodes (object_id, version, node, parent, position, kind, operator, ref_id,"
        " transform) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9)");
    for (const auto& node : object.nodes) {
      std::optional<int64_t> refId;
      if (node.refIndex >= 0) {
        if (static_cast<size_t>(node.refIndex) >= children.size())
          throw Error(errc::kInvalidDocument,
                      "node " + std::to_string(node.index) + " refers to reference " +
                          std::to_string(node.refIndex) + " of " + std::to_string(children.size()));
        refId = children[static_cast<size_t>(node.refIndex)];
      }
      statement->reset();
      statement->bind(1, row.id).bind(2, version).bind(3, node.index).bind(4, node.parent);
      statement->bind(5, node.position).bind(6, node.kind);
      if (node.operatorJson.empty()) statement->bindNull(7); else statement->bind(7, node.operatorJson);
      statement->bind(8, refId);
      if (node.transformJson.empty()) statement->bindNull(9); else statement->bind(9, node.transformJson);
      statement->run();
    }
  }
  {
    auto statement = connection.prepare("DELETE FROM refs WHERE parent_id = ?1");
    statement->bind(1, row.id);
    statement->run();
  }
  {
    auto statement = connection.prepare("INSERT OR IGNORE INTO refs (parent_id, child_id) VALUES (?1, ?2)");
    for (int64_t child : children) {
      statement->reset();
      statement->bind(1, row.id).bind(2, child);
      statement->run();
    }
  }
  writeDescriptorRows(connection, row.id, row.kind, object.descriptors);
  // Rows computed from referenced documents the caller read before this transaction may already
  // be stale: the server recomputes them after the commit (db/store.h, the descriptor index).
  if (object.references.empty()) clearDescriptorsPending(connection, row.id);
  else markDescriptorsPending(connection, row.id);
}

void checkKind(const std::string& kind) {
  if (!knownKind(kind)) throw Error(errc::kInvalidDocument, "unknown kind '" + kind + "'", "kind");
}

std::vector<int64_t> sortedUnique(std::vector<int64_t> ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

// The record of a write: what get() would return for the new version.
StoredObject written(const ObjectRow& row, int version, const NewObject& object,
                     const std::vector<int64_t>& children, const std::string& now) {
  return StoredObject{row.id, row.kind, row.name, version, version, object.documentJson,
                      object.contentHash, now, sortedUnique(children)};
}

// create inside the caller's transaction.
StoredObject createIn(Connection& connection, const NewObject& object) {
  checkKind(object.kind);
  if (auto existing = idByName(connection, object.kind, object.name))
    throw Error(errc::kConflict,
                describe(object.kind, object.name, *existing) + " already exists", "name");
  // A new object cannot close a cycle: nothing refers to it yet, and it cannot refer to itself
  // because its id and name are not in the database until the insert below.
  auto children = resolveAll(connection, object.references);
  std::string now = isoNow();
  {
    auto statement = connection.prepare(
        "INSERT INTO objects (kind, name, latest_version) VALUES (?1, ?2, 1)");
    statement->bind(1, object.kind).bind(2, object.name);
    statement->run();
  }
  ObjectRow row{connection.lastInsertId(), object.kind, object.name, 1};
  writeVersion(connection, row, 1, object, children, now);
  return written(row, 1, object, children, now);
}

// put inside the caller's transaction.
StoredObject putIn(Connection& connection, int64_t id, const NewObject& object) {
  auto row = objectRow(connection, id);
  if (!row || row->kind != object.kind)
    throw Error(errc::kNotFound, object.kind + " " + std::to_string(id) + " not found");
  if (row->name != object.name)
    throw Error(errc::kConflict,
                "cannot rename " + describe(row->kind, row->name, id) + " to '" + object.name +
                    "' by a new version",
                "name");
  auto children = resolveAll(connection, object.references);
  checkCycles(connection, *row, object.references, children);
  // The objects that reach this one are its ancestors in refs, which this write does not change
  // (it replaces only the object's own outgoing edges), so the order against writeVersion is free.
  invalidateDependents(connection, id, dependentsOf(connection, id));
  std::string now = isoNow();
  int version = row->latestVersion + 1;
  {
    auto statement = connection.prepare(
        "UPDATE objects SET latest_version = ?2 WHERE id = ?1");
    statement->bind(1, id).bind(2, version);
    statement->run();
  }
  writeVersion(connection, *row, version, object, children, now);
  return written(*row, version, object, children, now);
}

// createBatch's kUpsert item inside the caller's transaction.
StoredObject upsertIn(Connection& connection, const NewObject& object) {
  checkKind(object.kind);
  auto id = idByName(connection, object.kind, object.name);
  if (!id) return createIn(connection, object);
  auto statement = connection.prepare(
      "SELECT v.version, v.content_hash FROM objects o JOIN versions v"
      " ON v.object_id = o.id AND v.version = o.latest_version WHERE o.id = ?1");
  statement->bind(1, *id);
  if (statement->step() && statement->columnText(1) == object.contentHash) {
    StoredObject same;
    same.id = *id;
    same.version = same.latestVersion = static_cast<int>(statement->columnInt(0));
    return same;
  }
  return putIn(connection, *id, object);
}

std::vector<int64_t> referencesOf(Connection& connection, int64_t id) {
  auto statement = connection.prepare("SELECT child_id FROM refs WHERE parent_id = ?1 ORDER BY child_id");
  statement->bind(1, id);
  std::vector<int64_t> ids;
  while (statement->step()) ids.push_back(statement->columnInt(0));
  return ids;
}

// Columns: o.id, o.kind, o.name, o.latest_version, v.version, v.document, v.content_hash,
// v.created_at. References are filled for the latest version (refs holds only its edges).
StoredObject readObject(sqlite::Statement& row) {
  StoredObject object;
  object.id = row.columnInt(0);
  object.kind = row.columnText(1);
  object.name = row.columnText(2);
  object.latestVersion = static_cast<int>(row.columnInt(3));
  object.version = static_cast<int>(row.columnInt(4));
  object.documentJson = row.columnText(5);
  object.contentHash = row.columnText(6);
  object.createdAt = row.columnText(7);
  return object;
}

constexpr const char* kObjectColumns =
    "SELECT o.id, o.kind, o.name, o.latest_version, v.version, v.document, v.content_hash,"
    " v.created_at FROM objects o JOIN versions v ON v.object_id = o.id";

// The object of `kind` with this id (or, without one, this name) at `version` (else the latest).
std::optional<StoredObject> loadObject(Connection& connection, const std::string& kind, std::optional<int64_t> id,
                                       const std::string& name, std::optional<int> version) {
  std::optional<StoredObject> object;
  {
    // Two statements, not one with OR, so each is a plain index lookup.
    auto statement = connection.prepare(std::string(kObjectColumns) +
                                        " AND v.version = COALESCE(?3, o.latest_version) WHERE o.kind = ?2 AND " +
                                        (id ? "o.id = ?1" : "o.name = ?1"));
    if (id) statement->bind(1, *id); else statement->bind(1, name);
    statement->bind(2, kind);
    statement->bind(3, version ? std::optional<int64_t>(*version) : std::nullopt);
    if (statement->step()) object = readObject(*statement);
  }
  if (object && object->version == object->latestVersion)
    object->references = referencesOf(connection, object->id);
  return object;
}

}  // namespace

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
