// See server/cli/allocator.h.
#include "server/cli/allocator.h"

#include <malloc.h>

#include <algorithm>
#include <cstdlib>

namespace fsdb {

namespace {

// The sanitizer build (FSDB_SANITIZE, CMakeLists.txt) replaces malloc with ASan's.
#ifdef FSDB_SANITIZE
constexpr bool kSanitizerAllocator = true;
#else
constexpr bool kSanitizerAllocator = false;
#endif

bool inEnvironment(const char* name) {
  const char* v = std::getenv(name);
  return v != nullptr && *v != '\0';
}

}  // namespace

AllocatorSettings tuneAllocatorForServing(unsigned cores) {
  AllocatorSettings s;
  if (kSanitizerAllocator) {
    s.description = "allocator left as it is (a sanitizer's allocator)";
    return s;
  }
  std::string parts;
  if (inEnvironment("MALLOC_ARENA_MAX")) {
    parts = "arenas as MALLOC_ARENA_MAX says";
  } else {
    const int arenas = static_cast<int>(std::max(2u, cores));
    if (mallopt(M_ARENA_MAX, arenas) == 1) {
      s.arenaMax = arenas;
      parts = "arenas at most " + std::to_string(arenas);
    }
  }
  if (!parts.empty()) parts += ", ";
  if (inEnvironment("MALLOC_MMAP_THRESHOLD_")) {
    parts += "mmap threshold as MALLOC_MMAP_THRESHOLD_ says";
  } else if (mallopt(M_MMAP_THRESHOLD, static_cast<int>(kServingMmapThreshold)) == 1) {
    // Setting it also stops glibc from raising it as large blocks are freed.
    s.mmapThreshold = kServingMmapThreshold;
    parts += "blocks of " + std::to_string(kServingMmapThreshold >> 20) + " MiB or more mapped on their own";
  }
  s.description = parts;
  return s;
}

}  // namespace fsdb
