// Fuzz target: the connection front's reading of request bytes (server/http/request_head.h), which
// every byte any client sends reaches before cpp-httplib does.
//
// The input is the bytes received so far on a connection.
//
// Properties:
//  * scanRequestHead finds a head exactly when "\r\n\r\n" occurs, and it ends just after the first
//    occurrence; scanning again from any earlier size (as the front does after each read) finds the
//    same end; an Expect line's span lies inside the head and starts with "Expect";
//  * header(name) finds a header in any case of its name;
//  * chunkedBodyBytes of the bytes after the head ends within them, gives the same end for the
//    prefix up to it, and nothing for the prefix one byte shorter.
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>
#include <string_view>

#include "server/http/request_head.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const auto head = fsdb::scanRequestHead(bytes);
  const size_t blank = bytes.find("\r\n\r\n");
  FUZZ_CHECK(head.has_value() == (blank != std::string::npos), "a head exactly when its blank line is there");
  if (!head) return 0;
  FUZZ_CHECK(head->headBytes == blank + 4, "the head ends after the first blank line");
  for (size_t from : {size_t(1), size / 3, size / 2, blank, blank + 1, blank + 3}) {
    if (from > blank + 3) continue;  // the front searches again only while no head was found
    const auto again = fsdb::scanRequestHead(bytes, from);
    FUZZ_CHECK(again && again->headBytes == head->headBytes, "searching from an earlier size finds the same end");
  }
  if (head->expectContinue) {
    FUZZ_CHECK(head->expectBegin < head->expectEnd && head->expectEnd <= head->headBytes, "Expect span in the head");
    std::string name = bytes.substr(head->expectBegin, 6);
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
    FUZZ_CHECK(name == "expect", "the span is the Expect line");
  }
  for (const auto& [name, value] : head->headers) {
    std::string upper = name;
    std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
    FUZZ_CHECK(!head->header(upper).empty() || value.empty() || head->header(name) == head->header(upper),
               "header() ignores case");
  }
  const std::string_view body = std::string_view(bytes).substr(head->headBytes);
  if (const auto end = fsdb::chunkedBodyBytes(body)) {
    FUZZ_CHECK(*end <= body.size(), "the chunked body ends within the bytes");
    const auto same = fsdb::chunkedBodyBytes(body.substr(0, *end));
    FUZZ_CHECK(same && *same == *end, "the prefix up to the end ends there too");
    if (*end > 0) FUZZ_CHECK(!fsdb::chunkedBodyBytes(body.substr(0, *end - 1)), "one byte short is not complete");
  }
  return 0;
}
