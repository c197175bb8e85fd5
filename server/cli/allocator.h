#pragma once
// The C library allocator's settings for a long-running server (`fsdb serve`).
//
// Why: glibc gives each thread that meets a locked arena a new one, up to 8 per core, and each
// arena keeps the memory its thread freed for that arena's later use. The server's worker and
// grid threads each touch a few MiB at a time (an answer, a search's candidates, a 32³ grid),
// so the process's RSS became the sum of every arena's own high-water mark and crept up for
// minutes under a steady load (the soak, bench/soak.sh: 155 → 169 MiB in 60 s; a malloc_trim
// then gave back 25 MiB, and the same load re-took it in 10 s). glibc also raises its mmap
// threshold to the size of each large block freed (up to 32 MiB), after which large blocks come
// from an arena and stay there when freed.
//
// Contract:
// - tuneAllocatorForServing(cores) caps the arenas at max(2, cores) and pins the mmap threshold
//   at kServingMmapThreshold: blocks of that size or more are mapped on their own and given back
//   to the system when freed. Measured in the soak on 2 cores: RSS about 155 → 100 MiB after
//   the warm-up, reads at the same rate (docs/performance.md).
// - A setting the user gave in the environment (MALLOC_ARENA_MAX, MALLOC_MMAP_THRESHOLD_, which
//   glibc reads at start) is left as it is.
// - The answer says what was set, for the start-up log. Under a sanitizer's allocator (which
//   replaces malloc) nothing is set and the answer says so.
#include <cstddef>
#include <string>

namespace fsdb {

inline constexpr std::size_t kServingMmapThreshold = std::size_t(1) << 20;

struct AllocatorSettings {
  int arenaMax = 0;               // 0: left as it was
  std::size_t mmapThreshold = 0;  // 0: left as it was
  std::string description;        // one line, e.g. "arenas at most 2, blocks of 1 MiB or more mapped"
};

AllocatorSettings tuneAllocatorForServing(unsigned cores);

}  // namespace fsdb
