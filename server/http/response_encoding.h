#pragma once
// What a browser needs of a GET answer beyond its body (RFC 9110 §8.8.3, §13.1.2; RFC 1952):
// an entity tag, a 304 for a client that already has the body, and gzip for the large binary
// exports that cpp-httplib does not compress itself (it gzips JSON, SVG and text on its own when
// the client accepts it).
//
// Contract:
// - entityTag(body) is a weak tag W/"<16 hex digits>" of the body's bytes (64-bit FNV-1a): the
//   same body, the same tag; weak, because one tag stands for the gzip and identity encodings.
// - ifNoneMatchHits(header, tag) follows the weak comparison of If-None-Match: "*" or any tag of
//   the comma-separated list equal to `tag` with or without its W/ prefix.
// - gzipBody(bytes) is a complete gzip member (deflate, default level) that gunzip restores to
//   `bytes`; acceptsGzip(header) reads Accept-Encoding (gzip with a q-value above 0).
// - compressedHere(contentType): the media types fsdb gzips itself: model/* (OBJ, STL, glTF) and
//   application/octet-stream (VDB grids).
// - contentDisposition(type, filename) is a Content-Disposition value (RFC 6266) for an object's
//   file: `type; filename="..."; filename*=UTF-8''...`. The quoted name keeps letters, digits,
//   space and . _ - + ( ) of the name and writes every other byte as _, so a quote, backslash,
//   semicolon or control byte in a stored name can end neither the string nor the header; the
//   RFC 5987 form carries the name's exact UTF-8 bytes, percent-encoded, for clients that read it.
#include <string>

namespace fsdb {

std::string entityTag(const std::string& body);
bool ifNoneMatchHits(const std::string& ifNoneMatch, const std::string& tag);

bool acceptsGzip(const std::string& acceptEncoding);
bool compressedHere(const std::string& contentType);
// Throws std::runtime_error only when zlib itself fails (out of memory).
std::string gzipBody(const std::string& bytes);

std::string contentDisposition(const std::string& type, const std::string& filename);

}  // namespace fsdb
