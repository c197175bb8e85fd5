// The stored-graph cache (server/service/stored_graphs.h): partKey and samePart, one id for equal leaf parts
// across trees, entries served while the versions hold and rebuilt after a write they depend on;
// graphs() (the parallel build) gives the entries of serial graph() calls, builds each graph once
// when two threads ask at the same time, and skips deleted shapes; its memory follows the live
// catalogue (interned parts no entry uses and entries of deleted shapes are dropped).
#include "server/service/stored_graphs.h"

#include <gtest/gtest.h>

#include <set>
#include <thread>

#include "server/service/documents.h"
#include "tests/db/temp_dir.h"
#include "tests/db/test_database.h"

namespace fsdb {
namespace {

using nlohmann::json;

TEST(StoredGraphs, PartKeyAndSamePart) {
  FuzzyPart a, b;
  EXPECT_EQ(partKey(a), partKey(b));
  EXPECT_TRUE(samePart(a, b));
  b.kv = FuzzyNumber::triangular(0, 0.1, 0.2);
  EXPECT_NE(partKey(a), partKey(b));
  EXPECT_FALSE(samePart(a, b));
  FuzzyPart c;
  c.axis = {1, 0, 0};  // the axis counts too
  EXPECT_FALSE(samePart(a, c));
  EXPECT_NE(partKey(a), partKey(c));
}

TEST(StoredGraphs, EqualLeavesShareAnIdAndWritesRebuild) {
  TempDir dir;
  auto store = Store::open(test::storeLocation(dir, "fsdb.sqlite"));
  const auto create = [&](const json& doc, const std::string& kind) {
    return store->create(prepareDocument(doc, kind, *store, DocumentLimits{}, "")).id;
  };
  const int64_t rod = create({{"name", "rod"}, {"params", {{"a1", 1}, {"a3", 3}}}}, "part");
  const json sphere = {{"part", {{"text", "a sphere"}}}};
  const int64_t s1 = create({{"name", "s1"}, {"tree", {{"op", "union"}, {"children", {{{"part", "rod"}}, sphere}}}}}, "shape");
  const int64_t s2 = create({{"name", "s2"}, {"tree", {{"op", "difference"}, {"children", {sphere, {{"part", rod}}}}}}}, "shape");
  StoredGraphCache cache;
  StoreVersions versions = StoreVersions::read(*store);
  const std::vector<ObjectVersion> shapes = versions.shapes;
  EXPECT_EQ(versions.latest.size(), 3u);
  ASSERT_EQ(shapes.size(), 2u);
  const auto g1 = cache.graph(*store, shapes[0], versions, 1000);
  const auto g2 = cache.graph(*store, shapes[1], versions, 1000);
  EXPECT_EQ(g1->id, s1);
  EXPECT_EQ(g2->id, s2);
  ASSERT_EQ(g1->leafParts.size(), 2u);
  ASSERT_EQ(g2->leafParts.size(), 2u);
  EXPECT_EQ(g1->leafParts[0], g2->leafParts[1]);  // the stored rod
  EXPECT_EQ(g1->leafParts[1], g2->leafParts[0]);  // the sphere from words
  EXPECT_NE(g1->leafParts[0], g1->leafParts[1]);
  EXPECT_EQ(g1->signature.unions, 1);
  EXPECT_EQ(g2->signature.differences, 1);
  EXPECT_EQ(g1->leafDescriptors.size(), 2u);
  EXPECT_EQ(cache.graph(*store, shapes[0], versions, 1000), g1);  // served from the cache
  EXPECT_EQ(cache.builds(), 2u);
  store->put(rod, prepareDocument({{"name", "rod"}, {"params", {{"a1", 2}, {"a3", 3}}}}, "part", *store, DocumentLimits{}, ""));
  versions = StoreVersions::read(*store);
  const auto again = cache.graph(*store, shapes[0], versions, 1000);
  EXPECT_NE(again, g1);  // the rod it reached has a new version
  EXPECT_NE(again->leafParts[0], g1->leafParts[0]);
  EXPECT_EQ(cache.builds(), 3u);
  EXPECT_EQ(cache.size(), 2u);
}

// A catalogue of `n` trees over two stored parts and a few parts from words (leaves repeat, so the
// interned ids matter).
std::unique_ptr<Store> catalogue(const TempDir& dir, int n) {
  auto store = Store::open(test::storeLocation(dir, "fsdb.sqlite"));
  const auto create = [&](const json& doc, const std::string& kind) {
    return store->create(prepareDocument(doc, kind, *store, DocumentLimits{}, "")).id;
  };
  create({{"name", "rod"}, {"params", {{"a1", 1}, {"a3", 3}}}}, "part");
  create({{"name", "plate"}, {"params", {{"a1", 2}, {"a2", 2}, {"a3", 0.2}}}}, "part");
  const std::vector<json> leaves = {{{"part", "rod"}}, {{"part", "plate"}}, {{"part", {{"text", "a sphere"}}}},
                                    {{"part", {{"text", "a very bent cylinder"}}}}, {{"part", {{"text", "a box"}}}}};
  const std::vector<std::string> ops = {"union", "intersection", "difference"};
  for (int i = 0; i < n; ++i) {
    json tree = {{"op", ops[size_t(i) % 3]},
                 {"children", {leaves[size_t(i) % 5], leaves[size_t(i * 7 + 1) % 5]}}};
    if (i % 4 == 0) tree = {{"op", "union"}, {"children", {tree, leaves[size_t(i / 4) % 5]}}};
    create({{"name", "s" + std::to_string(i)}, {"tree", tree}}, "shape");
  }
  return store;
}

void expectSameGraph(const StoredGraph& a, const StoredGraph& b) {
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.version, b.version);
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.leafParts, b.leafParts);
  EXPECT_EQ(a.reached, b.reached);
  EXPECT_EQ(a.signature.nodes(), b.signature.nodes());
  EXPECT_EQ(a.signature.unions, b.signature.unions);
  EXPECT_EQ(a.signature.differences, b.signature.differences);
  EXPECT_EQ(a.shape.graph.nodes.size(), b.shape.graph.nodes.size());
  ASSERT_EQ(a.shape.leaves.size(), b.shape.leaves.size());
  for (size_t i = 0; i < a.shape.leaves.size(); ++i) EXPECT_TRUE(samePart(a.shape.leaves[i].part, b.shape.leaves[i].part));
  ASSERT_EQ(a.leafDescriptors.size(), b.leafDescriptors.size());
  for (size_t i = 0; i < a.leafDescriptors.size(); ++i) {
    ASSERT_EQ(a.leafDescriptors[i].size(), b.leafDescriptors[i].size());
    for (size_t j = 0; j < a.leafDescriptors[i].size(); ++j) {
      EXPECT_EQ(a.leafDescriptors[i][j].descriptor, b.leafDescriptors[i][j].descriptor);
      EXPECT_TRUE(a.leafDescriptors[i][j].value == b.leafDescriptors[i][j].value);
    }
  }
}

TEST(StoredGraphs, ParallelBuildGivesTheSerialGraphs) {
  TempDir dir;
  auto store = catalogue(dir, 120);
  const StoreVersions versions = StoreVersions::read(*store);
  ASSERT_EQ(versions.shapes.size(), 120u);
  StoredGraphCache serial, parallel;
  std::vector<std::shared_ptr<const StoredGraph>> one;
  for (const ObjectVersion& shape : versions.shapes) one.push_back(serial.graph(*store, shape, versions, 1000));
  const auto all = parallel.graphs(*store, versions, 1000);
  ASSERT_EQ(all.size(), one.size());
  for (size_t i = 0; i < all.size(); ++i) {
    ASSERT_TRUE(all[i]);
    expectSameGraph(*all[i], *one[i]);
  }
  EXPECT_EQ(parallel.builds(), 120u);
  EXPECT_EQ(parallel.graphs(*store, versions, 1000), all);  // served from the cache, nothing rebuilt
  EXPECT_EQ(parallel.builds(), 120u);
  EXPECT_EQ(parallel.graph(*store, versions.shapes[7], versions, 1000), all[7]);
}

TEST(StoredGraphs, ConcurrentBuildsBuildEachGraphOnce) {
  TempDir dir;
  auto store = catalogue(dir, 200);
  const StoreVersions versions = StoreVersions::read(*store);
  StoredGraphCache cache;
  std::vector<std::shared_ptr<const StoredGraph>> a, b;
  std::thread other([&]() { a = cache.graphs(*store, versions, 1000); });
  b = cache.graphs(*store, versions, 1000);
  other.join();
  EXPECT_EQ(cache.builds(), 200u);  // the second waited for the first and found every graph
  EXPECT_EQ(a, b);
}

TEST(StoredGraphs, GraphsSkipDeletedShapesAndStopOnCheck) {
  TempDir dir;
  auto store = catalogue(dir, 10);
  const StoreVersions versions = StoreVersions::read(*store);
  store->remove("shape", versions.shapes[3].id, false);
  StoredGraphCache cache;
  const auto all = cache.graphs(*store, versions, 1000);
  ASSERT_EQ(all.size(), 10u);
  EXPECT_FALSE(all[3]);  // deleted after the versions were read
  EXPECT_TRUE(all[2] && all[4]);
  StoredGraphCache stopped;
  EXPECT_THROW(stopped.graphs(*store, StoreVersions::read(*store), 1000, []() { throw std::runtime_error("stop"); }),
               std::runtime_error);
  EXPECT_EQ(stopped.builds(), 0u);
}

// The soak (bench/soak.sh) grew the server's memory without end: every PUT of a part left its old
// version interned, and deleted shapes kept their entries. Many rewrites of one part and a deleted
// shape now leave what the live trees use.
TEST(StoredGraphs, MemoryFollowsTheLiveCatalogueNotTheWrites) {
  TempDir dir;
  auto store = catalogue(dir, 10);
  StoredGraphCache cache;
  cache.graphs(*store, StoreVersions::read(*store), 1000);
  const size_t parts = cache.internedParts();
  EXPECT_EQ(parts, 5u);  // rod, plate and three parts from words
  int64_t rod = INT64_MAX;  // the first object catalogue() creates
  for (const auto& [id, version] : StoreVersions::read(*store).latest) rod = std::min(rod, id);
  ASSERT_EQ(store->get("part", rod).name, "rod");
  for (int k = 0; k < 20; ++k) {
    store->put(rod, prepareDocument({{"name", "rod"}, {"params", {{"a1", 1 + 0.01 * (k + 1)}, {"a3", 3}}}}, "part",
                                    *store, DocumentLimits{}, ""));
    const auto graphs = cache.graphs(*store, StoreVersions::read(*store), 1000);
    EXPECT_EQ(cache.internedParts(), parts) << "after write " << k;
    ASSERT_TRUE(graphs[0]);
  }
  const StoreVersions before = StoreVersions::read(*store);
  store->remove("shape", before.shapes[0].id, false);
  store->remove("shape", before.shapes[5].id, false);
  const auto after = cache.graphs(*store, StoreVersions::read(*store), 1000);
  EXPECT_EQ(after.size(), 8u);
  EXPECT_EQ(cache.size(), 8u);  // the deleted shapes' entries are gone
  std::set<int64_t> used;        // the parts the live entries use
  for (const auto& g : after)
    for (int64_t id : g->leafParts) used.insert(id);
  EXPECT_EQ(cache.internedParts(), used.size());
}

}  // namespace
}  // namespace fsdb
