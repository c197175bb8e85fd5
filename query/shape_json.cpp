#include "query/shape_json.h"

#include "geometry/csg_field.h"
#include "geometry/error.h"
#include "geometry/fuzzy_part_field.h"
#include "geometry/smooth_csg_field.h"
#include "query/json_body.h"
#include "query/operator_json.h"
#include "query/part_json.h"

namespace fsdb {
namespace {

struct Walker {
  size_t maxNodes;
  ParsedShape out;

  void count(const std::string& path) {
    if (++out.nodeCount > maxNodes)
      throw Error(errc::kLimitExceeded, "the tree has more than max_nodes=" + std::to_string(maxNodes) + " nodes", path);
  }

  std::shared_ptr<const AlphaFieldSource> leaf(const nlohmann::json& node, const std::string& path,
                                               std::shared_ptr<const CsgTree>* tree) {
    const std::string pp = joinPath(path, "part");
    const nlohmann::json& partDoc = node["part"];
    if (partDoc.is_string())
      throw Error(errc::kInvalidDocument,
                  "references to stored parts need the store, which this server does not have yet; "
                  "give the part inline as an object",
                  pp);
    nlohmann::json doc = requireObject(partDoc, pp);
    if (node.contains("transform")) {
      if (doc.contains("transform"))
        throw Error(errc::kInvalidDocument,
                    "the part has its own transform; give one transform, on the part or on the leaf",
                    joinPath(path, "transform"));
      doc["transform"] = node["transform"];
    }
    for (auto it = node.begin(); it != node.end(); ++it)
      if (it.key() != "part" && it.key() != "transform")
        throw Error(errc::kInvalidDocument, "unknown field '" + it.key() + "' in a leaf; expected part, transform",
                    joinPath(path, it.key()));
    FuzzyPart part;
    try {
      part = parsePart(doc, pp);
    } catch (const Error& e) {
      // A leaf transform was moved into the part document: report it where the user wrote it.
      const std::string prefix = pp + ".transform";
      if (node.contains("transform") && e.path().rfind(prefix, 0) == 0)
        throw Error(e.code(), e.what(), joinPath(path, "transform") + e.path().substr(prefix.size()));
      throw;
    }
    ++out.partCount;
    auto t = std::make_shared<CsgTree>();
    t->part = part;
    *tree = t;
    return std::make_shared<FuzzyPartField>(part);
  }

  std::shared_ptr<const AlphaFieldSource> node(const nlohmann::json& node, const std::string& path,
                                               std::shared_ptr<const CsgTree>* tree) {
    requireObject(node, path);
    count(path);
    if (node.contains("part")) return leaf(node, path, tree);
    if (node.contains("ref"))
      throw Error(errc::kInvalidDocument,
                  "references to stored shapes need the store, which this server does not have yet",
                  joinPath(path, "ref"));
    const std::string opPath = joinPath(path, "op");
    const std::string& op = requireString(requireField(node, "op", path), opPath);
    CsgOp csg;
    if (op == "union") csg = CsgOp::kUnion;
    else if (op == "intersection") csg = CsgOp::kIntersection;
    else if (op == "difference") csg = CsgOp::kDifference;
    else throw Error(errc::kInvalidDocument, "unknown op '" + op + "'; expected union, intersection, difference", opPath);
    for (auto it = node.begin(); it != node.end(); ++it)
      if (it.key() != "op" && it.key() != "operator" && it.key() != "children" && it.key() != "range" &&
          it.key() != "step")
        throw Error(errc::kInvalidDocument,
                    "unknown field '" + it.key() + "' in a Boolean node; expected op, operator, children, range, step",
                    joinPath(path, it.key()));
    OperatorConfig config{"zadeh", {}, {}};
    if (node.contains("operator")) config = parseOperatorConfig(node["operator"], joinPath(path, "operator"));
    const bool smooth = config.name != "zadeh";  // geometry/smooth_csg_field.h
    if (smooth && out.smoothOperatorPath.empty()) out.smoothOperatorPath = joinPath(path, "operator");
    LeafSmoothing smoothing;
    for (const char* key : {"range", "step"})
      if (node.contains(key) && !smooth)
        throw Error(errc::kInvalidDocument,
                    std::string(key) + " applies to smooth operators only (the zadeh Booleans keep crisp parts crisp)",
                    joinPath(path, key));
    if (node.contains("range")) smoothing.range = requireNumber(node["range"], joinPath(path, "range"));
    if (node.contains("step")) smoothing.step = parseOperatorConfig(node["step"], joinPath(path, "step"));
    const std::string cp = joinPath(path, "children");
    const auto& children = requireArray(requireField(node, "children", path), cp);
    if (children.size() < 2) throw Error(errc::kInvalidDocument, "a Boolean node needs at least two children", cp);
    std::vector<std::shared_ptr<const AlphaFieldSource>> fields;
    auto t = std::make_shared<CsgTree>();
    t->leaf = false;
    t->op = csg;
    for (size_t i = 0; i < children.size(); ++i) {
      std::shared_ptr<const CsgTree> child;
      fields.push_back(this->node(children[i], joinPath(cp, i), &child));
      t->children.push_back(std::move(child));
    }
    *tree = t;
    if (!smooth) return std::make_shared<CsgField>(csg, std::move(fields));
    try {
      return std::make_shared<SmoothCsgField>(csg, config, smoothing, std::move(fields));
    } catch (const Error& e) {
      throw e.withPathPrefix(path);
    }
  }
};

}  // namespace

ParsedShape parseShapeField(const nlohmann::json& doc, const std::string& path, size_t maxNodes) {
  requireObject(doc, path);
  Walker w{maxNodes, {}};
  const std::string kind = doc.contains("kind") ? requireString(doc["kind"], joinPath(path, "kind")) : "shape";
  if (kind == "part") {
    w.count(path);
    auto t = std::make_shared<CsgTree>();
    t->part = parsePart(doc, path);
    w.out.field = std::make_shared<FuzzyPartField>(t->part);
    w.out.tree = t;
    w.out.partCount = 1;
    return w.out;
  }
  if (kind != "shape")
    throw Error(errc::kInvalidDocument, "expected kind \"shape\" or \"part\", got \"" + kind + "\"", joinPath(path, "kind"));
  if (doc.contains("csg"))
    throw Error(errc::kInvalidDocument,
                "the csg text form names stored parts and needs the store, which this server does not have yet; "
                "give \"tree\"",
                joinPath(path, "csg"));
  for (auto it = doc.begin(); it != doc.end(); ++it)
    if (it.key() != "kind" && it.key() != "name" && it.key() != "tree" && it.key() != "meta" &&
        it.key() != "descriptors")
      throw Error(errc::kInvalidDocument, "unknown field '" + it.key() + "'; expected kind, name, tree, meta",
                  joinPath(path, it.key()));
  w.out.field = w.node(requireField(doc, "tree", path), joinPath(path, "tree"), &w.out.tree);
  return w.out;
}

}  // namespace fsdb
