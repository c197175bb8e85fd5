// See db/content_hash.h.
#include "db/content_hash.h"

#include <cstdint>

namespace fsdb {

namespace {

constexpr uint64_t kFnvPrime = 0x100000001b3ULL;
constexpr uint64_t kFnvOffsetBasis = 0xcbf29ce484222325ULL;
// The low 64 bits of FNV-1a 128's offset basis: a published constant, not a made-up one.
constexpr uint64_t kSecondOffsetBasis = 0x62b821756295c58dULL;

template <class It>
uint64_t fnv1a(It begin, It end, uint64_t basis) {
  uint64_t hash = basis;
  for (It it = begin; it != end; ++it) {
    hash ^= static_cast<unsigned char>(*it);
    hash *= kFnvPrime;
  }
  return hash;
}

void appendHex(std::string& out, uint64_t value) {
  static const char kDigits[] = "0123456789abcdef";
  for (int shift = 60; shift >= 0; shift -= 4) out += kDigits[(value >> shift) & 0xf];
}

}  // namespace

std::string contentHash(const std::string& text) {
  std::string out;
  out.reserve(32);
  appendHex(out, fnv1a(text.begin(), text.end(), kFnvOffsetBasis));
  appendHex(out, fnv1a(text.rbegin(), text.rend(), kSecondOffsetBasis));
  return out;
}

}  // namespace fsdb
