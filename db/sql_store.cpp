// See db/sql_store.h. Layout: the connection pool, the writes, the reads, the change log, the
// descriptor index. The rows of one object (reference resolution, cycle check, versions, edges,
// cache invalidation, the change log) are db/object_rows.cpp.
#include "db/sql_store.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <unordered_map>

#include "db/descriptor_index.h"
#include "db/object_rows.h"
#include "geometry/core/error.h"

namespace fsdb {

using sql::Transaction;
using namespace object_rows;

// --- The connection pool ------------------------------------------------------------------------

namespace {

// The connection of this thread's readSnapshot, and its store (one at a time per thread).
struct SnapshotPin {
  const SqlStore* store = nullptr;
  sql::Connection* connection = nullptr;
};
thread_local SnapshotPin tSnapshot;

}  // namespace

SqlStore::Lease::Lease(const SqlStore& store, Use use) : store_(store) {
  if (use == Use::kRead && tSnapshot.store == &store_) {
    connection_ = tSnapshot.connection;
    shared_ = true;
    return;
  }
  {
    std::unique_lock<std::mutex> lock(store_.mutex_);
    ++store_.waiting_;
    store_.available_.wait(lock, [&] { return !store_.idle_.empty(); });
    --store_.waiting_;
    connection_ = store_.idle_.back();
    store_.idle_.pop_back();
  }
  try {
    store_.beforeUse(*connection_);
  } catch (...) {
    {
      std::lock_guard<std::mutex> lock(store_.mutex_);
      store_.idle_.push_back(connection_);
    }
    store_.available_.notify_one();
    throw;
  }
}

SqlStore::Lease::~Lease() {
  if (shared_) return;
  {
    std::lock_guard<std::mutex> lock(store_.mutex_);
    store_.idle_.push_back(connection_);
  }
  store_.available_.notify_one();
}

void SqlStore::readSnapshot(const std::function<void()>& body) const {
  if (tSnapshot.store == this) return body();  // nested: the outer snapshot
  Lease connection(*this, Lease::Use::kOwn);
  Transaction transaction(*connection, Transaction::Mode::kRead);
  const SnapshotPin outer = tSnapshot;  // another store's snapshot, restored after
  struct Restore {
    SnapshotPin outer;
    ~Restore() { tSnapshot = outer; }
  } restore{outer};
  tSnapshot = {this, &*connection};
  body();
  transaction.commit();
}

void SqlStore::addConnection(std::unique_ptr<sql::Connection> connection) {
  std::lock_guard<std::mutex> lock(mutex_);
  idle_.push_back(connection.get());
  connections_.push_back(std::move(connection));
}

// --- Writes -------------------------------------------------------------------------------------

StoredObject SqlStore::create(const NewObject& object) {
  Lease connection(*this, Lease::Use::kOwn);
  Transaction transaction(*connection);
  auto result = createIn(*connection, object);
  transaction.commit();
  return result;
}

StoredObject SqlStore::put(int64_t id, const NewObject& object, std::optional<int> ifVersion) {
  Lease connection(*this, Lease::Use::kOwn);
  Transaction transaction(*connection);
  auto result = putIn(*connection, id, object, ifVersion);
  transaction.commit();
  return result;
}

std::vector<int64_t> SqlStore::remove(const std::string& kind, int64_t id, bool cascade, std::optional<int> ifVersion) {
  Lease connection(*this, Lease::Use::kOwn);
  Transaction transaction(*connection);
  auto row = objectRow(*connection, id);
  if (!row || row->kind != kind) throw Error(errc::kNotFound, kind + " " + std::to_string(id) + " not found");
  checkVersion(*row, ifVersion);
  if (!cascade) {
    auto statement = (*connection)
                         .prepare(
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
  // One statement for all: refs.child_id has no ON DELETE (NO ACTION), and both engines check
  // such foreign keys at the end of a statement, when the parents are gone with their children. Versions, normalised
  // rows and cache rows go by ON DELETE CASCADE. RETURNING names what went, so the walk runs once.
  auto statement =
      (*connection).prepare("DELETE FROM objects WHERE id = ?1 OR id IN (" FSDB_REACHING_SQL ") RETURNING id");
  statement->bind(1, id);
  std::vector<int64_t> removed;
  while (statement->step())
    if (statement->columnInt(0) != id) removed.push_back(statement->columnInt(0));
  std::sort(removed.begin(), removed.end());
  removed.insert(removed.begin(), id);
  for (int64_t gone : removed) logChange(*connection, gone);
  transaction.commit();
  return removed;
}

std::vector<BulkItemResult> SqlStore::createBatch(const std::vector<NewObject>& items, BulkMode mode) {
  Lease connection(*this, Lease::Use::kOwn);
  Transaction transaction(*connection);
  // Read before the batch writes, so every pair is committed and stays (db/descriptor_index.h).
  const DescriptorClasses present = descriptorClassesIn(*connection);
  std::vector<BulkItemResult> results;
  results.reserve(items.size());
  for (const auto& item : items) {
    BulkItemResult result;
    sql::Savepoint savepoint(*connection, "bulk_item");
    try {
      auto stored =
          mode == BulkMode::kCreate ? createIn(*connection, item, &present) : upsertIn(*connection, item, &present);
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

namespace {

int64_t nowMs() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// A read refreshes its entry's `used` at most this often: a hit is a read, not a write each time.
constexpr int64_t kTouchEveryMs = 10000;

}  // namespace

void SqlStore::storeEvaluation(int64_t objectId, const std::string& key, const CachedEvaluation& value) {
  const std::uint64_t bytes = value.resultJson.size() + value.vdb.size();
  if (maxCacheBytes_ > 0 && bytes > maxCacheBytes_) return;  // it alone would not fit
  Lease connection(*this, Lease::Use::kOwn);
  Transaction transaction(*connection);
  if (!objectRow(*connection, objectId))
    throw Error(errc::kNotFound, "object " + std::to_string(objectId) + " not found");
  auto statement =
      (*connection)
          .prepare(
              "INSERT INTO eval_cache (key, object_id, result, vdb, bytes, used) VALUES (?1, ?2, ?3, ?4, ?5, ?6)"
              " ON CONFLICT (key) DO UPDATE SET object_id = excluded.object_id, result = excluded.result,"
              " vdb = excluded.vdb, bytes = excluded.bytes, used = excluded.used");
  statement->bind(1, key).bind(2, objectId).bind(3, value.resultJson);
  if (value.vdb.empty()) statement->bindNull(4);
  else statement->bindBlob(4, value.vdb);
  statement->bind(5, static_cast<int64_t>(bytes)).bind(6, nowMs());
  statement->run();
  if (maxCacheBytes_ > 0) {
    // Least recently used first out, until the entries fit (the new one is the most recent).
    auto total = (*connection).prepare("SELECT COALESCE(SUM(bytes), 0) FROM eval_cache");
    total->step();
    int64_t excess = total->columnInt(0) - static_cast<int64_t>(maxCacheBytes_);
    if (excess > 0) {
      auto oldest = (*connection).prepare("SELECT key, bytes FROM eval_cache WHERE key <> ?1 ORDER BY used, key");
      oldest->bind(1, key);
      std::vector<std::string> evicted;
      while (excess > 0 && oldest->step()) {
        evicted.push_back(oldest->columnText(0));
        excess -= oldest->columnInt(1);
      }
      auto remove = (*connection).prepare("DELETE FROM eval_cache WHERE key = ?1");
      for (const std::string& k : evicted) {
        remove->reset();
        remove->bind(1, k).run();
      }
      evictions_ += evicted.size();
    }
  }
  transaction.commit();
}

// --- Reads --------------------------------------------------------------------------------------
// Each read that runs more than one statement does so in one deferred transaction, so it sees
// one snapshot even while a writer commits beside it.

StoredObject SqlStore::get(const std::string& kind, int64_t id, std::optional<int> version) const {
  Lease connection(*this);
  // One statement (its own snapshot): no transaction to begin and end.
  if (auto object = loadObject(*connection, kind, id, "", version)) return *object;
  // Not there: why, for the message (a write in between can only make it more precise).
  auto row = objectRow(*connection, id);
  if (row && row->kind == kind && version)
    throw Error(errc::kNotFound, describe(kind, row->name, id) + " has no version " + std::to_string(*version) +
                                     " (latest is " + std::to_string(row->latestVersion) + ")");
  throw Error(errc::kNotFound, kind + " " + std::to_string(id) + " not found");
}

std::optional<StoredObject> SqlStore::find(const ObjectReference& reference) const {
  Lease connection(*this);
  return loadObject(*connection, reference.kind, reference.id, reference.name, std::nullopt);
}

std::vector<StoredObject> SqlStore::list(const ListQuery& query) const {
  Lease connection(*this);
  // One statement (references included): its own snapshot, no transaction around it.
  auto statement = (*connection)
                       .prepare(objectColumnsSql((*connection).dialect()) +
                                " AND v.version = COALESCE(?3, o.latest_version) WHERE o.kind = ?1 AND (CAST(?2 AS "
                                "TEXT) IS NULL OR o.name = ?2) AND o.id > ?4 ORDER BY o.id LIMIT ?5");
  statement->bind(1, query.kind);
  if (query.name) statement->bind(2, *query.name);
  else statement->bindNull(2);
  // A version only selects with a name (one object); otherwise every object's latest.
  if (query.name && query.version) statement->bind(3, *query.version);
  else statement->bindNull(3);
  statement->bind(4, query.afterId).bind(5, std::max(0, query.limit));
  std::vector<StoredObject> objects;
  while (statement->step()) objects.push_back(readObject(*statement));
  return objects;
}

std::vector<StoredObject> SqlStore::named(const std::vector<std::string>& names,
                                          const std::vector<std::string>& kinds) const {
  constexpr size_t kKinds = 8;
  if (names.size() > kMaxNamedLookups || kinds.size() > kKinds)
    throw Error(errc::kInvalidParameter, "at most " + std::to_string(kMaxNamedLookups) + " names and " +
                                             std::to_string(kKinds) + " kinds a lookup", "name");
  if (names.empty() || kinds.empty()) return {};
  Lease connection(*this);
  // Fixed placeholder counts (the shortest name and the last kind repeated to fill them): one
  // prepared text for the few spellings of a search-box text, one for the longer lists of near
  // spellings. The shortest, not the last: a text's last spellings join all its words, and 256
  // copies of a 5 MB word were over PostgreSQL's 1 GB message limit.
  constexpr size_t kFewNames = 16;
  const size_t shortest = static_cast<size_t>(
      std::min_element(names.begin(), names.end(),
                       [](const std::string& a, const std::string& b) { return a.size() < b.size(); }) -
      names.begin());
  const size_t slots = names.size() <= kFewNames ? kFewNames : kMaxNamedLookups;
  auto statement = (*connection)
                       .prepare(objectColumnsSql((*connection).dialect()) +
                                " AND v.version = o.latest_version WHERE o.kind IN (" + sql::listPlaceholders(1, static_cast<int>(kKinds)) +
                                ") AND o.name IN (" + sql::listPlaceholders(static_cast<int>(1 + kKinds), static_cast<int>(slots)) +
                                ") ORDER BY o.id");
  for (size_t i = 0; i < kKinds; ++i) statement->bind(static_cast<int>(1 + i), kinds[std::min(i, kinds.size() - 1)]);
  for (size_t i = 0; i < slots; ++i)
    statement->bind(static_cast<int>(1 + kKinds + i), names[i < names.size() ? i : shortest]);
  std::vector<StoredObject> objects;
  while (statement->step()) objects.push_back(readObject(*statement));
  return objects;
}

std::vector<StoredObject> SqlStore::described(const std::vector<std::string>& words,
                                              const std::vector<std::string>& kinds, int limit) const {
  if (words.size() > kMaxTextWords)
    throw Error(errc::kInvalidParameter, "at most " + std::to_string(kMaxTextWords) + " words a text search", "text");
  if (words.empty() || kinds.empty() || limit <= 0) return {};
  Lease connection(*this);
  const bool sqlite = (*connection).dialect() == sql::Dialect::kSqlite;
  // FTS5: each run of letters and digits of a word a quoted term of its own, so that no word is
  // read as an operator (AND, NOT, NEAR, a column filter) and none is a phrase ("2.5" is 2 and 5:
  // the table keeps no positions); PostgreSQL's plainto_tsquery takes plain text.
  std::string query;
  for (const std::string& w : words) {
    if (!sqlite) {
      query += (query.empty() ? "" : " ") + w;
      continue;
    }
    std::string term;
    const auto flush = [&] {
      if (!term.empty()) query += (query.empty() ? "\"" : " \"") + term + "\"";
      term.clear();
    };
    for (char c : w) {
      if (std::isalnum(static_cast<unsigned char>(c)) || static_cast<unsigned char>(c) >= 0x80) term += c;
      else flush();
    }
    flush();
  }
  if (query.empty()) return {};
  const std::string matches =
      sqlite ? "SELECT rowid AS id, 0 AS r FROM object_text WHERE object_text MATCH ?1"
             : "SELECT object_id AS id, -ts_rank(words, plainto_tsquery('english', ?1)) AS r FROM object_text"
               " WHERE words @@ plainto_tsquery('english', ?1)";
  std::vector<std::string> kindList = kinds;
  kindList.resize(2, kinds.back());  // two placeholders: the last kind repeated
  auto statement = (*connection)
                       .prepare("WITH m AS (" + matches + ") " + objectColumnsSql((*connection).dialect()) +
                                " AND v.version = o.latest_version JOIN m ON m.id = o.id WHERE o.kind IN (?2, ?3)"
                                " ORDER BY m.r, o.id LIMIT ?4");
  statement->bind(1, query).bind(2, kindList[0]).bind(3, kindList[1]).bind(4, std::min(limit, 1000));
  std::vector<StoredObject> objects;
  while (statement->step()) objects.push_back(readObject(*statement));
  return objects;
}

std::map<std::string, int64_t> SqlStore::counts() const {
  Lease connection(*this);
  auto statement = (*connection).prepare("SELECT kind, COUNT(*) FROM objects GROUP BY kind");
  std::map<std::string, int64_t> counts;
  while (statement->step()) counts[statement->columnText(0)] = statement->columnInt(1);
  return counts;
}

std::vector<int64_t> SqlStore::dependents(int64_t id) const {
  Lease connection(*this);
  return dependentsOf(*connection, id);
}

// --- The change log -----------------------------------------------------------------------------

int64_t SqlStore::changeSeq() const {
  Lease connection(*this);
  auto statement = (*connection).prepare("SELECT COALESCE(MAX(seq), 0) FROM change_log");
  return statement->step() ? statement->columnInt(0) : 0;
}

ChangeFeed SqlStore::changesSince(int64_t seq) const {
  Lease connection(*this);
  Transaction transaction(*connection, Transaction::Mode::kRead);
  ChangeFeed feed;
  int64_t oldest = 0;
  {
    auto statement = (*connection).prepare("SELECT COALESCE(MIN(seq), 0), COALESCE(MAX(seq), 0) FROM change_log");
    if (statement->step()) {
      oldest = statement->columnInt(0);
      feed.seq = statement->columnInt(1);
    }
  }
  // The log keeps the newest kChangeLogKept entries (object_rows.h logChange): a caller older than
  // the oldest kept one (less the one just before it) may have missed pruned changes. So may one
  // newer than the newest, which has seen another database.
  feed.reset = seq <= 0 || seq > feed.seq || (oldest > 0 && seq < oldest - 1);
  auto statement =
      (*connection)
          .prepare(
              feed.reset
                  ? "SELECT id, kind, name, latest_version FROM objects ORDER BY id"
                  : "SELECT c.object_id, o.kind, o.name, o.latest_version FROM (SELECT DISTINCT object_id FROM"
                    " change_log WHERE seq > ?1) c LEFT JOIN objects o ON o.id = c.object_id ORDER BY c.object_id");
  if (!feed.reset) statement->bind(1, seq);
  while (statement->step())
    feed.changes.push_back({statement->columnInt(0), statement->columnText(1), statement->columnText(2),
                            static_cast<int>(statement->columnInt(3))});
  return feed;
}

// --- The descriptor index -----------------------------------------------------------------------

std::vector<DescriptorCandidate> SqlStore::descriptorCandidates(const std::string& kind,
                                                                const DescriptorOverlap& test) const {
  Lease connection(*this);
  Transaction transaction(*connection, Transaction::Mode::kRead);
  return descriptorCandidatesIn(*connection, kind, test);
}

std::vector<DescriptorRange> SqlStore::descriptorRanges(const DescriptorOverlap& test) const {
  Lease connection(*this);
  return descriptorRangesIn(*connection, test);
}

std::vector<DescriptorCandidate> SqlStore::descriptorRangeRows(const std::string& kind, const DescriptorRange& range,
                                                               const DescriptorRangeRead& read) const {
  Lease connection(*this);
  std::vector<DescriptorCandidate> rows;
  descriptorRangeRowsIn(*connection, kind, range, rows, read);
  return rows;
}

std::vector<DescriptorCandidate> SqlStore::descriptorSupports(const std::string& descriptor,
                                                              const std::vector<int64_t>& ids) const {
  Lease connection(*this);
  // kIds ids a statement, the last repeated to fill it (one prepared statement, few round trips);
  // each is a primary-key lookup (object_id, component, descriptor).
  constexpr int kIds = 64;
  auto statement = (*connection).prepare(
      "SELECT object_id, support_lo, support_hi FROM descriptor_index WHERE descriptor = ?1 AND object_id IN (" +
      sql::listPlaceholders(2, kIds) + ")");
  std::vector<DescriptorCandidate> rows;
  for (size_t from = 0; from < ids.size(); from += kIds) {
    statement->reset();
    statement->bind(1, descriptor);
    for (int i = 0; i < kIds; ++i) statement->bind(i + 2, ids[std::min(ids.size() - 1, from + static_cast<size_t>(i))]);
    while (statement->step())
      rows.push_back({statement->columnInt(0), statement->columnDouble(1), statement->columnDouble(2), false});
  }
  return rows;
}

int64_t SqlStore::lastObjectId() const {
  Lease connection(*this);
  auto statement = (*connection).prepare("SELECT coalesce(max(id), 0) FROM objects");
  return statement->step() ? statement->columnInt(0) : 0;
}

std::vector<int64_t> SqlStore::pendingDescriptorIds(const std::string& kind) const {
  Lease connection(*this);
  return pendingDescriptorIdsIn(*connection, kind);
}

std::vector<int64_t> SqlStore::objectIds(const std::string& kind) const {
  Lease connection(*this);
  auto statement = (*connection).prepare("SELECT id FROM objects WHERE kind = ?1 ORDER BY id");
  statement->bind(1, kind);
  std::vector<int64_t> ids;
  while (statement->step()) ids.push_back(statement->columnInt(0));
  return ids;
}

std::vector<ObjectVersion> SqlStore::objectVersions(const std::string& kind) const {
  Lease connection(*this);
  auto statement = (*connection).prepare("SELECT id, name, latest_version FROM objects WHERE kind = ?1 ORDER BY id");
  statement->bind(1, kind);
  std::vector<ObjectVersion> out;
  while (statement->step())
    out.push_back({statement->columnInt(0), statement->columnText(1), static_cast<int>(statement->columnInt(2))});
  return out;
}

std::vector<IndexedObject> SqlStore::indexedObjects(const std::string& kind, const std::vector<int64_t>& ids) const {
  Lease connection(*this);
  // kIdsPerStatement ids a statement (the last repeated to fill it), so scoring 1000 candidates
  // costs 16 round trips to a server instead of 1000. No transaction around them: each object's
  // rows come from one statement, which sees one snapshot, and BEGIN and COMMIT would be two more
  // round trips per call (the search calls this per chunk of 64).
  constexpr int kIdsPerStatement = 64;
  auto statement = (*connection).prepare(indexedObjectsSql((*connection).dialect(), kIdsPerStatement));
  std::unordered_map<int64_t, IndexedObject> found;
  for (size_t from = 0; from < ids.size(); from += kIdsPerStatement) {
    statement->reset();
    statement->bind(1, kind);
    for (int i = 0; i < kIdsPerStatement; ++i)
      statement->bind(i + 2, ids[std::min(ids.size() - 1, from + static_cast<size_t>(i))]);
    while (statement->step()) {
      const int64_t id = statement->columnInt(0);
      auto [it, fresh] = found.try_emplace(id);
      IndexedObject& object = it->second;
      if (fresh) {
        object.id = id;
        object.name = statement->columnText(1);
        object.pending = statement->columnInt(2) != 0;
        object.version = static_cast<int>(statement->columnInt(5));
      }
      if (!statement->isNull(3))
        object.components.emplace_back(static_cast<int>(statement->columnInt(3)), statement->columnBlob(4));
    }
  }
  std::vector<IndexedObject> objects;
  objects.reserve(found.size());
  for (int64_t id : ids) {
    auto it = found.find(id);
    if (it == found.end()) continue;
    std::sort(it->second.components.begin(), it->second.components.end());
    objects.push_back(std::move(it->second));
    found.erase(it);  // an id given twice appears once
  }
  return objects;
}

std::vector<DescriptorComponent> SqlStore::descriptorRows(int64_t id) const {
  Lease connection(*this);
  Transaction transaction(*connection, Transaction::Mode::kRead);
  std::vector<DescriptorComponent> components;
  {
    auto statement =
        (*connection)
            .prepare(
                "SELECT component, descriptor_values FROM descriptor_values WHERE object_id = ?1 ORDER BY component");
    statement->bind(1, id);
    while (statement->step()) {
      DescriptorComponent component;
      component.component = static_cast<int>(statement->columnInt(0));
      component.values = statement->columnBlob(1);
      components.push_back(std::move(component));
    }
  }
  auto statement =
      (*connection)
          .prepare(
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

std::vector<PendingDescriptors> SqlStore::pendingDescriptors(int64_t afterId, int limit) const {
  Lease connection(*this);
  auto statement =
      (*connection)
          .prepare(
              "SELECT p.object_id, o.kind, p.generation FROM descriptor_pending p JOIN objects o ON o.id = p.object_id"
              " WHERE p.object_id > ?1 ORDER BY p.object_id LIMIT ?2");
  statement->bind(1, afterId).bind(2, std::max(0, limit));
  std::vector<PendingDescriptors> pending;
  while (statement->step())
    pending.push_back({statement->columnInt(0), statement->columnText(1), statement->columnInt(2)});
  return pending;
}

size_t SqlStore::replaceDescriptors(
    const std::vector<std::pair<PendingDescriptors, std::vector<DescriptorComponent>>>& refreshed) {
  Lease connection(*this, Lease::Use::kOwn);
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

StoreStats SqlStore::stats() const {
  StoreStats out;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    out.poolConnections = static_cast<int>(connections_.size());
    out.poolIdle = static_cast<int>(idle_.size());
  }
  out.poolWaiting = waiting_.load();
  out.cacheEvictions = evictions_.load();
  Lease connection(*this);
  auto statement = (*connection).prepare("SELECT COALESCE(SUM(bytes), 0), COUNT(*) FROM eval_cache");
  if (statement->step()) {
    out.cacheBytes = static_cast<std::uint64_t>(statement->columnInt(0));
    out.cacheEntries = static_cast<std::uint64_t>(statement->columnInt(1));
  }
  return out;
}

std::optional<CachedEvaluation> SqlStore::cachedEvaluation(const std::string& key) const {
  std::optional<CachedEvaluation> hit;
  int64_t used = 0;
  {
    Lease connection(*this);
    auto statement = (*connection).prepare("SELECT result, vdb, used FROM eval_cache WHERE key = ?1");
    statement->bind(1, key);
    if (!statement->step()) return std::nullopt;
    hit = CachedEvaluation{statement->columnText(0), statement->columnBlob(1)};
    used = statement->columnInt(2);
  }
  const int64_t now = nowMs();
  if (maxCacheBytes_ > 0 && now - used > kTouchEveryMs) {
    // Best effort: a busy database or a lost race costs the entry its place in the order, never
    // the read.
    try {
      Lease connection(*this, Lease::Use::kOwn);
      auto touch = (*connection).prepare("UPDATE eval_cache SET used = ?2 WHERE key = ?1 AND used < ?2");
      touch->bind(1, key).bind(2, now).run();
    } catch (const Error&) {
    }
  }
  return hit;
}

}  // namespace fsdb
