// See db/descriptor_index.h.
#include "db/descriptor_index.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "db/sql.h"

namespace fsdb {

int widthClass(double width) {
  if (!(width > 0)) return kCrispWidthClass;
  int exponent = 0;
  std::frexp(width, &exponent);  // width = m * 2^exponent, m in [0.5, 1): width < 2^exponent
  return exponent;
}

double lowestSupportLo(double lo, int widthClass) {
  if (widthClass == kCrispWidthClass) return lo;
  return std::nextafter(lo - std::ldexp(1.0, widthClass), -std::numeric_limits<double>::infinity());
}

DescriptorClasses descriptorClassesIn(sql::Connection& connection) {
  auto statement = connection.prepare("SELECT descriptor, width_class FROM descriptor_classes");
  DescriptorClasses classes;
  while (statement->step()) classes.emplace(statement->columnText(0), static_cast<int>(statement->columnInt(1)));
  return classes;
}

void writeDescriptorRows(sql::Connection& connection, int64_t objectId, const std::string& kind,
                         const std::vector<DescriptorComponent>& components, bool fresh,
                         const DescriptorClasses* present) {
  if (!fresh)
    for (const char* sql :
         {"DELETE FROM descriptor_index WHERE object_id = ?1", "DELETE FROM descriptor_values WHERE object_id = ?1"}) {
      auto statement = connection.prepare(sql);
      statement->bind(1, objectId);
      statement->run();
    }
  // Multi-row statements (sql::rowPlaceholders): a part's 13 rows are one round trip to a server.
  struct Row {
    int component;
    const DescriptorSpan* span;
    int widthClass;
  };
  std::vector<Row> rows;
  std::vector<std::pair<std::string, int>> classes;
  for (const DescriptorComponent& component : components)
    for (const DescriptorSpan& span : component.spans) {
      rows.push_back({component.component, &span, widthClass(span.supportHi - span.supportLo)});
      std::pair<std::string, int> pair(span.descriptor, rows.back().widthClass);
      if (present == nullptr || present->count(pair) == 0) classes.push_back(std::move(pair));
    }
  std::sort(classes.begin(), classes.end());
  classes.erase(std::unique(classes.begin(), classes.end()), classes.end());
  for (size_t from = 0; from < rows.size(); from += sql::kRowsPerStatement) {
    const int n = static_cast<int>(std::min<size_t>(sql::kRowsPerStatement, rows.size() - from));
    auto statement = connection.prepare(
        "INSERT INTO descriptor_index (object_id, kind, component, descriptor, width_class, support_lo, core_lo, core_hi,"
        " support_hi) VALUES " +
        sql::rowPlaceholders(n, 9));
    for (int r = 0; r < n; ++r) {
      const Row& row = rows[from + static_cast<size_t>(r)];
      const DescriptorSpan& span = *row.span;
      const int k = 9 * r;
      statement->bind(k + 1, objectId).bind(k + 2, kind).bind(k + 3, row.component).bind(k + 4, span.descriptor);
      statement->bind(k + 5, row.widthClass).bind(k + 6, span.supportLo).bind(k + 7, span.coreLo);
      statement->bind(k + 8, span.coreHi).bind(k + 9, span.supportHi);
    }
    statement->run();
  }
  for (size_t from = 0; from < classes.size(); from += sql::kRowsPerStatement) {
    const int n = static_cast<int>(std::min<size_t>(sql::kRowsPerStatement, classes.size() - from));
    auto statement =
        connection.prepare("INSERT INTO descriptor_classes (descriptor, width_class) VALUES " +
                           sql::rowPlaceholders(n, 2) + " ON CONFLICT (descriptor, width_class) DO NOTHING");
    for (int r = 0; r < n; ++r)
      statement->bind(2 * r + 1, classes[from + static_cast<size_t>(r)].first)
          .bind(2 * r + 2, classes[from + static_cast<size_t>(r)].second);
    statement->run();
  }
  for (size_t from = 0; from < components.size(); from += sql::kRowsPerStatement) {
    const int n = static_cast<int>(std::min<size_t>(sql::kRowsPerStatement, components.size() - from));
    auto statement = connection.prepare(
        "INSERT INTO descriptor_values (object_id, component, descriptor_values) VALUES " + sql::rowPlaceholders(n, 3));
    for (int r = 0; r < n; ++r) {
      const DescriptorComponent& component = components[from + static_cast<size_t>(r)];
      statement->bind(3 * r + 1, objectId).bind(3 * r + 2, component.component).bindBlob(3 * r + 3, component.values);
    }
    statement->run();
  }
}

void markDescriptorsPending(sql::Connection& connection, int64_t objectId) {
  int64_t generation = 0;
  {
    auto clock =
        connection.prepare("UPDATE descriptor_clock SET generation = generation + 1 WHERE id = 1 RETURNING generation");
    if (clock->step()) generation = clock->columnInt(0);
  }
  auto statement = connection.prepare(
      "INSERT INTO descriptor_pending (object_id, generation) VALUES (?1, ?2)"
      " ON CONFLICT (object_id) DO UPDATE SET generation = excluded.generation");
  statement->bind(1, objectId).bind(2, generation);
  statement->run();
}

void clearDescriptorsPending(sql::Connection& connection, int64_t objectId) {
  auto statement = connection.prepare("DELETE FROM descriptor_pending WHERE object_id = ?1");
  statement->bind(1, objectId);
  statement->run();
}

namespace {

double above(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }
double below(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }

}  // namespace

std::vector<DescriptorRange> descriptorRangesIn(sql::Connection& connection, const DescriptorOverlap& test) {
  std::vector<DescriptorRange> ranges;
  auto statement = connection.prepare("SELECT width_class FROM descriptor_classes WHERE descriptor = ?1");
  statement->bind(1, test.descriptor);
  while (statement->step()) {
    const int c = static_cast<int>(statement->columnInt(0));
    DescriptorRange r;  // support_lo BETWEEN fromLo AND toLo AND support_hi >= leastHi
    r.descriptor = test.descriptor;
    r.widthClass = c;
    if (c == kCrispWidthClass) {
      r.fromLo = test.loIncluded ? test.lo : above(test.lo);
      r.toLo = test.hiIncluded ? test.hi : below(test.hi);
      r.leastHi = r.fromLo;
    } else {
      r.fromLo = lowestSupportLo(test.lo, c);
      r.toLo = test.wideStrict ? below(test.hi) : test.hi;
      r.leastHi = test.wideStrict ? above(test.lo) : test.lo;
    }
    if (r.fromLo <= r.toLo) ranges.push_back(r);
  }
  return ranges;
}

std::string descriptorRangeSql(const DescriptorRangeRead& read) {
  using Order = DescriptorRangeRead::Order;
  if (read.order == Order::kById)
    // descriptor_index_walk (migration 006) holds the class's rows in id order: one entry an id.
    return "SELECT object_id, support_lo, support_hi FROM descriptor_index WHERE kind = ?1 AND descriptor = ?2"
           " AND width_class = ?3 AND object_id > ?7 AND object_id <= ?8 AND support_lo BETWEEN ?4 AND ?5"
           " AND support_hi >= ?6 ORDER BY object_id";
  const std::string way = read.order == Order::kDescending ? " DESC" : "";
  return "SELECT object_id, support_lo, support_hi FROM descriptor_index WHERE kind = ?1 AND descriptor = ?2"
         " AND width_class = ?3 AND support_lo BETWEEN ?4 AND ?5 AND support_hi >= ?6 ORDER BY support_lo" +
         way + ", support_hi" + way + ", object_id" + way + (read.limit > 0 ? " LIMIT ?7" : "");
}

void descriptorRangeRowsIn(sql::Connection& connection, const std::string& kind, const DescriptorRange& range,
                           std::vector<DescriptorCandidate>& rows, const DescriptorRangeRead& read) {
  auto scan = connection.prepare(descriptorRangeSql(read));
  scan->bind(1, kind).bind(2, range.descriptor).bind(3, range.widthClass).bind(4, range.fromLo).bind(5, range.toLo);
  scan->bind(6, range.leastHi);
  if (read.order == DescriptorRangeRead::Order::kById) scan->bind(7, read.afterId).bind(8, read.throughId);
  else if (read.limit > 0) scan->bind(7, read.limit);
  while (scan->step()) rows.push_back({scan->columnInt(0), scan->columnDouble(1), scan->columnDouble(2), false});
}

std::vector<int64_t> pendingDescriptorIdsIn(sql::Connection& connection, const std::string& kind) {
  // Driven by the (usually empty) pending table, not by every object of the kind: SQLite's CROSS
  // JOIN fixes that order; PostgreSQL's planner finds it from the statistics.
  auto pending = connection.prepare(
      connection.dialect() == sql::Dialect::kSqlite
          ? "SELECT p.object_id FROM descriptor_pending p CROSS JOIN objects o ON o.id = p.object_id WHERE o.kind = ?1"
          : "SELECT p.object_id FROM descriptor_pending p JOIN objects o ON o.id = p.object_id WHERE o.kind = ?1");
  pending->bind(1, kind);
  std::vector<int64_t> ids;
  while (pending->step()) ids.push_back(pending->columnInt(0));
  return ids;
}

std::vector<DescriptorCandidate> descriptorCandidatesIn(sql::Connection& connection, const std::string& kind,
                                                        const DescriptorOverlap& test) {
  std::vector<DescriptorCandidate> rows;
  for (const DescriptorRange& range : descriptorRangesIn(connection, test))
    descriptorRangeRowsIn(connection, kind, range, rows);
  for (int64_t id : pendingDescriptorIdsIn(connection, kind)) rows.push_back({id, 0, 0, true});
  return rows;
}

}  // namespace fsdb
