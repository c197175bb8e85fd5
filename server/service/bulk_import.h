#pragma once
// Bulk import (docs/api.md §4 POST /parts/bulk, /shapes/bulk; docs/api.md §1 `fsdb import`).
//
// The body forms and their line numbers: server/service/bulk_body.h.
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
#include "server/service/bulk_body.h"
#include "server/service/documents.h"

namespace fsdb {

// How many errors a report lists by default: every failed line is counted, but only the first
// ones (by line) are listed, so that a body of bad lines cannot grow the answer or the server's
// memory beyond a fixed bound.
constexpr size_t kDefaultMaxBulkErrors = 1000;

struct BulkOptions {
  std::string kind;  // "part" / "shape": every line must be of it; "": each line's "kind" decides
  BulkMode mode = BulkMode::kCreate;
  size_t batchSize = 500;
  size_t maxErrors = kDefaultMaxBulkErrors;  // errors listed (0: none); the rest only counted
  DocumentLimits limits;                     // of every document (server/service/documents.h)
  // Called after each committed batch with (lines done, lines total).
  std::function<void(size_t, size_t)> progress;
};

struct BulkReport {
  size_t imported = 0;
  size_t failed = 0;
  std::vector<int64_t> ids;                         // of the imported lines, in line order
  nlohmann::json errors = nlohmann::json::array();  // [{"line":k,"error":{"code","message","path"}}]
  bool errorsTruncated = false;                     // more lines failed than `errors` lists
  size_t maxErrors = kDefaultMaxBulkErrors;
  // {"imported","failed","ids","errors","errors_truncated"}
  nlohmann::json toJson() const;
  // Counts a failed line and records its error ({"code","message","path"}) for closeErrors;
  // once closeErrors has listed maxErrors, later failures (of later lines) are only counted.
  void addFailure(size_t line, nlohmann::json error);
  // brief  Puts errors[from..] (added since `from`, all of lines after those before it) in line
  //        order and keeps only the first maxErrors of all, marking the report truncated when
  //        any is dropped.
  void closeErrors(size_t from);
  // True once closeErrors has listed maxErrors (or maxErrors is 0): later lines' errors are only
  // counted, so their messages need not be built.
  bool errorsFull() const { return errorsFull_ || maxErrors == 0; }

 private:
  bool errorsFull_ = false;  // maxErrors listed: every later line's error is dropped
};

// Imports `lines` (splitBulkBody's), `options.batchSize` lines a transaction. Within a batch the
// lines are parsed and validated on all cores (TBB) while the batch before is written by one
// thread; shapes, whose references may name earlier lines, are validated by the writer in line
// order. Throws fsdb::Error (storage_error) when a batch cannot commit: every batch before it is
// stored and was reported through `progress`.
BulkReport importDocuments(Store& store, const std::vector<BulkLine>& lines, const BulkOptions& options);
// brief  The same for a whole body (bulk_body.h's forms, same line numbers).
// note   The body is read a document at a time (BulkBodyReader) and each document parsed inside
//        the pipeline, so beyond the body only the batches in flight and the listed errors are
//        held in memory, however many lines the body has.
// throws As BulkBodyReader (a malformed array: nothing imported), and as importDocuments.
BulkReport importBody(Store& store, const std::string& body, int maxJsonDepth, const BulkOptions& options);

}  // namespace fsdb
