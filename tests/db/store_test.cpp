// db/store.h: the Store contract, method by method, on both backends: a real SQLite file in a
// temporary directory and a fresh schema on the test PostgreSQL cluster (tests/db/test_database.h).
#include "db/store.h"

#include <gtest/gtest.h>

#include <atomic>
#include <regex>
#include <thread>

#include "db/content_hash.h"
#include "db/migrations.h"
#include "db/sqlite.h"
#include "geometry/core/error.h"
#include "tests/db/expect_error.h"
#include "tests/db/temp_dir.h"
#include "tests/db/test_database.h"

namespace fsdb {
namespace {

NewObject part(const std::string& name, const std::string& document = "{\"eps1\":1}") {
  return NewObject{"part", name, document, contentHash(document), {}, {}, {}, {}};
}

// A shape whose tree is a union of "ref" leaves naming `children` (parts by default).
NewObject shape(const std::string& name, const std::vector<ObjectReference>& children, const std::string& salt = "") {
  std::string document = "{\"union\":" + std::to_string(children.size()) + salt + "}";
  NewObject object{"shape", name, document, contentHash(document), children, {}, {}, {}};
  object.nodes.push_back({0, -1, 0, "union", "", -1, ""});
  for (size_t i = 0; i < children.size(); ++i)
    object.nodes.push_back(
        {static_cast<int>(i + 1), 0, static_cast<int>(i), "ref", "", static_cast<int>(i), "{\"translate\":[1,0,0]}"});
  return object;
}

ObjectReference byName(const std::string& kind, const std::string& name, int index = 0) {
  return {kind, std::nullopt, name, "tree.children[" + std::to_string(index) + "]." + kind};
}

ObjectReference byId(const std::string& kind, int64_t id, int index = 0) {
  return {kind, id, "", "tree.children[" + std::to_string(index) + "].ref"};
}

class StoreTest : public testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    FSDB_USE_BACKEND(GetParam());
    store = Store::open(database.location());
  }
  test::TestDatabase database{GetParam()};
  const std::string& path = database.location();
  std::unique_ptr<Store> store;

  // Rows of `table` with object_id = id, read through a separate connection.
  int64_t rows(const std::string& table, const std::string& column, int64_t id) {
    auto db = database.connect();
    auto statement = db->prepare("SELECT COUNT(*) FROM " + table + " WHERE " + column + " = ?1");
    statement->bind(1, id);
    EXPECT_TRUE(statement->step());
    return statement->columnInt(0);
  }
};

TEST_P(StoreTest, OpenMigrates) {
  EXPECT_EQ(store->backend(), GetParam());
  EXPECT_EQ(store->schemaVersion(),
            GetParam() == "sqlite" ? embeddedMigrations().back().first : embeddedPostgresMigrations().back().first);
  EXPECT_EQ(embeddedMigrations().back().first, embeddedPostgresMigrations().back().first);
  EXPECT_EQ(store->integrityCheck(), "ok");
}

TEST(SqliteStoreOpen, CreatesParentDirectories) {
  TempDir dir;
  const std::string path = dir.file("nested/dir/fsdb.db");
  auto store = Store::open(path);
  EXPECT_TRUE(std::filesystem::exists(path));
  EXPECT_EQ(store->path(), path);
}

TEST(SqliteStoreOpen, FailsWithPathWhenItCannot) {
  TempDir dir;
  std::string blocker = dir.file("a_file");
  { sqlite::Connection make(blocker); }  // a regular file where a directory is needed
  std::string bad = blocker + "/sub/x.db";
  auto message = expectError([&] { Store::open(bad); }, errc::kStorage);
  FSDB_EXPECT_CONTAINS(message, bad);
  expectError([&] { Store::open(":memory:"); }, errc::kStorage);
}

// A URL that is not PostgreSQL's is an error naming both forms fsdb takes, not a new SQLite file
// in a folder named after the scheme (before: "postgresql:/db" made a folder "postgresql:").
TEST(StoreOpen, AUrlOfAnotherSchemeIsAClearErrorAndCreatesNothing) {
  TempDir dir;
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir.file(""));
  for (const std::string location : {"postgresql:/db", "postgres:db", "mysql://u:pw@host/db", "sqlite:///x.db",
                                     "sqlite:x.db", "FILE:x.db", "http://host/x"}) {
    const std::string message = expectError([&] { Store::open(location); }, errc::kStorage);
    FSDB_EXPECT_CONTAINS(message, "postgresql://user@host:5432/database");
    FSDB_EXPECT_CONTAINS(message, "SQLite file path");
    EXPECT_EQ(message.find("pw"), std::string::npos) << message;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.file("")));
  // A file path that merely holds a colon is still a file path.
  Store::open("my:catalogue.sqlite");
  Store::open("./postgresql:/db.sqlite");
  std::filesystem::current_path(cwd);
  EXPECT_TRUE(std::filesystem::exists(dir.file("my:catalogue.sqlite")));
}

TEST_P(StoreTest, CreateAndGet) {
  auto created = store->create(part("bolt"));
  EXPECT_GT(created.id, 0);
  EXPECT_EQ(created.version, 1);
  EXPECT_EQ(created.latestVersion, 1);
  EXPECT_TRUE(std::regex_match(created.createdAt, std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z)")))
      << created.createdAt;
  auto got = store->get("part", created.id);
  EXPECT_EQ(got.name, "bolt");
  EXPECT_EQ(got.kind, "part");
  EXPECT_EQ(got.documentJson, "{\"eps1\":1}");
  EXPECT_EQ(got.contentHash, contentHash("{\"eps1\":1}"));
  EXPECT_EQ(got.createdAt, created.createdAt);
}

TEST_P(StoreTest, GetOfWrongKindOrMissingIsNotFound) {
  auto bolt = store->create(part("bolt"));
  expectError([&] { store->get("shape", bolt.id); }, errc::kNotFound);
  expectError([&] { store->get("part", bolt.id + 100); }, errc::kNotFound);
  auto message = expectError([&] { store->get("part", bolt.id, 7); }, errc::kNotFound);
  FSDB_EXPECT_CONTAINS(message, std::to_string(bolt.id));
  FSDB_EXPECT_CONTAINS(message, "version 7");
}

TEST_P(StoreTest, PutAddsVersionsAndOldOnesStayReadable) {
  auto bolt = store->create(part("bolt", "{\"v\":1}"));
  auto second = store->put(bolt.id, part("bolt", "{\"v\":2}"));
  EXPECT_EQ(second.id, bolt.id);
  EXPECT_EQ(second.version, 2);
  EXPECT_EQ(store->get("part", bolt.id).documentJson, "{\"v\":2}");
  auto first = store->get("part", bolt.id, 1);
  EXPECT_EQ(first.documentJson, "{\"v\":1}");
  EXPECT_EQ(first.version, 1);
  EXPECT_EQ(first.latestVersion, 2);
  EXPECT_EQ(rows("versions", "object_id", bolt.id), 2);
}

TEST_P(StoreTest, PutRefusesRenameAndOtherKinds) {
  auto bolt = store->create(part("bolt"));
  expectError([&] { store->put(bolt.id, part("nut")); }, errc::kConflict, "name");
  auto asShape = shape("bolt", {});
  expectError([&] { store->put(bolt.id, asShape); }, errc::kNotFound);
  expectError([&] { store->put(bolt.id + 50, part("bolt")); }, errc::kNotFound);
  EXPECT_EQ(store->get("part", bolt.id).latestVersion, 1);
}

TEST_P(StoreTest, NameConflictWithinKindOnly) {
  store->create(part("bolt"));
  expectError([&] { store->create(part("bolt")); }, errc::kConflict, "name");
  EXPECT_NO_THROW(store->create(shape("bolt", {})));  // names are per kind
  auto unknownKind = part("x");
  unknownKind.kind = "widget";
  expectError([&] { store->create(unknownKind); }, errc::kInvalidDocument, "kind");
}

TEST_P(StoreTest, IdsAreNeverReused) {
  auto first = store->create(part("bolt"));
  store->remove("part", first.id, false);
  auto again = store->create(part("bolt"));  // the name is free again, the id is not
  EXPECT_GT(again.id, first.id);
}

TEST_P(StoreTest, ReferencesResolveByNameAndId) {
  auto bolt = store->create(part("bolt"));
  auto nut = store->create(part("nut"));
  auto s = store->create(shape("pair", {byName("part", "bolt", 0), byId("part", nut.id, 1)}));
  EXPECT_EQ(s.references, (std::vector<int64_t>{bolt.id, nut.id}));
  EXPECT_EQ(store->get("shape", s.id).references, (std::vector<int64_t>{bolt.id, nut.id}));
  // csg_nodes got the resolved ids of the ref leaves.
  auto db = database.connect();
  auto nodes = db->prepare("SELECT ref_id FROM csg_nodes WHERE object_id = ?1 ORDER BY node");
  nodes->bind(1, s.id);
  std::vector<std::optional<int64_t>> refs;
  while (nodes->step()) refs.push_back(nodes->columnOptionalInt(0));
  EXPECT_EQ(refs, (std::vector<std::optional<int64_t>>{std::nullopt, bolt.id, nut.id}));
}

TEST_P(StoreTest, UnknownReferenceNamesPathAndLeavesNothing) {
  auto bolt = store->create(part("bolt"));
  auto message = expectError(
      [&] {
        store->create(shape("s", {byName("part", "bolt", 0), byName("part", "washer", 1)}));
      },
      errc::kUnknownReference, "tree.children[1].part");
  EXPECT_EQ(message, "unknown part 'washer'");
  // An id of the wrong kind is unknown too.
  expectError([&] { store->create(shape("s", {byId("shape", bolt.id)})); }, errc::kUnknownReference,
              "tree.children[0].ref");
  EXPECT_FALSE(store->find(byName("shape", "s")));
  EXPECT_EQ(store->counts(), (std::map<std::string, int64_t>{{"part", 1}}));
  auto db = database.connect();
  auto versions = db->prepare("SELECT COUNT(*) FROM versions");
  ASSERT_TRUE(versions->step());
  EXPECT_EQ(versions->columnInt(0), 1);  // bolt's only
}

TEST_P(StoreTest, CycleOnPutIsRefused) {
  auto b = store->create(shape("B", {}));
  auto a = store->create(shape("A", {byName("shape", "B")}));
  auto message = expectError([&] { store->put(b.id, shape("B", {byName("shape", "A", 0)})); }, errc::kReferenceCycle,
                             "tree.children[0].shape");
  FSDB_EXPECT_CONTAINS(message, "'A'");
  // Self-reference by id is a cycle too.
  expectError([&] { store->put(a.id, shape("A", {byId("shape", a.id)})); }, errc::kReferenceCycle,
              "tree.children[0].ref");
  EXPECT_EQ(store->get("shape", b.id).latestVersion, 1);
  EXPECT_TRUE(store->get("shape", b.id).references.empty());
}

TEST_P(StoreTest, FindByNameAndId) {
  auto bolt = store->create(part("bolt"));
  store->put(bolt.id, part("bolt", "{\"v\":2}"));
  auto found = store->find(byName("part", "bolt"));
  ASSERT_TRUE(found);
  EXPECT_EQ(found->id, bolt.id);
  EXPECT_EQ(found->version, 2);
  EXPECT_TRUE(store->find(byId("part", bolt.id)));
  EXPECT_FALSE(store->find(byId("shape", bolt.id)));
  EXPECT_FALSE(store->find(byName("part", "nut")));
}

TEST_P(StoreTest, ListPagesByIdAndFilters) {
  std::vector<int64_t> ids;
  for (int i = 0; i < 5; ++i) ids.push_back(store->create(part("p" + std::to_string(i))).id);
  store->create(shape("s", {}));
  ListQuery query;
  query.kind = "part";
  query.limit = 2;
  auto page1 = store->list(query);
  ASSERT_EQ(page1.size(), 2u);
  EXPECT_EQ(page1[0].id, ids[0]);
  query.afterId = page1.back().id;
  auto page2 = store->list(query);
  ASSERT_EQ(page2.size(), 2u);
  EXPECT_EQ(page2[0].id, ids[2]);
  query.afterId = 0;
  query.limit = 100;
  EXPECT_EQ(store->list(query).size(), 5u);
  store->put(ids[3], part("p3", "{\"v\":2}"));
  query.name = "p3";
  auto latest = store->list(query);
  ASSERT_EQ(latest.size(), 1u);
  EXPECT_EQ(latest[0].version, 2);
  query.version = 1;
  auto old = store->list(query);
  ASSERT_EQ(old.size(), 1u);
  EXPECT_EQ(old[0].version, 1);
  EXPECT_EQ(old[0].documentJson, "{\"eps1\":1}");
}

// named: every spelling and kind in one statement, the latest versions, live objects only.
TEST_P(StoreTest, NamedFindsAnyOfTheNamesAcrossKinds) {
  const int64_t bolt = store->create(part("bolt")).id;
  const int64_t pair = store->create(shape("the pair", {})).id;
  store->create(part("nut"));
  store->put(bolt, part("bolt", "{\"v\":2}"));
  const auto found = store->named({"bolt", "the-pair", "the pair", "washer"}, {"part", "shape"});
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].id, bolt);
  EXPECT_EQ(found[0].version, 2);
  EXPECT_EQ(found[1].id, pair);
  EXPECT_EQ(found[1].kind, "shape");
  EXPECT_TRUE(store->named({"the pair"}, {"part"}).empty());
  EXPECT_TRUE(store->named({}, {"part"}).empty());
  store->remove("part", bolt, false);
  EXPECT_TRUE(store->named({"bolt"}, {"part", "shape"}).empty());
  EXPECT_THROW(store->named(std::vector<std::string>(Store::kMaxNamedLookups + 1, "x"), {"part"}), Error);
  // A long list (the near spellings of a word): more than the few-names statement holds, up to the
  // limit, with the match anywhere in it.
  std::vector<std::string> many;
  for (size_t i = 0; i + 1 < Store::kMaxNamedLookups; ++i) many.push_back("nut" + std::to_string(i));
  many.insert(many.begin() + 40, "nut");
  const auto nut = store->named(many, {"part"});
  ASSERT_EQ(nut.size(), 1u);
  EXPECT_EQ(nut[0].name, "nut");
  many.erase(many.begin() + 40);
  EXPECT_TRUE(store->named(many, {"part"}).empty());
  // The statement's free slots repeat the shortest name, not the last: seventeen names ending in
  // 5 MB filled 256 slots with 1.3 GB, over PostgreSQL's message limit (the connection closed).
  std::vector<std::string> seventeen{"nut"};
  for (int i = 0; i < 15; ++i) seventeen.push_back("bolt" + std::to_string(i));
  seventeen.push_back(std::string(5'000'000, 'q'));
  const auto withLong = store->named(seventeen, {"part"});
  ASSERT_EQ(withLong.size(), 1u);
  EXPECT_EQ(withLong[0].name, "nut");
}

// described: every word (stemmed) of the name and search text, the latest version's, live objects
// of the kinds asked; words that look like FTS operators are words.
TEST_P(StoreTest, DescribedFindsObjectsByEveryWordOfTheirText) {
  NewObject lamp = part("desk-lamp");
  lamp.searchText = "a lamp with a bent arm";
  const int64_t lampId = store->create(lamp).id;
  NewObject pair = shape("pair", {});
  pair.searchText = "two balls glued AND stacked";
  const int64_t pairId = store->create(pair).id;
  store->create(part("bare"));
  const auto ids = [&](const std::vector<std::string>& words, const std::vector<std::string>& kinds) {
    std::vector<int64_t> out;
    for (const StoredObject& o : store->described(words, kinds, 10)) out.push_back(o.id);
    return out;
  };
  EXPECT_EQ(ids({"bent", "lamp"}, {"part", "shape"}), std::vector<int64_t>{lampId});
  EXPECT_EQ(ids({"arms", "lamps"}, {"part"}), std::vector<int64_t>{lampId});  // stems
  EXPECT_EQ(ids({"desk"}, {"part"}), std::vector<int64_t>{lampId});               // the name's words
  EXPECT_TRUE(ids({"bent", "ball"}, {"part", "shape"}).empty());                 // every word
  EXPECT_EQ(ids({"balls", "and"}, {"shape"}), std::vector<int64_t>{pairId});
  EXPECT_TRUE(ids({"balls"}, {"part"}).empty());
  EXPECT_TRUE(ids({"NEAR", "lamp"}, {"part"}).empty());  // a word, not FTS5's operator
  EXPECT_TRUE(ids({"\"lamp"}, {"part"}).size() <= 1u);  // a quote is text, not syntax
  EXPECT_TRUE(ids({}, {"part"}).empty());
  // A new version replaces the words; deleting the object deletes them.
  lamp.searchText = "a reading light";
  store->put(lampId, lamp);
  EXPECT_TRUE(ids({"bent", "lamp"}, {"part"}).empty());
  EXPECT_EQ(ids({"reading", "light"}, {"part"}), std::vector<int64_t>{lampId});
  store->remove("part", lampId, false);
  EXPECT_TRUE(ids({"reading", "light"}, {"part"}).empty());
  EXPECT_THROW(store->described(std::vector<std::string>(Store::kMaxTextWords + 1, "x"), {"part"}, 10), Error);
}

TEST_P(StoreTest, RemoveInUseUnlessCascade) {
  auto bolt = store->create(part("bolt"));
  auto inner = store->create(shape("inner", {byName("part", "bolt")}));
  auto outer = store->create(shape("outer", {byName("shape", "inner")}));
  auto other = store->create(part("other"));
  auto message = expectError([&] { store->remove("part", bolt.id, false); }, errc::kInUse);
  FSDB_EXPECT_CONTAINS(message, "shape 'inner' (id " + std::to_string(inner.id) + ")");
  EXPECT_EQ(store->dependents(bolt.id), (std::vector<int64_t>{inner.id, outer.id}));
  auto removed = store->remove("part", bolt.id, true);
  EXPECT_EQ(removed, (std::vector<int64_t>{bolt.id, inner.id, outer.id}));
  expectError([&] { store->get("shape", outer.id); }, errc::kNotFound);
  EXPECT_EQ(store->counts(), (std::map<std::string, int64_t>{{"part", 1}}));
  EXPECT_EQ(store->get("part", other.id).name, "other");
  EXPECT_EQ(rows("versions", "object_id", inner.id), 0);
  EXPECT_EQ(rows("csg_nodes", "object_id", inner.id), 0);
  EXPECT_EQ(rows("refs", "child_id", bolt.id), 0);
  expectError([&] { store->remove("part", bolt.id, true); }, errc::kNotFound);
  EXPECT_EQ(store->integrityCheck(), "ok");
}

TEST_P(StoreTest, InUseMessageNamesAtMostFive) {
  auto bolt = store->create(part("bolt"));
  for (int i = 0; i < 7; ++i) store->create(shape("s" + std::to_string(i), {byName("part", "bolt")}));
  auto message = expectError([&] { store->remove("part", bolt.id, false); }, errc::kInUse);
  FSDB_EXPECT_CONTAINS(message, "'s4'");
  EXPECT_EQ(message.find("'s5'"), std::string::npos) << message;
  FSDB_EXPECT_CONTAINS(message, "and 2 more");
}

TEST_P(StoreTest, ReferenceDroppedByPutNoLongerBlocksRemove) {
  auto bolt = store->create(part("bolt"));
  auto s = store->create(shape("s", {byName("part", "bolt")}));
  store->put(s.id, shape("s", {}, "v2"));
  EXPECT_TRUE(store->dependents(bolt.id).empty());
  EXPECT_EQ(store->remove("part", bolt.id, false), (std::vector<int64_t>{bolt.id}));
  // The old version still reads, with its recorded (now dangling) ref id in csg_nodes.
  EXPECT_EQ(store->get("shape", s.id, 1).version, 1);
}

TEST_P(StoreTest, EvaluationCacheRoundTripAndInvalidationThroughChain) {
  auto p = store->create(part("P"));
  auto s = store->create(shape("S", {byName("part", "P")}));
  auto t = store->create(shape("T", {byName("shape", "S")}));
  auto unrelated = store->create(part("Q"));
  std::string vdb("\0grid\xff", 6);
  store->storeEvaluation(s.id, "key-s", {"{\"volume\":1}", vdb});
  store->storeEvaluation(t.id, "key-t", {"{\"volume\":2}", ""});
  store->storeEvaluation(unrelated.id, "key-q", {"{}", ""});
  auto hit = store->cachedEvaluation("key-s");
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->resultJson, "{\"volume\":1}");
  EXPECT_EQ(hit->vdb, vdb);
  EXPECT_EQ(store->cachedEvaluation("key-t")->vdb, "");
  EXPECT_FALSE(store->cachedEvaluation("missing"));
  expectError([&] { store->storeEvaluation(9999, "k", {"{}", ""}); }, errc::kNotFound);

  store->put(p.id, part("P", "{\"eps1\":2}"));
  EXPECT_FALSE(store->cachedEvaluation("key-s"));  // S uses P
  EXPECT_FALSE(store->cachedEvaluation("key-t"));  // T uses S uses P
  EXPECT_TRUE(store->cachedEvaluation("key-q"));   // untouched
}

// --max-cache-mb: every new request (alpha=0.400001, ...) kept a mesh for ever. The cache holds
// at most maxCacheBytes of entries (result and grid bytes), the least recently used out first;
// an entry larger than the bound is not kept, and nothing is evicted for it.
TEST_P(StoreTest, EvaluationCacheEvictsTheLeastRecentlyUsedPastItsBound) {
  store.reset();
  StoreOptions options;
  options.maxCacheBytes = 3000;
  store = Store::open(database.location(), options);
  auto p = store->create(part("P"));
  const std::string grid(990, 'g');  // 992 bytes an entry with its "{}"
  for (const char* key : {"k1", "k2", "k3"}) store->storeEvaluation(p.id, key, {"{}", grid});
  for (const char* key : {"k1", "k2", "k3"}) EXPECT_TRUE(store->cachedEvaluation(key)) << key;
  store->storeEvaluation(p.id, "k4", {"{}", grid});  // 3968 > 3000: the oldest goes
  EXPECT_FALSE(store->cachedEvaluation("k1"));
  for (const char* key : {"k2", "k3", "k4"}) EXPECT_TRUE(store->cachedEvaluation(key)) << key;
  store->storeEvaluation(p.id, "big", {"{}", std::string(3001, 'g')});  // larger than the bound
  EXPECT_FALSE(store->cachedEvaluation("big"));
  for (const char* key : {"k2", "k3", "k4"}) EXPECT_TRUE(store->cachedEvaluation(key)) << key;
  store->storeEvaluation(p.id, "k3", {"{}", grid});  // stored again: now the most recent
  store->storeEvaluation(p.id, "k5", {"{}", grid});
  EXPECT_FALSE(store->cachedEvaluation("k2"));
  for (const char* key : {"k3", "k4", "k5"}) EXPECT_TRUE(store->cachedEvaluation(key)) << key;
  auto db = database.connect();
  auto total = db->prepare("SELECT SUM(bytes), COUNT(*) FROM eval_cache");
  ASSERT_TRUE(total->step());
  EXPECT_EQ(total->columnInt(0), 3 * 992);
  EXPECT_EQ(total->columnInt(1), 3);

  // 0: no bound.
  store.reset();
  options.maxCacheBytes = 0;
  store = Store::open(database.location(), options);
  for (int i = 0; i < 6; ++i) store->storeEvaluation(p.id, "n" + std::to_string(i), {"{}", grid});
  for (int i = 0; i < 6; ++i) EXPECT_TRUE(store->cachedEvaluation("n" + std::to_string(i))) << i;
}

TEST_P(StoreTest, CreateBatchReportsBadItemAndCommitsOthers) {
  std::vector<NewObject> items = {part("a"), shape("s", {byName("part", "missing")}), part("b"), part("a")};
  auto results = store->createBatch(items, BulkMode::kCreate);
  ASSERT_EQ(results.size(), 4u);
  ASSERT_TRUE(results[0].id);
  EXPECT_EQ(results[0].version, 1);
  EXPECT_FALSE(results[1].id);
  EXPECT_EQ(results[1].errorCode, errc::kUnknownReference);
  EXPECT_EQ(results[1].errorPath, "tree.children[0].part");
  EXPECT_EQ(results[1].errorMessage, "unknown part 'missing'");
  ASSERT_TRUE(results[2].id);
  EXPECT_EQ(results[3].errorCode, errc::kConflict);
  EXPECT_TRUE(results[0].errorCode.empty());
  EXPECT_EQ(store->counts(), (std::map<std::string, int64_t>{{"part", 2}}));
  EXPECT_EQ(store->get("part", *results[2].id).name, "b");
}

TEST_P(StoreTest, BatchItemsMayReferToEarlierItems) {
  auto results = store->createBatch(
      {part("wheel"), shape("axle", {byName("part", "wheel")}), shape("car", {byName("shape", "axle")})},
      BulkMode::kCreate);
  ASSERT_EQ(results.size(), 3u);
  for (const auto& r : results) ASSERT_TRUE(r.id) << r.errorMessage;
  EXPECT_EQ(store->get("shape", *results[2].id).references, (std::vector<int64_t>{*results[1].id}));
  EXPECT_EQ(store->dependents(*results[0].id), (std::vector<int64_t>{*results[1].id, *results[2].id}));
}

TEST_P(StoreTest, UpsertIsIdempotentOnSameHash) {
  auto first = store->createBatch({part("bolt")}, BulkMode::kUpsert);
  ASSERT_TRUE(first[0].id);
  EXPECT_EQ(first[0].version, 1);
  auto same = store->createBatch({part("bolt")}, BulkMode::kUpsert);
  EXPECT_EQ(same[0].id, first[0].id);
  EXPECT_EQ(same[0].version, 1);
  EXPECT_EQ(rows("versions", "object_id", *first[0].id), 1);
  auto changed = store->createBatch({part("bolt", "{\"eps1\":3}")}, BulkMode::kUpsert);
  EXPECT_EQ(changed[0].id, first[0].id);
  EXPECT_EQ(changed[0].version, 2);
  // kCreate of the same name is a per-item conflict instead.
  auto conflict = store->createBatch({part("bolt")}, BulkMode::kCreate);
  EXPECT_EQ(conflict[0].errorCode, errc::kConflict);
}

TEST_P(StoreTest, UpsertInvalidatesDependentsCache) {
  store->create(part("P"));
  auto s = store->create(shape("S", {byName("part", "P")}));
  store->storeEvaluation(s.id, "key-s", {"{}", ""});
  store->createBatch({part("P")}, BulkMode::kUpsert);  // same hash: no write
  EXPECT_TRUE(store->cachedEvaluation("key-s"));
  store->createBatch({part("P", "{\"eps1\":9}")}, BulkMode::kUpsert);
  EXPECT_FALSE(store->cachedEvaluation("key-s"));
}

TEST(StoreReopen, DataPersists) {
  TempDir dir;
  std::string path = dir.file("fsdb.db");
  int64_t id = 0;
  {
    auto store = Store::open(path);
    id = store->create(part("bolt")).id;
    store->put(id, part("bolt", "{\"v\":2}"));
    store->checkpoint();
    // TRUNCATE leaves an empty WAL: the main file is whole on its own.
    EXPECT_EQ(std::filesystem::file_size(path + "-wal"), 0u);
  }
  auto store = Store::open(path, StoreOptions{1000, true, 2});
  EXPECT_EQ(store->schemaVersion(), embeddedMigrations().back().first);
  EXPECT_EQ(store->get("part", id).version, 2);
  EXPECT_EQ(store->get("part", id, 1).documentJson, "{\"eps1\":1}");
  EXPECT_EQ(store->create(part("nut")).id, id + 1);
}

TEST(StoreReopen, RefusesNewerSchema) {
  TempDir dir;
  std::string path = dir.file("fsdb.db");
  { Store::open(path); }
  {
    sqlite::Connection db(path);
    db.exec("PRAGMA user_version = 2000");
  }
  auto message = expectError([&] { Store::open(path); }, errc::kStorage);
  FSDB_EXPECT_CONTAINS(message, "2000");
}

TEST_P(StoreTest, ConcurrentCreatesAndGets) {
  constexpr int kThreads = 4, kOps = 200;
  std::atomic<int> errors{0}, created{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      std::vector<int64_t> mine;
      for (int i = 0; i < kOps; ++i) {
        try {
          if (i % 2 == 0 || mine.empty()) {
            auto name = "t" + std::to_string(t) + "_" + std::to_string(i);
            auto object = i % 4 == 0 ? part(name) : shape(name, {byName("part", "t" + std::to_string(t) + "_0")});
            mine.push_back(store->create(object).id);
            ++created;
          } else {
            auto id = mine[static_cast<size_t>(i) % mine.size()];
            auto got = store->find(byId("part", id));
            if (!got) got = store->get("shape", id);
            if (got->id != id) ++errors;
          }
        } catch (const std::exception& e) {
          ++errors;
          ADD_FAILURE() << e.what();
        }
      }
    });
  }
  for (auto& thread : threads) thread.join();
  EXPECT_EQ(errors.load(), 0);
  EXPECT_EQ(created.load(), kThreads * kOps / 2);
  auto counts = store->counts();
  EXPECT_EQ(counts["part"] + counts["shape"], created.load());
  EXPECT_EQ(counts["part"], kThreads * kOps / 4);
  EXPECT_EQ(store->integrityCheck(), "ok");
}

TEST_P(StoreTest, IfVersionRefusesAWriteToAMovedObject) {
  auto bolt = store->create(part("bolt"));
  EXPECT_EQ(store->put(bolt.id, part("bolt", "{\"v\":2}"), 1).version, 2);
  auto message = expectError([&] { store->put(bolt.id, part("bolt", "{\"v\":3}"), 1); }, errc::kPreconditionFailed);
  FSDB_EXPECT_CONTAINS(message, "is at version 2, not 1");
  EXPECT_EQ(store->get("part", bolt.id).version, 2);  // nothing written
  expectError([&] { store->remove("part", bolt.id, false, 1); }, errc::kPreconditionFailed);
  EXPECT_TRUE(store->find(byId("part", bolt.id)));
  EXPECT_EQ(store->remove("part", bolt.id, false, 2), (std::vector<int64_t>{bolt.id}));
}

TEST_P(StoreTest, ChangeLogListsWhatChangedAfterASequenceNumber) {
  auto bolt = store->create(part("bolt"));
  auto nut = store->create(part("nut"));
  const int64_t seq = store->changeSeq();
  EXPECT_GT(seq, 0);
  ChangeFeed all = store->changesSince(0);
  EXPECT_TRUE(all.reset);
  EXPECT_EQ(all.seq, seq);
  ASSERT_EQ(all.changes.size(), 2u);
  EXPECT_EQ(all.changes[0].id, bolt.id);
  EXPECT_EQ(all.changes[1].name, "nut");

  ChangeFeed none = store->changesSince(seq);
  EXPECT_FALSE(none.reset);
  EXPECT_TRUE(none.changes.empty());

  store->put(bolt.id, part("bolt", "{\"v\":2}"));
  store->put(bolt.id, part("bolt", "{\"v\":3}"));
  auto pair = store->create(shape("pair", {byName("part", "nut")}));
  store->remove("part", nut.id, true);  // takes pair with it
  ChangeFeed feed = store->changesSince(seq);
  EXPECT_FALSE(feed.reset);
  EXPECT_GT(feed.seq, seq);
  EXPECT_EQ(feed.seq, store->changeSeq());
  ASSERT_EQ(feed.changes.size(), 3u);  // bolt once, though written twice
  EXPECT_EQ(feed.changes[0].id, bolt.id);
  EXPECT_EQ(feed.changes[0].latestVersion, 3);
  EXPECT_EQ(feed.changes[0].kind, "part");
  EXPECT_EQ(feed.changes[1].id, nut.id);
  EXPECT_EQ(feed.changes[1].latestVersion, 0);  // deleted
  EXPECT_EQ(feed.changes[2].id, pair.id);
  EXPECT_EQ(feed.changes[2].latestVersion, 0);
  // A failed write logs nothing; a sequence number newer than the log's is another database's.
  expectError([&] { store->create(part("bolt")); }, errc::kConflict);
  EXPECT_EQ(store->changeSeq(), feed.seq);
  EXPECT_TRUE(store->changesSince(feed.seq + 5).reset);
}

TEST_P(StoreTest, TwoStoresOnOneDatabaseSeeEachOthersWrites) {
  auto other = Store::open(database.location());  // as a second server would
  const int64_t seq = other->changeSeq();
  auto bolt = store->create(part("bolt"));
  EXPECT_EQ(other->get("part", bolt.id).name, "bolt");
  EXPECT_GT(other->changeSeq(), seq);
  ChangeFeed feed = other->changesSince(seq);
  ASSERT_EQ(feed.changes.size(), 1u);
  EXPECT_EQ(feed.changes[0].id, bolt.id);
  other->put(bolt.id, part("bolt", "{\"v\":2}"));
  EXPECT_EQ(store->get("part", bolt.id).version, 2);
  expectError([&] { store->put(bolt.id, part("bolt", "{\"v\":3}"), 1); }, errc::kPreconditionFailed);
}

// Two writers close a cycle from both ends at once (a -> b and b -> a): the write lock orders
// them, so exactly one of each pair lands and the other is a reference_cycle; never both.
TEST_P(StoreTest, ReadsInOneSnapshotMissWritesMadeAfterItsFirstRead) {
  const int64_t first = store->create(part("first")).id;
  auto other = Store::open(path);  // another store on the database (another process, say)
  int64_t second = 0, third = 0;
  store->readSnapshot([&] {
    EXPECT_EQ(store->counts()["part"], 1);  // the snapshot starts with the first read
    second = other->create(part("second")).id;
    third = store->create(part("third")).id;  // a write inside takes a connection of its own
    EXPECT_EQ(store->counts()["part"], 1);
    EXPECT_EQ(store->lastObjectId(), first);
    EXPECT_FALSE(store->find(byId("part", second)));
    EXPECT_EQ(store->objectIds("part"), std::vector<int64_t>{first});
    // Reads that open a read transaction of their own join the snapshot's.
    EXPECT_EQ(store->changesSince(0).changes.size(), 1u);
    EXPECT_EQ(store->descriptorCandidates("part", {"bendness", 0, 1, true, true, false}).size(), 0u);
    store->readSnapshot([&] { EXPECT_EQ(store->counts()["part"], 1); });  // nested: the same snapshot
  });
  EXPECT_EQ(store->counts()["part"], 3);
  EXPECT_EQ(store->objectIds("part"), (std::vector<int64_t>{first, second, third}));
}

TEST_P(StoreTest, ReadSnapshotEndsWhenItsBodyThrows) {
  store->create(part("first"));
  EXPECT_THROW(store->readSnapshot([&] {
    EXPECT_EQ(store->counts()["part"], 1);
    throw Error(errc::kNotFound, "gone");
  }),
               Error);
  store->create(part("second"));
  EXPECT_EQ(store->counts()["part"], 2);  // this thread reads the latest again
  // Every pooled connection is back, and none is left inside a transaction: as many snapshots
  // at once as the pool holds, each seeing the latest state.
  std::vector<std::thread> readers;
  std::atomic<int> sawBoth{0};
  for (int i = 0; i < 8; ++i)
    readers.emplace_back([&] { store->readSnapshot([&] { sawBoth += store->counts()["part"] == 2; }); });
  for (auto& reader : readers) reader.join();
  EXPECT_EQ(sawBoth.load(), 8);
}

TEST_P(StoreTest, SnapshotsOfTwoStoresOnOneThreadStayApart) {
  auto other = Store::open(path);
  store->create(part("first"));
  store->readSnapshot([&] {
    EXPECT_EQ(store->counts()["part"], 1);
    other->readSnapshot([&] {
      EXPECT_EQ(other->counts()["part"], 1);
      other->create(part("second"));
      EXPECT_EQ(other->counts()["part"], 1);  // other's snapshot began before its write
    });
    EXPECT_EQ(store->counts()["part"], 1);  // still store's own snapshot
  });
  EXPECT_EQ(store->counts()["part"], 2);
}

TEST_P(StoreTest, CycleRejectionHoldsUnderConcurrentWriters) {
  auto second = Store::open(database.location());
  store->create(part("leaf"));
  constexpr int kRounds = 25;
  int refused = 0;
  for (int round = 0; round < kRounds; ++round) {
    const std::string a = "a" + std::to_string(round), b = "b" + std::to_string(round);
    auto sa = store->create(shape(a, {byName("part", "leaf")}));
    auto sb = store->create(shape(b, {byName("part", "leaf")}));
    std::atomic<int> cycles{0}, others{0};
    std::thread one([&] {
      try {
        store->put(sa.id, shape(a, {byName("shape", b)}));
      } catch (const Error& e) {
        (e.code() == std::string(errc::kReferenceCycle) ? cycles : others)++;
      }
    });
    std::thread two([&] {
      try {
        second->put(sb.id, shape(b, {byName("shape", a)}));
      } catch (const Error& e) {
        (e.code() == std::string(errc::kReferenceCycle) ? cycles : others)++;
      }
    });
    one.join();
    two.join();
    EXPECT_EQ(others.load(), 0) << "round " << round;
    EXPECT_EQ(cycles.load(), 1) << "round " << round;
    refused += cycles.load();
    // What landed has no cycle: the walk down from a never returns to a.
    EXPECT_TRUE(store->dependents(sa.id).empty() || store->dependents(sb.id).empty()) << "round " << round;
  }
  EXPECT_EQ(refused, kRounds);
}

TEST(PostgresStoreOpen, ReopenKeepsDataAndRefusesNewerSchema) {
  FSDB_USE_BACKEND("postgresql");
  test::TestDatabase database("postgresql");
  int64_t id = 0;
  {
    auto store = Store::open(database.location());
    id = store->create(part("bolt")).id;
    store->put(id, part("bolt", "{\"v\":2}"));
  }
  {
    auto store = Store::open(database.location(), StoreOptions{1000, true, 2});
    EXPECT_EQ(store->get("part", id).version, 2);
    EXPECT_EQ(store->get("part", id, 1).documentJson, "{\"eps1\":1}");
    EXPECT_GT(store->create(part("nut")).id, id);
  }
  database.connect()->exec("UPDATE fsdb_schema SET version = 2000");
  auto message = expectError([&] { Store::open(database.location()); }, errc::kStorage);
  FSDB_EXPECT_CONTAINS(message, "2000");
}

TEST(PostgresStoreOpen, UnreachableServerNamesTheUrlWithoutItsPassword) {
  // Port 1 on loopback: nothing listens there.
  auto message = expectError([&] { Store::open("postgresql://alice:secret@127.0.0.1:1/fsdb"); }, errc::kStorage);
  FSDB_EXPECT_CONTAINS(message, "cannot connect to postgresql://alice:***@127.0.0.1:1/fsdb");
  EXPECT_EQ(message.find("secret"), std::string::npos);
  message = expectError([&] { Store::open("postgres://127.0.0.1:1/fsdb?schema=1bad"); }, errc::kStorage);
  FSDB_EXPECT_CONTAINS(message, "schema '1bad'");
}

INSTANTIATE_TEST_SUITE_P(Backends, StoreTest, testing::ValuesIn(test::kBackends));

}  // namespace
}  // namespace fsdb
