// The stored-graph cache (server/stored_graphs.h): partKey and samePart, one id for equal leaf parts
// across trees, entries served while the versions hold and rebuilt after a write they depend on.
#include "server/stored_graphs.h"

#include <gtest/gtest.h>

#include "server/documents.h"
#include "tests/db/temp_dir.h"

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
  auto store = Store::open(dir.file("fsdb.sqlite"));
  const auto create = [&](const json& doc, const std::string& kind) {
    return store->create(prepareDocument(doc, kind, *store, DocumentLimits{1000}, "")).id;
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
  store->put(rod, prepareDocument({{"name", "rod"}, {"params", {{"a1", 2}, {"a3", 3}}}}, "part", *store, DocumentLimits{1000}, ""));
  versions = StoreVersions::read(*store);
  const auto again = cache.graph(*store, shapes[0], versions, 1000);
  EXPECT_NE(again, g1);  // the rod it reached has a new version
  EXPECT_NE(again->leafParts[0], g1->leafParts[0]);
  EXPECT_EQ(cache.builds(), 3u);
  EXPECT_EQ(cache.size(), 2u);
}

}  // namespace
}  // namespace fsdb
