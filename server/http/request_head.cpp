#include "server/http/request_head.h"

#include <algorithm>
#include <cctype>
#include <limits>

namespace fsdb {

namespace {

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

bool containsIgnoringCase(std::string_view haystack, std::string_view needle) {
  if (needle.size() > haystack.size()) return false;
  for (size_t i = 0; i + needle.size() <= haystack.size(); ++i)
    if (equalsIgnoringCase(haystack.substr(i, needle.size()), needle)) return true;
  return false;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// A plain decimal number that fits size_t; nullopt otherwise (signs, spaces inside, overflow).
std::optional<size_t> decimal(std::string_view s) {
  if (s.empty() || s.size() > 19) return std::nullopt;
  size_t v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return std::nullopt;
    v = v * 10 + static_cast<size_t>(c - '0');
  }
  return v;
}

}  // namespace

std::string RequestHead::header(std::string_view name) const {
  for (const auto& [n, v] : headers)
    if (equalsIgnoringCase(n, name)) return v;
  return {};
}

std::string RequestHead::path() const { return target.substr(0, target.find_first_of("?#")); }

std::optional<RequestHead> scanRequestHead(std::string_view bytes, size_t searchFrom) {
  const size_t from = searchFrom > 3 ? std::min(searchFrom - 3, bytes.size()) : 0;
  const size_t end = bytes.find("\r\n\r\n", from);
  if (end == std::string_view::npos) return std::nullopt;
  RequestHead head;
  head.headBytes = end + 4;
  size_t lineBegin = 0;
  bool first = true;
  while (lineBegin < end + 2) {
    const size_t lineEnd = bytes.find("\r\n", lineBegin);
    const std::string_view line = bytes.substr(lineBegin, lineEnd - lineBegin);
    if (first) {
      first = false;
      const size_t sp1 = line.find(' ');
      const size_t sp2 = sp1 == std::string_view::npos ? sp1 : line.find(' ', sp1 + 1);
      head.method = std::string(line.substr(0, sp1));
      if (sp1 != std::string_view::npos) head.target = std::string(line.substr(sp1 + 1, sp2 - sp1 - 1));
    } else if (const size_t colon = line.find(':'); colon != std::string_view::npos) {
      const std::string_view name = trim(line.substr(0, colon)), value = trim(line.substr(colon + 1));
      head.headers.emplace_back(std::string(name), std::string(value));
      if (equalsIgnoringCase(name, "Content-Length")) {
        const auto n = decimal(value);
        // Two different lengths are as bad as one unreadable length (request smuggling).
        if (!n || (head.contentLength && *head.contentLength != *n)) head.bodyLengthInvalid = true;
        else head.contentLength = n;
      } else if (equalsIgnoringCase(name, "Transfer-Encoding")) {
        head.chunked = head.chunked || containsIgnoringCase(value, "chunked");
      } else if (equalsIgnoringCase(name, "Expect") && equalsIgnoringCase(value, "100-continue")) {
        head.expectContinue = true;
        head.expectBegin = lineBegin;
        head.expectEnd = lineEnd + 2;
      }
    }
    lineBegin = lineEnd + 2;
  }
  return head;
}

std::optional<size_t> chunkedBodyBytes(std::string_view bytes) {
  size_t at = 0;
  for (;;) {
    const size_t lineEnd = bytes.find("\r\n", at);
    if (lineEnd == std::string_view::npos) return std::nullopt;
    // "1a;name=value": the size in hex, then extensions.
    const std::string_view line = bytes.substr(at, lineEnd - at);
    const std::string_view sizeText = trim(line.substr(0, line.find(';')));
    size_t size = 0;
    if (sizeText.empty() || sizeText.size() > 15) return lineEnd + 2;  // malformed: the reader finds it
    for (char c : sizeText) {
      const int d = std::isdigit(static_cast<unsigned char>(c)) ? c - '0'
                    : (c >= 'a' && c <= 'f')                   ? c - 'a' + 10
                    : (c >= 'A' && c <= 'F')                   ? c - 'A' + 10
                                                               : -1;
      if (d < 0) return lineEnd + 2;
      size = size * 16 + static_cast<size_t>(d);
    }
    at = lineEnd + 2;
    if (size == 0) {
      // The trailer: header lines, then a blank line.
      for (;;) {
        const size_t e = bytes.find("\r\n", at);
        if (e == std::string_view::npos) return std::nullopt;
        const bool blank = e == at;
        at = e + 2;
        if (blank) return at;
      }
    }
    if (bytes.size() - at < size + 2) return std::nullopt;
    at += size + 2;  // the data and its CRLF
  }
}

}  // namespace fsdb
