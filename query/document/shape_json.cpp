#include "query/document/shape_json.h"

#include <map>

#include "geometry/core/closest_names.h"
#include "geometry/core/error.h"
#include "geometry/field/csg_field.h"
#include "geometry/field/fuzzy_part_field.h"
#include "geometry/field/shared_field.h"
#include "geometry/field/smooth_csg_field.h"
#include "query/document/csg_text.h"
#include "query/document/operator_json.h"
#include "query/document/part_json.h"
#include "query/document/placement_words.h"
#include "query/json/json_body.h"
#include "query/linguistic/vocabulary.h"

namespace fsdb {
namespace {

std::string describeKey(const std::string& kind, const nlohmann::json& key) {
  return kind + " " + (key.is_string() ? "'" + key.get<std::string>() + "'" : key.dump());
}

// A reference must be a non-empty name or a positive integer id.
void checkReferenceKey(const nlohmann::json& key, const std::string& path) {
  if (key.is_string() && !key.get<std::string>().empty()) return;
  if (key.is_number_integer() && key.get<int64_t>() > 0) return;
  throw Error(errc::kInvalidDocument,
              "a reference is a stored object's name (non-empty string) or id (positive integer), got " +
                  key.dump(),
              path);
}

struct Walker {
  size_t maxNodes;
  ReferenceResolver resolver;  // rememberingResolver(the caller's)
  ParsedShape out;
  // Stored shapes already built (shared subtrees are built once) and the chain of stored
  // shapes being expanded (a repeat is a cycle).
  std::map<int64_t, std::pair<std::shared_ptr<const AlphaFieldSource>, std::shared_ptr<const CsgTree>>> built;
  std::vector<int64_t> expanding;
  std::map<std::string, FuzzyPart> placed;  // leaves by name, in pre-order, for "place"

  ResolvedReference resolve(const std::string& kind, const nlohmann::json& key, const std::string& path) {
    checkReferenceKey(key, path);
    if (!resolver)
      throw Error(errc::kInvalidDocument,
                  "references to stored " + kind + "s are resolved only against a database; give the " + kind +
                      " inline as an object",
                  path);
    std::optional<ResolvedReference> r = resolver(kind, key);
    if (!r) throw Error(errc::kUnknownReference, "unknown " + describeKey(kind, key), path);
    return *r;
  }

  void count(const std::string& path) {
    if (++out.nodeCount > maxNodes)
      throw Error(errc::kLimitExceeded, "the tree has more than max_nodes=" + std::to_string(maxNodes) + " nodes", path);
  }

  std::shared_ptr<const AlphaFieldSource> leaf(const nlohmann::json& node, const std::string& path,
                                               std::shared_ptr<const CsgTree>* tree) {
    const std::string pp = joinPath(path, "part");
    const nlohmann::json& partDoc = node["part"];
    nlohmann::json doc = partDoc.is_object() ? partDoc : resolve("part", partDoc, pp).document;
    std::string transformPath = joinPath(pp, "transform");
    if (node.contains("transform")) {
      if (doc.contains("transform"))
        throw Error(errc::kInvalidDocument,
                    "the part has its own transform; give one transform, on the part or on the leaf",
                    joinPath(path, "transform"));
      doc["transform"] = node["transform"];
      transformPath = joinPath(path, "transform");
    }
    rejectUnknownKeys(node, path, {"part", "transform"}, " in a leaf");
    if (doc.contains("transform") && doc["transform"].is_object() && doc["transform"].contains("place"))
      doc["transform"] = placeFromWords(doc, pp, transformPath);
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
    // The name later leaves may be placed against (query/document/placement_words.h).
    if (partDoc.is_string()) placed[partDoc.get<std::string>()] = part;
    else if (doc.contains("name") && doc["name"].is_string()) placed[doc["name"].get<std::string>()] = part;
    auto t = std::make_shared<CsgTree>();
    t->part = part;
    *tree = t;
    return std::make_shared<FuzzyPartField>(part);
  }

  // {"place":{...}} (query/document/placement_words.h): the translation against an earlier leaf.
  nlohmann::json placeFromWords(const nlohmann::json& doc, const std::string& partPath, const std::string& transformPath) {
    const PlacementWords words = parsePlacementWords(doc["transform"], transformPath, activeVocabulary());
    auto reference = placed.find(words.relativeTo);
    if (reference == placed.end()) {
      std::string known;
      for (const auto& kv : placed) known += (known.empty() ? "" : ", ") + kv.first;
      throw Error(errc::kInvalidDocument,
                  "relative_to names no earlier leaf '" + words.relativeTo + "' of this shape (known so far: " +
                      (known.empty() ? "none" : known) + ")",
                  transformPath + ".place.relative_to");
    }
    nlohmann::json bare = doc;
    bare.erase("transform");
    return placedTransform(words, reference->second, parsePart(bare, partPath));
  }

  // {"ref": name or id}: a stored shape evaluated in place, built once however often it is named.
  std::shared_ptr<const AlphaFieldSource> reference(const nlohmann::json& node, const std::string& path,
                                                    std::shared_ptr<const CsgTree>* tree) {
    const std::string rp = joinPath(path, "ref");
    if (node.contains("transform"))
      throw Error(errc::kInvalidDocument,
                  "a transform on a stored shape is not supported yet: a fuzzy placement of a whole "
                  "subtree does not reduce to placements of its parts; place the parts instead",
                  joinPath(path, "transform"));
    rejectUnknownKeys(node, path, {"ref"}, " in a reference");
    const ResolvedReference r = resolve("shape", node["ref"], rp);
    if (auto it = built.find(r.id); it != built.end()) {
      *tree = it->second.second;
      return it->second.first;
    }
    for (int64_t e : expanding)
      if (e == r.id)
        throw Error(errc::kReferenceCycle, describeKey("shape", node["ref"]) + " contains itself", rp);
    const nlohmann::json& doc = r.document;
    if (!doc.is_object() || (doc.contains("kind") && doc["kind"] != "shape"))
      throw Error(errc::kInvalidDocument, describeKey("shape", node["ref"]) + " is not a shape document", rp);
    expanding.push_back(r.id);
    std::shared_ptr<const CsgTree> t;
    // Errors inside the stored shape name the reference, then the path inside that shape.
    auto field = this->node(shapeTree(doc, rp, resolver), joinPath(rp, doc.contains("tree") ? "tree" : "csg"), &t);
    expanding.pop_back();
    // Every parent that names this shape gets the same node, evaluated once per point, box or
    // block however many name it (geometry/field/shared_field.h).
    field = std::make_shared<SharedField>(std::move(field));
    built[r.id] = {field, t};
    *tree = t;
    return field;
  }

  std::shared_ptr<const AlphaFieldSource> node(const nlohmann::json& node, const std::string& path,
                                               std::shared_ptr<const CsgTree>* tree) {
    requireObject(node, path);
    count(path);
    if (node.contains("part")) return leaf(node, path, tree);
    if (node.contains("ref")) return reference(node, path, tree);
    const std::string opPath = joinPath(path, "op");
    const std::string& op = requireString(requireField(node, "op", path), opPath);
    CsgOp csg;
    if (!csgOpFromName(op, &csg)) throw Error(errc::kInvalidDocument, "unknown op '" + quotedWord(op) + "'; expected union, intersection, difference", opPath);
    rejectUnknownKeys(node, path, {"op", "operator", "children", "range", "step"}, " in a Boolean node");
    OperatorConfig config{"zadeh", {}, {}};
    if (node.contains("operator")) config = parseOperatorConfig(node["operator"], joinPath(path, "operator"));
    const bool smooth = config.name != "zadeh";  // geometry/field/smooth_csg_field.h
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
      return makeSmoothCsgNode(csg, config, smoothing, std::move(fields));
    } catch (const Error& e) {
      throw e.withPathPrefix(path);
    }
  }
};

}  // namespace

ReferenceResolver rememberingResolver(const ReferenceResolver& resolver) {
  if (!resolver) return {};
  auto answers = std::make_shared<std::map<std::string, std::optional<ResolvedReference>>>();
  return [resolver, answers](const std::string& kind, const nlohmann::json& key) {
    const std::string k = kind + '\n' + key.dump();
    auto it = answers->find(k);
    if (it == answers->end()) it = answers->emplace(k, resolver(kind, key)).first;
    return it->second;
  };
}

nlohmann::json shapeTree(const nlohmann::json& doc, const std::string& path, const ReferenceResolver& resolver) {
  const bool hasTree = doc.contains("tree"), hasCsg = doc.contains("csg");
  if (hasTree && hasCsg)
    throw Error(errc::kInvalidDocument, "give either \"tree\" or \"csg\", not both", joinPath(path, "csg"));
  if (hasTree) return doc["tree"];
  if (!hasCsg) throw Error(errc::kInvalidDocument, "missing required field \"tree\" (or \"csg\")", path);
  const std::string cp = joinPath(path, "csg");
  const std::string& text = requireString(doc["csg"], cp);
  auto kindOf = [&](const std::string& name, size_t column) -> std::string {
    if (!resolver)
      throw Error(errc::kInvalidDocument, "the csg text form names stored parts and shapes; it needs a database",
                  cp);
    if (resolver("part", name)) return "part";
    if (resolver("shape", name)) return "shape";
    throw Error(errc::kUnknownReference,
                "csg: '" + name + "' at column " + std::to_string(column) + " is no stored part or shape", cp);
  };
  CsgText parsed = parseCsgText(text, kindOf, cp);
  if (!parsed.name.empty() && doc.contains("name") && doc["name"].is_string() && doc["name"] != parsed.name)
    throw Error(errc::kInvalidDocument,
                "csg names the shape '" + parsed.name + "' but \"name\" is '" + doc["name"].get<std::string>() + "'",
                cp);
  return parsed.tree;
}

TreeOutline outlineTree(const nlohmann::json& tree, const std::string& path) {
  TreeOutline out;
  // Pre-order walk with an explicit stack of (node, parent, position, path).
  struct Item {
    const nlohmann::json* node;
    int parent, position;
    std::string path;
  };
  std::vector<Item> stack{{&tree, -1, 0, path}};
  while (!stack.empty()) {
    Item it = std::move(stack.back());
    stack.pop_back();
    const nlohmann::json& n = *it.node;
    TreeNodeOutline o;
    o.parent = it.parent;
    o.position = it.position;
    if (n.contains("transform")) o.transform = n["transform"];
    if (n.contains("part")) {
      o.kind = "part";
      if (!n["part"].is_object()) {
        o.kind = "ref";
        o.reference = static_cast<int>(out.references.size());
        out.references.push_back({"part", n["part"], joinPath(it.path, "part")});
      }
    } else if (n.contains("ref")) {
      o.kind = "ref";
      o.reference = static_cast<int>(out.references.size());
      out.references.push_back({"shape", n["ref"], joinPath(it.path, "ref")});
    } else {
      o.kind = n.value("op", "");
      if (n.contains("operator")) o.operatorDoc = n["operator"];
    }
    const int index = static_cast<int>(out.nodes.size());
    out.nodes.push_back(std::move(o));
    if (n.contains("children") && n["children"].is_array()) {
      const auto& c = n["children"];
      const std::string cp = joinPath(it.path, "children");
      for (size_t i = c.size(); i-- > 0;) stack.push_back({&c[i], index, static_cast<int>(i), joinPath(cp, i)});
    }
  }
  return out;
}

ParsedShape parseShapeField(const nlohmann::json& doc, const std::string& path, size_t maxNodes,
                            const ReferenceResolver& resolver) {
  requireObject(doc, path);
  Walker w{maxNodes, rememberingResolver(resolver), {}, {}, {}, {}};
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
  rejectUnknownKeys(doc, path, {"kind", "name", "tree", "csg", "meta", "descriptors"});
  w.out.documentTree = shapeTree(doc, path, w.resolver);
  w.out.documentTreePath = joinPath(path, doc.contains("tree") ? "tree" : "csg");
  w.out.field = w.node(w.out.documentTree, w.out.documentTreePath, &w.out.tree);
  return w.out;
}

}  // namespace fsdb
