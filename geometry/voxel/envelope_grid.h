#pragma once
// EnvelopeGrid: a fuzzy solid sampled on a sparse voxel grid, as two OpenVDB float grids over one
// shared topology (the voxel layer; docs/api.md §3 and §4):
//   "upper" holds u(p) (background 0), "lower" holds l(p) (background kNeverInside), with u, l
//   and the Booleans as defined in geometry/field/alpha_field.h.
// Lattice: cell-centred. Voxel (i, j, k) is the cube [i·h, (i+1)·h] × ... and is sampled at its
// centre ((i+½)·h, (j+½)·h, (k+½)·h); the openvdb transform says the same (scale h, shift h/2),
// so meshes and .vdb files come out in world coordinates.
// Sparsity: 8³ blocks (OpenVDB leaves) whose levels a source proves uniform are stored as one
// active tile (or nothing, when uniform at the background); only the rest holds voxels. Upper
// and lower share one topology, so a voxel or tile is active in both grids or in neither; the
// pruning is done on both at once for that reason.
// A grid is immutable once built; copies share it, and every const member is thread-safe.
// OpenVDB types stay out of this header: geometry/voxel/envelope_grid_vdb.h hands out the grids.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "geometry/field/alpha_field.h"
#include "geometry/core/vec3.h"

namespace fsdb {

// The fuzzy volume at one level (docs/api.md §3): [vol(lower(α)), vol(upper(α))].
struct LevelVolume {
  double alpha = 0.0;
  double lower_volume = 0.0;
  double upper_volume = 0.0;
};

struct EnvelopeGridStats {
  std::uint64_t activeVoxels = 0;  // voxels stored one by one (in leaves), per grid
  std::uint64_t activeTiles = 0;   // tiles, each standing for 8³ or 128³ voxels of one value
  std::uint64_t tileVoxels = 0;    // voxels covered by those tiles
  std::uint64_t leafCount = 0;     // 8³ leaves, per grid
  std::size_t memoryBytes = 0;     // both grids, as openvdb's memUsage() reports
  double buildMillis = 0.0;        // wall time of build() or combine()
};

enum class BooleanOp { kUnion, kIntersection, kDifference };

// Limits of one build, so that a caller (a server thread) gets control back from a build that
// would take too much memory or time. Both are checked while the build runs; a build that stops
// throws and keeps nothing (the leaves made so far are freed, no grid is returned).
struct EnvelopeBuildLimits {
  // Most bytes of 8³ leaves, both grids together (leafPairBytes() per leaf pair); 0: no limit.
  // Exceeded: Error(limit_exceeded, ..., kMaxLeafBytesPath) as soon as the leaf that would pass
  // it is about to be made.
  std::uint64_t maxLeafBytes = 0;
  // Checked before every 8³ block is sampled (every TBB task checks it), and by a source between
  // its costly voxels (BlockLattice::checkpoint: a fuzzy part before each voxel's search), so a
  // build stops within about one voxel's search past it: Error(limit_exceeded, ..., kDeadlinePath).
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  // Called with leafPairBytes() before each leaf pair is made (from any task of the build), so a
  // caller can hold the memory to a budget shared with other builds; whatever it throws stops
  // the build like the limits above. Empty: nothing to call.
  std::function<void(std::uint64_t)> reserveLeafBytes;
};
inline constexpr const char* kMaxLeafBytesPath = "max_leaf_bytes";
inline constexpr const char* kDeadlinePath = "deadline";

class EnvelopeGrid {
 public:
  // Samples `source` at voxel size h over its bounding box padded by one voxel, in parallel
  // (TBB). Throws Error(invalid_parameter, "voxel_size") unless h is finite and positive and
  // the box fits the index range of openvdb coordinates at that size; the errors of `limits`.
  static EnvelopeGrid build(const AlphaFieldSource& source, double voxelSize,
                            const EnvelopeBuildLimits& limits = {});
  // Bytes of one leaf in each of the two grids (a voxel block of 8³ levels), as openvdb's own
  // memUsage() counts them (the counting of stats().memoryBytes): what maxLeafBytes is made of.
  static std::uint64_t leafPairBytes();

  double voxelSize() const;
  // Levels of the voxel that holds p (nearest voxel centre); the background far away.
  AlphaLevels levelsAt(const Vec3& p) const;
  // Voxels stored one by one (tiles not counted): grows like the fuzzy region's volume, and
  // like the surface for a crisp solid. docs/api.md §4 "active_voxels".
  std::uint64_t activeVoxelCount() const;
  const EnvelopeGridStats& stats() const;

  // For each α (any order, repeats allowed; answered in the given order):
  //   lower_volume = h³·#{voxels with l ≤ α},  upper_volume = h³·#{voxels with u ≥ α, u > 0},
  // tile voxels included, in one pass over the grids for all levels at once.
  std::vector<LevelVolume> volumes(const std::vector<double>& alphas) const;

  // The openvdb grids behind this object: opaque unless geometry/voxel/envelope_grid_vdb.h is included.
  struct Impl;
  const Impl& impl() const { return *impl_; }
  explicit EnvelopeGrid(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

 private:
  std::shared_ptr<const Impl> impl_;
};

// The Boolean of two grids of the same voxel size, voxel by voxel with the exact formulas of
// alpha_field.h, over the region where the result can differ from the background (union: both
// grids' active boxes; intersection: their overlap; difference: a's box). Where one side has no
// voxels its background or tile value enters the formula, so a − (nothing) = a exactly.
// Throws Error(invalid_parameter, "voxel_size") when the voxel sizes differ (no resampling).
EnvelopeGrid combine(const EnvelopeGrid& a, const EnvelopeGrid& b, BooleanOp op);

}  // namespace fsdb
