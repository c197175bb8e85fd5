#pragma once
// The bodies of bulk import (docs/api.md §4 POST /parts/bulk; `fsdb import`): JSON Lines (one
// document per line; blank lines skipped) or one JSON array of documents. Lines are numbered from
// 1 as in the file (for an array: element index + 1).
//
// BulkBodyReader walks a body one document at a time without parsing the documents, so memory
// beyond the body stays bounded however many documents it holds; each document is parsed on its
// own (parseBulkLine), on whatever thread imports it.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace fsdb {

// A non-blank line of a JSON Lines body, or an element of an array body: its number (from 1;
// blank lines counted) and its bytes [begin, end) in the body.
struct LineSpan {
  size_t line, begin, end;
};

struct BulkLine {
  size_t line = 0;
  nlohmann::json document;    // null when the line is not JSON
  nlohmann::json parseError;  // {"code","message","path"} when it is not (parseBulkLine)
};

// A body whose first non-blank byte is '[': one JSON array of documents, not JSON Lines.
bool isJsonArrayBody(const std::string& body);

class BulkBodyReader {
 public:
  // brief  Reads `body`, which must outlive the reader.
  // note   An array body is checked whole first (one pass, nothing kept), so that a malformed
  //        array stops the import before its first write.
  // throws fsdb::Error malformed_json (with the byte offset) for an array that is not JSON,
  //        limit_exceeded (path "body") for nesting deeper than maxJsonDepth, invalid_document
  //        for a number beyond double range: the errors parseJsonBody gives for the whole body.
  BulkBodyReader(const std::string& body, int maxJsonDepth);
  // The number of documents in the body.
  size_t count() const { return count_; }
  // brief  The next document's number and bytes; false after the last one.
  bool next(LineSpan& span);

 private:
  const std::string& body_;
  bool array_ = false;
  size_t count_ = 0;
  size_t pos_ = 0;   // where the next document's search starts
  size_t line_ = 0;  // the number of the last document (lines: the last line) read
};

// brief  A document of the body parsed, or its error recorded on it (never thrown): malformed_json,
//        limit_exceeded for nesting, invalid_document for a number beyond double range.
// note   Without `withMessage` (a line whose error will not be listed) the error is only the code
//        malformed_json, found without raising an exception.
BulkLine parseBulkLine(const std::string& body, const LineSpan& span, int maxJsonDepth, bool withMessage = true);

// brief  Every document of a body parsed (BulkBodyReader + parseBulkLine); for tests and small
//        bodies: an import reads a body a document at a time instead.
// throws As BulkBodyReader's constructor.
std::vector<BulkLine> splitBulkBody(const std::string& body, int maxJsonDepth);

}  // namespace fsdb
