#pragma once
// Internal to db/: the rows of one object on one connection, inside the caller's transaction:
// reference resolution, the cycle check, version rows, reference edges and cache invalidation
// (the write path that Store::create, put and createBatch share), and reading objects back.
// Store (db/store.h) is the public face; only db/sql_store.cpp includes this header.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "db/descriptor_index.h"
#include "db/sql.h"
#include "db/store.h"

namespace fsdb::object_rows {

// The ids of the objects whose latest version reaches ?1 (its ancestors in refs; ?1 itself only
// through a cycle), as a subquery. UNION (not UNION ALL) makes the walk terminate whatever the graph.
#define FSDB_REACHING_SQL                                                    \
  "WITH RECURSIVE up(id) AS (SELECT parent_id FROM refs WHERE child_id = ?1" \
  " UNION SELECT refs.parent_id FROM refs JOIN up ON refs.child_id = up.id) SELECT id FROM up"

// "SELECT <the columns readObject reads> FROM objects o JOIN versions v ON v.object_id = o.id":
// one version of an object with, for the latest version, its children aggregated in the same
// row (refs holds only the latest version's edges), so a read is one statement.
std::string objectColumnsSql(sql::Dialect dialect);

// The objects row of one object.
struct ObjectRow {
  int64_t id = 0;
  std::string kind, name;
  int latestVersion = 0;
};

// "part 'bolt' (id 3)": how messages name an object.
std::string describe(const std::string& kind, const std::string& name, int64_t id);
// The objects whose latest version reaches id (FSDB_REACHING_SQL), sorted, without id itself.
std::vector<int64_t> dependentsOf(sql::Connection& connection, int64_t id);
std::optional<ObjectRow> objectRow(sql::Connection& connection, int64_t id);
// Store::create, put and upsert (createBatch's modes), inside the caller's transaction.
// present: as writeDescriptorRows's (db/descriptor_index.h), descriptor classes known to be stored.
StoredObject createIn(sql::Connection& connection, const NewObject& object,
                      const DescriptorClasses* present = nullptr);
StoredObject putIn(sql::Connection& connection, int64_t id, const NewObject& object,
                   std::optional<int> ifVersion = std::nullopt, const DescriptorClasses* present = nullptr);
// precondition_failed unless ifVersion is empty or the object's latest version.
void checkVersion(const ObjectRow& row, std::optional<int> ifVersion);
// Appends `id` to the change log (migration 004) under the next sequence number, and drops the
// entries older than the newest kChangeLogKept now and then.
constexpr int64_t kChangeLogKept = 100000;
void logChange(sql::Connection& connection, int64_t id);
StoredObject upsertIn(sql::Connection& connection, const NewObject& object,
                      const DescriptorClasses* present = nullptr);
// One row of objectColumnsSql, references sorted (empty for an older version).
StoredObject readObject(sql::Statement& row);
// The object of `kind` with this id (or, without one, this name) at `version` (else the latest).
std::optional<StoredObject> loadObject(sql::Connection& connection, const std::string& kind, std::optional<int64_t> id,
                                       const std::string& name, std::optional<int> version);

// The statement of Store::indexedObjects for `ids` ids (?2...): each object's name, pending mark,
// version and descriptor_values rows, found by primary key. On SQLite the kind test is written
// +o.kind so the planner cannot walk objects_kind_name (every object of the kind) instead of the
// id lookups: without statistics it took that plan, and the linguistic search at 1M parts spent
// 88 % of its time there (tests/db/query_plan_test.cpp).
std::string indexedObjectsSql(sql::Dialect dialect, int ids);

}  // namespace fsdb::object_rows
