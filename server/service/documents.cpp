#include "server/service/documents.h"

#include <functional>

#include "db/content_hash.h"
#include "geometry/core/error.h"
#include "geometry/superquadric/fuzzy_part.h"
#include "query/document/bezier_json.h"
#include "query/document/curve_document.h"
#include "query/document/part_json.h"
#include "query/json/json_body.h"
#include "server/service/descriptor_rows.h"
#include "server/service/limits.h"

namespace fsdb {
namespace {

void checkName(const nlohmann::json& doc, const std::string& path) {
  const std::string np = joinPath(path, "name");
  const std::string& name = requireString(requireField(doc, "name", path), np);
  if (name.empty()) throw Error(errc::kInvalidDocument, "name must not be empty", np);
  if (name.size() > kMaxNameLength)
    throw Error(errc::kInvalidDocument, "name is longer than " + std::to_string(kMaxNameLength) + " bytes", np);
  for (unsigned char c : name)
    if (c < 0x20 || c == 0x7f) throw Error(errc::kInvalidDocument, "name must not contain control characters", np);
}

ObjectReference objectReference(const DocumentReference& r) {
  ObjectReference out;
  out.kind = r.kind;
  if (r.key.is_number_integer()) out.id = r.key.get<int64_t>();
  else out.name = r.key.get<std::string>();
  out.path = r.path;
  return out;
}

std::string dumpOrEmpty(const nlohmann::json& j) { return j.is_null() ? std::string() : j.dump(); }

}  // namespace

void PendingDocuments::add(const std::string& kind, const std::string& name, const nlohmann::json& document) {
  documents_[{kind, name}] = document;
}

void PendingDocuments::add(const std::string& kind, const std::string& name, nlohmann::json&& document) {
  documents_[{kind, name}] = std::move(document);
}

const nlohmann::json* PendingDocuments::find(const std::string& kind, const std::string& name) const {
  auto it = documents_.find({kind, name});
  return it == documents_.end() ? nullptr : &it->second;
}

ReferenceResolver storeResolver(const Store& store, const PendingDocuments* pending) {
  return [&store, pending](const std::string& kind, const nlohmann::json& key) -> std::optional<ResolvedReference> {
    if (pending && key.is_string()) {
      if (const nlohmann::json* doc = pending->find(kind, key.get<std::string>())) {
        // Not yet stored: a pseudo-id below zero, the same for the same name, never a real id.
        const auto h = std::hash<std::string>{}(kind + '\n' + key.get<std::string>());
        return ResolvedReference{-static_cast<int64_t>(h >> 2) - 1, *doc};
      }
    }
    ObjectReference r;
    r.kind = kind;
    if (key.is_number_integer()) r.id = key.get<int64_t>();
    else if (key.is_string()) r.name = key.get<std::string>();
    else return std::nullopt;
    std::optional<StoredObject> found = store.find(r);
    if (!found) return std::nullopt;
    return ResolvedReference{found->id, nlohmann::json::parse(found->documentJson)};
  };
}

DocumentLimits documentLimits(const ServerLimits& limits) {
  return DocumentLimits{limits.maxNodes, limits.maxControlPoints, limits.fairCurve};
}

NewObject prepareDocument(const nlohmann::json& document, const std::string& kind, const Store& store,
                          const DocumentLimits& limits, const std::string& path, const PendingDocuments* pending) {
  requireObject(document, path);
  nlohmann::json doc = document;
  if (doc.contains("kind")) {
    const std::string& k = requireString(doc["kind"], joinPath(path, "kind"));
    if (k != kind)
      throw Error(errc::kInvalidDocument, "expected a " + kind + " document here, got kind \"" + k + "\"",
                  joinPath(path, "kind"));
  } else {
    doc["kind"] = kind;
  }
  checkName(doc, path);

  NewObject out;
  out.kind = kind;
  out.name = doc["name"].get<std::string>();
  if (kind == "curve" || kind == "surface") {
    BezierJsonLimits bezier;
    bezier.maxControlPoints = limits.maxControlPoints;
    if (kind == "curve") parseCurveDocument(doc, path, bezier, limits.fairCurve);
    else parseSurfaceDocument(doc, path, bezier);
  } else if (kind == "part") {
    const FuzzyPart part = parsePart(doc, path);
    out.descriptors = partDescriptorRows(part);
  } else {
    // Validates everything, references included, and keeps the resolved tree (csg text parsed).
    const ParsedShape parsed = parseShapeField(doc, path, limits.maxNodes, storeResolver(store, pending));
    if (parsed.tree) out.descriptors = shapeDescriptorRows(shapeComponents(*parsed.tree));
    const TreeOutline outline = outlineTree(parsed.documentTree, parsed.documentTreePath);
    for (const DocumentReference& r : outline.references) out.references.push_back(objectReference(r));
    for (size_t i = 0; i < outline.nodes.size(); ++i) {
      const TreeNodeOutline& n = outline.nodes[i];
      CsgNodeRow row;
      row.index = static_cast<int>(i);
      row.parent = n.parent;
      row.position = n.position;
      row.kind = n.kind;
      row.operatorJson = dumpOrEmpty(n.operatorDoc);
      row.transformJson = dumpOrEmpty(n.transform);
      row.refIndex = n.reference;
      out.nodes.push_back(std::move(row));
    }
  }
  if (kind == "part" || kind == "shape") out.searchText = documentSearchText(doc);
  out.documentJson = doc.dump();
  out.contentHash = contentHash(out.documentJson);
  return out;
}

std::string documentSearchText(const nlohmann::json& document) {
  // The same words as schema/migrations/009_object_text.sql takes from documents stored before.
  std::string text;
  const auto add = [&text](const nlohmann::json& value) {
    if (!value.is_string()) return;
    if (!text.empty()) text += ' ';
    text += value.get<std::string>();
  };
  if (document.contains("meta") && document["meta"].is_object() && document["meta"].contains("description"))
    add(document["meta"]["description"]);
  if (document.contains("descriptors") && document["descriptors"].is_array())
    for (const nlohmann::json& d : document["descriptors"]) add(d);
  return text;
}

std::string storedObjectText(const StoredObject& object) {
  const auto text = [](const std::string& s) {
    return nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  };
  // Keys in nlohmann's order (sorted), as the dump of the object's JSON writes them.
  std::string out;
  out.reserve(object.documentJson.size() + object.name.size() + 160);
  out += "{\"content_hash\":" + text(object.contentHash);
  out += ",\"created_at\":" + text(object.createdAt);
  out += ",\"document\":";
  out += object.documentJson;
  out += ",\"id\":" + std::to_string(object.id);
  out += ",\"kind\":" + text(object.kind);
  out += ",\"latest_version\":" + std::to_string(object.latestVersion);
  out += ",\"name\":" + text(object.name);
  out += ",\"version\":" + std::to_string(object.version) + "}";
  return out;
}

}  // namespace fsdb
