#pragma once
// fsdb::Error: the one error type of every layer. It carries what the HTTP error body
// {"error":{"code","message","path"}} needs, so a failure deep in the math reaches the user
// with the name of the value that caused it. Geometry code sets `path` to a parameter name
// ("delta"); parsers prefix it with the JSON path of the enclosing object ("operator.delta").
#include <stdexcept>
#include <string>

namespace fsdb {

// Error codes. The server maps each to an HTTP status (see server/service/error_json.cpp).
namespace errc {
inline constexpr const char* kInvalidParameter = "invalid_parameter";  // 422
inline constexpr const char* kInvalidDocument = "invalid_document";    // 422
inline constexpr const char* kUnknownName = "unknown_name";            // 422
inline constexpr const char* kMalformedJson = "malformed_json";        // 400
inline constexpr const char* kLimitExceeded = "limit_exceeded";        // 413
inline constexpr const char* kNotFound = "not_found";                  // 404
inline constexpr const char* kDomainError = "domain_error";            // 422 (e.g. division by a number whose support holds 0)
// The store (db/) and the service (server/):
inline constexpr const char* kConflict = "conflict";                    // 409 (name taken, version mismatch)
inline constexpr const char* kInUse = "in_use";                         // 409 (delete of something still referenced)
inline constexpr const char* kUnknownReference = "unknown_reference";  // 422 (a reference to no stored part/shape)
inline constexpr const char* kReferenceCycle = "reference_cycle";      // 422 (a shape that would contain itself)
inline constexpr const char* kUnauthorized = "unauthorized";            // 401 (write without the bearer token)
inline constexpr const char* kUnsupportedMediaType = "unsupported_media_type";  // 415 (a multipart body)
inline constexpr const char* kStorage = "storage_error";                // 503 (database busy, disk full, I/O error)
inline constexpr const char* kOverloaded = "overloaded";                // 503 + Retry-After (the memory budget is spent)
inline constexpr const char* kPreconditionFailed = "precondition_failed";  // 412 (If-Match names a version the object moved past)
inline constexpr const char* kRequestTimeout = "request_timeout";      // 408 (a request's head or body arrived too slowly)
inline constexpr const char* kHeaderTooLarge = "header_too_large";     // 431 (a request head past its bound)
}  // namespace errc

class Error : public std::runtime_error {
 public:
  Error(std::string code, std::string message, std::string path = "")
      : std::runtime_error(message), code_(std::move(code)), path_(std::move(path)) {}

  const std::string& code() const { return code_; }
  const std::string& path() const { return path_; }

  // Returns the same error with `prefix` prepended to its path ("operator" + "delta" ->
  // "operator.delta"; "points" + "[3]" -> "points[3]").
  Error withPathPrefix(const std::string& prefix) const {
    std::string p = prefix;
    if (!path_.empty()) p += (path_[0] == '[' || prefix.empty()) ? path_ : "." + path_;
    return Error(code_, what(), p);
  }

 private:
  std::string code_;
  std::string path_;
};

}  // namespace fsdb
