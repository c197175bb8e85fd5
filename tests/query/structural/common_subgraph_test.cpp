// largestCommonSubgraph against a brute-force enumeration of every injective partial map, checked
// against the definition in query/structural/common_subgraph.h (labels, induced edges with difference roles,
// connectedness), on thousands of random small trees and DAGs.
#include "query/structural/common_subgraph.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <string>

#include "geometry/core/error.h"
#include "query/structural/csg_graph.h"
#include "tests/testing/random_csg_graph.h"

namespace fsdb {
namespace {

using testing::randomDag;
using testing::randomLeafSimilarity;
using testing::randomTree;

// The roles of the edges a -> b: "m" (minuend), "s" (subtrahend), "p" (union / intersection), sorted.
std::string roles(const CsgGraph& g, int a, int b) {
  std::string r;
  const CsgGraphNode& n = g.nodes[size_t(a)];
  for (size_t i = 0; i < n.children.size(); ++i)
    if (n.children[i] == b) r += n.op != CsgGraphOp::Difference ? 'p' : i == 0 ? 'm' : 's';
  std::sort(r.begin(), r.end());
  return r;
}

double admissible(const CsgGraph& q, const CsgGraph& s, const LeafSimilarityMatrix& m, double threshold, int u, int v) {
  const CsgGraphNode& a = q.nodes[size_t(u)];
  const CsgGraphNode& b = s.nodes[size_t(v)];
  if (a.op != b.op) return -1;
  if (a.op != CsgGraphOp::Leaf) return 1;
  const double x = m.at(a.leaf, b.leaf);
  return x > 0 && x >= threshold ? x : -1;
}

bool edgesAgree(const CsgGraph& q, const CsgGraph& s, int u, int w, int mu, int mw) {
  return roles(q, u, w) == roles(s, mu, mw) && roles(q, w, u) == roles(s, mw, mu);
}

bool connected(const CsgGraph& q, const std::vector<int>& map) {
  std::vector<int> matched;
  for (size_t u = 0; u < map.size(); ++u)
    if (map[u] >= 0) matched.push_back(int(u));
  if (matched.empty()) return true;
  std::vector<char> seen(q.size(), 0);
  std::vector<int> stack{matched[0]};
  seen[size_t(matched[0])] = 1;
  size_t reached = 1;
  while (!stack.empty()) {
    const int x = stack.back();
    stack.pop_back();
    for (int y : matched)
      if (!seen[size_t(y)] && (!roles(q, x, y).empty() || !roles(q, y, x).empty())) {
        seen[size_t(y)] = 1;
        ++reached;
        stack.push_back(y);
      }
  }
  return reached == matched.size();
}

// The definition, checked on a complete map (query node -> stored node or -1); its weight, or -1.
double definitionWeight(const CsgGraph& q, const CsgGraph& s, const LeafSimilarityMatrix& m, double threshold,
                        const std::vector<int>& map) {
  double w = 0;
  std::vector<char> used(s.size(), 0);
  for (size_t u = 0; u < map.size(); ++u) {
    if (map[u] < 0) continue;
    if (used[size_t(map[u])]) return -1;
    used[size_t(map[u])] = 1;
    const double x = admissible(q, s, m, threshold, int(u), map[u]);
    if (x < 0) return -1;
    w += x;
    for (size_t t = 0; t < u; ++t)
      if (map[t] >= 0 && !edgesAgree(q, s, int(u), int(t), map[u], map[t])) return -1;
  }
  return connected(q, map) ? w : -1;
}

double bruteForce(const CsgGraph& q, const CsgGraph& s, const LeafSimilarityMatrix& m, double threshold) {
  std::vector<int> map(q.size(), -1);
  std::vector<char> used(s.size(), 0);
  double best = 0;
  // Every injective label-compatible map; induced edges checked as pairs are added (part of the
  // definition), connectedness at the end.
  std::function<void(size_t, double)> go = [&](size_t u, double w) {
    if (u == q.size()) {
      if (w > best && connected(q, map)) best = w;
      return;
    }
    go(u + 1, w);
    for (size_t v = 0; v < s.size(); ++v) {
      if (used[v]) continue;
      const double x = admissible(q, s, m, threshold, int(u), int(v));
      if (x < 0) continue;
      bool ok = true;
      for (size_t t = 0; t < u && ok; ++t)
        if (map[t] >= 0) ok = edgesAgree(q, s, int(u), int(t), int(v), map[t]);
      if (!ok) continue;
      map[u] = int(v);
      used[v] = 1;
      go(u + 1, w + x);
      map[u] = -1;
      used[v] = 0;
    }
  };
  go(0, 0);
  return best;
}

// The result is a valid common subgraph whose weight and counts are what it reports.
void expectValid(const CsgGraph& q, const CsgGraph& s, const LeafSimilarityMatrix& m, double threshold,
                 const CommonSubgraph& r) {
  std::vector<int> map(q.size(), -1);
  int leaves = 0;
  for (size_t i = 0; i < r.matches.size(); ++i) {
    const NodeMatch& x = r.matches[i];
    if (i > 0) {
      EXPECT_LT(r.matches[i - 1].queryNode, x.queryNode);
    }
    ASSERT_EQ(map[size_t(x.queryNode)], -1);
    map[size_t(x.queryNode)] = x.storedNode;
    EXPECT_DOUBLE_EQ(x.similarity, admissible(q, s, m, threshold, x.queryNode, x.storedNode));
    if (q.nodes[size_t(x.queryNode)].op == CsgGraphOp::Leaf) ++leaves;
  }
  EXPECT_NEAR(definitionWeight(q, s, m, threshold, map), r.weight, 1e-9);
  EXPECT_EQ(r.matchedNodes, int(r.matches.size()));
  EXPECT_EQ(r.matchedLeaves, leaves);
}

LeafSimilarityMatrix transpose(const LeafSimilarityMatrix& m) {
  LeafSimilarityMatrix t;
  t.rows = m.cols;
  t.cols = m.rows;
  for (int i = 0; i < t.rows; ++i)
    for (int j = 0; j < t.cols; ++j) t.values.push_back(m.at(j, i));
  return t;
}

LeafSimilarityMatrix ones(int rows, int cols) { return {rows, cols, std::vector<double>(size_t(rows) * cols, 1.0)}; }

// Node helpers for hand-written graphs.
CsgGraphNode op(CsgGraphOp o, std::vector<int> children) {
  CsgGraphNode n;
  n.op = o;
  n.children = std::move(children);
  return n;
}
CsgGraphNode leaf(int index) {
  CsgGraphNode n;
  n.leaf = index;
  return n;
}
CsgGraph graph(std::vector<CsgGraphNode> nodes) {
  CsgGraph g;
  g.nodes = std::move(nodes);
  for (const CsgGraphNode& n : g.nodes)
    if (n.op == CsgGraphOp::Leaf) ++g.leafCount;
  return g;
}

struct RandomPair {
  CsgGraph query, stored;
  LeafSimilarityMatrix leaves;
};
// Two random DAGs of dagNodes (two extra edges each) or two random trees of treeNodes.
RandomPair randomPair(std::mt19937& rng, bool dag, int dagNodes, int treeNodes) {
  RandomPair p;
  p.query = dag ? randomDag(rng, dagNodes, 2) : randomTree(rng, treeNodes);
  p.stored = dag ? randomDag(rng, dagNodes, 2) : randomTree(rng, treeNodes);
  p.leaves = randomLeafSimilarity(rng, p.query.leafCount, p.stored.leafCount);
  return p;
}

TEST(CommonSubgraph, TreeDynamicProgrammeEqualsBruteForceOnRandomTrees) {
  std::mt19937 rng(6001);
  for (int trial = 0; trial < 3000; ++trial) {
    const CsgGraph q = randomTree(rng, std::uniform_int_distribution<int>(1, 8)(rng));
    const CsgGraph s = randomTree(rng, std::uniform_int_distribution<int>(1, 8)(rng));
    const LeafSimilarityMatrix m = randomLeafSimilarity(rng, q.leafCount, s.leafCount);
    const double threshold = trial % 4 == 0 ? 0.5 : 0.0;
    ASSERT_TRUE(q.isTree() && s.isTree());
    const CommonSubgraph r = largestCommonSubgraph(q, s, m, {threshold, 100});
    ASSERT_NEAR(r.weight, bruteForce(q, s, m, threshold), 1e-9) << "trial " << trial;
    EXPECT_TRUE(r.complete);
    expectValid(q, s, m, threshold, r);
  }
}

TEST(CommonSubgraph, BranchAndBoundEqualsBruteForceOnRandomDags) {
  std::mt19937 rng(6002);
  int dags = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const CsgGraph q = randomDag(rng, std::uniform_int_distribution<int>(1, 8)(rng), trial % 3);
    const CsgGraph s = randomDag(rng, std::uniform_int_distribution<int>(1, 8)(rng), (trial / 3) % 3);
    if (!q.isTree() || !s.isTree()) ++dags;
    const LeafSimilarityMatrix m = randomLeafSimilarity(rng, q.leafCount, s.leafCount);
    const double threshold = trial % 5 == 0 ? 0.5 : 0.0;
    const CommonSubgraph r = largestCommonSubgraph(q, s, m, {threshold, 10000});
    ASSERT_TRUE(r.complete);
    ASSERT_NEAR(r.weight, bruteForce(q, s, m, threshold), 1e-9) << "trial " << trial;
    expectValid(q, s, m, threshold, r);
  }
  EXPECT_GT(dags, 1500);  // most pairs exercise the general search
}

TEST(CommonSubgraph, TreeDynamicProgrammeEqualsBranchAndBoundOnTrees) {
  std::mt19937 rng(6003);
  for (int trial = 0; trial < 500; ++trial) {
    const CsgGraph q = randomTree(rng, std::uniform_int_distribution<int>(1, 12)(rng));
    const CsgGraph s = randomTree(rng, std::uniform_int_distribution<int>(1, 12)(rng));
    const LeafSimilarityMatrix m = randomLeafSimilarity(rng, q.leafCount, s.leafCount);
    const CommonSubgraph dp = largestCommonSubgraph(q, s, m);
    const CommonSubgraph bb = largestCommonSubgraphSearch(q, s, m, {0, 60000});
    ASSERT_TRUE(bb.complete);
    ASSERT_NEAR(dp.weight, bb.weight, 1e-9) << "trial " << trial;
    expectValid(q, s, m, 0, bb);
  }
}

TEST(CommonSubgraph, SymmetricInQueryAndStored) {
  std::mt19937 rng(6004);
  for (int trial = 0; trial < 1000; ++trial) {
    const auto [q, s, m] = randomPair(rng, trial % 2 == 1, 7, 9);
    const CommonSubgraph a = largestCommonSubgraph(q, s, m, {0, 10000});
    const CommonSubgraph b = largestCommonSubgraph(s, q, transpose(m), {0, 10000});
    ASSERT_NEAR(a.weight, b.weight, 1e-9) << "trial " << trial;
    EXPECT_EQ(a.matchedNodes > 0, b.matchedNodes > 0);
  }
}

TEST(CommonSubgraph, AGraphMatchesItselfCompletely) {
  std::mt19937 rng(6005);
  for (int trial = 0; trial < 300; ++trial) {
    const CsgGraph g = trial % 2 ? randomDag(rng, 8, 2) : randomTree(rng, 15);
    LeafSimilarityMatrix m{g.leafCount, g.leafCount, std::vector<double>(size_t(g.leafCount) * g.leafCount, 0.0)};
    for (int i = 0; i < g.leafCount; ++i) m.values[size_t(i) * g.leafCount + i] = 1;
    const CommonSubgraph r = largestCommonSubgraph(g, g, m, {0, 10000});
    EXPECT_EQ(r.matchedNodes, int(g.size()));
    EXPECT_NEAR(r.weight, double(g.size()), 1e-12);
  }
}

// Reordering union / intersection children and subtrahends changes nothing (they are unordered).
TEST(CommonSubgraph, ReorderingUnorderedChildrenKeepsTheWeight) {
  std::mt19937 rng(6007);
  for (int trial = 0; trial < 1000; ++trial) {
    const auto [q, s, m] = randomPair(rng, trial % 2 == 1, 8, 12);
    CsgGraph shuffled = s;
    for (CsgGraphNode& n : shuffled.nodes) {
      const size_t from = n.op == CsgGraphOp::Difference ? 1 : 0;
      if (n.children.size() > from) std::shuffle(n.children.begin() + long(from), n.children.end(), rng);
    }
    ASSERT_NEAR(largestCommonSubgraph(q, s, m, {0, 10000}).weight, largestCommonSubgraph(q, shuffled, m, {0, 10000}).weight,
                1e-9)
        << "trial " << trial;
  }
}

// Swapping a difference's minuend with a subtrahend breaks the complete self match. (Trees, and
// each leaf like itself only: siblings have disjoint leaves, so no other map can repair the swap.)
TEST(CommonSubgraph, SwappingAMinuendBreaksTheCompleteMatch) {
  std::mt19937 rng(6008);
  int tested = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const CsgGraph g = randomTree(rng, std::uniform_int_distribution<int>(3, 14)(rng));
    CsgGraph swapped = g;
    bool changed = false;
    for (CsgGraphNode& n : swapped.nodes)
      if (!changed && n.op == CsgGraphOp::Difference && n.children[0] != n.children[1]) {
        std::swap(n.children[0], n.children[1]);
        changed = true;
      }
    if (!changed) continue;
    ++tested;
    LeafSimilarityMatrix m{g.leafCount, g.leafCount, std::vector<double>(size_t(g.leafCount) * g.leafCount, 0.0)};
    for (int i = 0; i < g.leafCount; ++i) m.values[size_t(i) * g.leafCount + i] = 1;
    for (const CommonSubgraph& r : {largestCommonSubgraph(g, swapped, m), largestCommonSubgraphSearch(g, swapped, m, {0, 10000})}) {
      EXPECT_LT(r.matchedNodes, int(g.size())) << "trial " << trial;
      EXPECT_LT(r.weight, double(g.size()));
    }
  }
  EXPECT_GT(tested, 200);
}

// (A ∪ B) against (B ∪ A): union children are unordered.
TEST(CommonSubgraph, SwappedUnionChildrenMatchFully) {
  const CsgGraph q = graph({op(CsgGraphOp::Union, {1, 2}), leaf(0), leaf(1)});
  const CsgGraph s = graph({op(CsgGraphOp::Union, {1, 2}), leaf(0), leaf(1)});
  // stored leaf 1 is query leaf 0 and vice versa.
  const LeafSimilarityMatrix m{2, 2, {0, 1, 1, 0}};
  const CommonSubgraph r = largestCommonSubgraph(q, s, m);
  EXPECT_EQ(r.matchedNodes, 3);
  EXPECT_DOUBLE_EQ(r.weight, 3);
  ASSERT_EQ(r.matches.size(), 3u);
  EXPECT_EQ(r.matches[1].storedNode, 2);
  EXPECT_EQ(r.matches[2].storedNode, 1);
  EXPECT_DOUBLE_EQ(largestCommonSubgraphSearch(q, s, m).weight, 3);
}

// (A − B) against (B − A): the minuend must stay the minuend.
TEST(CommonSubgraph, SwappedDifferenceChildrenDoNotMatchFully) {
  const CsgGraph q = graph({op(CsgGraphOp::Difference, {1, 2}), leaf(0), leaf(1)});
  const CsgGraph s = graph({op(CsgGraphOp::Difference, {1, 2}), leaf(0), leaf(1)});
  const LeafSimilarityMatrix swapped{2, 2, {0, 1, 1, 0}};
  for (const CommonSubgraph& r : {largestCommonSubgraph(q, s, swapped), largestCommonSubgraphSearch(q, s, swapped)}) {
    EXPECT_LT(r.matchedNodes, 3);
    // Each leaf resembles only the other role's leaf: the root alone (or one leaf alone) matches.
    EXPECT_DOUBLE_EQ(r.weight, 1);
  }
  const LeafSimilarityMatrix same{2, 2, {1, 0, 0, 1}};
  EXPECT_DOUBLE_EQ(largestCommonSubgraph(q, s, same).weight, 3);
}

// Subtrahends are an unordered set: A − B − C against A − C − B.
TEST(CommonSubgraph, SubtrahendsAreUnordered) {
  const CsgGraph q = graph({op(CsgGraphOp::Difference, {1, 2, 3}), leaf(0), leaf(1), leaf(2)});
  const LeafSimilarityMatrix m{3, 3, {1, 0, 0, 0, 0, 1, 0, 1, 0}};
  EXPECT_DOUBLE_EQ(largestCommonSubgraph(q, q, m).weight, 4);
  EXPECT_DOUBLE_EQ(largestCommonSubgraphSearch(q, q, m).weight, 4);
}

// The query is a subtree deep inside the stored tree: the mapping need not contain the roots.
TEST(CommonSubgraph, CommonPartMayBeRootedAnywhere) {
  const CsgGraph q = graph({op(CsgGraphOp::Intersection, {1, 2}), leaf(0), leaf(1)});
  const CsgGraph s = graph({op(CsgGraphOp::Union, {1, 2}), leaf(0), op(CsgGraphOp::Intersection, {3, 4}), leaf(1),
                            leaf(2)});
  const LeafSimilarityMatrix m{2, 3, {0, 0.8, 0, 0, 0, 0.6}};
  const CommonSubgraph r = largestCommonSubgraph(q, s, m);
  EXPECT_NEAR(r.weight, 2.4, 1e-12);
  ASSERT_EQ(r.matches.size(), 3u);
  EXPECT_EQ(r.matches[0].storedNode, 2);
}

TEST(CommonSubgraph, LeafThresholdExcludesWeakLeaves) {
  const CsgGraph q = graph({op(CsgGraphOp::Union, {1, 2}), leaf(0), leaf(1)});
  const LeafSimilarityMatrix m{2, 2, {0.9, 0, 0, 0.3}};
  EXPECT_NEAR(largestCommonSubgraph(q, q, m).weight, 2.2, 1e-12);
  const CommonSubgraph r = largestCommonSubgraph(q, q, m, {0.5, 100});
  EXPECT_NEAR(r.weight, 1.9, 1e-12);
  EXPECT_EQ(r.matchedLeaves, 1);
}

// A node shared by two parents (DAG) must be shared in the image too, else only a tree part maps.
TEST(CommonSubgraph, SharedNodeMapsOntoSharedNode) {
  // q: U(I(a, x), D(x, b)) with x shared; s: the same shape with x copied.
  const CsgGraph q = graph({op(CsgGraphOp::Union, {1, 2}), op(CsgGraphOp::Intersection, {3, 4}),
                            op(CsgGraphOp::Difference, {4, 5}), leaf(0), leaf(1), leaf(2)});
  const CsgGraph s = graph({op(CsgGraphOp::Union, {1, 2}), op(CsgGraphOp::Intersection, {3, 4}),
                            op(CsgGraphOp::Difference, {5, 6}), leaf(0), leaf(1), leaf(2), leaf(3)});
  ASSERT_FALSE(q.isTree());
  const LeafSimilarityMatrix m{3, 4, {1, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1}};
  const CommonSubgraph r = largestCommonSubgraph(q, s, m);
  EXPECT_TRUE(r.complete);
  EXPECT_EQ(r.matchedNodes, 5);  // everything but one of the two edges into x
  expectValid(q, s, m, 0, r);
  EXPECT_DOUBLE_EQ(largestCommonSubgraph(q, q, ones(3, 3)).weight, 6);
}

TEST(CommonSubgraph, TimeBudgetCutsTheSearchShort) {
  std::mt19937 rng(6006);
  const CsgGraph q = randomDag(rng, 60, 20), s = randomDag(rng, 60, 20);
  const LeafSimilarityMatrix m = ones(q.leafCount, s.leafCount);
  const CommonSubgraph r = largestCommonSubgraph(q, s, m, {0, 0});
  EXPECT_FALSE(r.complete);
  expectValid(q, s, m, 0, r);
}

// A union of 3000 leaves against a union of 3 (a long CSG list query): the children's assignment
// augments the 3, and the poll runs; a throwing poll abandons the match (the search's time limit).
TEST(CommonSubgraph, WideUnionsMatchQuicklyAndPollStopsThem) {
  std::vector<CsgGraphNode> wide{op(CsgGraphOp::Union, {})};
  for (int i = 0; i < 3000; ++i) wide[0].children.push_back(i + 1), wide.push_back(leaf(i));
  const CsgGraph q = graph(wide);
  const CsgGraph s = graph({op(CsgGraphOp::Union, {1, 2, 3}), leaf(0), leaf(1), leaf(2)});
  LeafSimilarityMatrix m = ones(3000, 3);
  int polls = 0;
  const CommonSubgraph r = largestCommonSubgraph(q, s, m, {}, [&] { ++polls; });
  EXPECT_DOUBLE_EQ(r.weight, 4);  // the union and three leaves
  EXPECT_GT(polls, 0);
  EXPECT_THROW(largestCommonSubgraph(q, q, ones(3000, 3000), {}, [] { throw Error(errc::kLimitExceeded, "stop"); }),
               Error);
}

TEST(CommonSubgraph, RejectsAMatrixOfTheWrongSize) {
  const CsgGraph q = graph({leaf(0)});
  try {
    largestCommonSubgraph(q, q, LeafSimilarityMatrix{1, 2, {1, 1}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter);
    EXPECT_EQ(e.path(), "leafSimilarity");
  }
}

TEST(CommonSubgraph, RejectsAChildOutsideTheGraph) {
  const CsgGraph bad = graph({op(CsgGraphOp::Union, {1, 5}), leaf(0)});
  try {
    largestCommonSubgraph(bad, bad, ones(1, 1));
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter);
    EXPECT_EQ(e.path(), "graph");
  }
}

TEST(CommonSubgraph, NothingInCommonIsTheEmptyMap) {
  const CsgGraph q = graph({op(CsgGraphOp::Union, {1, 2}), leaf(0), leaf(1)});
  const CsgGraph s = graph({leaf(0)});
  const CommonSubgraph r = largestCommonSubgraph(q, s, LeafSimilarityMatrix{2, 1, {0, 0}});
  EXPECT_EQ(r.matchedNodes, 0);
  EXPECT_EQ(r.weight, 0);
  EXPECT_TRUE(r.matches.empty());
}

}  // namespace
}  // namespace fsdb
