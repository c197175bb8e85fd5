#pragma once
// AlphaField: the exact alpha-cut description of a fuzzy solid, point by point (docs/api.md §3).
//
// A fuzzy solid has, at every level α in [0,1], an upper shape upper(α) (points possibly
// inside) and a lower shape lower(α) (points necessarily inside), with
//   lower(α) ⊆ S(core) ⊆ upper(α),  upper(α) shrinking and lower(α) growing as α rises
// (the parameter box P(α) shrinks with α; Zhang, Pham & Chen, §3.2). So each point p is described
// for every α at once by two numbers:
//   upper level u(p) = sup{α : p ∈ upper(α)}   in [0,1]; 0 when p is in upper(0) at most
//                      (p ∈ upper(α) ⇔ α ≤ u(p), up to the boundary of a level set)
//   lower level l(p) = inf{α : p ∈ lower(α)}   in [0,1], or kNeverInside when p ∉ lower(1)
//                      (p ∈ lower(α) ⇔ l(p) ≤ α)
// Points outside upper(0) have u = 0 and l = kNeverInside: the background of sparse grids.
//
// Booleans act on (u, l) exactly, for every α at once (docs/api.md §3: union (lower_A ∪ lower_B,
// upper_A ∪ upper_B), intersection likewise with ∩, difference A − B = (lower_A − upper_B,
// upper_A − lower_B)):
//   union:        u = max(uA, uB),  l = min(lA, lB)
//   intersection: u = min(uA, uB),  l = max(lA, lB)
//   difference:   u = min(uA, lB),  l = max(lA, uB)   (p ∉ lower_B(α) ⇔ α < lB; p ∉ upper_B(α) ⇔ α > uB)
//                 except l = kNeverInside where uB = 1: p ∈ upper_B(α) for every α, so p is in
//                 no lower_A(α) − upper_B(α), not even at α = 1 (max(lA, 1) = 1 would claim it)
// The difference is exact except on the single level α = uB itself when 0 < uB < 1 (a point
// counts as necessarily inside from α = uB on, instead of just above it): a set of measure zero
// in α, and for one requested α a set of measure zero in space; volumes are unaffected.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <unordered_set>

#include "geometry/core/vec3.h"

namespace fsdb {

// l(p) of a point that is not even in lower(1).
inline constexpr float kNeverInside = 2.0f;

struct AlphaLevels {
  float upper = 0.0f;          // u(p)
  float lower = kNeverInside;  // l(p)
};

inline AlphaLevels alphaUnion(AlphaLevels a, AlphaLevels b) {
  return {a.upper > b.upper ? a.upper : b.upper, a.lower < b.lower ? a.lower : b.lower};
}
inline AlphaLevels alphaIntersection(AlphaLevels a, AlphaLevels b) {
  return {a.upper < b.upper ? a.upper : b.upper, a.lower > b.lower ? a.lower : b.lower};
}
inline AlphaLevels alphaDifference(AlphaLevels a, AlphaLevels b) {
  const float u = a.upper < b.lower ? a.upper : b.lower;
  // p ∉ upper_B(α) ⇔ α > uB, strictly: when uB = 1 (p in B's core shape) no level is left, so
  // p is never necessarily inside A − B. Without this, crisp A − B would keep A ∩ B at α = 1.
  const float l = b.upper >= 1.0f ? kNeverInside : (a.lower > b.upper ? a.lower : b.upper);
  // When u = 0 the point is outside upper(α) for every α > 0; at most lower(α) empties too.
  return {u < 0.0f ? 0.0f : (u > 1.0f ? 1.0f : u), l};
}

// Membership at one level.
inline bool inUpper(AlphaLevels v, double alpha) { return v.upper > 0.0f && alpha <= v.upper; }
inline bool inLower(AlphaLevels v, double alpha) { return v.lower <= alpha; }

// Bounds of (u, l) over a box of points, for block pruning: a source proves a whole block
// uniform when upperMin == upperMax and lowerMin == lowerMax.
struct AlphaLevelBounds {
  float upperMin = 0.0f, upperMax = 1.0f;
  float lowerMin = 0.0f, lowerMax = kNeverInside;
  bool uniform() const { return upperMin == upperMax && lowerMin == lowerMax; }
};

// The voxel centres of one 8³ block, per axis: voxel (i, j, k) of the block is the point
// (x[i], y[j], z[k]), and its levels go to index (i·8 + j)·8 + k (OpenVDB's leaf order). The
// block's box of centres is [(x[0], y[0], z[0]), (x[7], y[7], z[7])] (coordinates increase).
// `checkpoint` is the running check of the build that asks for the block (its deadline), or
// null: a source whose voxels cost much (a fuzzy part's searches) calls check() between them, and
// whatever it throws stops the build, which then keeps nothing of the block. Without it a build
// could run past its deadline by one block's samples, seconds for a part with every value fuzzy.
struct BlockLattice {
  static constexpr int kDim = 8;
  static constexpr int kSize = kDim * kDim * kDim;
  double x[kDim], y[kDim], z[kDim];
  const std::function<void()>* checkpoint = nullptr;
  Vec3 lo() const { return {x[0], y[0], z[0]}; }
  Vec3 hi() const { return {x[kDim - 1], y[kDim - 1], z[kDim - 1]}; }
  Vec3 at(int i, int j, int k) const { return {x[i], y[j], z[k]}; }
  void check() const {
    if (checkpoint && *checkpoint) (*checkpoint)();
  }
  // The same voxel centres (whatever the checkpoint).
  bool samePoints(const BlockLattice& o) const {
    return std::equal(x, x + kDim, o.x) && std::equal(y, y + kDim, o.y) && std::equal(z, z + kDim, o.z);
  }
};

// Directed conversions of a level to float storage: u rounds down and l up, so that the stored
// upper(α) and lower(α) only shrink.
inline float floatDown(double v) {
  const float f = static_cast<float>(v);
  return static_cast<double>(f) > v ? std::nextafter(f, -1.0f) : f;
}
inline float floatUp(double v) {
  const float f = static_cast<float>(v);
  return static_cast<double>(f) < v ? std::nextafter(f, 2.0f) : f;
}

// A fuzzy solid as the voxel evaluator sees it. Implementations: fuzzy superquadric parts
// (geometry/field/fuzzy_part_field.h) and analytic test solids. Every call is thread-safe.
class AlphaFieldSource {
 public:
  virtual ~AlphaFieldSource() = default;
  // Exact levels at a point (to the documented tolerance of the implementation).
  virtual AlphaLevels levelsAt(const Vec3& p) const = 0;
  // Guaranteed bounds of the levels over the axis-aligned box [lo, hi].
  virtual AlphaLevelBounds boundsOver(const Vec3& lo, const Vec3& hi) const = 0;
  // An axis-aligned box that holds upper(0) (everything outside has u = 0, l = never).
  virtual void boundingBox(Vec3* lo, Vec3* hi) const = 0;
  // The levels of the 8³ voxels of a block (out[(i·8 + j)·8 + k] = levelsAt(b.at(i, j, k)), the
  // same values). The default asks levelsAt voxel by voxel, with b.check() before each row;
  // implementations override it to share work across the block (CSG nodes drop the children
  // that cannot matter there) and call b.check() between their costly voxels.
  virtual void sampleBlock(const BlockLattice& b, AlphaLevels* out) const {
    for (int i = 0; i < BlockLattice::kDim; ++i)
      for (int j = 0; j < BlockLattice::kDim; ++j) {
        b.check();  // a row of levelsAt may be a row of fuzzy searches (a smooth node's children)
        for (int k = 0; k < BlockLattice::kDim; ++k)
          out[(i * BlockLattice::kDim + j) * BlockLattice::kDim + k] = levelsAt(b.at(i, j, k));
      }
  }
  // How many point searches ran out of their budget since construction and answered with a
  // conservative bound instead of the level to the tolerance (upper too high, lower too low):
  // fuzzy parts count theirs (geometry/field/fuzzy_part_field.h), CSG nodes report the sum over their
  // children (sumBudgetExhaustions: a node shared in a DAG counts once), exact sources 0. A caller
  // that wants the count of one evaluation takes the difference before and after it.
  virtual std::uint64_t budgetExhaustions() const { return 0; }
};

// The sum of budgetExhaustions() over a node's children (shared pointers to sources), each
// distinct source of the whole call once: a DAG's shared nodes are visited once, so the count of a
// shape naming the previous one twice, 30 deep, takes 30 steps, not 2^30. The outermost call on
// a thread keeps the set of sources visited; the nested calls of the children's own sums use it.
template <class Children>
std::uint64_t sumBudgetExhaustions(const Children& children) {
  thread_local std::unordered_set<const AlphaFieldSource*>* visited = nullptr;
  std::unordered_set<const AlphaFieldSource*> own;
  const bool outermost = visited == nullptr;
  if (outermost) visited = &own;
  struct Reset {
    bool outermost;
    std::unordered_set<const AlphaFieldSource*>** visited;
    ~Reset() {
      if (outermost) *visited = nullptr;
    }
  } reset{outermost, &visited};
  std::uint64_t n = 0;
  for (const auto& child : children)
    if (visited->insert(&*child).second) n += child->budgetExhaustions();
  return n;
}

}  // namespace fsdb
