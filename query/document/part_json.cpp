#include "query/document/part_json.h"

#include <cmath>

#include "geometry/core/closest_names.h"
#include "geometry/core/error.h"
#include "query/document/part_from_words.h"
#include "query/json/fuzzy_json.h"
#include "query/json/json_body.h"
#include "query/linguistic/vocabulary.h"

namespace fsdb {
namespace {

struct NamedParam {
  const char* name;
  FuzzyNumber FuzzyPart::*member;
};

const NamedParam kParams[] = {{"eps1", &FuzzyPart::eps1}, {"eps2", &FuzzyPart::eps2}, {"a1", &FuzzyPart::a1},
                              {"a2", &FuzzyPart::a2},     {"a3", &FuzzyPart::a3},     {"kx", &FuzzyPart::kx},
                              {"ky", &FuzzyPart::ky},     {"kv", &FuzzyPart::kv},     {"t", &FuzzyPart::t}};

void parseTransform(const nlohmann::json& t, const std::string& path, FuzzyPart* part) {
  requireObject(t, path);
  if (t.contains("place"))
    throw Error(errc::kInvalidDocument,
                "a placement from words places a leaf of a shape against an earlier leaf; a part on its own "
                "has nothing to be placed against (give \"translate\")",
                joinPath(path, "place"));
  rejectUnknownKeys(t, path, {"translate", "rotate", "scale"});
  if (t.contains("translate")) {
    const std::string p = joinPath(path, "translate");
    const auto& tr = requireArray(t["translate"], p);
    if (tr.size() != 3) throw Error(errc::kInvalidDocument, "translate needs [x, y, z]", p);
    part->tx = parseFuzzyNumber(tr[0], joinPath(p, std::size_t{0}));
    part->ty = parseFuzzyNumber(tr[1], joinPath(p, std::size_t{1}));
    part->tz = parseFuzzyNumber(tr[2], joinPath(p, std::size_t{2}));
  }
  if (t.contains("rotate")) {
    const std::string p = joinPath(path, "rotate");
    const auto& r = requireObject(t["rotate"], p);
    rejectUnknownKeys(r, p, {"axis", "deg"});
    const std::string ap = joinPath(p, "axis");
    const auto& axis = requireArray(requireField(r, "axis", p), ap);
    if (axis.size() != 3) throw Error(errc::kInvalidDocument, "axis needs [x, y, z]", ap);
    part->axis = {requireNumber(axis[0], joinPath(ap, std::size_t{0})),
                  requireNumber(axis[1], joinPath(ap, std::size_t{1})),
                  requireNumber(axis[2], joinPath(ap, std::size_t{2}))};
    if (part->axis.x == 0 && part->axis.y == 0 && part->axis.z == 0)
      throw Error(errc::kInvalidDocument, "the rotation axis must not be the zero vector", ap);
    part->deg = parseFuzzyNumber(requireField(r, "deg", p), joinPath(p, "deg"));
  }
  if (t.contains("scale")) part->scale = parseFuzzyNumber(t["scale"], joinPath(path, "scale"));
}

FuzzyPart validated(const FuzzyPart& part, const std::string& path) {
  try {
    part.validate();
  } catch (const Error& e) {
    throw e.withPathPrefix(path);
  }
  return part;
}

}  // namespace

FuzzyPart parsePart(const nlohmann::json& doc, const std::string& path) {
  requireObject(doc, path);
  if (doc.contains("place"))
    throw Error(errc::kInvalidDocument,
                "a placement from words goes in the transform of a leaf of a shape: "
                "{\"transform\":{\"place\":{\"relative_to\":\"<earlier leaf>\",\"direction\":\"top right\","
                "\"distance\":\"about 3\"}}}",
                joinPath(path, "place"));
  rejectUnknownKeys(doc, path,
                    {"kind", "name", "descriptors", "params", "text", "transform", "meta", "id", "version"});
  if (doc.contains("kind") && doc["kind"] != "part")
    throw Error(errc::kInvalidDocument, "expected kind \"part\"", joinPath(path, "kind"));

  FuzzyPart part;
  const bool fromWords = doc.contains("text");
  if (fromWords) {
    const std::string tp = joinPath(path, "text");
    try {
      part = partFromWords(requireString(doc["text"], tp), activeVocabulary());
    } catch (const Error& e) {
      throw Error(errc::kInvalidDocument, e.what(), tp);
    }
  }
  const std::string pp = joinPath(path, "params");
  if (fromWords && !doc.contains("params")) {
    if (doc.contains("transform")) parseTransform(doc["transform"], joinPath(path, "transform"), &part);
    return validated(part, path);
  }
  const auto& params = requireObject(requireField(doc, "params", path), pp);
  for (auto it = params.begin(); it != params.end(); ++it) {
    bool known = false;
    for (const NamedParam& np : kParams) known = known || it.key() == np.name;
    if (!known)
      throw Error(errc::kInvalidDocument,
                  "unknown parameter '" + quotedWord(it.key()) + "'; expected eps1, eps2, a1, a2, a3, kx, ky, kv, t",
                  joinPath(pp, it.key()));
  }
  if (!fromWords && !params.contains("a1"))
    throw Error(errc::kInvalidDocument, "missing required parameter 'a1' (size)", joinPath(pp, "a1"));
  for (const NamedParam& np : kParams)
    if (params.contains(np.name)) part.*np.member = parseFuzzyNumber(params[np.name], joinPath(pp, np.name));
  if (doc.contains("transform")) parseTransform(doc["transform"], joinPath(path, "transform"), &part);
  return validated(part, path);
}

nlohmann::json partToJson(const FuzzyPart& part) {
  nlohmann::json params = nlohmann::json::object();
  for (const NamedParam& np : kParams) params[np.name] = toJson(part.*np.member);
  nlohmann::json transform = {
      {"translate", {toJson(part.tx), toJson(part.ty), toJson(part.tz)}},
      {"rotate", {{"axis", {part.axis.x, part.axis.y, part.axis.z}}, {"deg", toJson(part.deg)}}},
      {"scale", toJson(part.scale)}};
  return {{"kind", "part"}, {"params", params}, {"transform", transform}};
}

}  // namespace fsdb
