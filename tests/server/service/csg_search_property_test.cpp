// Exact pruning of the structural search (server/service/csg_search.h): on random catalogues of stored
// trees (inline parts from words, stored parts, stored shapes referenced in place) and random
// queries (trees, the texts of schema/csg_query_grammar.ebnf), the pruned search returns exactly
// the hits of the unpruned one (ids, scores, order) for small and large limits, thresholds, leaf
// thresholds and weights, and prunes often. Also: the stored-graph cache rebuilds a graph after a
// PUT of a part its tree reaches, and only then.
#include <gtest/gtest.h>

#include <random>

#include "db/store.h"
#include "query/linguistic/vocabulary.h"
#include "server/service/csg_search.h"
#include "server/service/documents.h"
#include "tests/db/temp_dir.h"
#include "tests/db/test_database.h"
#include "tests/testing/grammar_examples.h"

namespace fsdb {
namespace {

using nlohmann::json;

const std::vector<std::string> kWords = {"a very bent cylinder", "a straight cylinder", "a very sharp pyramid",
                                         "a sphere", "a box", "a slightly tapered cone", "a cube", "a long rod"};

int pick(std::mt19937& rng, int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); }

class Catalogue {
 public:
  explicit Catalogue(uint32_t seed) : rng_(seed), store_(Store::open(test::storeLocation(dir_, "fsdb.sqlite"))) {}

  void build(int parts, int shapes) {
    for (int i = 0; i < parts; ++i) {
      json doc = {{"kind", "part"}, {"name", "p" + std::to_string(i)}, {"text", kWords[size_t(pick(rng_, int(kWords.size())))]}};
      if (i % 3 == 0) doc["params"] = {{"a1", 1 + i % 4}};
      parts_.push_back(store_->create(prepareDocument(doc, "part", *store_, DocumentLimits{}, "")).id);
    }
    for (int i = 0; i < shapes; ++i) {
      const json doc = {{"kind", "shape"}, {"name", "s" + std::to_string(i)}, {"tree", tree(3, i > 5)}};
      shapes_.push_back(store_->create(prepareDocument(doc, "shape", *store_, DocumentLimits{}, "")).id);
    }
  }

  // A random tree: a leaf (inline from words, a stored part, sometimes a stored shape) or an
  // operation of 2-3 children.
  json tree(int depth, bool refs = false) {
    if (depth == 0 || pick(rng_, 3) == 0) {
      const int k = pick(rng_, 10);
      if (refs && k == 0 && !shapes_.empty()) return {{"ref", shapes_[size_t(pick(rng_, int(shapes_.size())))]}};
      if (k < 4 && !parts_.empty()) return {{"part", parts_[size_t(pick(rng_, int(parts_.size())))]}};
      json leaf = {{"part", {{"text", kWords[size_t(pick(rng_, int(kWords.size())))]}}}};
      if (k == 9) leaf["transform"] = {{"translate", {pick(rng_, 3), 0, 0}}};
      return leaf;
    }
    static const char* ops[] = {"union", "intersection", "difference"};
    json children = json::array();
    for (int n = 2 + pick(rng_, 2); n > 0; --n) children.push_back(tree(depth - 1, refs));
    return {{"op", ops[pick(rng_, 3)]}, {"children", children}};
  }

  Store& store() { return *store_; }
  std::mt19937& rng() { return rng_; }
  const std::vector<int64_t>& parts() const { return parts_; }

 private:
  TempDir dir_;
  std::mt19937 rng_;
  std::unique_ptr<Store> store_;
  std::vector<int64_t> parts_, shapes_;
};

// Compares pruned and unpruned; returns whether the pruned one matched fewer candidates.
bool expectSameHits(const Store& store, const CsgQuery& query, CsgSearchOptions options, StoredGraphCache& cache,
                    const std::string& what) {
  options.prune = true;
  const CsgSearchResult pruned = searchCsg(store, query, options, cache);
  options.prune = false;
  const CsgSearchResult full = searchCsg(store, query, options, cache);
  EXPECT_EQ(full.matched, full.candidates);
  EXPECT_LE(pruned.matched, full.matched);
  EXPECT_EQ(pruned.hits.size(), full.hits.size()) << what;
  for (size_t i = 0; i < std::min(pruned.hits.size(), full.hits.size()); ++i) {
    const CsgHit &a = pruned.hits[i], &b = full.hits[i];
    EXPECT_EQ(a.id, b.id) << what << " rank " << i;
    EXPECT_EQ(a.score.score, b.score.score) << what << " rank " << i;
    EXPECT_TRUE(a.match.complete && b.match.complete);
    EXPECT_GT(a.score.score, 0.0);
    EXPECT_GE(a.score.score, options.threshold);
    if (i > 0) {
      const CsgHit& prev = pruned.hits[i - 1];
      EXPECT_TRUE(prev.score.score > a.score.score || (prev.score.score == a.score.score && prev.id < a.id)) << what;
    }
  }
  return pruned.matched < full.matched;
}

TEST(CsgSearchProperty, PrunedEqualsUnpruned) {
  const std::vector<CsgWeights> weights = {{}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.1, 0.1, 0.8}};
  const std::vector<std::string> texts = testing::grammarExamples("csg_query_grammar.ebnf");
  ASSERT_GT(texts.size(), 10u);
  size_t runs = 0, prunedRuns = 0, hits = 0;
  for (uint32_t seed = 1; seed <= 3; ++seed) {
    Catalogue c(seed);
    c.build(12, 70);
    const ReferenceResolver resolver = storeResolver(c.store());
    StoredGraphCache cache;  // one for the catalogue: the searches compare, the graphs are the same
    std::vector<std::pair<std::string, CsgQuery>> queries;
    for (const std::string& t : texts) queries.emplace_back(t, parseCsgQuery(t, Vocabulary::builtin(), resolver, 1000));
    for (int q = 0; q < 15; ++q) {
      const json tree = c.tree(2);
      queries.emplace_back(tree.dump(), csgQueryFromDocument(tree, 1000, resolver));
    }
    for (const auto& [what, query] : queries)
      for (int limit : {1, 3, 1000}) {
        CsgSearchOptions options;
        options.limit = limit;
        options.weights = weights[size_t(pick(c.rng(), int(weights.size())))];
        options.threshold = pick(c.rng(), 4) == 0 ? 0.3 : 0.0;
        options.leafThreshold = pick(c.rng(), 4) == 0 ? 0.5 : 0.0;
        options.timeBudgetMs = 1000;
        prunedRuns += expectSameHits(c.store(), query, options, cache, what + " limit " + std::to_string(limit));
        ++runs;
        if (limit == 1000) {
          hits += searchCsg(c.store(), query, options, cache).hits.size();
        }
      }
  }
  EXPECT_GT(prunedRuns, runs / 3) << prunedRuns << " of " << runs;
  EXPECT_GT(hits, runs / 3);
}

TEST(CsgSearchProperty, CacheRebuildsWhatAWriteChanged) {
  Catalogue c(9);
  c.build(6, 30);
  StoredGraphCache cache;
  const CsgQuery query = parseCsgQuery("a sphere and a box", Vocabulary::builtin(), {}, 100);
  CsgSearchOptions options;
  options.limit = 1000;
  const CsgSearchResult first = searchCsg(c.store(), query, options, cache);
  EXPECT_EQ(cache.builds(), 30u);
  searchCsg(c.store(), query, options, cache);
  EXPECT_EQ(cache.builds(), 30u);  // all cached
  // A new version of a part: exactly the shapes reaching it are rebuilt.
  const int64_t part = c.parts()[0];
  const size_t reaching = c.store().dependents(part).size();
  c.store().put(part, prepareDocument({{"kind", "part"}, {"name", "p0"}, {"text", "a very bent cylinder"}}, "part",
                                      c.store(), DocumentLimits{}, ""));
  searchCsg(c.store(), query, options, cache);
  EXPECT_EQ(cache.builds(), 30u + reaching);
  // And their answers are those of fresh graphs.
  StoredGraphCache fresh;
  const CsgSearchResult a = searchCsg(c.store(), query, options, cache), b = searchCsg(c.store(), query, options, fresh);
  ASSERT_EQ(a.hits.size(), b.hits.size());
  for (size_t i = 0; i < a.hits.size(); ++i) {
    EXPECT_EQ(a.hits[i].id, b.hits[i].id);
    EXPECT_EQ(a.hits[i].score.score, b.hits[i].score.score);
  }
  EXPECT_FALSE(first.hits.empty());
}

// A described leaf scores as the linguistic search does, over the descriptors' degree domains: a
// shape whose box was made from "an extremely square box" (squariness cut at 0.99, where every
// degree is read) scores as a shape of the same tree whose box is crisp in the words' core. Read
// as written, the made box's leaf scored 0.971 and its shape came second.
TEST(CsgSearchProperty, DescribedLeavesAreReadOverTheDegreeDomains) {
  Catalogue c(4);
  const auto shape = [&](const std::string& name, const json& box) {
    const json doc = {{"kind", "shape"},
                      {"name", name},
                      {"tree", {{"op", "union"}, {"children", {{{"part", box}}, {{"part", {{"name", "s"}, {"text", "a sphere"}}}}}}}}};
    return c.store().create(prepareDocument(doc, "shape", c.store(), DocumentLimits{}, "")).id;
  };
  const int64_t crisp = shape("crisp", {{"name", "b"}, {"text", "a box"}, {"params", {{"eps1", 0.03}, {"eps2", 0.03}}}});
  const int64_t made = shape("made", {{"name", "b"}, {"text", "an extremely square box"}});
  StoredGraphCache cache;
  const CsgQuery query = parseCsgQuery("the union of an extremely square box and a sphere", Vocabulary::builtin(), {}, 100);
  CsgSearchOptions options;
  options.limit = 10;
  const CsgSearchResult found = searchCsg(c.store(), query, options, cache);
  double crispScore = -1, madeScore = -1;
  for (const CsgHit& h : found.hits) {
    if (h.id == crisp) crispScore = h.score.score;
    if (h.id == made) madeScore = h.score.score;
  }
  ASSERT_GT(crispScore, 0.0);
  EXPECT_EQ(madeScore, crispScore);
}

}  // namespace
}  // namespace fsdb
