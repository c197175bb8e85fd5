// See geometry/field/shared_field.h.
#include "geometry/field/shared_field.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstring>
#include <unordered_map>

namespace fsdb {
namespace {

struct Remembered {
  bool hasPoint = false;
  Vec3 point;
  AlphaLevels levels;
  bool hasBox = false;
  Vec3 lo, hi;
  AlphaLevelBounds bounds;
  bool hasBlock = false;
  BlockLattice lattice;
  std::unique_ptr<std::array<AlphaLevels, BlockLattice::kSize>> block;  // made on the first block
};

// Beyond this many SharedFields seen by one thread (those of evaluations long done among them),
// its memory starts again: a cost of one recomputation each, never a wrong answer.
constexpr size_t kRememberedFields = 4096;

Remembered& memoryOf(std::uint64_t id) {
  thread_local std::unordered_map<std::uint64_t, Remembered> memory;
  if (memory.size() >= kRememberedFields && memory.find(id) == memory.end()) memory.clear();
  return memory[id];
}

bool same(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

}  // namespace

SharedField::SharedField(std::shared_ptr<const AlphaFieldSource> source) : source_(std::move(source)) {
  static std::atomic<std::uint64_t> next{1};
  id_ = next.fetch_add(1, std::memory_order_relaxed);
}

// Each method looks its memory up again after the source's call: that call may evaluate other
// SharedFields of this thread, and a start-over of the memory (kRememberedFields) frees entries.
AlphaLevels SharedField::levelsAt(const Vec3& p) const {
  {
    const Remembered& m = memoryOf(id_);
    if (m.hasPoint && same(m.point, p)) return m.levels;
  }
  const AlphaLevels levels = source_->levelsAt(p);
  Remembered& m = memoryOf(id_);
  m.point = p;
  m.levels = levels;
  m.hasPoint = true;
  return levels;
}

AlphaLevelBounds SharedField::boundsOver(const Vec3& lo, const Vec3& hi) const {
  {
    Remembered& m = memoryOf(id_);
    if (m.hasBox && same(m.lo, lo) && same(m.hi, hi)) return m.bounds;
  }
  const AlphaLevelBounds bounds = source_->boundsOver(lo, hi);
  Remembered& m = memoryOf(id_);
  m.lo = lo;
  m.hi = hi;
  m.bounds = bounds;
  m.hasBox = true;
  return bounds;
}

void SharedField::sampleBlock(const BlockLattice& b, AlphaLevels* out) const {
  {
    Remembered& m = memoryOf(id_);
    if (m.hasBlock && std::memcmp(&m.lattice, &b, sizeof b) == 0) {
      std::copy(m.block->begin(), m.block->end(), out);
      return;
    }
  }
  source_->sampleBlock(b, out);
  Remembered& m = memoryOf(id_);
  if (!m.block) m.block = std::make_unique<std::array<AlphaLevels, BlockLattice::kSize>>();
  std::copy(out, out + BlockLattice::kSize, m.block->begin());
  m.lattice = b;
  m.hasBlock = true;
}

std::uint64_t SharedField::budgetExhaustions() const {
  const std::shared_ptr<const AlphaFieldSource> only[] = {source_};
  return sumBudgetExhaustions(only);
}

}  // namespace fsdb
