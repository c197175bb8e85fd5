#pragma once
// SharedField: a node of a CSG DAG that several parents name (a stored shape referenced twice,
// parsed once), evaluated once per point, box or block however many parents ask.
//
// Without it a DAG costs its expansion at every point: a shape naming the previous one twice,
// 16 levels deep, asks its bottom part 65,536 times per voxel (10 s for 16³ voxels; 30 levels
// would never end). The Booleans of alpha_field.h read each child once per call, so what a
// shared node answered for the call just made is what its next parent in the same call needs:
// the voxel layer evaluates a block depth first, and every parent of a shared node asks it
// for the same block (sampleBlock), box (boundsOver) or point (levelsAt) in turn.
//
// Contract:
// - The same answers as the wrapped source, call for call (it forwards, or repeats the answer
//   the source gave to the same arguments on this thread).
// - Per thread that calls it, it remembers its last point, box and block and their answers;
//   that is all the memory it takes (a block's answer: 4 KiB, made on its first block), and it
//   goes with the SharedField. Thread-safe like every AlphaFieldSource: each thread reads and
//   writes only its own entry (found under a shared lock, added under an exclusive one). (A
//   first version kept the entries in thread-local maps keyed by an id: they outlived their
//   fields, up to 4096 per thread, and the soak's RSS grew with every evaluation.)
// - boundingBox is the source's, asked once and kept (a smooth node's box asked its children's
//   every time, so a DAG of them cost its expansion for one box: 24 levels 1.3 s at 16³, doubling
//   with each level). budgetExhaustions forwards (counted once per source however many parents
//   share it: sumBudgetExhaustions).
#include <cstdint>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <thread>
#include <unordered_map>

#include "geometry/field/alpha_field.h"

namespace fsdb {

class SharedField : public AlphaFieldSource {
 public:
  explicit SharedField(std::shared_ptr<const AlphaFieldSource> source);
  ~SharedField() override;

  AlphaLevels levelsAt(const Vec3& p) const override;
  AlphaLevelBounds boundsOver(const Vec3& lo, const Vec3& hi) const override;
  void boundingBox(Vec3* lo, Vec3* hi) const override;
  void sampleBlock(const BlockLattice& b, AlphaLevels* out) const override;
  std::uint64_t budgetExhaustions() const override;

  const AlphaFieldSource& source() const { return *source_; }

 private:
  struct Remembered;
  Remembered& memory() const;  // this thread's entry

  std::shared_ptr<const AlphaFieldSource> source_;
  mutable std::once_flag boxOnce_;  // the source's box, asked once: a node's box asks its children's
  mutable Vec3 boxLo_, boxHi_;
  mutable std::shared_mutex mutex_;
  mutable std::unordered_map<std::thread::id, std::unique_ptr<Remembered>> memory_;
};

}  // namespace fsdb
