#include "server/service/bulk_import.h"

#include <algorithm>

#include "geometry/core/error.h"
#include "query/json/json_body.h"
#include "server/service/descriptor_rows.h"
#include "server/service/documents.h"
#include "server/service/error_json.h"

namespace fsdb {
namespace {

// The kind of a line: the route's, or (for mixed files) the document's own.
std::string lineKind(const nlohmann::json& doc, const std::string& routeKind) {
  if (!routeKind.empty()) return routeKind;
  if (doc.is_object() && doc.contains("kind") && doc["kind"].is_string()) {
    const std::string k = doc["kind"].get<std::string>();
    if (k == "part" || k == "shape" || k == "curve" || k == "surface") return k;
    throw Error(errc::kInvalidDocument, "kind must be \"part\", \"shape\", \"curve\" or \"surface\", got \"" + k + "\"",
                "kind");
  }
  throw Error(errc::kInvalidDocument, "each line needs \"kind\": \"part\", \"shape\", \"curve\" or \"surface\"", "kind");
}

}  // namespace

std::vector<BulkLine> splitBulkBody(const std::string& body, int maxJsonDepth) {
  std::vector<BulkLine> out;
  size_t first = body.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && body[first] == '[') {
    const nlohmann::json array = parseJsonBody(body, maxJsonDepth);
    for (size_t i = 0; i < array.size(); ++i) out.push_back({i + 1, array[i], nullptr});
    return out;
  }
  size_t line = 0, pos = 0;
  while (pos <= body.size()) {
    size_t end = body.find('\n', pos);
    if (end == std::string::npos) end = body.size();
    ++line;
    const std::string text = body.substr(pos, end - pos);
    pos = end + 1;
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    BulkLine l;
    l.line = line;
    try {
      l.document = parseJsonBody(text, maxJsonDepth);
    } catch (const Error& e) {
      l.parseError = errorObject(e.code(), e.what(), e.path());
    }
    out.push_back(std::move(l));
  }
  return out;
}

nlohmann::json BulkReport::toJson() const {
  return {{"imported", imported}, {"failed", failed}, {"ids", ids}, {"errors", errors}};
}

void BulkReport::addFailure(size_t line, nlohmann::json error) {
  ++failed;
  errors.push_back({{"line", line}, {"error", std::move(error)}});
}

void BulkReport::sortErrors() {
  std::stable_sort(errors.begin(), errors.end(),
                   [](const nlohmann::json& a, const nlohmann::json& b) { return a["line"] < b["line"]; });
}

BulkReport importDocuments(Store& store, const std::vector<BulkLine>& lines, const BulkOptions& options) {
  BulkReport report;
  const size_t batch = options.batchSize == 0 ? 1 : options.batchSize;
  for (size_t start = 0; start < lines.size(); start += batch) {
    const size_t end = std::min(lines.size(), start + batch);
    PendingDocuments pending;
    std::vector<NewObject> items;
    std::vector<size_t> itemLines;
    for (size_t i = start; i < end; ++i) {
      const BulkLine& l = lines[i];
      if (!l.parseError.is_null()) {
        report.addFailure(l.line, l.parseError);
        continue;
      }
      try {
        const std::string kind = lineKind(l.document, options.kind);
        NewObject object = prepareDocument(l.document, kind, store, options.limits, "", &pending);
        pending.add(object.kind, object.name, l.document);  // as given: the resolver needs no "kind"
        items.push_back(std::move(object));
        itemLines.push_back(l.line);
      } catch (const Error& e) {
        report.addFailure(l.line, errorObject(e.code(), e.what(), e.path()));
      }
    }
    if (!items.empty()) {
      const std::vector<BulkItemResult> results = store.createBatch(items, options.mode);
      for (size_t k = 0; k < results.size(); ++k) {
        if (results[k].id) {
          ++report.imported;
          report.ids.push_back(*results[k].id);
        } else {
          report.addFailure(itemLines[k], errorObject(results[k].errorCode, results[k].errorMessage, results[k].errorPath));
        }
      }
      refreshPendingDescriptors(store, options.limits.maxNodes);  // shapes with references, upserted versions
    }
    if (options.progress) options.progress(end, lines.size());
  }
  report.sortErrors();
  return report;
}

}  // namespace fsdb
