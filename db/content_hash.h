#pragma once
// contentHash(text): a 128-bit digest of a document's text as 32 lowercase hex digits, for
// change detection (upsert idempotence) and evaluation cache keys.
//
// NOT cryptographic: anyone can construct collisions. It is two independent 64-bit FNV-1a
// hashes: the first is standard FNV-1a 64 over the bytes in order (so its 16 digits match the
// published FNV test vectors), the second FNV-1a 64 over the bytes in reverse order from a
// different offset basis; an accidental collision needs both to collide. The value is part of
// the stored data (versions.content_hash): never change the function.
#include <string>

namespace fsdb {

std::string contentHash(const std::string& text);

}  // namespace fsdb
