// Fuzz target: bulk import bodies, JSON Lines or one array (server/service/bulk_body.h).
// Properties: the reader refuses only array bodies, exactly those a whole-body parse refuses; it
// yields count() documents with increasing numbers, each inside the body; an array's documents
// parse to the elements of the whole-body parse; parsing a document never throws.
#include <cstdint>
#include <optional>
#include <string>

#include "geometry/core/error.h"
#include "query/json/json_body.h"
#include "server/service/bulk_body.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string body(reinterpret_cast<const char*>(data), size);
  constexpr int kDepth = 16;
  const bool array = fsdb::isJsonArrayBody(body);
  const std::optional<nlohmann::json> whole = array ? fsdb::tryParseJsonBody(body, kDepth) : std::nullopt;
  std::optional<fsdb::BulkBodyReader> reader;
  try {
    reader.emplace(body, kDepth);
  } catch (const fsdb::Error&) {
    FUZZ_CHECK(array && !whole, "only an array body that does not parse whole is refused");
    return 0;
  }
  FUZZ_CHECK(!array || (whole && whole->is_array()), "an accepted array body parses whole");
  if (array) FUZZ_CHECK(reader->count() == whole->size(), "one document per element");
  fsdb::LineSpan span{};
  size_t n = 0, lastLine = 0;
  while (reader->next(span)) {
    FUZZ_CHECK(span.begin <= span.end && span.end <= body.size(), "a document lies inside the body");
    FUZZ_CHECK(span.line > lastLine, "numbers increase");
    lastLine = span.line;
    const fsdb::BulkLine line = fsdb::parseBulkLine(body, span, kDepth);
    FUZZ_CHECK(line.parseError.is_null() || line.document.is_null(), "a line with an error has no document");
    if (array) FUZZ_CHECK(line.parseError.is_null() && line.document == (*whole)[n], "an element as the whole parse");
    const fsdb::BulkLine quiet = fsdb::parseBulkLine(body, span, kDepth, false);
    FUZZ_CHECK(quiet.document == line.document && quiet.parseError.is_null() == line.parseError.is_null(),
               "the same verdict without messages");
    ++n;
  }
  FUZZ_CHECK(n == reader->count(), "count() documents");
  return 0;
}
