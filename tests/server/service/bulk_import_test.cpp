// server/service/bulk_import and server/service/documents: validating documents on the way
// into the store, per-line errors, references to earlier lines, batches and upserts.
#include "server/service/bulk_import.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"
#include "server/service/documents.h"
#include "tests/db/temp_dir.h"
#include "tests/db/test_database.h"

namespace fsdb {
namespace {

// Document limits with at most `n` CSG nodes, the rest at their defaults.
DocumentLimits nodeLimit(size_t n) {
  DocumentLimits limits;
  limits.maxNodes = n;
  return limits;
}

using nlohmann::json;

std::string part(const std::string& name, double a1) {
  return json{{"kind", "part"}, {"name", name}, {"params", {{"a1", a1}}}}.dump();
}

// importBody gives what splitBulkBody + importDocuments give, whatever the batch size against
// the chunks the pipeline prepares in (128 lines): same ids order, same errors, same lines.
TEST(ImportBody, AnswersAsImportDocumentsAcrossBatchesAndChunks) {
  std::string body;
  for (int i = 0; i < 300; ++i) {
    if (i % 97 == 5) body += "not json\n";
    else if (i % 61 == 7) body += part("dup", 1) + "\n";  // the second and later: conflict
    else if (i % 50 == 9) body += "\n";
    else body += part("p" + std::to_string(i), 1 + i % 3) + "\n";
    if (i == 200) body += json{{"kind", "shape"}, {"name", "s"}, {"csg", "p1 + p2"}}.dump() + "\n";
  }
  for (size_t batch : {size_t{7}, size_t{129}, size_t{5000}}) {
    TempDir a, b;
    auto viaBody = Store::open(test::storeLocation(a, "a.sqlite"));
    auto viaLines = Store::open(test::storeLocation(b, "b.sqlite"));
    BulkOptions options;
    options.batchSize = batch;
    std::vector<std::pair<size_t, size_t>> progress;
    options.progress = [&progress](size_t done, size_t total) { progress.emplace_back(done, total); };
    const BulkReport r = importBody(*viaBody, body, 64, options);
    options.progress = nullptr;
    const BulkReport expected = importDocuments(*viaLines, splitBulkBody(body, 64), options);
    EXPECT_EQ(r.toJson(), expected.toJson()) << "batch " << batch;
    EXPECT_EQ(r.imported + r.failed, BulkBodyReader(body, 64).count());
    ASSERT_FALSE(progress.empty());
    EXPECT_EQ(progress.back().first, progress.back().second) << "batch " << batch;
    for (size_t k = 1; k < progress.size(); ++k) EXPECT_LT(progress[k - 1].first, progress[k].first);
  }
}

TEST(ImportDocuments, GoodLinesOfABatchWithBadOnesCommitAndErrorsNameTheirLines) {
  TempDir dir;
  auto store = Store::open(test::storeLocation(dir, "db.sqlite"));
  const std::string body = part("a", 1) + "\n" + part("bad", -1) + "\n" + part("a", 2) + "\n" +
                           json{{"kind", "shape"}, {"name", "s"}, {"csg", "a + b"}}.dump() + "\n" + part("b", 1) +
                           "\n" + json{{"kind", "shape"}, {"name", "t"}, {"csg", "a + b"}}.dump();
  BulkOptions options;
  options.batchSize = 3;  // lines 1-3 and 4-6: "s" names "b" before it exists, "t" after
  const BulkReport r = importDocuments(*store, splitBulkBody(body, 64), options);
  EXPECT_EQ(r.imported, 3u);  // a, b, t
  EXPECT_EQ(r.failed, 3u);
  ASSERT_EQ(r.errors.size(), 3u);
  EXPECT_EQ(r.errors[0]["line"], 2);
  EXPECT_EQ(r.errors[0]["error"]["path"], "params.a1");
  EXPECT_EQ(r.errors[1]["line"], 3);
  EXPECT_EQ(r.errors[1]["error"]["code"], errc::kConflict);
  EXPECT_EQ(r.errors[2]["line"], 4);
  EXPECT_EQ(r.errors[2]["error"]["code"], errc::kUnknownReference);
  EXPECT_EQ(store->counts().at("part"), 2);
  EXPECT_EQ(store->counts().at("shape"), 1);
  EXPECT_EQ(r.toJson()["ids"].size(), 3u);
}

TEST(ImportDocuments, AShapeMayUseAPartFromAnEarlierLineOfTheSameBatch) {
  TempDir dir;
  auto store = Store::open(test::storeLocation(dir, "db.sqlite"));
  const std::string body =
      part("p", 1) + "\n" + json{{"kind", "shape"}, {"name", "s"}, {"tree", {{"part", "p"}}}}.dump();
  const BulkReport r = importDocuments(*store, splitBulkBody(body, 64), {});
  EXPECT_EQ(r.imported, 2u) << r.toJson().dump();
  const StoredObject s = store->get("shape", r.ids[1]);
  ASSERT_EQ(s.references.size(), 1u);
  EXPECT_EQ(s.references[0], r.ids[0]);
}

TEST(ImportDocuments, UpsertAddsVersionsOnlyForChangedDocumentsAndReportsProgress) {
  TempDir dir;
  auto store = Store::open(test::storeLocation(dir, "db.sqlite"));
  BulkOptions options;
  options.mode = BulkMode::kUpsert;
  options.batchSize = 1;
  std::vector<std::pair<size_t, size_t>> progress;
  options.progress = [&progress](size_t done, size_t total) { progress.emplace_back(done, total); };
  importDocuments(*store, splitBulkBody(part("a", 1) + "\n" + part("b", 1), 64), options);
  const BulkReport again = importDocuments(*store, splitBulkBody(part("a", 1) + "\n" + part("b", 3), 64), options);
  EXPECT_EQ(again.imported, 2u);
  EXPECT_EQ(store->get("part", again.ids[0]).latestVersion, 1);  // unchanged: no new version
  EXPECT_EQ(store->get("part", again.ids[1]).latestVersion, 2);
  EXPECT_EQ(progress.back(), std::make_pair(size_t{2}, size_t{2}));
  EXPECT_EQ(progress.size(), 4u);
}

// A body of bad lines: every one counted, only the first maxErrors listed (in line order, across
// batches and with storage errors found after validation ones), and the report says so.
TEST(ImportBody, ListsTheFirstMaxErrorsFailuresAndCountsTheRest) {
  std::string body;
  for (int i = 1; i <= 40; ++i)
    body += (i % 3 == 0 ? part("dup", 1) : std::string("0")) + "\n";  // 3: ok, 6,9..: conflict
  for (size_t maxErrors : {size_t{0}, size_t{5}, size_t{38}, size_t{39}, size_t{1000}}) {
    TempDir dir;
    auto store = Store::open(test::storeLocation(dir, "db.sqlite"));
    BulkOptions options;
    options.batchSize = 4;
    options.maxErrors = maxErrors;
    const BulkReport r = importBody(*store, body, 64, options);
    EXPECT_EQ(r.imported, 1u);
    EXPECT_EQ(r.failed, 39u);
    ASSERT_EQ(r.errors.size(), std::min<size_t>(maxErrors, 39)) << maxErrors;
    EXPECT_EQ(r.errorsTruncated, maxErrors < 39) << maxErrors;
    EXPECT_EQ(r.toJson()["errors_truncated"], maxErrors < 39);
    // The first ones by line: 1, 2, 4, 5, 6 (a conflict, found by the store after 4 and 5), ...
    size_t expectLine = 1;
    for (const auto& e : r.errors) {
      if (expectLine == 3) ++expectLine;
      EXPECT_EQ(e["line"], expectLine++) << maxErrors;
    }
  }
}

// The report's own record of a full list: out-of-order failures of one batch are kept until
// closeErrors sorts them; only then is the list full and later failures only counted.
TEST(BulkReport, ErrorsFullOnceClosedWithMaxErrors) {
  BulkReport r;
  r.maxErrors = 2;
  EXPECT_FALSE(r.errorsFull());
  for (size_t line : {5, 3, 4}) r.addFailure(line, {{"code", "x"}});
  EXPECT_FALSE(r.errorsFull());  // not closed yet: all three kept
  EXPECT_EQ(r.errors.size(), 3u);
  r.closeErrors(0);
  EXPECT_TRUE(r.errorsFull());
  ASSERT_EQ(r.errors.size(), 2u);
  EXPECT_EQ(r.errors[0]["line"], 3);
  EXPECT_EQ(r.errors[1]["line"], 4);
  EXPECT_TRUE(r.errorsTruncated);
  r.addFailure(9, {{"code", "x"}});
  EXPECT_EQ(r.errors.size(), 2u);
  EXPECT_EQ(r.failed, 4u);
  BulkReport none;
  none.maxErrors = 0;
  EXPECT_TRUE(none.errorsFull());
  none.addFailure(1, {{"code", "x"}});
  EXPECT_TRUE(none.errors.empty());
  EXPECT_TRUE(none.errorsTruncated);
}

TEST(ImportDocuments, WithoutARouteKindEachLineNeedsItsKind) {
  TempDir dir;
  auto store = Store::open(test::storeLocation(dir, "db.sqlite"));
  const BulkReport r = importDocuments(*store, splitBulkBody(R"({"name":"x","params":{"a1":1}})", 64), {});
  EXPECT_EQ(r.failed, 1u);
  EXPECT_EQ(r.errors[0]["error"]["path"], "kind");
  BulkOptions parts;
  parts.kind = "part";
  EXPECT_EQ(importDocuments(*store, splitBulkBody(R"({"name":"x","params":{"a1":1}})", 64), parts).imported, 1u);
}

TEST(PrepareDocument, FillsKindChecksNamesAndComputesNormalisedColumns) {
  TempDir dir;
  auto store = Store::open(test::storeLocation(dir, "db.sqlite"));
  NewObject p = prepareDocument(json{{"name", "p"}, {"params", {{"a1", {{"tri", {1, 2, 3}}}}}}}, "part", *store,
                                nodeLimit(10), "");
  EXPECT_EQ(json::parse(p.documentJson)["kind"], "part");
  ASSERT_EQ(p.descriptors.size(), 1u);  // a part: one component
  EXPECT_FALSE(p.descriptors[0].spans.empty());
  EXPECT_FALSE(p.descriptors[0].values.empty());
  EXPECT_FALSE(p.contentHash.empty());
  store->create(p);

  NewObject s = prepareDocument(
      json{{"name", "s"},
           {"tree", {{"op", "union"}, {"children", {{{"part", "p"}}, {{"part", {{"params", {{"a1", 1}}}}}}}}}}},
      "shape", *store, nodeLimit(10), "");
  ASSERT_EQ(s.nodes.size(), 3u);
  EXPECT_EQ(s.nodes[1].kind, "ref");
  EXPECT_EQ(s.nodes[1].refIndex, 0);
  ASSERT_EQ(s.references.size(), 1u);
  EXPECT_EQ(s.references[0].name, "p");
  EXPECT_EQ(s.references[0].path, "tree.children[0].part");

  auto errorPath = [&](const json& doc, const std::string& kind) {
    try {
      prepareDocument(doc, kind, *store, nodeLimit(10), "line");
    } catch (const Error& e) {
      return e.path();
    }
    return std::string("no error");
  };
  EXPECT_EQ(errorPath(json{{"params", {{"a1", 1}}}}, "part"), "line.name");  // missing
  EXPECT_EQ(errorPath(json{{"name", ""}, {"params", {{"a1", 1}}}}, "part"), "line.name");
  EXPECT_EQ(errorPath(json{{"name", "a\nb"}, {"params", {{"a1", 1}}}}, "part"), "line.name");
  EXPECT_EQ(errorPath(json{{"name", std::string(201, 'x')}, {"params", {{"a1", 1}}}}, "part"), "line.name");
  EXPECT_EQ(errorPath(json{{"kind", "shape"}, {"name", "x"}, {"params", {{"a1", 1}}}}, "part"), "line.kind");
  EXPECT_EQ(errorPath(json{{"name", "x"}, {"tree", {{"part", "nope"}}}}, "shape"), "line.tree.part");
}

// Each limit means one thing: max_nodes counts a shape's CSG nodes, max_control_points a stored
// curve's or surface's control points, max_fair_points a stored fair curve's given points.
TEST(PrepareDocument, EachKindIsLimitedByItsOwnOption) {
  TempDir dir;
  auto store = Store::open(test::storeLocation(dir, "db.sqlite"));
  DocumentLimits limits;
  limits.maxNodes = 2;
  limits.maxControlPoints = 3;
  limits.fairCurve.maxPoints = 3;
  auto limitError = [&](const json& doc, const std::string& kind) {
    try {
      prepareDocument(doc, kind, *store, limits, "");
    } catch (const Error& e) {
      return e.code() + " " + e.path() + ": " + e.what();
    }
    return std::string("no error");
  };
  const json three = {{0, 0}, {1, 1}, {2, 0}}, four = {{0, 0}, {1, 1}, {2, 0}, {3, 1}};
  // Three control points pass with max_nodes = 2, four do not with max_control_points = 3.
  EXPECT_EQ(limitError({{"name", "c3"}, {"bezier", {{"control_points", three}}}}, "curve"), "no error");
  const std::string curve = limitError({{"name", "c4"}, {"bezier", {{"control_points", four}}}}, "curve");
  EXPECT_EQ(curve.rfind("limit_exceeded bezier.control_points: ", 0), 0u) << curve;
  EXPECT_NE(curve.find("max_control_points=3"), std::string::npos) << curve;
  const std::string surface = limitError(
      {{"name", "s4"}, {"bezier", {{"control_grid", {{{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}, {1, 1, 0}}}}}}}, "surface");
  EXPECT_NE(surface.find("max_control_points=3"), std::string::npos) << surface;
  EXPECT_EQ(limitError({{"name", "f3"}, {"fair", {{"points", three}}}}, "curve"), "no error");
  const std::string fair = limitError({{"name", "f4"}, {"fair", {{"points", four}}}}, "curve");
  EXPECT_EQ(fair.rfind("limit_exceeded fair.points: ", 0), 0u) << fair;
  EXPECT_NE(fair.find("max_fair_points=3"), std::string::npos) << fair;
  const json tree = {{"op", "union"},
                     {"children", {{{"part", {{"params", {{"a1", 1}}}}}}, {{"part", {{"params", {{"a1", 2}}}}}}}}};
  const std::string shape = limitError({{"name", "s"}, {"tree", tree}}, "shape");
  EXPECT_NE(shape.find("max_nodes=2"), std::string::npos) << shape;
}

TEST(StoreResolver, FindsStoredObjectsByNameOrIdAndPendingOnesFirst) {
  TempDir dir;
  auto store = Store::open(test::storeLocation(dir, "db.sqlite"));
  const StoredObject p =
      store->create(prepareDocument(json{{"name", "p"}, {"params", {{"a1", 1}}}}, "part", *store, nodeLimit(10), ""));
  PendingDocuments pending;
  pending.add("part", "q", json{{"params", {{"a1", 2}}}});
  const ReferenceResolver resolve = storeResolver(*store, &pending);
  EXPECT_EQ(resolve("part", "p")->id, p.id);
  EXPECT_EQ(resolve("part", p.id)->document["name"], "p");
  EXPECT_LT(resolve("part", "q")->id, 0);  // pending: a pseudo-id
  EXPECT_EQ(resolve("part", "q")->id, resolve("part", "q")->id);
  EXPECT_FALSE(resolve("shape", "p"));
  EXPECT_FALSE(resolve("part", "zzz"));
  EXPECT_FALSE(resolve("part", 2.5));
  EXPECT_EQ(pending.find("part", "nope"), nullptr);

  const json out = json::parse(storedObjectText(store->get("part", p.id)));
  EXPECT_EQ(out["id"], p.id);
  EXPECT_EQ(out["version"], 1);
  EXPECT_EQ(out["document"]["params"]["a1"], 1);
}

// The text GET answers is what building the JSON and dumping it would give, byte for byte:
// names that need escaping, non-ASCII text, numbers of every form in the document.
TEST(StoredObjectText, IsTheDumpOfTheObjectsJson) {
  TempDir dir;
  auto store = Store::open(test::storeLocation(dir, "db.sqlite"));
  const json docs[] = {json{{"name", "plain"}, {"params", {{"a1", 1}}}},
                       json{{"name", "quote \" back\\slash / tab\u00e9 \u4e2d"},
                            {"meta", {{"note", "line\u2028sep"}, {"big", 1e21}, {"tiny", -2.5e-300}}},
                            {"params", {{"a1", {{"tri", {2.5e-7, 1.0 / 3, 0.7}}}}, {"eps1", 1.5}}}},
                       json{{"name", "zz"},
                            {"descriptors", {"slightly bent"}},
                            {"params", {{"a1", 2}, {"kx", -0.0}, {"a2", 1.25}}},
                            {"meta", {{"n", 123456789012}}}}};
  for (const json& doc : docs) {
    const StoredObject stored =
        store->get("part", store->create(prepareDocument(doc, "part", *store, nodeLimit(10), "")).id);
    const json expected = {{"id", stored.id},
                           {"kind", stored.kind},
                           {"name", stored.name},
                           {"version", stored.version},
                           {"latest_version", stored.latestVersion},
                           {"created_at", stored.createdAt},
                           {"content_hash", stored.contentHash},
                           {"document", json::parse(stored.documentJson)}};
    EXPECT_EQ(storedObjectText(stored), expected.dump()) << doc.dump();
  }
}

}  // namespace
}  // namespace fsdb
