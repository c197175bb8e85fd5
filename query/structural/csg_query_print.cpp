// See query/structural/csg_query_print.h.
#include "query/structural/csg_query_print.h"

#include <algorithm>
#include <optional>

#include "geometry/core/error.h"
#include "query/linguistic/query_print.h"

namespace fsdb {
namespace {

constexpr int kNoHead = -1;

[[noreturn]] void unprintable(const std::string& what) {
  throw Error(errc::kInvalidParameter, "the phrase form cannot say " + what, "query");
}

struct Printed {
  std::string text;
  int head = kNoHead;      // the leaf the item is about, for a relation of the item after it
  bool operation = false;  // "the union of ...": in parentheses as an operand (its list takes every item after it)
  std::string operand() const { return operation ? "(" + text + ")" : text; }
};

class Printer {
 public:
  Printer(const CsgQuery& q, const Vocabulary& v) : q_(q), v_(v) {}

  // `chain`: a union that is one chain of relations may print as that chain (its head is then its
  // subject); the root prints as "the union of", which POST /query sends to the structural search.
  Printed node(int index, bool chain = true) const {
    const CsgGraphNode& n = q_.graph.nodes[size_t(index)];
    if (n.op == CsgGraphOp::Leaf) return {leafText(n.leaf), n.leaf};
    if (n.op == CsgGraphOp::Difference) {
      if (n.children.size() != 2) unprintable("a difference of " + std::to_string(n.children.size()) + " operands");
      if (relationOf(n.children[0])) unprintable("a placed minuend");
      const Printed minuend = node(n.children[0]);
      return {"the difference of " + minuend.operand() + " and " + operandAfter(n.children[1], minuend.head), kNoHead,
              true};
    }
    if (n.op == CsgGraphOp::Union && chain)
      if (auto printed = asChain(n)) return *printed;
    // Operands in order, each leaf placed against another operand's head right after it.
    std::vector<int> order;
    std::vector<bool> done(n.children.size(), false);
    std::vector<int> heads(n.children.size());
    std::vector<Printed> printed(n.children.size());
    for (size_t i = 0; i < n.children.size(); ++i) heads[i] = headOf(n.children[i]);
    std::string text = n.op == CsgGraphOp::Union ? "the union of " : "the intersection of ";
    bool first = true;
    for (size_t i = 0; i < n.children.size(); ++i) {
      if (done[i] || placedAgainstSibling(n, i, heads)) continue;
      size_t at = i;
      while (true) {
        done[at] = true;
        const Printed p = node(n.children[at]);
        const bool placed = relationOf(n.children[at]) != nullptr;
        text += (first ? "" : " and ") + p.operand() + (placed ? " " + itsWords(*relationOf(n.children[at])) : "");
        first = false;
        // The operand placed against this one's head comes next.
        size_t next = n.children.size();
        for (size_t j = 0; j < n.children.size(); ++j)
          if (!done[j] && relationOf(n.children[j]) && int(relationOf(n.children[j])->to) == heads[at] &&
              heads[at] != kNoHead)
            next = j;
        if (next == n.children.size()) break;
        at = next;
      }
    }
    if (std::find(done.begin(), done.end(), false) != done.end()) unprintable("relations that form a cycle");
    return {text, kNoHead, true};
  }

 private:
  std::string leafText(int leaf) const {
    const CsgQueryLeaf& l = q_.leaves[size_t(leaf)];
    if (!l.condition) unprintable("the stored part '" + l.text + "' (the formula form names stored parts)");
    return nounPhraseText(*l.condition, v_, "the");
  }

  const CsgRelation* relationOf(int node) const {
    const CsgGraphNode& n = q_.graph.nodes[size_t(node)];
    if (n.op != CsgGraphOp::Leaf) return nullptr;
    const auto& r = q_.leaves[size_t(n.leaf)].relation;
    return r ? &*r : nullptr;
  }

  // Whether child i is a leaf placed against the head of another child (it is printed after that one).
  bool placedAgainstSibling(const CsgGraphNode& n, size_t i, const std::vector<int>& heads) const {
    const CsgRelation* r = relationOf(n.children[i]);
    if (!r) return false;
    for (size_t j = 0; j < n.children.size(); ++j)
      if (j != i && heads[j] == int(r->to)) return true;
    unprintable("a relation whose other part is no operand beside it");
  }

  // The head a child's printed form has: a leaf is its own, a union that is one chain its subject.
  int headOf(int index) const {
    const CsgGraphNode& n = q_.graph.nodes[size_t(index)];
    if (n.op == CsgGraphOp::Leaf) return n.leaf;
    if (n.op == CsgGraphOp::Union)
      if (auto chain = asChain(n)) return chain->head;
    return kNoHead;
  }

  std::string distanceWords(const CsgRelation& r) const {
    return r.distance ? distanceText(*r.distance, v_) + " " : "";
  }
  std::string itsWords(const CsgRelation& r) const { return distanceWords(r) + "to its " + r.direction.word; }

  // The second operand of a difference, placed against the minuend's head when it says so.
  std::string operandAfter(int index, int previousHead) const {
    const Printed p = node(index);
    const CsgRelation* r = relationOf(index);
    if (!r) return p.operand();
    if (int(r->to) != previousHead) unprintable("a relation whose other part is no operand beside it");
    return p.text + " " + itsWords(*r);
  }

  // A union whose operands are leaves forming one chain s_k -> ... -> s_0 (each placed against
  // the next, s_0 placed against nothing): "s_k to the D of s_(k-1) ... s_0".
  std::optional<Printed> asChain(const CsgGraphNode& n) const {
    std::vector<int> leaves;
    for (int c : n.children) {
      const CsgGraphNode& child = q_.graph.nodes[size_t(c)];
      if (child.op != CsgGraphOp::Leaf) return std::nullopt;
      leaves.push_back(child.leaf);
    }
    // The subject: the leaf no other leaf here is placed against.
    int subject = kNoHead;
    for (int l : leaves) {
      bool referenced = false;
      for (int other : leaves)
        if (q_.leaves[size_t(other)].relation && int(q_.leaves[size_t(other)].relation->to) == l) referenced = true;
      if (!referenced) {
        if (subject != kNoHead) return std::nullopt;
        subject = l;
      }
    }
    if (subject == kNoHead) return std::nullopt;
    std::string text;
    size_t visited = 0;
    for (int at = subject; visited < leaves.size(); ++visited) {
      text += leafText(at);
      const auto& r = q_.leaves[size_t(at)].relation;
      if (!r) break;
      if (std::find(leaves.begin(), leaves.end(), int(r->to)) == leaves.end()) return std::nullopt;
      text += " " + distanceWords(*r) + "to the " + r->direction.word + " of ";
      at = int(r->to);
    }
    if (visited + 1 != leaves.size()) return std::nullopt;
    return Printed{text, subject};
  }

  const CsgQuery& q_;
  const Vocabulary& v_;
};

}  // namespace

std::string csgQueryText(const CsgQuery& query, const Vocabulary& vocabulary) {
  return "find " + Printer(query, vocabulary).node(query.graph.root, false).text;
}

}  // namespace fsdb
