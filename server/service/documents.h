#pragma once
// Documents on their way into the store: validation with the query/ parsers, references
// resolved against the store, and the normalised columns the store keeps (db/store.h).
//
// Contract:
// - Curves (query/document/curve_document.h: a Bézier or a fair curve) and surfaces (query/document/bezier_json.h)
//   are validated with DocumentLimits: at most maxControlPoints control points (413 naming
//   max_control_points), a fair curve within the fair-curve limits (max_fair_*). They keep no
//   normalised columns. A shape has at most maxNodes CSG nodes (max_nodes): each limit means
//   one thing, and each is the `fsdb serve` option of the same name (server/service/limits.h).
// - prepareDocument validates a part or shape document exactly as evaluation would (every
//   fuzzy number, range, reference and limit), so nothing the store holds fails to evaluate
//   for a reason visible at write time. Errors are fsdb::Error with the JSON path inside the
//   document, prefixed by `path` ("" for a request body, "line 7" style paths are the caller's).
// - A part document may omit "kind" (it is the route's); a document of the other kind is
//   invalid_document naming "kind". "name" is required: a non-empty string of at most 200
//   characters without control characters.
// - The descriptor index rows (server/service/descriptor_rows.h) go with the object: a part's one
//   component, a shape's leaves (references expanded).
// - The stored text is the document as given, re-serialised compactly (key order kept as
//   parsed by nlohmann::json: sorted), with "kind" filled in.
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "db/store.h"
#include "query/document/fair_curve_json.h"
#include "query/document/shape_json.h"

namespace fsdb {

// The longest name a stored object has, in bytes ("name" of a document): the search box looks up
// no longer spelling (server/service/query_search.cpp).
inline constexpr size_t kMaxNameLength = 200;

struct ServerLimits;

// What prepareDocument enforces; the defaults are those of `fsdb serve`.
struct DocumentLimits {
  size_t maxNodes = 10000;        // --max-nodes: CSG nodes of a shape
  size_t maxControlPoints = 256;  // --max-control-points: of a stored Bézier curve or surface grid
  FairCurveLimits fairCurve;      // --max-fair-*: a stored fair curve's request form
};
DocumentLimits documentLimits(const ServerLimits& limits);

// Names → documents that are about to be written in the same batch, visible to references
// before they are committed (bulk import: a shape may use a part from an earlier line).
class PendingDocuments {
 public:
  void add(const std::string& kind, const std::string& name, const nlohmann::json& document);
  void add(const std::string& kind, const std::string& name, nlohmann::json&& document);
  const nlohmann::json* find(const std::string& kind, const std::string& name) const;

 private:
  std::map<std::pair<std::string, std::string>, nlohmann::json> documents_;
};

// Resolves references against the store (latest versions), then `pending` (may be null).
// Pending documents get negative pseudo-ids (stable within the resolver's life).
ReferenceResolver storeResolver(const Store& store, const PendingDocuments* pending = nullptr);

NewObject prepareDocument(const nlohmann::json& document, const std::string& kind, const Store& store,
                          const DocumentLimits& limits, const std::string& path,
                          const PendingDocuments* pending = nullptr);

// The words the search box finds a part or shape by besides its name (NewObject::searchText): its
// meta.description and the strings of its descriptors list, where they are strings.
std::string documentSearchText(const nlohmann::json& document);

// The JSON the API returns for a stored version, as text:
//   {"content_hash","created_at","document","id","kind","latest_version","name","version"}
// byte for byte the dump of that object built with nlohmann::json, written without parsing
// the document: the stored text is spliced in as it is (it is nlohmann's compact dump of the
// parsed document, keys sorted, which parsing and dumping again reproduces). GET /parts/{id}
// answers with it (docs/performance.md, "Service: import and reads").
std::string storedObjectText(const StoredObject& object);

}  // namespace fsdb
