#include "server/service/bulk_import.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_pipeline.h>

#include <algorithm>
#include <atomic>
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

nlohmann::json BulkReport::toJson() const {
  return {{"imported", imported},
          {"failed", failed},
          {"ids", ids},
          {"errors", errors},
          {"errors_truncated", errorsTruncated}};
}

void BulkReport::addFailure(size_t line, nlohmann::json error) {
  ++failed;
  if (errorsFull()) {
    errorsTruncated = true;
    return;
  }
  errors.push_back({{"line", line}, {"error", std::move(error)}});
}

void BulkReport::closeErrors(size_t from) {
  std::stable_sort(errors.begin() + static_cast<std::ptrdiff_t>(std::min(from, errors.size())), errors.end(),
                   [](const nlohmann::json& a, const nlohmann::json& b) { return a["line"] < b["line"]; });
  if (errors.size() > maxErrors) {
    errors.erase(errors.begin() + static_cast<std::ptrdiff_t>(maxErrors), errors.end());
    errorsTruncated = true;
  }
  errorsFull_ = errors.size() >= maxErrors;
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
  nlohmann::json error;             // {"code","message","path"} when the line failed (just the code
                                    // when it will not be listed)
};

// `withMessage`: false once the report lists all the errors it may (every later line's error is
// only counted), so that bad lines cost no message and no exception.
PreparedLine prepareLine(BulkLine&& in, const Store& store, const BulkOptions& options, bool withMessage) {
  PreparedLine out;
  out.line = in.line;
  if (!in.parseError.is_null()) {
    out.error = std::move(in.parseError);
    return out;
  }
  out.document = std::move(in.document);
  // A line that is not an object fails as prepareDocument would, without the cost of an
  // exception: millions of such lines are the cheapest body to send.
  if (!out.document.is_object()) {
    out.error = withMessage
                    ? errorObject(errc::kInvalidDocument, "expected an object, got " + jsonTypeName(out.document), "")
                    : nlohmann::json(errc::kInvalidDocument);
    return out;
  }
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

// Imports the lines of `source`: source.count() lines, source.next(item) giving the next one's
// handle and source.read(item, withMessage) its BulkLine. Lines are prepared in parallel (prepareLine) and
// batches written in line order by one thread at a time (writeBatch).
template <typename Source>
BulkReport importLines(Store& store, Source& source, const BulkOptions& options) {
  using Item = typename Source::Item;
  BulkReport report;
  report.maxErrors = options.maxErrors;
  const size_t count = source.count();
  const size_t batch = options.batchSize == 0 ? 1 : options.batchSize;
  size_t next = 0;
  struct Chunk {
    size_t end = 0;  // one past its last line
    std::vector<Item> items;
    std::vector<PreparedLine> lines;
  };
  std::vector<PreparedLine> pending;  // the batch being accumulated by the writer
  // report.errorsFull() published to the preparing threads: the lines prepared after it is set
  // are of later batches, whose errors are only counted.
  std::atomic<bool> errorsFull{report.errorsFull()};
  tbb::parallel_pipeline(
      kChunksInFlight,
      tbb::make_filter<void, std::shared_ptr<Chunk>>(tbb::filter_mode::serial_in_order,
                                                     [&](tbb::flow_control& control) -> std::shared_ptr<Chunk> {
                                                       const size_t size =
                                                           std::min(kChunkLines, (next / batch + 1) * batch - next);
                                                       auto chunk = std::make_shared<Chunk>();
                                                       Item item;
                                                       while (chunk->items.size() < size && source.next(item))
                                                         chunk->items.push_back(item);
                                                       if (chunk->items.empty()) {
                                                         control.stop();
                                                         return nullptr;
                                                       }
                                                       next += chunk->items.size();
                                                       chunk->end = next;
                                                       return chunk;
                                                     }) &
          tbb::make_filter<std::shared_ptr<Chunk>, std::shared_ptr<Chunk>>(
              tbb::filter_mode::parallel,
              [&](std::shared_ptr<Chunk> chunk) {
                chunk->lines.resize(chunk->items.size());
                tbb::parallel_for(
                    tbb::blocked_range<size_t>(0, chunk->items.size(), 16), [&](const tbb::blocked_range<size_t>& r) {
                      const bool withMessage = !errorsFull.load(std::memory_order_relaxed);
                      for (size_t i = r.begin(); i != r.end(); ++i)
                        chunk->lines[i] =
                            prepareLine(source.read(chunk->items[i], withMessage), store, options, withMessage);
                    });
                return chunk;
              }) &
          tbb::make_filter<std::shared_ptr<Chunk>, void>(tbb::filter_mode::serial_in_order,
                                                         [&](const std::shared_ptr<Chunk>& chunk) {
                                                           for (PreparedLine& l : chunk->lines)
                                                             pending.push_back(std::move(l));
                                                           if (chunk->end % batch != 0 && chunk->end != count)
                                                             return;  // the batch goes on
                                                           const size_t errorsBefore = report.errors.size();
                                                           writeBatch(store, pending, options, report);
                                                           report.closeErrors(errorsBefore);
                                                           if (report.errorsFull())
                                                             errorsFull.store(true, std::memory_order_relaxed);
                                                           pending.clear();
                                                           if (options.progress) options.progress(chunk->end, count);
                                                         }));
  return report;
}

// The lines of a vector, by index.
struct VectorSource {
  using Item = size_t;
  const std::vector<BulkLine>& lines;
  size_t at = 0;
  size_t count() const { return lines.size(); }
  bool next(Item& i) { return at < lines.size() ? (i = at++, true) : false; }
  BulkLine read(Item i, bool) const { return lines[i]; }
};

// The documents of a body, by span, each parsed when read.
struct BodySource {
  using Item = LineSpan;
  const std::string& body;
  BulkBodyReader reader;
  int maxJsonDepth;
  size_t count() const { return reader.count(); }
  bool next(Item& span) { return reader.next(span); }
  BulkLine read(const Item& span, bool withMessage) const {
    return parseBulkLine(body, span, maxJsonDepth, withMessage);
  }
};

}  // namespace

BulkReport importDocuments(Store& store, const std::vector<BulkLine>& lines, const BulkOptions& options) {
  VectorSource source{lines};
  return importLines(store, source, options);
}

BulkReport importBody(Store& store, const std::string& body, int maxJsonDepth, const BulkOptions& options) {
  BodySource source{body, BulkBodyReader(body, maxJsonDepth), maxJsonDepth};
  return importLines(store, source, options);
}

}  // namespace fsdb
