// See geometry/field/shared_field.h.
#include "geometry/field/shared_field.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <mutex>

namespace fsdb {

struct SharedField::Remembered {
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

namespace {

bool same(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

}  // namespace

SharedField::SharedField(std::shared_ptr<const AlphaFieldSource> source) : source_(std::move(source)) {}

SharedField::~SharedField() = default;

SharedField::Remembered& SharedField::memory() const {
  const std::thread::id me = std::this_thread::get_id();
  {
    std::shared_lock<std::shared_mutex> lock(mutex_);
    auto it = memory_.find(me);
    if (it != memory_.end()) return *it->second;
  }
  std::unique_lock<std::shared_mutex> lock(mutex_);
  auto& entry = memory_[me];
  if (!entry) entry = std::make_unique<Remembered>();
  return *entry;  // never moved: the map holds it by pointer
}

// Each method reads its entry before the source's call and writes it after: the call may
// evaluate this field again on this thread only through another parent, for another point.
AlphaLevels SharedField::levelsAt(const Vec3& p) const {
  Remembered& m = memory();
  if (m.hasPoint && same(m.point, p)) return m.levels;
  const AlphaLevels levels = source_->levelsAt(p);
  m.point = p;
  m.levels = levels;
  m.hasPoint = true;
  return levels;
}

AlphaLevelBounds SharedField::boundsOver(const Vec3& lo, const Vec3& hi) const {
  Remembered& m = memory();
  if (m.hasBox && same(m.lo, lo) && same(m.hi, hi)) return m.bounds;
  const AlphaLevelBounds bounds = source_->boundsOver(lo, hi);
  m.lo = lo;
  m.hi = hi;
  m.bounds = bounds;
  m.hasBox = true;
  return bounds;
}

void SharedField::sampleBlock(const BlockLattice& b, AlphaLevels* out) const {
  Remembered& m = memory();
  if (m.hasBlock && m.lattice.samePoints(b)) {
    std::copy(m.block->begin(), m.block->end(), out);
    return;
  }
  source_->sampleBlock(b, out);
  if (!m.block) m.block = std::make_unique<std::array<AlphaLevels, BlockLattice::kSize>>();
  std::copy(out, out + BlockLattice::kSize, m.block->begin());
  m.lattice = b;
  m.lattice.checkpoint = nullptr;  // the build's, gone with it
  m.hasBlock = true;
}

void SharedField::boundingBox(Vec3* lo, Vec3* hi) const {
  std::call_once(boxOnce_, [this] { source_->boundingBox(&boxLo_, &boxHi_); });
  *lo = boxLo_;
  *hi = boxHi_;
}

std::uint64_t SharedField::budgetExhaustions() const {
  const std::shared_ptr<const AlphaFieldSource> only[] = {source_};
  return sumBudgetExhaustions(only);
}

}  // namespace fsdb
