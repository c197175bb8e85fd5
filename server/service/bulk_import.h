#pragma once
// Bulk import (docs/api.md §4 POST /parts/bulk, /shapes/bulk; docs/api.md §1 `fsdb import`).
//
// Input: JSON Lines (one document per line; blank lines skipped) or one JSON array of documents.
// Lines are numbered from 1 as in the file (for an array: element index + 1).
//
// What happens to the good lines of a batch that has bad ones: lines are taken in batches of
// `batchSize`. Each line is validated on its own (JSON, document, references); a line that fails
// is reported with its line number and skipped. The valid lines of a batch are then written in
// ONE transaction, each in a savepoint, so a line the store refuses (a name already taken, a
// reference to something deleted meanwhile) is reported too while the rest of its batch
// commits. A crash or kill loses at most the batch being written, never part of one: every batch
// acknowledged through `progress` (and every line counted in `imported`) is durable.
// References may name documents of earlier lines of the same batch or of earlier batches.
// After each batch the descriptor rows the batch left pending are recomputed
// (server/service/descriptor_rows.h refreshPendingDescriptors).
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "db/store.h"
#include "server/service/documents.h"

namespace fsdb {

struct BulkLine {
  size_t line = 0;
  nlohmann::json document;    // null when the line is not JSON
  nlohmann::json parseError;  // {"code","message","path"} when it is not
};

// A body whose first non-blank byte is '[': one JSON array of documents, not JSON Lines.
bool isJsonArrayBody(const std::string& body);

// A non-blank line of a JSON Lines body: its number (from 1, blank lines counted) and its bytes
// [begin, end) in the body.
struct LineSpan {
  size_t line, begin, end;
};
std::vector<LineSpan> lineSpans(const std::string& body);

// Splits a body into documents. A body whose first non-blank byte is '[' is a JSON array
// (malformed: one malformed_json error for the whole body, thrown); otherwise JSON Lines,
// each line parsed separately (errors recorded on the line, never thrown).
std::vector<BulkLine> splitBulkBody(const std::string& body, int maxJsonDepth);

struct BulkOptions {
  std::string kind;  // "part" / "shape": every line must be of it; "": each line's "kind" decides
  BulkMode mode = BulkMode::kCreate;
  size_t batchSize = 500;
  DocumentLimits limits;  // of every document (server/service/documents.h)
  // Called after each committed batch with (lines done, lines total).
  std::function<void(size_t, size_t)> progress;
};

struct BulkReport {
  size_t imported = 0;
  size_t failed = 0;
  std::vector<int64_t> ids;                         // of the imported lines, in line order
  nlohmann::json errors = nlohmann::json::array();  // [{"line":k,"error":{"code","message","path"}}]
  nlohmann::json toJson() const;                    // {"imported","failed","ids","errors"}
  // Counts a failed line and records its error ({"code","message","path"}).
  void addFailure(size_t line, nlohmann::json error);
  // Errors in line order (failures are found per batch, validation before storage).
  void sortErrors();
};

// Imports `lines` (splitBulkBody's), `options.batchSize` lines a transaction. Within a batch the
// lines are parsed and validated on all cores (TBB) while the batch before is written by one
// thread; shapes, whose references may name earlier lines, are validated by the writer in line
// order. Throws fsdb::Error (storage_error) when a batch cannot commit: every batch before it is
// stored and was reported through `progress`.
BulkReport importDocuments(Store& store, const std::vector<BulkLine>& lines, const BulkOptions& options);
// The same for a whole body (splitBulkBody's forms, same line numbers); JSON Lines are parsed
// a batch at a time inside the pipeline, so only the batches in flight are held as documents.
BulkReport importBody(Store& store, const std::string& body, int maxJsonDepth, const BulkOptions& options);

}  // namespace fsdb
