// Whether ThreadSanitizer can check fsdb: a correct TBB program, built with -fsanitize=thread.
// Debian's libtbb is not built with TSan, so the synchronisation inside parallel_for and
// concurrent_hash_map is invisible to it and it reports races that are not there (with clang 14 and
// TBB 2021.8: 24 to 30 data race reports per run). fsdb evaluates, meshes and imports on TBB, so
// make test-sanitize has no TSan run; run this again when TBB or clang changes:
//   clang++ -std=c++17 -O1 -g -fsanitize=thread tests/sanitize/tsan_tbb_probe.cpp -ltbb -o /tmp/tsan_probe &&
//   /tmp/tsan_probe
// A usable TSan prints no WARNING.
#include <atomic>
#include <cstdio>
#include <tbb/concurrent_hash_map.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_pipeline.h>
#include <vector>
int main() {
  tbb::concurrent_hash_map<int, std::vector<int>> map;
  std::atomic<long> sum{0};
  tbb::parallel_for(0, 20000, [&](int i) {
    tbb::concurrent_hash_map<int, std::vector<int>>::accessor a;
    map.insert(a, i % 97);
    a->second.push_back(i);
    sum += i;
  });
  // A result handed from one task to the next through TBB's own synchronisation only.
  std::vector<int> results(1000);
  tbb::parallel_for(0, 1000, [&](int i) { results[i] = i * 2; });
  long total = 0;
  for (int v : results) total += v;
  std::printf("%ld %zu %ld\n", sum.load(), map.size(), total);
}
