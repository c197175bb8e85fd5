// Fuzz target: shape documents (query/document/shape_json.h: trees, inline and stored parts,
// "ref" leaves, node operators, placements from words, the "csg" text member) and bare CSG formula
// texts (query/document/csg_text.h). An input whose first non-blank byte is '{' is a shape (or
// part) document; any other input is a formula text such as "C = sphere + (cube - pair)".
// References resolve against a fixed resolver that knows only the parts "sphere" (id 1) and "cube"
// (id 2) and the shapes "pair" (id 3, "sphere + cube") and "loop" (id 4, which contains itself);
// every other reference is a clean fsdb::Error (unknown_reference).
// Properties:
//  * an accepted document has 1 <= parts <= nodes <= max_nodes; its document tree outlines
//    (outlineTree) to at most that many nodes, every reference in it names an object the resolver
//    knows, and the same tree given as {"kind":"shape","tree":...} parses to the same counts;
//  * its alpha field (small trees only, at two points) gives u in [0, 1] and l in [0, 1] or
//    kNeverInside;
//  * a formula text that parses gives a tree of known names that parseShapeField accepts (unless
//    it reaches the self-containing "loop" or exceeds max_nodes), with the same counts as the
//    document {"kind":"shape","csg":text}.
// No voxel grid is built.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "geometry/core/error.h"
#include "query/document/csg_text.h"
#include "query/document/shape_json.h"
#include "query/json/json_body.h"
#include "tests/fuzz/fuzz_check.h"

namespace {

constexpr int kDepth = 16;
constexpr size_t kMaxNodes = 64;

struct Stored {
  const char* kind;
  const char* name;
  int64_t id;
  const char* document;
};

const Stored kStored[] = {
    {"part", "sphere", 1, R"({"kind":"part","name":"sphere","params":{"a1":1}})"},
    {"part", "cube", 2, R"({"kind":"part","name":"cube","params":{"eps1":0.1,"eps2":0.1,"a1":{"tri":[0.9,1,1.1]}}})"},
    {"shape", "pair", 3, R"({"kind":"shape","name":"pair","csg":"sphere + cube"})"},
    {"shape", "loop", 4,
     R"({"kind":"shape","name":"loop","tree":{"op":"union","children":[{"part":"sphere"},{"ref":"loop"}]}})"},
};

std::optional<fsdb::ResolvedReference> resolve(const std::string& kind, const nlohmann::json& key) {
  for (const Stored& s : kStored) {
    if (kind != s.kind) continue;
    if ((key.is_string() && key.get<std::string>() == s.name) ||
        (key.is_number_integer() && key.get<int64_t>() == s.id))
      return fsdb::ResolvedReference{s.id, nlohmann::json::parse(s.document)};
  }
  return std::nullopt;
}

bool finite(const fsdb::Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void checkLevels(const fsdb::AlphaLevels& v) {
  FUZZ_CHECK(v.upper >= 0.0f && v.upper <= 1.0f, "u in [0, 1]");
  FUZZ_CHECK(v.lower == fsdb::kNeverInside || (v.lower >= 0.0f && v.lower <= 1.0f), "l in [0, 1] or never");
}

void checkAccepted(const fsdb::ParsedShape& s, const fsdb::ReferenceResolver& resolver) {
  FUZZ_CHECK(s.field && s.tree, "an accepted shape has a field and a tree");
  FUZZ_CHECK(s.partCount >= 1 && s.partCount <= s.nodeCount && s.nodeCount <= kMaxNodes,
             "1 <= parts <= nodes <= max_nodes");
  if (!s.documentTree.is_null()) {
    const fsdb::TreeOutline outline = fsdb::outlineTree(s.documentTree, s.documentTreePath);
    FUZZ_CHECK(!outline.nodes.empty() && outline.nodes.size() <= s.nodeCount,
               "the document tree outlines to at most the nodes counted");
    for (const fsdb::DocumentReference& r : outline.references)
      FUZZ_CHECK(resolver(r.kind, r.key).has_value(), "every reference of an accepted tree is known");
    const nlohmann::json again = {{"kind", "shape"}, {"tree", s.documentTree}};
    try {
      const fsdb::ParsedShape t = fsdb::parseShapeField(again, "", kMaxNodes, resolver);
      FUZZ_CHECK(t.nodeCount == s.nodeCount && t.partCount == s.partCount,
                 "the document tree parses to the same counts");
    } catch (const fsdb::Error& e) {
      std::fprintf(stderr, "tree %s: %s (%s)\n", again.dump().c_str(), e.what(), e.path().c_str());
      FUZZ_CHECK(false, "the document tree of an accepted shape is accepted");
    }
  }
  // A few points of the field, for small trees (each fuzzy part searches its parameter box).
  if (s.partCount <= 4) {
    fsdb::Vec3 lo, hi;
    s.field->boundingBox(&lo, &hi);
    const fsdb::Vec3 centre{lo.x / 2 + hi.x / 2, lo.y / 2 + hi.y / 2, lo.z / 2 + hi.z / 2};
    for (const fsdb::Vec3& p : {centre, fsdb::Vec3{0.0, 0.0, 0.0}})
      if (finite(p)) checkLevels(s.field->levelsAt(p));
  }
}

void fuzzDocument(const std::string& body, const fsdb::ReferenceResolver& resolver) {
  nlohmann::json doc;
  fsdb::ParsedShape s;
  try {
    doc = fsdb::parseJsonBody(body, kDepth);
    s = fsdb::parseShapeField(doc, "shape", kMaxNodes, resolver);
  } catch (const fsdb::Error&) {
    return;  // a refusal
  }
  checkAccepted(s, resolver);
}

void fuzzFormula(const std::string& text, const fsdb::ReferenceResolver& resolver) {
  auto kindOf = [&](const std::string& name, size_t column) -> std::string {
    if (resolver("part", name)) return "part";
    if (resolver("shape", name)) return "shape";
    throw fsdb::Error(fsdb::errc::kUnknownReference, "no stored '" + name + "' at column " + std::to_string(column),
                      "csg");
  };
  fsdb::CsgText parsed;
  try {
    parsed = fsdb::parseCsgText(text, kindOf, "csg");
  } catch (const fsdb::Error&) {
    return;  // a refusal
  }
  const nlohmann::json treeDoc = {{"kind", "shape"}, {"tree", parsed.tree}};
  const nlohmann::json csgDoc = {{"kind", "shape"}, {"csg", text}};
  std::optional<fsdb::ParsedShape> fromTree, fromCsg;
  std::string treeError, csgError;
  try {
    fromTree = fsdb::parseShapeField(treeDoc, "", kMaxNodes, resolver);
  } catch (const fsdb::Error& e) {
    treeError = e.code();
    FUZZ_CHECK(e.code() == fsdb::errc::kReferenceCycle || e.code() == fsdb::errc::kLimitExceeded,
               "the tree of a parsed formula is refused only for a cycle or its size");
  }
  try {
    fromCsg = fsdb::parseShapeField(csgDoc, "", kMaxNodes, resolver);
  } catch (const fsdb::Error& e) {
    csgError = e.code();
  }
  FUZZ_CHECK(fromTree.has_value() == fromCsg.has_value() && treeError == csgError,
             "the formula as \"csg\" and as its tree get the same verdict");
  if (fromTree) {
    FUZZ_CHECK(fromTree->nodeCount == fromCsg->nodeCount && fromTree->partCount == fromCsg->partCount,
               "the formula as \"csg\" and as its tree give the same counts");
    checkAccepted(*fromCsg, resolver);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 64 * 1024) return 0;
  const std::string body(reinterpret_cast<const char*>(data), size);
  const fsdb::ReferenceResolver resolver = resolve;
  const size_t first = body.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && body[first] == '{') fuzzDocument(body, resolver);
  else fuzzFormula(body, resolver);
  return 0;
}
