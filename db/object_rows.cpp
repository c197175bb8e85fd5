// See db/object_rows.h.
#include "db/object_rows.h"

#include <algorithm>
#include <chrono>
#include <ctime>

#include "db/descriptor_index.h"
#include "geometry/core/closest_names.h"
#include "geometry/core/error.h"

namespace fsdb::object_rows {

using sql::Connection;

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

std::vector<int64_t> dependentsOf(Connection& connection, int64_t id) {
  auto statement = connection.prepare("SELECT id FROM (" FSDB_REACHING_SQL ") AS reaching WHERE id != ?1 ORDER BY id");
  statement->bind(1, id);
  std::vector<int64_t> ids;
  while (statement->step()) ids.push_back(statement->columnInt(0));
  return ids;
}

std::optional<ObjectRow> objectRow(Connection& connection, int64_t id) {
  auto statement = connection.prepare("SELECT kind, name, latest_version FROM objects WHERE id = ?1");
  statement->bind(1, id);
  if (!statement->step()) return std::nullopt;
  return ObjectRow{id, statement->columnText(0), statement->columnText(1), static_cast<int>(statement->columnInt(2))};
}

std::optional<int64_t> idByName(Connection& connection, const std::string& kind, const std::string& name) {
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
void checkCycles(Connection& connection, const ObjectRow& object, const std::vector<ObjectReference>& references,
                 const std::vector<int64_t>& children) {
  auto statement = connection.prepare(
      "WITH RECURSIVE down(id) AS (SELECT CAST(?1 AS BIGINT)"
      " UNION SELECT refs.child_id FROM refs JOIN down ON refs.parent_id = down.id)"
      " SELECT 1 FROM down WHERE id = ?2 LIMIT 1");
  for (size_t i = 0; i < children.size(); ++i) {
    statement->reset();
    statement->bind(1, children[i]).bind(2, object.id);
    if (!statement->step()) continue;
    auto child = objectRow(connection, children[i]);
    std::string through = child ? describe(child->kind, child->name, child->id) : "itself";
    throw Error(errc::kReferenceCycle,
                describe(object.kind, object.name, object.id) + " would contain itself through " + through,
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

std::vector<int64_t> sortedUnique(std::vector<int64_t> ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

// The search box's row of an object (schema/migrations/009_object_text.sql): its name and search
// text, replacing the previous version's.
void writeObjectText(Connection& connection, const ObjectRow& row, const NewObject& object, bool fresh) {
  const std::string words = object.searchText.empty() ? row.name : row.name + " " + object.searchText;
  if (connection.dialect() == sql::Dialect::kSqlite) {
    if (!fresh) {
      auto statement = connection.prepare("DELETE FROM object_text WHERE rowid = ?1");
      statement->bind(1, row.id);
      statement->run();
    }
    auto statement = connection.prepare("INSERT INTO object_text (rowid, words) VALUES (?1, ?2)");
    statement->bind(1, row.id).bind(2, words);
    statement->run();
    return;
  }
  auto statement = connection.prepare(
      "INSERT INTO object_text (object_id, words) VALUES (?1, to_tsvector('english', ?2))"
      " ON CONFLICT (object_id) DO UPDATE SET words = excluded.words");
  statement->bind(1, row.id).bind(2, words);
  statement->run();
}

// Writes version `version` of object `row` (whose objects row exists) with its normalised rows,
// and makes its edges those of `children`. Version 1 is a new object: an id is never reused, so
// it has no edges, descriptor rows or pending mark to replace, and those deletes are skipped
// (four of the eight statements a part's creation ran).
void writeVersion(Connection& connection, const ObjectRow& row, int version, const NewObject& object,
                  const std::vector<int64_t>& children, const std::string& now, const DescriptorClasses* present) {
  const bool fresh = version == 1;
  {
    auto statement = connection.prepare(
        "INSERT INTO versions (object_id, version, document, content_hash, created_at)"
        " VALUES (?1, ?2, ?3, ?4, ?5)");
    statement->bind(1, row.id).bind(2, version).bind(3, object.documentJson);
    statement->bind(4, object.contentHash).bind(5, now);
    statement->run();
  }
  for (size_t from = 0; from < object.nodes.size(); from += sql::kRowsPerStatement) {
    const int rows = static_cast<int>(std::min<size_t>(sql::kRowsPerStatement, object.nodes.size() - from));
    auto statement = connection.prepare(
        "INSERT INTO csg_nodes (object_id, version, node, parent, position, kind, operator, ref_id, transform) VALUES " +
        sql::rowPlaceholders(rows, 9));
    for (int r = 0; r < rows; ++r) {
      const CsgNodeRow& node = object.nodes[from + static_cast<size_t>(r)];
      std::optional<int64_t> refId;
      if (node.refIndex >= 0) {
        if (static_cast<size_t>(node.refIndex) >= children.size())
          throw Error(errc::kInvalidDocument, "node " + std::to_string(node.index) + " refers to reference " +
                                                  std::to_string(node.refIndex) + " of " +
                                                  std::to_string(children.size()));
        refId = children[static_cast<size_t>(node.refIndex)];
      }
      const int k = 9 * r;
      statement->bind(k + 1, row.id).bind(k + 2, version).bind(k + 3, node.index).bind(k + 4, node.parent);
      statement->bind(k + 5, node.position).bind(k + 6, node.kind);
      if (node.operatorJson.empty()) statement->bindNull(k + 7);
      else statement->bind(k + 7, node.operatorJson);
      statement->bind(k + 8, refId);
      if (node.transformJson.empty()) statement->bindNull(k + 9);
      else statement->bind(k + 9, node.transformJson);
    }
    statement->run();
  }
  if (!fresh) {
    auto statement = connection.prepare("DELETE FROM refs WHERE parent_id = ?1");
    statement->bind(1, row.id);
    statement->run();
  }
  const std::vector<int64_t> edges = sortedUnique(children);
  for (size_t from = 0; from < edges.size(); from += sql::kRowsPerStatement) {
    const int rows = static_cast<int>(std::min<size_t>(sql::kRowsPerStatement, edges.size() - from));
    auto statement =
        connection.prepare("INSERT INTO refs (parent_id, child_id) VALUES " + sql::rowPlaceholders(rows, 2));
    for (int r = 0; r < rows; ++r)
      statement->bind(2 * r + 1, row.id).bind(2 * r + 2, edges[from + static_cast<size_t>(r)]);
    statement->run();
  }
  writeDescriptorRows(connection, row.id, row.kind, object.descriptors, fresh, present);
  if (row.kind == "part" || row.kind == "shape") writeObjectText(connection, row, object, fresh);
  // Rows computed from referenced documents the caller read before this transaction may already
  // be stale: the server recomputes them after the commit (db/store.h, the descriptor index).
  if (object.references.empty()) {
    if (!fresh) clearDescriptorsPending(connection, row.id);
  } else markDescriptorsPending(connection, row.id);
}

void checkKind(const std::string& kind) {
  if (!knownKind(kind)) throw Error(errc::kInvalidDocument, "unknown kind '" + quotedWord(kind) + "'", "kind");
}

// The record of a write: what get() would return for the new version.
StoredObject written(const ObjectRow& row, int version, const NewObject& object, const std::vector<int64_t>& children,
                     const std::string& now) {
  return StoredObject{row.id,
                      row.kind,
                      row.name,
                      version,
                      version,
                      object.documentJson,
                      object.contentHash,
                      now,
                      sortedUnique(children)};
}

// create inside the caller's transaction.
StoredObject createIn(Connection& connection, const NewObject& object, const DescriptorClasses* present) {
  checkKind(object.kind);
  if (auto existing = idByName(connection, object.kind, object.name))
    throw Error(errc::kConflict, describe(object.kind, object.name, *existing) + " already exists", "name");
  // A new object cannot close a cycle: nothing refers to it yet, and it cannot refer to itself
  // because its id and name are not in the database until the insert below.
  auto children = resolveAll(connection, object.references);
  std::string now = isoNow();
  int64_t id = 0;
  {
    auto statement =
        connection.prepare("INSERT INTO objects (kind, name, latest_version) VALUES (?1, ?2, 1) RETURNING id");
    statement->bind(1, object.kind).bind(2, object.name);
    if (statement->step()) id = statement->columnInt(0);
    statement->run();
  }
  ObjectRow row{id, object.kind, object.name, 1};
  writeVersion(connection, row, 1, object, children, now, present);
  logChange(connection, id);
  return written(row, 1, object, children, now);
}

void checkVersion(const ObjectRow& row, std::optional<int> ifVersion) {
  if (ifVersion && *ifVersion != row.latestVersion)
    throw Error(errc::kPreconditionFailed, describe(row.kind, row.name, row.id) + " is at version " +
                                               std::to_string(row.latestVersion) + ", not " +
                                               std::to_string(*ifVersion) + " (If-Match)");
}

void logChange(Connection& connection, int64_t id) {
  int64_t seq = 0;
  {
    auto statement = connection.prepare("INSERT INTO change_log (object_id) VALUES (?1) RETURNING seq");
    statement->bind(1, id);
    if (statement->step()) seq = statement->columnInt(0);
    statement->run();
  }
  if (seq % 1024 != 0) return;  // prune now and then: one range delete per 1024 writes
  auto statement = connection.prepare("DELETE FROM change_log WHERE seq <= ?1");
  statement->bind(1, seq - kChangeLogKept);
  statement->run();
}

// put inside the caller's transaction.
StoredObject putIn(Connection& connection, int64_t id, const NewObject& object, std::optional<int> ifVersion,
                   const DescriptorClasses* present) {
  auto row = objectRow(connection, id);
  if (!row || row->kind != object.kind)
    throw Error(errc::kNotFound, object.kind + " " + std::to_string(id) + " not found");
  checkVersion(*row, ifVersion);
  if (row->name != object.name)
    throw Error(errc::kConflict,
                "cannot rename " + describe(row->kind, row->name, id) + " to '" + object.name + "' by a new version",
                "name");
  auto children = resolveAll(connection, object.references);
  checkCycles(connection, *row, object.references, children);
  // The objects that reach this one are its ancestors in refs, which this write does not change
  // (it replaces only the object's own outgoing edges), so the order against writeVersion is free.
  invalidateDependents(connection, id, dependentsOf(connection, id));
  std::string now = isoNow();
  int version = row->latestVersion + 1;
  {
    auto statement = connection.prepare("UPDATE objects SET latest_version = ?2 WHERE id = ?1");
    statement->bind(1, id).bind(2, version);
    statement->run();
  }
  writeVersion(connection, *row, version, object, children, now, present);
  logChange(connection, id);
  return written(*row, version, object, children, now);
}

// createBatch's kUpsert item inside the caller's transaction.
StoredObject upsertIn(Connection& connection, const NewObject& object, const DescriptorClasses* present) {
  checkKind(object.kind);
  auto id = idByName(connection, object.kind, object.name);
  if (!id) return createIn(connection, object, present);
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
  return putIn(connection, *id, object, std::nullopt, present);
}

std::string objectColumnsSql(sql::Dialect dialect) {
  // The children as "3,5,9" (no order is promised inside the aggregate: readObject sorts them).
  const char* children = dialect == sql::Dialect::kSqlite
                             ? "(SELECT group_concat(child_id) FROM refs WHERE parent_id = o.id)"
                             : "(SELECT string_agg(CAST(child_id AS TEXT), ',') FROM refs WHERE parent_id = o.id)";
  return std::string(
             "SELECT o.id, o.kind, o.name, o.latest_version, v.version, v.document, v.content_hash, v.created_at,"
             " CASE WHEN v.version = o.latest_version THEN ") +
         children + " END FROM objects o JOIN versions v ON v.object_id = o.id";
}

StoredObject readObject(sql::Statement& row) {
  StoredObject object;
  object.id = row.columnInt(0);
  object.kind = row.columnText(1);
  object.name = row.columnText(2);
  object.latestVersion = static_cast<int>(row.columnInt(3));
  object.version = static_cast<int>(row.columnInt(4));
  object.documentJson = row.columnText(5);
  object.contentHash = row.columnText(6);
  object.createdAt = row.columnText(7);
  const std::string children = row.columnText(8);
  for (size_t at = 0; at < children.size();) {
    size_t end = children.find(',', at);
    if (end == std::string::npos) end = children.size();
    object.references.push_back(std::stoll(children.substr(at, end - at)));
    at = end + 1;
  }
  std::sort(object.references.begin(), object.references.end());
  return object;
}

// One statement: one snapshot without a transaction (GET /parts/{id} is this statement alone).
std::optional<StoredObject> loadObject(Connection& connection, const std::string& kind, std::optional<int64_t> id,
                                       const std::string& name, std::optional<int> version) {
  // Two statements (by id, by name), not one with OR, so each is a plain index lookup.
  auto statement = connection.prepare(objectColumnsSql(connection.dialect()) +
                                      " AND v.version = COALESCE(?3, o.latest_version) WHERE o.kind = ?2 AND " +
                                      (id ? "o.id = ?1" : "o.name = ?1"));
  if (id) statement->bind(1, *id);
  else statement->bind(1, name);
  statement->bind(2, kind);
  statement->bind(3, version ? std::optional<int64_t>(*version) : std::nullopt);
  if (!statement->step()) return std::nullopt;
  return readObject(*statement);
}

std::string indexedObjectsSql(sql::Dialect dialect, int ids) {
  const std::string in = sql::listPlaceholders(2, ids);
  return std::string(
             "SELECT o.id, o.name, CASE WHEN p.object_id IS NULL THEN 0 ELSE 1 END, v.component, v.descriptor_values,"
             " o.latest_version FROM objects o"
             " LEFT JOIN descriptor_pending p ON p.object_id = o.id LEFT JOIN descriptor_values v ON v.object_id = o.id"
             " WHERE ") +
         (dialect == sql::Dialect::kSqlite ? "+o.kind" : "o.kind") + " = ?1 AND o.id IN (" + in + ")";
}

}  // namespace fsdb::object_rows
