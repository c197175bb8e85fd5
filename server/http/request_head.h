#pragma once
// brief: Finds where an HTTP/1.1 request's head and body end in the bytes received so far, so the
// connection front (server/http/connection_front.h) can tell a whole request from part of one
// without a worker.
// note: Lenient on purpose: it reads only what it needs to find the ends (the request line's method
// and target, Content-Length, Transfer-Encoding, Expect, Authorization). Parsing proper, and the
// 400 for a malformed head, stay with cpp-httplib, which reads the same bytes afterwards.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fsdb {

struct RequestHead {
  std::string method;  // "GET"; as sent
  std::string target;  // "/parts/3?x=1"; as sent
  std::vector<std::pair<std::string, std::string>> headers;  // name and value, trimmed, as sent
  size_t headBytes = 0;                                      // through the blank line ending the head
  // Content-Length when present and a plain decimal number; bodyLengthInvalid when present but not.
  std::optional<size_t> contentLength;
  bool bodyLengthInvalid = false;
  bool chunked = false;  // Transfer-Encoding names chunked: the body ends with its zero-size chunk
  // An "Expect: 100-continue" line (any case): the client waits for "100 Continue" before its body.
  // Its bytes [expectBegin, expectEnd) in the buffer, so the front can answer it and take it out.
  bool expectContinue = false;
  size_t expectBegin = 0, expectEnd = 0;

  // The first value of header `name` (case-insensitive); "" when absent.
  std::string header(std::string_view name) const;
  // The target's path: up to '?' or '#'.
  std::string path() const;
};

// The head at the start of `bytes`, once its blank line ("\r\n\r\n") has arrived; nullopt before.
// `searchFrom` lets a caller that appends skip what it searched before (pass the previous size;
// the function backs up 3 bytes itself).
std::optional<RequestHead> scanRequestHead(std::string_view bytes, size_t searchFrom = 0);

// How many bytes of `bytes` a chunked body takes, its last chunk and trailer included, when all of
// it has arrived; nullopt while it has not. A malformed chunk size ends the scan (returns the bytes
// up to it): the body's reader then finds the fault and answers 400.
std::optional<size_t> chunkedBodyBytes(std::string_view bytes);

}  // namespace fsdb
