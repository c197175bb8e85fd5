#include "server/service/bulk_import.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_pipeline.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <utility>

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
  throw Error(errc::kInvalidDocument, "each line needs \"kind\": \"part\", \"shape\", \"curve\" or \"surface\"",
              "kind");
}

}  // namespace

std::vector<LineSpan> lineSpans(const std::string& body) {
  std::vector<LineSpan> spans;
  size_t line = 0, pos = 0;
  while (pos <= body.size()) {
    size_t end = body.find('\n', pos);
    if (end == std::string::npos) end = body.size();
    ++line;
    for (size_t k = pos; k < end; ++k)
      if (body[k] != ' ' && body[k] != '\t' && body[k] != '\r') {
        spans.push_back({line, pos, end});
        break;
      }
    pos = end + 1;
  }
  return spans;
}

namespace {

// A line's document, or its error recorded on it (never thrown).
BulkLine parseLine(const std::string& body, const LineSpan& span, int maxJsonDepth) {
  BulkLine l;
  l.line = span.line;
  try {
    l.document = parseJsonBody(body.substr(span.begin, span.end - span.begin), maxJsonDepth);
  } catch (const Error& e) {
    l.parseError = errorObject(e.code(), e.what(), e.path());
  }
  return l;
}

}  // namespace

bool isJsonArrayBody(const std::string& body) {
  const size_t first = body.find_first_not_of(" \t\r\n");
  return first != std::string::npos && body[first] == '[';
}

std::vector<BulkLine> splitBulkBody(const std::string& body, int maxJsonDepth) {
  std::vector<BulkLine> out;
  if (isJsonArrayBody(body)) {
    const nlohmann::json array = parseJsonBody(body, maxJsonDepth);
    for (size_t i = 0; i < array.size(); ++i) out.push_back({i + 1, array[i], nullptr});
    return out;
  }
  for (const LineSpan& span : lineSpans(body)) out.push_back(parseLine(body, span, maxJsonDepth));
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

namespace {

// A line on its way in. Parsing and validating need nothing but the line for parts, curves and
// surfaces, so that runs on any thread; a shape's references may name earlier lines (pending)
// or stored objects, so shapes are validated by the writer, in line order.
struct PreparedLine {
  size_t line = 0;
  std::string kind;
  nlohmann::json document;
  std::optional<NewObject> object;  // prepared; for a shape, by the writer
  nlohmann::json error;             // {"code","message","path"} when the line failed
};

PreparedLine prepareLine(BulkLine&& in, const Store& store, const BulkOptions& options) {
  PreparedLine out;
  out.line = in.line;
  if (!in.parseError.is_null()) {
    out.error = std::move(in.parseError);
    return out;
  }
  out.document = std::move(in.document);
  try {
    out.kind = lineKind(out.document, options.kind);
    if (out.kind != "shape") out.object = prepareDocument(out.document, out.kind, store, options.limits, "");
  } catch (const Error& e) {
    out.error = errorObject(e.code(), e.what(), e.path());
  }
  return out;
}

// The writer's part of one batch: shapes validated in line order, then every valid line written
// in one transaction (Store::createBatch: a savepoint per line).
void writeBatch(Store& store, std::vector<PreparedLine>& lines, const BulkOptions& options, BulkReport& report) {
  PendingDocuments pending;
  std::vector<NewObject> items;
  std::vector<size_t> itemLines;
  items.reserve(lines.size());
  for (PreparedLine& l : lines) {
    if (!l.error.is_null()) {
      report.addFailure(l.line, std::move(l.error));
      continue;
    }
    try {
      if (!l.object) l.object = prepareDocument(l.document, l.kind, store, options.limits, "", &pending);
      pending.add(l.object->kind, l.object->name, std::move(l.document));  // as given: the resolver needs no "kind"
      items.push_back(std::move(*l.object));
      itemLines.push_back(l.line);
    } catch (const Error& e) {
      report.addFailure(l.line, errorObject(e.code(), e.what(), e.path()));
    }
  }
  if (items.empty()) return;
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

// Lines are prepared in chunks of at most kChunkLines (never across a batch boundary), up to
// kChunksInFlight of them at once: the writer accumulates a batch from its chunks and writes it
// while the chunks of the next batch are being prepared.
constexpr size_t kChunkLines = 128;
constexpr size_t kChunksInFlight = 48;

// Imports `count` lines, line i given by readLine(i) (a BulkLine): lines prepared in parallel
// (prepareLine), batches written in line order by one thread at a time (writeBatch).
template <typename ReadLine>
BulkReport importLines(Store& store, size_t count, ReadLine readLine, const BulkOptions& options) {
  BulkReport report;
  const size_t batch = options.batchSize == 0 ? 1 : options.batchSize;
  size_t next = 0;
  struct Chunk {
    size_t end = 0;  // one past its last line
    std::vector<PreparedLine> lines;
  };
  std::vector<PreparedLine> pending;  // the batch being accumulated by the writer
  tbb::parallel_pipeline(kChunksInFlight,
                         tbb::make_filter<void, std::pair<size_t, size_t>>(
                             tbb::filter_mode::serial_in_order,
                             [&](tbb::flow_control& control) -> std::pair<size_t, size_t> {
                               if (next >= count) {
                                 control.stop();
                                 return {0, 0};
                               }
                               const size_t start = next;
                               next = std::min({count, start + kChunkLines, (start / batch + 1) * batch});
                               return {start, next};
                             }) &
                             tbb::make_filter<std::pair<size_t, size_t>, std::shared_ptr<Chunk>>(
                                 tbb::filter_mode::parallel,
                                 [&](std::pair<size_t, size_t> range) {
                                   auto chunk = std::make_shared<Chunk>();
                                   chunk->end = range.second;
                                   chunk->lines.resize(range.second - range.first);
                                   tbb::parallel_for(tbb::blocked_range<size_t>(range.first, range.second, 16),
                                                     [&](const tbb::blocked_range<size_t>& r) {
                                                       for (size_t i = r.begin(); i != r.end(); ++i)
                                                         chunk->lines[i - range.first] =
                                                             prepareLine(readLine(i), store, options);
                                                     });
                                   return chunk;
                                 }) &
                             tbb::make_filter<std::shared_ptr<Chunk>, void>(
                                 tbb::filter_mode::serial_in_order, [&](const std::shared_ptr<Chunk>& chunk) {
                                   for (PreparedLine& l : chunk->lines) pending.push_back(std::move(l));
                                   if (chunk->end % batch != 0 && chunk->end != count) return;  // the batch goes on
                                   writeBatch(store, pending, options, report);
                                   pending.clear();
                                   if (options.progress) options.progress(chunk->end, count);
                                 }));
  report.sortErrors();
  return report;
}

}  // namespace

BulkReport importDocuments(Store& store, const std::vector<BulkLine>& lines, const BulkOptions& options) {
  return importLines(
      store, lines.size(), [&lines](size_t i) { return BulkLine(lines[i]); }, options);
}

BulkReport importBody(Store& store, const std::string& body, int maxJsonDepth, const BulkOptions& options) {
  if (isJsonArrayBody(body)) return importDocuments(store, splitBulkBody(body, maxJsonDepth), options);
  // JSON Lines: the lines are found here (cheap) and parsed inside the pipeline, a batch at a
  // time, so a large file never has every document in memory at once.
  const std::vector<LineSpan> spans = lineSpans(body);
  return importLines(
      store, spans.size(), [&](size_t i) { return parseLine(body, spans[i], maxJsonDepth); }, options);
}

}  // namespace fsdb
