#include "query/structural/csg_graph.h"

#include <map>
#include <memory>
#include <optional>

#include "geometry/field/boundary_method.h"
#include "geometry/core/error.h"
#include "query/json/json_path.h"

namespace fsdb {

const char* csgGraphOpName(CsgGraphOp op) {
  switch (op) {
    case CsgGraphOp::Union: return "union";
    case CsgGraphOp::Intersection: return "intersection";
    case CsgGraphOp::Difference: return "difference";
    case CsgGraphOp::Leaf: return "leaf";
  }
  return "leaf";
}

std::vector<std::vector<int>> CsgGraph::parents() const {
  std::vector<std::vector<int>> p(nodes.size());
  for (size_t x = 0; x < nodes.size(); ++x)
    for (int c : nodes[x].children) p[size_t(c)].push_back(int(x));
  return p;
}

std::vector<std::string> CsgGraph::leafPaths() const {
  std::vector<std::string> out(static_cast<size_t>(leafCount));
  for (const CsgGraphNode& n : nodes)
    if (n.op == CsgGraphOp::Leaf && out[size_t(n.leaf)].empty()) out[size_t(n.leaf)] = n.path;
  return out;
}

bool CsgGraph::isTree() const {
  for (const std::vector<int>& p : parents())
    if (p.size() > 1) return false;
  return true;
}

namespace {

CsgGraphOp graphOp(CsgOp op) {
  switch (op) {
    case CsgOp::kUnion: return CsgGraphOp::Union;
    case CsgOp::kIntersection: return CsgGraphOp::Intersection;
    case CsgOp::kDifference: return CsgGraphOp::Difference;
  }
  return CsgGraphOp::Union;
}

// The document (paths, names, part ids, operators) walked beside the tree parseShapeField built
// (parts with their transforms, and shared subtrees as one shared CsgTree per stored shape).
class GraphBuilder {
 public:
  GraphBuilder(const ReferenceResolver& resolver, ShapeGraph* out) : resolver_(resolver), out_(out) {}

  void build(const nlohmann::json& tree, const std::string& path, const CsgTree* built) {
    countParents(built);
    out_->graph.root = visit(tree, path, built);
  }

 private:
  void countParents(const CsgTree* t) {
    if (seen_.count(t)) return;
    seen_[t] = 1;
    for (const auto& c : t->children) {
      ++parentEdges_[c.get()];
      countParents(c.get());
    }
  }

  // Follows {"ref"} nodes to the tree they name (parseShapeField has resolved them already).
  void throughReferences(const nlohmann::json** node, std::string* path) {
    while ((*node)->contains("ref")) {
      const std::string rp = joinPath(*path, "ref");
      const std::optional<ResolvedReference> r = resolver_("shape", (**node)["ref"]);
      if (!r) throw Error(errc::kUnknownReference, "unknown shape " + (**node)["ref"].dump(), rp);
      const nlohmann::json& doc = r->document;
      held_.push_back(std::make_unique<nlohmann::json>(shapeTree(doc, rp, resolver_)));
      *node = held_.back().get();
      *path = joinPath(rp, doc.contains("tree") ? "tree" : "csg");
    }
  }

  static nlohmann::json operatorOf(const nlohmann::json& node) {
    return node.contains("operator") ? node["operator"] : nlohmann::json{{"name", "zadeh"}};
  }

  int visit(const nlohmann::json& doc, const std::string& docPath, const CsgTree* t) {
    if (auto it = index_.find(t); it != index_.end()) return it->second;
    const nlohmann::json* node = &doc;
    std::string path = docPath;
    throughReferences(&node, &path);
    const int self = int(out_->graph.nodes.size());
    index_[t] = self;
    out_->graph.nodes.emplace_back();
    out_->graph.nodes.back().path = path;
    if (t->leaf) {
      leaf(*node, path, t, self);
      return self;
    }
    out_->graph.nodes[size_t(self)].op = graphOp(t->op);
    std::vector<int> children;
    addChildren(*node, path, t, operatorOf(*node), &children);
    out_->graph.nodes[size_t(self)].children = std::move(children);
    return self;
  }

  // The children of `node`, with unshared same-operation children flattened into it (associativity
  // of union and intersection with the same operator).
  void addChildren(const nlohmann::json& node, const std::string& path, const CsgTree* t,
                   const nlohmann::json& op, std::vector<int>* children) {
    const std::string cp = joinPath(path, "children");
    const nlohmann::json& docs = node["children"];
    for (size_t i = 0; i < t->children.size(); ++i) {
      const CsgTree* c = t->children[i].get();
      const nlohmann::json* child = &docs[i];
      std::string childPath = joinPath(cp, i);
      const bool associative = t->op != CsgOp::kDifference;
      if (associative && !c->leaf && c->op == t->op && parentEdges_[c] == 1) {
        throughReferences(&child, &childPath);
        if (operatorOf(*child) == op) {
          addChildren(*child, childPath, c, op, children);
          continue;
        }
      }
      children->push_back(visit(*child, childPath, c));
    }
  }

  void leaf(const nlohmann::json& node, const std::string& path, const CsgTree* t, int self) {
    CsgGraphLeaf l;
    l.part = t->part;
    const nlohmann::json& partDoc = node["part"];
    if (partDoc.is_object()) {
      if (partDoc.contains("name") && partDoc["name"].is_string()) l.name = partDoc["name"].get<std::string>();
    } else {
      const std::optional<ResolvedReference> r = resolver_("part", partDoc);
      if (!r) throw Error(errc::kUnknownReference, "unknown part " + partDoc.dump(), joinPath(path, "part"));
      l.partId = r->id;
      if (r->document.contains("name") && r->document["name"].is_string())
        l.name = r->document["name"].get<std::string>();
      else if (partDoc.is_string())
        l.name = partDoc.get<std::string>();
    }
    out_->graph.nodes[size_t(self)].leaf = out_->graph.leafCount++;
    out_->leaves.push_back(std::move(l));
  }

  const ReferenceResolver& resolver_;
  ShapeGraph* out_;
  std::map<const CsgTree*, int> index_, parentEdges_, seen_;
  std::vector<std::unique_ptr<nlohmann::json>> held_;  // referenced trees, kept while walked
};

}  // namespace

ShapeGraph shapeGraph(const nlohmann::json& doc, const std::string& path, size_t maxNodes,
                      const ReferenceResolver& resolver) {
  // One remembering resolver for both passes: each stored object is looked up once.
  const ReferenceResolver remembered = rememberingResolver(resolver);
  const ParsedShape parsed = parseShapeField(doc, path, maxNodes, remembered);
  ShapeGraph out;
  if (parsed.documentTree.is_null()) {  // a part document: one leaf
    CsgGraphNode n;
    n.leaf = 0;
    n.path = path;
    out.graph.nodes.push_back(std::move(n));
    out.graph.leafCount = 1;
    CsgGraphLeaf l;
    l.part = parsed.tree->part;
    if (doc.contains("name") && doc["name"].is_string()) l.name = doc["name"].get<std::string>();
    out.leaves.push_back(std::move(l));
    return out;
  }
  GraphBuilder(remembered, &out).build(parsed.documentTree, parsed.documentTreePath, parsed.tree.get());
  return out;
}

}  // namespace fsdb
