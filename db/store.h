#pragma once
// Store: fsdb's database of parts and shapes (Zhang, Pham & Chen, §4; docs/api.md §2, §4), an
// interface with two backends: SqliteStore (db/sqlite_store.h, one embedded file, the default) and
// PostgresStore (db/postgres_store.h, one PostgreSQL database shared by several stateless
// servers). Both are db/sql_store.h, the same queries on different engines; the tests run the
// same suites on both (docs/design/storage-backends.md says what differs and why).
//
// Model
// - Every stored thing is an *object*: a system id (INTEGER, AUTOINCREMENT: never reused, not
//   even after a delete), a kind ("part", "shape"; "curve" and "surface" reserved), a name unique
//   among the live objects of its kind, and versions 1, 2, ... Each version keeps the document as
//   given (canonical JSON text) and its content hash. PUT adds a version; old versions stay
//   readable. Ids are shared by all kinds (an id names one object of one kind).
// - References: a shape's tree names parts and shapes ("part":"bolt", "ref":"wheel", or an id).
//   The store resolves each to an object id inside the write transaction and records the edge
//   (parent -> child) for the parent's latest version, so a part used by a thousand trees is
//   stored once (shared subtrees; Zhang, Pham & Chen, §4). A reference always means the child's
//   latest version. Unknown references are 422 unknown_reference (path = the reference's JSON
//   path); an edge that would close a cycle is 422 reference_cycle.
// - Normalised columns beside the document: per version, the CSG nodes of a shape (for
//   structural search), and for the latest version the descriptor index rows (linguistic
//   search). The caller (server/, which owns the parsers) computes them; the store only keeps them.
// - Evaluation cache: results of evaluating a shape keyed by a caller-made key (content hash of
//   the resolved document + resolution + alphas + method). Any write to an object drops the cache
//   rows of that object and of every object that reaches it through references.
//
// - Change log: every write records the ids it changed under a store-wide sequence number, so a
//   server's in-memory caches see writes made through other servers (changesSince) without
//   reading every object's version per query.
//
// Guarantees
// - Every write is one transaction that holds the database's write lock (SQLite: BEGIN
//   IMMEDIATE; PostgreSQL: an advisory lock): it completes or leaves nothing, and writers from
//   all servers on one database run one at a time, so name, cycle and version checks cannot race.
// - A write that cannot get the lock in time, or any engine failure, is 503 storage_error, never
//   a partial write.
// - Thread-safe: any number of threads may call any method; each call takes a connection from a
//   pool (readers run beside the one writer).
// - Migrations (schema/migrations/NNN_*.sql and schema/migrations/postgresql/NNN_*.sql, compiled
//   into the binary) are applied in order at open(), each in its own transaction.
// Errors are fsdb::Error with the codes of geometry/core/error.h: not_found (404), conflict (409: name
// taken on create, name change on put), in_use (409: delete of a referenced object without
// cascade), precondition_failed (412: the object moved past the version a conditional write
// expected), unknown_reference / reference_cycle (422), storage_error (503: engine failures).
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fsdb {

// A reference from a document to another stored object, as written in the document.
struct ObjectReference {
  std::string kind;           // "part" or "shape"
  std::optional<int64_t> id;  // when the document gives an id
  std::string name;           // when it gives a name
  std::string path;           // JSON path of the reference, for errors ("tree.children[1].part")
};

// One node of a shape's CSG tree in pre-order; the root has parent -1.
struct CsgNodeRow {
  int index = 0;
  int parent = -1;
  int position = 0;           // child position under the parent (difference is ordered)
  std::string kind;           // "union", "intersection", "difference", "part" (inline), "ref"
  std::string operatorJson;   // node operator document, "" for zadeh / leaves
  int refIndex = -1;          // "ref" leaves: index into NewObject::references (the store
                              // records the object it resolves to as csg_nodes.ref_id)
  std::string transformJson;  // the leaf's transform document, "" when none
};

// One descriptor of one component in normalised form: the support [supportLo, supportHi] and
// core [coreLo, coreHi] of the component's fuzzy degree (migration 002, descriptor index).
struct DescriptorSpan {
  std::string descriptor;  // "squariness", ... (query/linguistic/descriptors.h descriptorNames())
  double supportLo = 0, coreLo = 0, coreHi = 0, supportHi = 0;
};

// The descriptor rows of one component of an object: a part has one (component 0), a shape one
// per leaf of its resolved tree. `values` holds the exact values in the caller's encoding
// (server/service/descriptor_rows.h); the store keeps it as given.
struct DescriptorComponent {
  int component = 0;
  std::vector<DescriptorSpan> spans;
  std::string values;
};

// What a create or put writes.
struct NewObject {
  std::string kind;
  std::string name;
  std::string documentJson;  // canonical JSON text of the document as given
  std::string contentHash;   // of documentJson (db/content_hash.h)
  std::vector<ObjectReference> references;
  std::vector<CsgNodeRow> nodes;
  std::vector<DescriptorComponent> descriptors;  // the descriptor index rows of this version
  // Parts and shapes: the words the search box finds the object by (its name, meta.description
  // and descriptors: documentSearchText, server/service/documents.h); empty: none but the name.
  std::string searchText;
};

struct StoredObject {
  int64_t id = 0;
  std::string kind;
  std::string name;
  int version = 0;        // the version this record holds
  int latestVersion = 0;  // the object's newest version
  std::string documentJson;
  std::string contentHash;
  std::string createdAt;            // of this version, ISO 8601 UTC
  std::vector<int64_t> references;  // resolved ids this version refers to (latest version only)
};

struct ObjectVersion {
  int64_t id = 0;
  std::string name;
  int latestVersion = 0;
};

struct ListQuery {
  std::string kind;
  std::optional<std::string> name;  // exact name
  std::optional<int> version;       // with name: that version (else the latest)
  int64_t afterId = 0;              // keyset paging: ids greater than this
  int limit = 100;
};

// Outcome of one bulk batch: per item either an id or an error.
struct BulkItemResult {
  std::optional<int64_t> id;
  int version = 0;
  std::string errorCode, errorMessage, errorPath;  // set when the item failed
};

enum class BulkMode {
  kCreate,  // an existing name is a per-item conflict
  kUpsert,  // an existing name gets a new version, unless the content hash equals its latest
};

struct StoreOptions {
  int busyTimeoutMs = 5000;
  bool synchronousFull = false;  // NORMAL (default) survives process crashes; FULL survives power loss
  int poolSize = 8;
  // The evaluation cache's bound (fsdb serve --max-cache-mb): storeEvaluation evicts the least
  // recently used entries (stored or read) until the entries' bytes fit; an entry larger than
  // the whole bound is not kept. 0: no bound.
  std::uint64_t maxCacheBytes = std::uint64_t(1024) << 20;
};

// A support test of the descriptor index: which rows of `descriptor` a prefilter wants (the
// store's side of query/linguistic/descriptor_prefilter.h SupportTest). A crisp row (support_lo ==
// support_hi = x) passes when x is in [lo, hi], each end only when included; a wide row when
// support_lo <= hi and support_hi >= lo, both strict when wideStrict.
struct DescriptorOverlap {
  std::string descriptor;
  double lo = 0, hi = 0;
  bool loIncluded = true, hiIncluded = true;
  bool wideStrict = false;
};

// A row found by a DescriptorOverlap (its support, from which the search bounds the score), or a
// pending object (no row to trust).
struct DescriptorCandidate {
  int64_t id = 0;
  double supportLo = 0, supportHi = 0;
  bool pending = false;
};

// One range scan of the descriptor index (db/descriptor_index.h): the rows of one descriptor and
// width class with support_lo in [fromLo, toLo] and support_hi >= leastHi. A DescriptorOverlap is
// the union of one such range per width class (Store::descriptorRanges); the level scan of the
// linguistic search reads pieces of them, best bound first (server/service/linguistic_search.h).
struct DescriptorRange {
  std::string descriptor;
  int widthClass = 0;
  double fromLo = 0, toLo = 0, leastHi = 0;
};

// How Store::descriptorRangeRows reads a range, so the level scan of the linguistic search can
// read a piece best rows first and stop early (server/service/linguistic_search.cpp):
// - kAscending, kDescending: by (support_lo, support_hi, object_id) that way, at most `limit`
//   rows (0: all); for crisp rows that is by value, then by id;
// - kById: the rows with object_id in (afterId, throughId], by id (a walk of the objects in id
//   order, for a piece whose rows all have the same bound, where ties go by id).
struct DescriptorRangeRead {
  enum class Order { kAscending, kDescending, kById };
  Order order = Order::kAscending;
  int64_t limit = 0;
  int64_t afterId = 0, throughId = 0;
};

// An object as the linguistic search scores it (Store::indexedObjects): its name and the
// encoded descriptor values of its components. pending: the rows are missing or may be stale
// (descriptor_pending), so the caller must describe the document instead of using `components`.
struct IndexedObject {
  int64_t id = 0;
  std::string name;
  int version = 0;  // the latest version, which the rows describe unless pending
  bool pending = false;
  std::vector<std::pair<int, std::string>> components;  // (component, values), by component
};

// An object whose descriptor rows the server must (re)compute; see replaceDescriptors.
struct PendingDescriptors {
  int64_t id = 0;
  std::string kind;
  int64_t generation = 0;
};

// What GET /metrics reports of a store (Store::stats).
struct StoreStats {
  int poolConnections = 0;  // connections in the pool
  int poolIdle = 0;         // of them, not lent to a call now
  int poolWaiting = 0;      // calls waiting for one
  std::uint64_t cacheBytes = 0, cacheEntries = 0;  // the evaluation cache's entries (result and grid bytes)
  std::uint64_t cacheEvictions = 0;                // entries this process evicted (--max-cache-mb)
};

struct CachedEvaluation {
  std::string resultJson;
  std::string vdb;  // may be empty
};

// One object a write changed since some sequence number (Store::changesSince): its latest version
// now, or latestVersion 0 when it was deleted.
struct ObjectChange {
  int64_t id = 0;
  std::string kind;  // "" when deleted
  std::string name;
  int latestVersion = 0;
};

// What changed after a sequence number, up to `seq`. reset: the log no longer reaches back that far
// (or the caller asked from 0), so `changes` lists every live object instead and the caller must
// forget what it knew. An object changed several times appears once.
struct ChangeFeed {
  int64_t seq = 0;
  bool reset = false;
  std::vector<ObjectChange> changes;
};

class Store {
 public:
  // Opens and migrates the store at `location`: a postgresql:// or postgres:// URL opens
  // PostgresStore (db/postgres_store.h), anything else is a file path for SqliteStore
  // (db/sqlite_store.h). ":memory:" is not supported (each pooled connection would get its own
  // database); use a temporary file.
  static std::unique_ptr<Store> open(const std::string& location, const StoreOptions& options = {});
  virtual ~Store() = default;
  Store(const Store&) = delete;
  Store& operator=(const Store&) = delete;

  // The file path, or the URL with any password hidden.
  virtual const std::string& path() const = 0;
  virtual std::string backend() const = 0;  // "sqlite" or "postgresql"
  virtual int schemaVersion() const = 0;    // highest applied migration

  // Creates an object at version 1. conflict when the kind already has a live object of that name.
  virtual StoredObject create(const NewObject& object) = 0;
  // Adds a version to object `id` (which must be of object.kind, else not_found). The name must
  // stay the same (conflict otherwise). References are re-resolved; the edges become the new
  // version's; cycles are refused. ifVersion: precondition_failed (412) unless the object's latest
  // version is that one when the write holds the lock (HTTP If-Match).
  virtual StoredObject put(int64_t id, const NewObject& object, std::optional<int> ifVersion = std::nullopt) = 0;
  // The latest version, or the given one. not_found when the object or version does not exist.
  virtual StoredObject get(const std::string& kind, int64_t id, std::optional<int> version = std::nullopt) const = 0;
  // Resolves a reference to the latest version of the object it names; not_found-free: nullopt.
  virtual std::optional<StoredObject> find(const ObjectReference& reference) const = 0;
  virtual std::vector<StoredObject> list(const ListQuery& query) const = 0;
  // The latest versions of the live objects of `kinds` whose name is one of `names` (exact), by
  // id: one statement however many names and kinds (the search box asks a text's few spellings
  // of one name on every query, and the spellings one letter from its unknown words where no
  // grammar reads it). At most kMaxNamedLookups names and 8 kinds (invalid_parameter).
  static constexpr size_t kMaxNamedLookups = 256;
  virtual std::vector<StoredObject> named(const std::vector<std::string>& names,
                                          const std::vector<std::string>& kinds) const = 0;
  // The latest versions of the parts and shapes of `kinds` whose search text (NewObject::
  // searchText, or the name) holds every one of `words` after stemming (SQLite FTS5's porter,
  // PostgreSQL's 'english' configuration, which leaves out its stop words), by id (PostgreSQL:
  // best ts_rank first), at most `limit` (1-1000). No words: none. invalid_parameter for more than kMaxTextWords words.
  static constexpr size_t kMaxTextWords = 32;
  virtual std::vector<StoredObject> described(const std::vector<std::string>& words,
                                              const std::vector<std::string>& kinds, int limit) const = 0;
  // Deletes the object and all its versions. in_use (409) when a live object's latest version
  // refers to it, unless cascade: then every object that reaches it is deleted too. Returns the
  // ids deleted (the object first). ifVersion as for put.
  virtual std::vector<int64_t> remove(const std::string& kind, int64_t id, bool cascade,
                                      std::optional<int> ifVersion = std::nullopt) = 0;

  // One transaction for the whole batch; each item in its own savepoint, so a failing item
  // (conflict, unknown reference, ...) is reported and the others of the batch still commit.
  // Items may refer to objects created earlier in the same batch.
  virtual std::vector<BulkItemResult> createBatch(const std::vector<NewObject>& items, BulkMode mode) = 0;

  // Live objects per kind ({"part": 31, "shape": 12}); kinds with no live object are absent.
  virtual std::map<std::string, int64_t> counts() const = 0;
  // Ids of the objects whose latest version reaches `id` through references (not `id` itself).
  virtual std::vector<int64_t> dependents(int64_t id) const = 0;

  // --- The change log (migration 004) ---
  // The newest sequence number: one indexed read, so a cache can check "anything new?" per query.
  virtual int64_t changeSeq() const = 0;
  // The objects changed after `seq` (0: everything, as a reset), in one snapshot.
  virtual ChangeFeed changesSince(int64_t seq) const = 0;

  // --- The descriptor index (migration 002) ---
  // Writes keep it in step: create and put replace the object's rows with NewObject::descriptors
  // in the write transaction (delete removes them by cascade). Rows may be stale where the store
  // cannot know them: a put of X marks every object reaching X pending (its components changed),
  // a create or put with references marks the object itself pending (the caller described the
  // referenced documents before the write transaction), and migration 002 marks every object
  // that existed before it. Pending objects are candidates of every prefilter, so the index never
  // hides a match; the server recomputes them (pendingDescriptors, replaceDescriptors).
  //
  // The component rows of objects of `kind` passing `test` (one index range scan per width
  // class, db/descriptor_index.h), and every pending object of `kind` (pending = true), in index
  // order (not by id: sorting is the caller's choice; a shape's rows may be apart).
  virtual std::vector<DescriptorCandidate> descriptorCandidates(const std::string& kind,
                                                                const DescriptorOverlap& test) const = 0;
  // The same rows in parts: the range per width class present (empty ranges left out), the rows
  // of one range (pending = false), and the ids of the pending objects of `kind`.
  virtual std::vector<DescriptorRange> descriptorRanges(const DescriptorOverlap& test) const = 0;
  virtual std::vector<DescriptorCandidate> descriptorRangeRows(const std::string& kind, const DescriptorRange& range,
                                                               const DescriptorRangeRead& read = {}) const = 0;
  virtual std::vector<int64_t> pendingDescriptorIds(const std::string& kind) const = 0;
  // The supports of `descriptor` of the objects among `ids` (every component's row; ids without
  // rows are left out), in no order: the level scan tightens a candidate's bound with them.
  virtual std::vector<DescriptorCandidate> descriptorSupports(const std::string& descriptor,
                                                              const std::vector<int64_t>& ids) const = 0;
  // The largest id of a live object (0: none); ids only grow, so a walk in id order ends there.
  virtual int64_t lastObjectId() const = 0;
  // Sorted ids of every live object of `kind` (the full scan's candidates).
  virtual std::vector<int64_t> objectIds(const std::string& kind) const = 0;
  // Every live object of `kind` by id with its name and latest version, in one read.
  virtual std::vector<ObjectVersion> objectVersions(const std::string& kind) const = 0;
  // The objects of `kind` among `ids`, in the order given (ids of other kinds or deleted are skipped).
  virtual std::vector<IndexedObject> indexedObjects(const std::string& kind, const std::vector<int64_t>& ids) const = 0;
  // The rows of the latest version of `id`, by component (tests, diagnostics).
  virtual std::vector<DescriptorComponent> descriptorRows(int64_t id) const = 0;
  // Pending objects with id > afterId, by id, at most `limit`.
  virtual std::vector<PendingDescriptors> pendingDescriptors(int64_t afterId = 0, int limit = 1000) const = 0;
  // For each (pending object, its rows): replaces the rows and clears the mark, but only when the
  // object is still pending with the same generation (a write since then marked it again or wrote
  // fresh rows). One transaction for all; returns how many it replaced. The caller computes the
  // rows from documents it read after pendingDescriptors.
  virtual size_t replaceDescriptors(
      const std::vector<std::pair<PendingDescriptors, std::vector<DescriptorComponent>>>& refreshed) = 0;

  // The pool and the evaluation cache now (one query of the cache's sums); a store without a pool
  // answers zeros.
  virtual StoreStats stats() const { return {}; }

  virtual std::optional<CachedEvaluation> cachedEvaluation(const std::string& key) const = 0;
  virtual void storeEvaluation(int64_t objectId, const std::string& key, const CachedEvaluation& value) = 0;

  // SQLite: PRAGMA wal_checkpoint(TRUNCATE), called at shutdown so the file is whole on its own.
  // PostgreSQL: nothing (the server owns durability).
  virtual void checkpoint() = 0;
  // "ok" or the first problem (SQLite: PRAGMA integrity_check; PostgreSQL: the store's own
  // invariants: every object has its latest version, every edge names live objects).
  virtual std::string integrityCheck() const = 0;

  // Runs `body`, and every read this thread makes on the store until it returns sees one
  // snapshot: the reads share one pooled connection in one read transaction, instead of a
  // transaction and a pool loan per call (a linguistic search makes ten to fifty calls). Writes
  // inside `body` take other connections and are not seen by its reads. Nested calls join the
  // outer snapshot. The default (a store without transactions) runs `body` as it is.
  virtual void readSnapshot(const std::function<void()>& body) const { body(); }

 protected:
  Store() = default;
};

}  // namespace fsdb
