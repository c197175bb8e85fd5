// See query/structural/csg_query_print.h.
#include "query/structural/csg_query_print.h"

#include <algorithm>
#include <optional>
#include <unordered_map>

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
    // Operands in order, each leaf placed against another operand's head right after it. Each leaf
    // is placed against at most one other and has at most one placed against it (the parser's
    // "its" and "of" each name one operand), so the operands form chains; one pass over maps.
    const size_t count = n.children.size();
    std::vector<bool> done(count, false);
    std::unordered_map<int, size_t> childOfHead;    // head leaf -> the child it heads
    std::unordered_map<int, size_t> placedAgainst;  // head leaf -> the child placed against it
    for (size_t i = 0; i < count; ++i) {
      const int head = headOf(n.children[i]);
      if (head != kNoHead) childOfHead[head] = i;
    }
    for (size_t i = 0; i < count; ++i)
      if (const CsgRelation* r = relationOf(n.children[i])) {
        if (!childOfHead.count(int(r->to))) unprintable("a relation whose other part is no operand beside it");
        if (!placedAgainst.emplace(int(r->to), i).second) unprintable("two parts placed against one");
      }
    std::string text = n.op == CsgGraphOp::Union ? "the union of " : "the intersection of ";
    bool first = true;
    for (size_t i = 0; i < count; ++i) {
      if (done[i] || relationOf(n.children[i])) continue;  // placed operands follow what they are placed against
      for (size_t at = i;;) {
        done[at] = true;
        const Printed p = node(n.children[at]);
        const CsgRelation* r = relationOf(n.children[at]);
        text += (first ? "" : " and ") + p.operand() + (r ? " " + itsWords(*r) : "");
        first = false;
        const int head = headOf(n.children[at]);
        const auto next = head == kNoHead ? placedAgainst.end() : placedAgainst.find(head);
        if (next == placedAgainst.end() || done[next->second]) break;
        at = next->second;
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
