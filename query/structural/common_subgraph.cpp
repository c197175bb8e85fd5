#include "query/structural/common_subgraph.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>

#include "geometry/core/error.h"
#include "query/structural/assignment.h"
#include "query/structural/csg_graph.h"

namespace fsdb {
namespace {

constexpr double kNoMatch = -1;  // pairWeight of an inadmissible pair
constexpr int kPollInterval = 4096;  // tree DP node pairs between CommonSubgraphOptions::poll calls

// The weight a pair (u, v) adds when matched (query/structural/common_subgraph.h objective), kNoMatch if it
// may not be matched.
double pairWeight(const CsgGraph& q, const CsgGraph& s, const LeafSimilarityMatrix& sim,
                  const CommonSubgraphOptions& o, int u, int v) {
  const CsgGraphNode& a = q.nodes[size_t(u)];
  const CsgGraphNode& b = s.nodes[size_t(v)];
  if (a.op != b.op) return kNoMatch;
  if (a.op != CsgGraphOp::Leaf) return 1;
  const double x = sim.at(a.leaf, b.leaf);
  return (x > 0 && x >= o.leafThreshold) ? x : kNoMatch;
}

void checkInputs(const CsgGraph& q, const CsgGraph& s, const LeafSimilarityMatrix& sim) {
  if (sim.rows != q.leafCount || sim.cols != s.leafCount || sim.values.size() != size_t(sim.rows) * size_t(sim.cols))
    throw Error(errc::kInvalidParameter,
                "the leaf similarity matrix must be query leaves x stored leaves (" + std::to_string(q.leafCount) +
                    " x " + std::to_string(s.leafCount) + ")",
                "leafSimilarity");
  for (const CsgGraph* g : {&q, &s})
    for (const CsgGraphNode& n : g->nodes) {
      if (n.op == CsgGraphOp::Leaf && (n.leaf < 0 || n.leaf >= g->leafCount))
        throw Error(errc::kInvalidParameter, "a leaf node's payload index is outside 0..leafCount-1", "leafSimilarity");
      for (int c : n.children)
        if (c < 0 || size_t(c) >= g->size())
          throw Error(errc::kInvalidParameter, "a child index is outside the graph's nodes", "graph");
    }
}

CommonSubgraph finish(std::vector<NodeMatch> matches, const CsgGraph& q, bool complete) {
  CommonSubgraph out;
  std::sort(matches.begin(), matches.end(), [](const NodeMatch& x, const NodeMatch& y) { return x.queryNode < y.queryNode; });
  for (const NodeMatch& m : matches) {
    out.weight += m.similarity;
    ++out.matchedNodes;
    if (q.nodes[size_t(m.queryNode)].op == CsgGraphOp::Leaf) ++out.matchedLeaves;
  }
  out.matches = std::move(matches);
  out.complete = complete;
  return out;
}

// ---- Trees: best(u, v) = pairWeight + best matching of the children (query/structural/common_subgraph.h) ----

class TreeMatcher {
 public:
  TreeMatcher(const CsgGraph& q, const CsgGraph& s, const LeafSimilarityMatrix& sim, const CommonSubgraphOptions& o,
              const CommonSubgraphPoll& poll)
      : q_(q), s_(s), sim_(sim), o_(o), poll_(poll), best_(q.size() * s.size(), kNoMatch) {}

  CommonSubgraph run() {
    const std::vector<int> qo = postOrder(q_), so = postOrder(s_);
    int bu = -1, bv = -1;
    double top = 0;
    int untilPoll = kPollInterval;
    for (int u : qo)
      for (int v : so) {
        if (poll_ && --untilPoll <= 0) poll_(), untilPoll = kPollInterval;
        const double w = pairWeight(q_, s_, sim_, o_, u, v);
        if (w == kNoMatch) continue;
        const double b = w + children(u, v, nullptr);
        best_[index(u, v)] = b;
        if (b > top) top = b, bu = u, bv = v;
      }
    std::vector<NodeMatch> matches;
    if (bu >= 0) collect(bu, bv, &matches);
    return finish(std::move(matches), q_, true);
  }

 private:
  size_t index(int u, int v) const { return size_t(u) * s_.size() + size_t(v); }
  double gain(int u, int v) const { return std::max(0.0, best_[index(u, v)]); }

  // Children first: every node after all of its descendants (a forest if some nodes hang loose).
  static std::vector<int> postOrder(const CsgGraph& g) {
    std::vector<int> order;
    std::vector<char> hasParent(g.size(), 0);
    for (const CsgGraphNode& n : g.nodes)
      for (int c : n.children) hasParent[size_t(c)] = 1;
    std::function<void(int)> visit = [&](int x) {
      for (int c : g.nodes[size_t(x)].children) visit(c);
      order.push_back(x);
    };
    for (size_t x = 0; x < g.size(); ++x)
      if (!hasParent[x]) visit(int(x));
    return order;
  }

  // Best total gain of u's children matched to v's children; with `pairs`, the chosen child pairs.
  double children(int u, int v, std::vector<std::pair<int, int>>* pairs) const {
    const std::vector<int>& a = q_.nodes[size_t(u)].children;
    const std::vector<int>& b = s_.nodes[size_t(v)].children;
    size_t from = 0;
    double total = 0;
    if (q_.nodes[size_t(u)].op == CsgGraphOp::Difference && !a.empty() && !b.empty()) {
      // Minuend to minuend only; the subtrahends are an unordered set.
      from = 1;
      const double g = gain(a[0], b[0]);
      if (g > 0) {
        total += g;
        if (pairs) pairs->push_back({a[0], b[0]});
      }
    }
    const int rows = int(a.size() - std::min(from, a.size())), cols = int(b.size() - std::min(from, b.size()));
    if (rows == 0 || cols == 0) return total;
    std::vector<double> w(size_t(rows) * size_t(cols));
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j) w[size_t(i) * cols + j] = gain(a[from + i], b[from + j]);
    const Assignment m = maxWeightAssignment(rows, cols, w, poll_);
    if (pairs)
      for (int i = 0; i < rows; ++i)
        if (m.columnOfRow[size_t(i)] >= 0) pairs->push_back({a[from + i], b[from + m.columnOfRow[size_t(i)]]});
    return total + m.weight;
  }

  void collect(int u, int v, std::vector<NodeMatch>* out) const {
    out->push_back({u, v, pairWeight(q_, s_, sim_, o_, u, v)});
    std::vector<std::pair<int, int>> pairs;
    children(u, v, &pairs);
    for (const auto& p : pairs) collect(p.first, p.second, out);
  }

  const CsgGraph& q_;
  const CsgGraph& s_;
  const LeafSimilarityMatrix& sim_;
  const CommonSubgraphOptions& o_;
  const CommonSubgraphPoll& poll_;
  std::vector<double> best_;
};

// ---- General graphs: McSplit-style branch and bound (McCreesh, Prosser, Trimble 2017) ----

// The edges from a to b as counts by role (minuend, subtrahend, plain), packed 20 bits each (more than
// any node limit); the relation of a to b is that code in both directions. Two unmatched vertices can
// join matched ones only with equal relations.
uint64_t edgeCode(const CsgGraph& g, int a, int b) {
  const CsgGraphNode& n = g.nodes[size_t(a)];
  uint64_t minuend = 0, subtrahend = 0, plain = 0;
  for (size_t i = 0; i < n.children.size(); ++i) {
    if (n.children[i] != b) continue;
    if (n.op != CsgGraphOp::Difference) ++plain;
    else if (i == 0) ++minuend;
    else ++subtrahend;
  }
  return minuend | (subtrahend << 20) | (plain << 40);
}

// Per node, its neighbours with the relation code (nodes not listed relate by 0): sparse, so a
// stored DAG of thousands of nodes costs memory in its edges, not its node pairs.
using Relation = std::pair<uint64_t, uint64_t>;  // (edges a -> b, edges b -> a)
std::vector<std::vector<std::pair<int, Relation>>> relations(const CsgGraph& g) {
  std::vector<std::vector<std::pair<int, Relation>>> r(g.size());
  const std::vector<std::vector<int>> parents = g.parents();
  for (size_t a = 0; a < g.size(); ++a) {
    std::vector<int> neighbours = g.nodes[a].children;
    neighbours.insert(neighbours.end(), parents[a].begin(), parents[a].end());
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    for (int b : neighbours) r[a].push_back({b, {edgeCode(g, int(a), b), edgeCode(g, b, int(a))}});
  }
  return r;
}

class BranchAndBound {
 public:
  BranchAndBound(const CsgGraph& q, const CsgGraph& s, const LeafSimilarityMatrix& sim, const CommonSubgraphOptions& o,
                 const CommonSubgraphPoll& poll)
      : q_(q), s_(s), sim_(sim), o_(o), poll_(poll), relQ_(relations(q)), relS_(relations(s)), codeQ_(q.size()),
        codeS_(s.size()),
        deadline_(std::chrono::steady_clock::now() +
                  std::chrono::microseconds(int64_t(std::max(0.0, std::min(o.timeBudgetMs, 1e12)) * 1000))) {}

  CommonSubgraph run() {
    clockInterval_ = untilClock_ = int(std::max<size_t>(1, 4096 / (q_.size() + s_.size() + 1)));
    // Initial label classes: one per operation, one for all leaves (leaf pairs are admissible by
    // the matrix, checked when a pair is chosen and in the bound).
    std::vector<Class> classes;
    for (CsgGraphOp op : {CsgGraphOp::Union, CsgGraphOp::Intersection, CsgGraphOp::Difference, CsgGraphOp::Leaf}) {
      Class c;
      c.op = op;
      for (size_t x = 0; x < q_.size(); ++x)
        if (q_.nodes[x].op == op) c.qs.push_back(int(x));
      for (size_t x = 0; x < s_.size(); ++x)
        if (s_.nodes[x].op == op) c.ss.push_back(int(x));
      if (!c.qs.empty() && !c.ss.empty()) classes.push_back(std::move(c));
    }
    search(classes, 0);
    return finish(best_, q_, !timedOut_);
  }

 private:
  struct Class {
    CsgGraphOp op = CsgGraphOp::Leaf;
    std::vector<int> qs, ss;
    bool adjacent = false;  // related to some matched pair (connectedness)
  };

  double weight(int u, int v) const { return pairWeight(q_, s_, sim_, o_, u, v); }

  // The most a class can still add: min(|qs|, |ss|) pairs, each of weight 1 for operations; for
  // leaves, the top min(|qs|,|ss|) best admissible similarities of either side (the smaller sum).
  double classBound(const Class& c) const {
    const size_t k = std::min(c.qs.size(), c.ss.size());
    if (c.op != CsgGraphOp::Leaf) return double(k);
    auto topSum = [&](const std::vector<int>& xs, const std::vector<int>& ys, bool queryRows) {
      std::vector<double> m;
      for (int x : xs) {
        double b = 0;
        for (int y : ys) b = std::max(b, queryRows ? weight(x, y) : weight(y, x));
        m.push_back(b);
      }
      std::sort(m.begin(), m.end(), std::greater<double>());
      double t = 0;
      for (size_t i = 0; i < k && i < m.size(); ++i) t += m[i];
      return t;
    };
    return std::min(topSum(c.qs, c.ss, true), topSum(c.ss, c.qs, false));
  }

  bool outOfTime() {
    if (timedOut_) return true;
    // A search node costs O(|Q| + |S|) or more: the clock is read about every 4096 such units of
    // work, so small graphs do not pay for it and large ones do not overrun the budget.
    if (--untilClock_ > 0) return false;
    untilClock_ = clockInterval_;
    if (poll_) poll_();
    if (std::chrono::steady_clock::now() > deadline_) timedOut_ = true;
    return timedOut_;
  }

  void search(std::vector<Class>& classes, double current) {
    if (current > bestWeight_) {
      bestWeight_ = current;
      best_ = matches_;
    }
    if (outOfTime()) return;
    double bound = current;
    for (const Class& c : classes) bound += classBound(c);
    if (bound <= bestWeight_ + 1e-12) return;
    // Branch on the eligible class (any before the first pair, then only adjacent ones: the matched
    // query nodes stay connected) with the smallest max(|qs|, |ss|), as McSplit does.
    int pick = -1;
    for (size_t i = 0; i < classes.size(); ++i) {
      const Class& c = classes[i];
      if (!matches_.empty() && !c.adjacent) continue;
      if (pick < 0 || std::max(c.qs.size(), c.ss.size()) <
                          std::max(classes[size_t(pick)].qs.size(), classes[size_t(pick)].ss.size()))
        pick = int(i);
    }
    if (pick < 0) return;
    const int u = classes[size_t(pick)].qs.front();
    // (weight, v) of the admissible pairs, heaviest first: each weight computed once, not at every
    // comparison of the sort.
    std::vector<std::pair<double, int>> candidates;
    for (int v : classes[size_t(pick)].ss) {
      const double w = weight(u, v);
      if (w != kNoMatch) candidates.push_back({w, v});
    }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const auto& x, const auto& y) { return x.first > y.first; });
    for (const auto& [w, v] : candidates) {
      std::vector<Class> next = refine(classes, u, v);
      matches_.push_back({u, v, w});
      search(next, current + w);
      matches_.pop_back();
      if (timedOut_) return;
    }
    // u stays unmatched.
    Class& c = classes[size_t(pick)];
    c.qs.erase(c.qs.begin());
    if (c.qs.empty()) classes.erase(classes.begin() + pick);
    search(classes, current);
  }

  // The classes after matching u -> v: each split by relation to u (query side) and to v (stored
  // side); parts with an empty side can never be matched and are dropped.
  std::vector<Class> refine(const std::vector<Class>& classes, int u, int v) {
    std::vector<Class> out;
    // codeQ_[x] / codeS_[y]: the relation of x to u / of y to v, set for the neighbours only.
    for (const auto& [x, code] : relQ_[size_t(u)]) codeQ_[size_t(x)] = code;
    for (const auto& [y, code] : relS_[size_t(v)]) codeS_[size_t(y)] = code;
    for (const Class& c : classes) {
      std::vector<std::pair<Relation, int>> qs, ss;
      for (int x : c.qs)
        if (x != u) qs.push_back({codeQ_[size_t(x)], x});
      for (int y : c.ss)
        if (y != v) ss.push_back({codeS_[size_t(y)], y});
      std::stable_sort(qs.begin(), qs.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      std::stable_sort(ss.begin(), ss.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      size_t i = 0, j = 0;
      while (i < qs.size() && j < ss.size()) {
        if (qs[i].first < ss[j].first) { ++i; continue; }
        if (ss[j].first < qs[i].first) { ++j; continue; }
        const Relation key = qs[i].first;
        Class d;
        d.op = c.op;
        d.adjacent = c.adjacent || key != Relation{};
        for (; i < qs.size() && qs[i].first == key; ++i) d.qs.push_back(qs[i].second);
        for (; j < ss.size() && ss[j].first == key; ++j) d.ss.push_back(ss[j].second);
        out.push_back(std::move(d));
      }
    }
    for (const auto& n : relQ_[size_t(u)]) codeQ_[size_t(n.first)] = {};
    for (const auto& n : relS_[size_t(v)]) codeS_[size_t(n.first)] = {};
    return out;
  }

  const CsgGraph& q_;
  const CsgGraph& s_;
  const LeafSimilarityMatrix& sim_;
  const CommonSubgraphOptions& o_;
  const CommonSubgraphPoll& poll_;
  std::vector<std::vector<std::pair<int, Relation>>> relQ_, relS_;
  std::vector<Relation> codeQ_, codeS_;
  std::chrono::steady_clock::time_point deadline_;
  std::vector<NodeMatch> matches_, best_;
  double bestWeight_ = 0;
  bool timedOut_ = false;
  int clockInterval_ = 1, untilClock_ = 1;
};

}  // namespace

CommonSubgraph largestCommonSubgraph(const CsgGraph& query, const CsgGraph& stored,
                                     const LeafSimilarityMatrix& leafSimilarity, const CommonSubgraphOptions& options,
                                     const CommonSubgraphPoll& poll) {
  checkInputs(query, stored, leafSimilarity);
  if (query.isTree() && stored.isTree()) return TreeMatcher(query, stored, leafSimilarity, options, poll).run();
  return BranchAndBound(query, stored, leafSimilarity, options, poll).run();
}

CommonSubgraph largestCommonSubgraphSearch(const CsgGraph& query, const CsgGraph& stored,
                                           const LeafSimilarityMatrix& leafSimilarity,
                                           const CommonSubgraphOptions& options, const CommonSubgraphPoll& poll) {
  checkInputs(query, stored, leafSimilarity);
  return BranchAndBound(query, stored, leafSimilarity, options, poll).run();
}

}  // namespace fsdb
