// See server/http/response_encoding.h.
#include "server/http/response_encoding.h"

#include <zlib.h>

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace fsdb {
namespace {

std::string trimmed(const std::string& s, size_t from, size_t to) {
  while (from < to && std::isspace(static_cast<unsigned char>(s[from]))) ++from;
  while (to > from && std::isspace(static_cast<unsigned char>(s[to - 1]))) --to;
  return s.substr(from, to - from);
}

std::string withoutWeakPrefix(const std::string& tag) { return tag.rfind("W/", 0) == 0 ? tag.substr(2) : tag; }

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::string entityTag(const std::string& body) {
  uint64_t h = 1469598103934665603ull;  // FNV-1a, 64 bits
  for (unsigned char c : body) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, "W/\"%016llx\"", static_cast<unsigned long long>(h));
  return buf;
}

bool ifNoneMatchHits(const std::string& header, const std::string& tag) {
  const std::string want = withoutWeakPrefix(tag);
  size_t start = 0;
  while (start <= header.size()) {
    size_t end = header.find(',', start);
    if (end == std::string::npos) end = header.size();
    const std::string item = trimmed(header, start, end);
    if (item == "*" || (!item.empty() && withoutWeakPrefix(item) == want)) return true;
    start = end + 1;
  }
  return false;
}

bool acceptsGzip(const std::string& header) {
  size_t start = 0;
  while (start <= header.size()) {
    size_t end = header.find(',', start);
    if (end == std::string::npos) end = header.size();
    const std::string item = lower(trimmed(header, start, end));
    const size_t semi = item.find(';');
    const std::string coding = trimmed(item, 0, semi == std::string::npos ? item.size() : semi);
    if (coding == "gzip" || coding == "*") {
      if (semi == std::string::npos) return true;
      const size_t q = item.find("q=", semi);
      return q == std::string::npos || std::strtod(item.c_str() + q + 2, nullptr) > 0;
    }
    start = end + 1;
  }
  return false;
}

bool compressedHere(const std::string& contentType) {
  return contentType.rfind("model/", 0) == 0 || contentType.rfind("application/octet-stream", 0) == 0;
}

std::string gzipBody(const std::string& bytes) {
  z_stream z{};
  // windowBits 15 + 16: a gzip header and trailer around the deflate stream.
  if (deflateInit2(&z, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("zlib: deflateInit2 failed");
  std::string out(deflateBound(&z, static_cast<uLong>(bytes.size())) + 32, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int rc = deflate(&z, Z_FINISH);
  const size_t written = z.total_out;
  deflateEnd(&z);
  if (rc != Z_STREAM_END) throw std::runtime_error("zlib: deflate did not finish");
  out.resize(written);
  return out;
}

std::string contentDisposition(const std::string& type, const std::string& filename) {
  std::string plain;
  std::string encoded;
  for (unsigned char c : filename) {
    const bool alnum = (c >= '0' && c <= '9') || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
    plain += alnum || c == ' ' || c == '.' || c == '_' || c == '-' || c == '+' || c == '(' || c == ')'
                 ? static_cast<char>(c)
                 : '_';
    // RFC 5987 attr-char: ALPHA DIGIT ! # $ & + - . ^ _ ` | ~; every other byte percent-encoded.
    if (alnum || (c != 0 && std::strchr("!#$&+-.^_`|~", c) != nullptr)) {
      encoded += static_cast<char>(c);
    } else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      encoded += hex;
    }
  }
  return type + "; filename=\"" + plain + "\"; filename*=UTF-8''" + encoded;
}

}  // namespace fsdb
