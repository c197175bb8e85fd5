// The descriptor index of the store (db/store.h, migration 002): rows written with the object,
// replaced by put, removed by delete, written by createBatch; pending marks; the width-class
// overlap scan against a brute-force overlap; migration of a database made before 002.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>

#include "db/content_hash.h"
#include "db/descriptor_index.h"
#include "db/migrations.h"
#include "db/sqlite.h"
#include "db/store.h"
#include "tests/db/temp_dir.h"
#include "tests/db/test_database.h"

namespace fsdb {
namespace {

DescriptorComponent component(int index, double lo, double hi, const std::string& values = "v") {
  DescriptorComponent c;
  c.component = index;
  c.spans.push_back({"bendness", lo, (lo + hi) / 2, (lo + hi) / 2, hi});
  c.spans.push_back({"size", 0.5, 0.5, 0.5, 0.5});
  c.values = values;
  return c;
}

NewObject part(const std::string& name, double lo, double hi, const std::string& salt = "") {
  const std::string document = "{\"name\":\"" + name + "\"" + salt + "}";
  NewObject object;
  object.kind = "part";
  object.name = name;
  object.documentJson = document;
  object.contentHash = contentHash(document);
  object.descriptors.push_back(component(0, lo, hi, "values of " + name + salt));
  return object;
}

NewObject shapeOf(const std::string& name, const std::vector<std::string>& parts, double lo, double hi) {
  const std::string document = "{\"shape\":\"" + name + "\"}";
  NewObject object;
  object.kind = "shape";
  object.name = name;
  object.documentJson = document;
  object.contentHash = contentHash(document);
  for (size_t i = 0; i < parts.size(); ++i) {
    object.references.push_back({"part", std::nullopt, parts[i], "tree.children[" + std::to_string(i) + "].part"});
    object.descriptors.push_back(component(static_cast<int>(i), lo, hi));
  }
  return object;
}

// The distinct ids descriptorCandidates finds, sorted.
std::vector<int64_t> ids(const Store& store, const std::string& kind, const DescriptorOverlap& test) {
  std::vector<int64_t> out;
  for (const DescriptorCandidate& c : store.descriptorCandidates(kind, test)) out.push_back(c.id);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<int64_t> pendingIds(const Store& store) {
  std::vector<int64_t> ids;
  for (const PendingDescriptors& p : store.pendingDescriptors()) ids.push_back(p.id);
  return ids;
}

// On both backends (tests/db/test_database.h): the level scan's bounds and answers must not
// depend on the engine.
class DescriptorIndexTest : public testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    FSDB_USE_BACKEND(GetParam());
    store = Store::open(database.location());
  }
  test::TestDatabase database{GetParam()};
  std::unique_ptr<Store> store;
};

TEST(WidthClass, BoundsTheWidth) {
  EXPECT_EQ(widthClass(0), kCrispWidthClass);
  std::mt19937 rng(5);
  for (int i = 0; i < 10000; ++i) {
    const double w = std::ldexp(std::uniform_real_distribution<double>(0.5, 1.0)(rng),
                                std::uniform_int_distribution<int>(-40, 10)(rng));
    const int c = widthClass(w);
    EXPECT_LT(w, std::ldexp(1.0, c));
    EXPECT_GE(w, std::ldexp(1.0, c - 1));
    const double lo = std::uniform_real_distribution<double>(-5, 5)(rng);
    // A row of width w meeting [lo, ...] has support_lo >= lo - w >= lowestSupportLo.
    EXPECT_LE(lowestSupportLo(lo, c), lo - w);
  }
  EXPECT_EQ(lowestSupportLo(0.25, kCrispWidthClass), 0.25);
}

TEST_P(DescriptorIndexTest, CreateWritesRowsAndCandidatesOverlap) {
  const int64_t id = store->create(part("bent", 0.2, 0.4)).id;
  const auto rows = store->descriptorRows(id);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].component, 0);
  EXPECT_EQ(rows[0].values, "values of bent");
  ASSERT_EQ(rows[0].spans.size(), 2u);
  EXPECT_EQ(rows[0].spans[0].descriptor, "bendness");
  EXPECT_EQ(rows[0].spans[0].supportLo, 0.2);
  EXPECT_EQ(rows[0].spans[0].coreLo, 0.30000000000000004);
  EXPECT_EQ(rows[0].spans[0].supportHi, 0.4);
  EXPECT_TRUE(pendingIds(*store).empty());
  const auto found = store->descriptorCandidates("part", {"bendness", 0.3, 0.35});
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].supportLo, 0.2);
  EXPECT_EQ(found[0].supportHi, 0.4);
  EXPECT_FALSE(found[0].pending);

  EXPECT_EQ(ids(*store, "part", {"bendness", 0.3, 0.35}), std::vector<int64_t>{id});
  EXPECT_EQ(ids(*store, "part", {"bendness", 0.4, 0.9}), std::vector<int64_t>{id});  // touching
  EXPECT_EQ(ids(*store, "part", {"bendness", 0.0, 0.2}), std::vector<int64_t>{id});
  EXPECT_TRUE(ids(*store, "part", {"bendness", 0.41, 0.9}).empty());
  EXPECT_TRUE(ids(*store, "part", {"bendness", 0.0, 0.19}).empty());
  EXPECT_TRUE(ids(*store, "shape", {"bendness", 0.0, 1.0}).empty());
  EXPECT_EQ(ids(*store, "part", {"size", 0.5, 0.5}), std::vector<int64_t>{id});  // crisp
  // Excluded ends and strict overlaps: a crisp 0.5 is not in (0.5, 1]; [0.2, 0.4] does not meet
  // (0.4, 0.9) strictly.
  EXPECT_TRUE(ids(*store, "part", {"size", 0.5, 1.0, false, true}).empty());
  EXPECT_TRUE(ids(*store, "part", {"size", 0.0, 0.5, true, false}).empty());
  EXPECT_EQ(ids(*store, "part", {"size", 0.0, 0.5, false, true}), std::vector<int64_t>{id});
  EXPECT_TRUE(ids(*store, "part", {"bendness", 0.4, 0.9, true, true, true}).empty());
  EXPECT_EQ(ids(*store, "part", {"bendness", 0.39, 0.9, true, true, true}), std::vector<int64_t>{id});
  EXPECT_TRUE(ids(*store, "part", {"twistness", 0.0, 1.0}).empty());

  const auto objects = store->indexedObjects("part", {id, id + 100});
  ASSERT_EQ(objects.size(), 1u);
  EXPECT_EQ(objects[0].name, "bent");
  EXPECT_FALSE(objects[0].pending);
  ASSERT_EQ(objects[0].components.size(), 1u);
  EXPECT_EQ(objects[0].components[0].second, "values of bent");
  EXPECT_TRUE(store->indexedObjects("shape", {id}).empty());
  EXPECT_EQ(store->objectIds("part"), std::vector<int64_t>{id});
}

// objectVersions: every live object of the kind, by id, with its name and latest version.
TEST_P(DescriptorIndexTest, ObjectVersionsFollowPutsAndDeletes) {
  const int64_t a = store->create(part("a", 0.2, 0.4)).id;
  const int64_t b = store->create(part("b", 0.2, 0.4)).id;
  store->put(a, part("a", 0.7, 0.8, ",\"v\":2"));
  std::vector<ObjectVersion> v = store->objectVersions("part");
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[0].id, a);
  EXPECT_EQ(v[0].name, "a");
  EXPECT_EQ(v[0].latestVersion, 2);
  EXPECT_EQ(v[1].id, b);
  EXPECT_EQ(v[1].latestVersion, 1);
  store->remove("part", b, false);
  v = store->objectVersions("part");
  ASSERT_EQ(v.size(), 1u);
  EXPECT_EQ(v[0].id, a);
  EXPECT_TRUE(store->objectVersions("shape").empty());
}

TEST_P(DescriptorIndexTest, PutReplacesAndDeleteRemoves) {
  const int64_t id = store->create(part("p", 0.2, 0.4)).id;
  store->put(id, part("p", 0.7, 0.8, ",\"v\":2"));
  EXPECT_TRUE(ids(*store, "part", {"bendness", 0.2, 0.4}).empty());
  EXPECT_EQ(ids(*store, "part", {"bendness", 0.75, 0.75}), std::vector<int64_t>{id});
  const auto rows = store->descriptorRows(id);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].values, "values of p,\"v\":2");
  EXPECT_EQ(rows[0].spans.size(), 2u);

  store->remove("part", id, false);
  EXPECT_TRUE(store->descriptorRows(id).empty());
  EXPECT_TRUE(ids(*store, "part", {"bendness", 0, 1}).empty());
  auto db = database.connect();
  for (const char* table : {"descriptor_index", "descriptor_values", "descriptor_pending"}) {
    auto statement = db->prepare(std::string("SELECT COUNT(*) FROM ") + table);
    ASSERT_TRUE(statement->step());
    EXPECT_EQ(statement->columnInt(0), 0) << table;
  }
}

TEST_P(DescriptorIndexTest, CreateBatchWritesRowsOfEveryItemThatCommits) {
  store->create(part("taken", 0.1, 0.2));
  const auto results =
      store->createBatch({part("a", 0.5, 0.6), part("taken", 0.5, 0.6), part("b", 0.55, 0.9)}, BulkMode::kCreate);
  ASSERT_TRUE(results[0].id && results[2].id);
  EXPECT_FALSE(results[1].id);
  EXPECT_EQ(ids(*store, "part", {"bendness", 0.58, 0.59}),
            (std::vector<int64_t>{*results[0].id, *results[2].id}));
}

// createBatch skips the class rows it read before writing (descriptorClassesIn); a class an item
// brings is still recorded, in its batch and in later ones, so the overlap scan finds its rows.
TEST_P(DescriptorIndexTest, CreateBatchRecordsTheClassesItsItemsBring) {
  store->create(part("first", 0.2, 0.4));
  const auto one = store->createBatch({part("same class", 0.25, 0.45), part("wider", 0.0, 3.0)}, BulkMode::kCreate);
  const auto two = store->createBatch({part("wider too", 0.1, 3.1), part("widest", -40, 40), part("crisp", 0.3, 0.3)},
                                      BulkMode::kCreate);
  for (const auto& results : {one, two})
    for (const BulkItemResult& r : results) ASSERT_TRUE(r.id) << r.errorMessage;
  EXPECT_EQ(ids(*store, "part", {"bendness", 0.3, 0.3}).size(), 6u);
  EXPECT_EQ(ids(*store, "part", {"bendness", 2.5, 2.5}),
            (std::vector<int64_t>{*one[1].id, *two[0].id, *two[1].id}));
}

TEST(DescriptorClasses, AreThePairsOfTheTable) {
  TempDir dir;
  Store::open(dir.file("classes.sqlite"))->create(part("p", 0.2, 0.4));
  sqlite::Connection db(dir.file("classes.sqlite"));
  EXPECT_EQ(descriptorClassesIn(db),
            (DescriptorClasses{{"bendness", widthClass(0.2)}, {"size", kCrispWidthClass}}));
}

TEST_P(DescriptorIndexTest, ReferencesAndNewVersionsMarkPending) {
  const int64_t bolt = store->create(part("bolt", 0.2, 0.4)).id;
  const int64_t plain = store->create(part("plain", 0.2, 0.4)).id;
  // A shape written with references: its rows came from documents read before the write.
  const int64_t frame = store->create(shapeOf("frame", {"bolt"}, 0.2, 0.4)).id;
  EXPECT_EQ(pendingIds(*store), std::vector<int64_t>{frame});
  // Pending objects are candidates of every overlap of their kind.
  EXPECT_EQ(ids(*store, "shape", {"bendness", 0.9, 1.0}), std::vector<int64_t>{frame});
  EXPECT_TRUE(store->indexedObjects("shape", {frame})[0].pending);

  auto pending = store->pendingDescriptors();
  ASSERT_EQ(pending.size(), 1u);
  EXPECT_EQ(pending[0].kind, "shape");
  EXPECT_EQ(store->replaceDescriptors({{pending[0], {component(0, 0.25, 0.3)}}}), 1u);
  EXPECT_TRUE(pendingIds(*store).empty());
  EXPECT_TRUE(ids(*store, "shape", {"bendness", 0.9, 1.0}).empty());
  EXPECT_FALSE(store->indexedObjects("shape", {frame})[0].pending);
  EXPECT_EQ(store->replaceDescriptors({{pending[0], {}}}), 0u);  // no longer pending

  // A new version of the bolt changes the frame's components: the frame is pending again, the
  // plain part (not reaching the bolt) is not.
  store->put(bolt, part("bolt", 0.9, 1.0, ",\"v\":2"));
  EXPECT_EQ(pendingIds(*store), std::vector<int64_t>{frame});
  const auto stale = store->pendingDescriptors();
  // Another write in between gives a new generation: the stale recomputation is refused.
  store->put(bolt, part("bolt", 0.9, 1.0, ",\"v\":3"));
  EXPECT_EQ(store->replaceDescriptors({{stale[0], {component(0, 0.0, 0.1)}}}), 0u);
  const auto fresh = store->pendingDescriptors();
  EXPECT_GT(fresh[0].generation, stale[0].generation);
  EXPECT_EQ(store->replaceDescriptors({{fresh[0], {component(0, 0.9, 1.0)}}}), 1u);
  EXPECT_EQ(ids(*store, "shape", {"bendness", 0.95, 0.95}), std::vector<int64_t>{frame});

  // A put that writes the object's own rows without references clears its mark.
  NewObject frame2 = shapeOf("frame", {}, 0.1, 0.2);
  frame2.descriptors.push_back(component(0, 0.1, 0.2));
  store->put(frame, frame2);
  EXPECT_TRUE(pendingIds(*store).empty());
  (void)plain;
}

TEST_P(DescriptorIndexTest, OverlapScanEqualsBruteForce) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<std::pair<double, double>> supports;
  std::vector<NewObject> items;
  for (int i = 0; i < 400; ++i) {
    const double lo = unit(rng);
    const double r = unit(rng);
    // crisp, narrow and wide supports, so several width classes hold rows
    const double width = r < 0.3 ? 0.0 : r < 0.8 ? std::pow(10.0, -1 - 4 * unit(rng)) : unit(rng);
    supports.emplace_back(lo, lo + width);
    items.push_back(part("p" + std::to_string(i), lo, lo + width));
  }
  const auto results = store->createBatch(items, BulkMode::kCreate);
  for (int q = 0; q < 600; ++q) {
    DescriptorOverlap test{"bendness", unit(rng) * 1.2 - 0.1, 0};
    test.hi = test.lo + (unit(rng) < 0.3 ? 0.0 : unit(rng) * 0.3);
    if (q % 10 == 0) test.lo = supports[q % supports.size()].first;  // exactly on a support end
    if (q % 10 == 1) test.hi = supports[q % supports.size()].second;
    if (test.hi < test.lo) test.hi = test.lo;
    test.loIncluded = q % 3 != 0;
    test.hiIncluded = q % 5 != 0;
    test.wideStrict = q % 2 == 0;
    std::vector<int64_t> expected;
    for (size_t i = 0; i < supports.size(); ++i) {
      const double slo = supports[i].first, shi = supports[i].second;
      bool pass;
      if (slo == shi)
        pass = (slo > test.lo || (slo == test.lo && test.loIncluded)) && (slo < test.hi || (slo == test.hi && test.hiIncluded));
      else if (test.wideStrict)
        pass = slo < test.hi && shi > test.lo;
      else
        pass = slo <= test.hi && shi >= test.lo;
      if (pass) expected.push_back(*results[i].id);
    }
    EXPECT_EQ(ids(*store, "part", test), expected) << test.lo << " " << test.hi << " " << q;
    // The same rows in parts: one range per class present, each row in exactly one range.
    std::vector<int64_t> parts;
    std::vector<int> classes;
    for (const DescriptorRange& range : store->descriptorRanges(test)) {
      EXPECT_EQ(range.descriptor, "bendness");
      EXPECT_LE(range.fromLo, range.toLo);
      classes.push_back(range.widthClass);
      for (const DescriptorCandidate& c : store->descriptorRangeRows("part", range)) {
        EXPECT_EQ(widthClass(c.supportHi - c.supportLo), range.widthClass);
        EXPECT_FALSE(c.pending);
        parts.push_back(c.id);
      }
    }
    std::sort(parts.begin(), parts.end());
    EXPECT_EQ(parts, expected) << q;
    std::sort(classes.begin(), classes.end());
    EXPECT_TRUE(std::adjacent_find(classes.begin(), classes.end()) == classes.end());
  }
  EXPECT_TRUE(store->pendingDescriptorIds("part").empty());
}

// The reads of one range the level scan uses (DescriptorRangeRead): by value either way with a
// limit (crisp rows: by value, then by id, across runs of equal values), and by id in a window.
TEST_P(DescriptorIndexTest, RangeRowsReadByValueOrInIdWindows) {
  EXPECT_EQ(store->lastObjectId(), 0);
  std::vector<NewObject> items;
  for (int i = 0; i < 40; ++i) {
    const double x = 0.1 * (1 + i % 3);  // runs of equal values, ids interleaved
    items.push_back(i % 5 == 4 ? part("w" + std::to_string(i), x, x + 0.05) : part("c" + std::to_string(i), x, x));
  }
  std::vector<std::pair<double, int64_t>> crisp;  // (value, id) of the crisp rows
  const auto results = store->createBatch(items, BulkMode::kCreate);
  for (size_t i = 0; i < items.size(); ++i)
    if (i % 5 != 4) crisp.emplace_back(0.1 * (1 + i % 3), *results[i].id);
  std::sort(crisp.begin(), crisp.end());
  const int64_t last = *results.back().id;
  EXPECT_EQ(store->lastObjectId(), last);

  DescriptorRange range;
  for (const DescriptorRange& r : store->descriptorRanges({"bendness", 0.0, 1.0}))
    if (r.widthClass == kCrispWidthClass) range = r;
  ASSERT_EQ(range.widthClass, kCrispWidthClass);
  using Order = DescriptorRangeRead::Order;
  const auto read = [&](const DescriptorRangeRead& how) {
    std::vector<std::pair<double, int64_t>> out;
    for (const DescriptorCandidate& c : store->descriptorRangeRows("part", range, how)) {
      EXPECT_EQ(c.supportLo, c.supportHi);
      out.emplace_back(c.supportLo, c.id);
    }
    return out;
  };
  EXPECT_EQ(read({Order::kAscending}), crisp);
  using Rows = std::vector<std::pair<double, int64_t>>;
  EXPECT_EQ(read({Order::kAscending, 7}), Rows(crisp.begin(), crisp.begin() + 7));
  EXPECT_EQ(read({Order::kDescending, 7}), Rows(crisp.rbegin(), crisp.rbegin() + 7));
  EXPECT_EQ(read({Order::kDescending, 1000}), Rows(crisp.rbegin(), crisp.rend()));
  // A window of ids: (after, through], by id.
  const int64_t after = *results[9].id, through = *results[25].id;
  std::vector<std::pair<double, int64_t>> window;
  for (const auto& row : crisp)
    if (row.second > after && row.second <= through) window.push_back(row);
  std::sort(window.begin(), window.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  EXPECT_EQ(read({Order::kById, 0, after, through}), window);
  EXPECT_TRUE(read({Order::kById, 0, last, last + 100}).empty());
  // The walk stays inside the range: a narrower one drops the other values.
  range.fromLo = range.toLo = 0.2;
  range.leastHi = 0.2;
  for (const auto& row : read({Order::kById, 0, 0, last})) EXPECT_EQ(row.first, 0.2);
  EXPECT_EQ(read({Order::kById, 0, 0, last}).size(), read({Order::kAscending}).size());
  // The supports of one descriptor of given objects (more ids than one statement takes, one
  // unknown id): each object's row, found by its key.
  std::vector<int64_t> ids{last + 7};
  std::map<int64_t, std::pair<double, double>> expected;
  for (size_t i = 0; i < items.size(); i += 2) {
    ids.push_back(*results[i].id);
    const DescriptorSpan& span = items[i].descriptors[0].spans[0];
    expected[*results[i].id] = {span.supportLo, span.supportHi};
  }
  for (int copy = 0; copy < 3; ++copy) ids.insert(ids.end(), ids.begin(), ids.begin() + 20);  // 81 ids
  std::map<int64_t, std::pair<double, double>> found;
  for (const DescriptorCandidate& c : store->descriptorSupports("bendness", ids)) found[c.id] = {c.supportLo, c.supportHi};
  EXPECT_EQ(found, expected);
  EXPECT_TRUE(store->descriptorSupports("twistness", ids).empty());  // no rows of that descriptor
}

TEST_P(DescriptorIndexTest, PendingIdsAreThePendingObjectsOfTheKind) {
  const int64_t a = store->create(part("a", 0.1, 0.2)).id;
  const int64_t s = store->create(shapeOf("s", {"a"}, 0.1, 0.2)).id;  // references: pending
  EXPECT_TRUE(store->pendingDescriptorIds("part").empty());
  EXPECT_EQ(store->pendingDescriptorIds("shape"), std::vector<int64_t>{s});
  // Pending objects are also descriptorCandidates' pending rows.
  std::vector<int64_t> pending;
  for (const DescriptorCandidate& c : store->descriptorCandidates("shape", {"bendness", 0.9, 1.0}))
    if (c.pending) pending.push_back(c.id);
  EXPECT_EQ(pending, std::vector<int64_t>{s});
  EXPECT_NE(a, s);
}

TEST(DescriptorIndexMigration, ObjectsOfAnOlderDatabaseArePending) {
  TempDir dir;
  const std::string path = dir.file("old.db");
  {
    sqlite::Connection db(path);
    ASSERT_EQ(applyMigrations(db, {embeddedMigrations().front()}), 1);
    db.exec("INSERT INTO objects (kind, name, latest_version) VALUES ('part', 'old', 1), ('shape', 'older', 1)");
    db.exec("INSERT INTO versions VALUES (1, 1, '{}', 'h', '2026-01-01T00:00:00.000Z'),"
            " (2, 1, '{}', 'h', '2026-01-01T00:00:00.000Z')");
  }
  auto store = Store::open(path);
  EXPECT_EQ(store->schemaVersion(), embeddedMigrations().back().first);
  EXPECT_EQ(pendingIds(*store), (std::vector<int64_t>{1, 2}));
  EXPECT_EQ(ids(*store, "part", {"bendness", 0, 1}), std::vector<int64_t>{1});
  EXPECT_EQ(ids(*store, "shape", {"size", 0, 1}), std::vector<int64_t>{2});
  // The next generation is above the migration's.
  const int64_t id = store->create(part("new", 0.1, 0.2)).id;
  store->put(id, part("new", 0.1, 0.2, ",\"v\":2"));
  EXPECT_EQ(pendingIds(*store), (std::vector<int64_t>{1, 2}));
}

INSTANTIATE_TEST_SUITE_P(Backends, DescriptorIndexTest, testing::ValuesIn(test::kBackends));

}  // namespace
}  // namespace fsdb
