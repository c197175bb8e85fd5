// tuneAllocatorForServing (server/cli/allocator.h): what it sets, that the mmap threshold stays
// pinned after large blocks are freed (glibc would otherwise raise it), and that the user's
// environment wins.
#include "server/cli/allocator.h"

#include <gtest/gtest.h>
#include <malloc.h>

#include <cstdlib>
#include <cstring>
#include <thread>

namespace fsdb {
namespace {

class AllocatorTest : public ::testing::Test {
 protected:
  void SetUp() override {
#ifdef FSDB_SANITIZE
    GTEST_SKIP() << "a sanitizer's allocator replaces glibc's (SanitizerAllocatorIsLeftAsItIs)";
#endif
    unsetenv("MALLOC_ARENA_MAX");
    unsetenv("MALLOC_MMAP_THRESHOLD_");
  }
};

#ifdef FSDB_SANITIZE
TEST(AllocatorSanitized, SanitizerAllocatorIsLeftAsItIs) {
  const AllocatorSettings s = tuneAllocatorForServing(2);
  EXPECT_EQ(s.arenaMax, 0);
  EXPECT_EQ(s.mmapThreshold, 0u);
  EXPECT_NE(s.description.find("sanitizer"), std::string::npos) << s.description;
}
#endif

// Blocks mapped on their own right now (glibc's count).
std::size_t mappedBlocks() { return mallinfo2().hblks; }

// Allocates `bytes`, touches them, and says whether the block was mapped on its own.
bool mappedOnItsOwn(std::size_t bytes) {
  const std::size_t before = mappedBlocks();
  char* p = static_cast<char*>(std::malloc(bytes));
  std::memset(p, 1, bytes);
  asm volatile("" : : "r"(p) : "memory");  // the block escapes: the compiler may not drop the pair
  const bool mapped = mappedBlocks() == before + 1;
  std::free(p);
  return mapped;
}

TEST_F(AllocatorTest, CapsTheArenasAndPinsTheMmapThreshold) {
  const AllocatorSettings s = tuneAllocatorForServing(1);
  EXPECT_EQ(s.arenaMax, 2);  // never fewer than two
  EXPECT_EQ(s.mmapThreshold, kServingMmapThreshold);
  EXPECT_NE(s.description.find("arenas at most 2"), std::string::npos) << s.description;
  EXPECT_NE(s.description.find("1 MiB"), std::string::npos) << s.description;
  EXPECT_EQ(tuneAllocatorForServing(6).arenaMax, 6);
}

TEST_F(AllocatorTest, LargeBlocksStayMappedAfterLargerOnesAreFreed) {
  tuneAllocatorForServing(2);
  EXPECT_TRUE(mappedOnItsOwn(2 * kServingMmapThreshold));
  // Left to itself, glibc would now raise its threshold to 24 MiB, and the next 2 MiB block would
  // come from an arena and stay there after it is freed.
  EXPECT_TRUE(mappedOnItsOwn(24 * kServingMmapThreshold));
  EXPECT_TRUE(mappedOnItsOwn(2 * kServingMmapThreshold));
  // The same from another thread (another arena).
  bool mapped = false;
  std::thread([&] { mapped = mappedOnItsOwn(2 * kServingMmapThreshold); }).join();
  EXPECT_TRUE(mapped);
  EXPECT_FALSE(mappedOnItsOwn(kServingMmapThreshold / 4));  // small blocks come from an arena
}

TEST_F(AllocatorTest, LeavesWhatTheEnvironmentSays) {
  setenv("MALLOC_ARENA_MAX", "3", 1);
  setenv("MALLOC_MMAP_THRESHOLD_", "65536", 1);
  const AllocatorSettings s = tuneAllocatorForServing(8);
  unsetenv("MALLOC_ARENA_MAX");
  unsetenv("MALLOC_MMAP_THRESHOLD_");
  EXPECT_EQ(s.arenaMax, 0);
  EXPECT_EQ(s.mmapThreshold, 0u);
  EXPECT_NE(s.description.find("as MALLOC_ARENA_MAX says"), std::string::npos) << s.description;
  EXPECT_NE(s.description.find("as MALLOC_MMAP_THRESHOLD_ says"), std::string::npos) << s.description;
}

}  // namespace
}  // namespace fsdb
