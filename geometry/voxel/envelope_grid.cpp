// EnvelopeGrid: build by hierarchical block pruning, Booleans, volumes (envelope_grid.h).
// The only translation unit of the library that includes OpenVDB: its headers are heavy.
#include "geometry/voxel/envelope_grid.h"

#include <openvdb/tree/LeafManager.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <utility>

#include "geometry/voxel/envelope_grid_vdb.h"
#include "geometry/core/error.h"

namespace fsdb {

void initializeOpenVdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

namespace {

using openvdb::Coord;
using openvdb::CoordBBox;
using openvdb::FloatGrid;
using openvdb::FloatTree;
using LeafT = FloatTree::LeafNodeType;
using Node1 = FloatTree::RootNodeType::ChildNodeType::ChildNodeType;  // 128³ voxels of 8³ tiles

constexpr int kLeafDim = static_cast<int>(LeafT::DIM);  // 8
constexpr int kSuperDim = 4 * kLeafDim;                 // 32: the middle level of the test
constexpr int kNodeDim = static_cast<int>(Node1::DIM);  // 128
constexpr int kLeafTileLevel = 1;                        // addTile level of an 8³ tile
constexpr int kNodeTileLevel = 2;                        // addTile level of a 128³ tile
// Index coordinates are 32-bit; stay well inside so that padding and alignment cannot overflow.
constexpr double kMaxIndex = 1 << 29;

bool isBackground(AlphaLevels v) { return v.upper == 0.0f && v.lower == kNeverInside; }
bool sameLevels(AlphaLevels a, AlphaLevels b) { return a.upper == b.upper && a.lower == b.lower; }

int floorTo(int v, int dim) { return v >= 0 ? v / dim * dim : -((-v + dim - 1) / dim * dim); }

// What the builder samples, in index space. Both calls are made concurrently.
class BlockSampler {
 public:
  virtual ~BlockSampler() = default;
  // True, with the value, when every voxel of `box` provably has the same levels.
  virtual bool uniformOver(const CoordBBox& box, AlphaLevels* value) const = 0;
  // The levels of the 8³ voxels of the leaf at `origin`, in leaf offset order; `checkpoint`
  // is the build's running check, for samplers whose voxels cost much (BlockLattice).
  virtual void sampleLeaf(const Coord& origin, AlphaLevels* out, const std::function<void()>& checkpoint) const = 0;
};

// The running checks of EnvelopeBuildLimits, shared by every task of one build. Throwing from a
// TBB task cancels the others and rethrows in the caller; each of them stops at its next check.
class BuildGuard {
 public:
  explicit BuildGuard(const EnvelopeBuildLimits& limits) : limits_(limits) {
    if (limits_.deadline != std::chrono::steady_clock::time_point::max()) checkpoint_ = [this] { checkTime(); };
  }
  BuildGuard(const BuildGuard&) = delete;
  BuildGuard& operator=(const BuildGuard&) = delete;
  void checkTime() const {
    if (limits_.deadline != std::chrono::steady_clock::time_point::max() &&
        std::chrono::steady_clock::now() > limits_.deadline)
      throw Error(errc::kLimitExceeded, "the grid build ran past its deadline", kDeadlinePath);
  }
  // checkTime for a source's block (BlockLattice::checkpoint); empty without a deadline.
  const std::function<void()>& checkpoint() const { return checkpoint_; }
  // Before a leaf pair is made: counts it, and throws when the leaves would pass the limit.
  void countLeafPair() {
    if (limits_.reserveLeafBytes) limits_.reserveLeafBytes(EnvelopeGrid::leafPairBytes());
    if (limits_.maxLeafBytes == 0) return;
    const std::uint64_t n = leafPairs_.fetch_add(1, std::memory_order_relaxed) + 1;
    if (n * EnvelopeGrid::leafPairBytes() > limits_.maxLeafBytes)
      throw Error(errc::kLimitExceeded,
                  "the grid needs more than " + std::to_string(limits_.maxLeafBytes) + " bytes of leaves (" +
                      std::to_string(n) + " leaf pairs of " + std::to_string(EnvelopeGrid::leafPairBytes()) +
                      " bytes so far)",
                  kMaxLeafBytesPath);
  }

 private:
  const EnvelopeBuildLimits& limits_;
  std::atomic<std::uint64_t> leafPairs_{0};
  std::function<void()> checkpoint_;
};

// One 8³ block of the result: a leaf pair, or (upper == nullptr) an active tile of value `tile`.
struct Block {
  Coord origin;
  AlphaLevels tile;
  std::unique_ptr<LeafT> upper, lower;
};

void buildLeafBlock(const BlockSampler& s, const Coord& origin, BuildGuard& guard, std::vector<Block>* out) {
  guard.checkTime();
  AlphaLevels v;
  if (s.uniformOver(CoordBBox::createCube(origin, kLeafDim), &v)) {
    if (!isBackground(v)) out->push_back({origin, v, nullptr, nullptr});
    return;
  }
  std::array<AlphaLevels, LeafT::SIZE> values;
  s.sampleLeaf(origin, values.data(), guard.checkpoint());
  bool constant = true, any = false;
  for (const AlphaLevels& x : values) {
    constant = constant && sameLevels(x, values[0]);
    any = any || !isBackground(x);
  }
  if (!any) return;
  // Joint leaf pruning: a leaf whose (u, l) pairs are all equal becomes a tile in both grids.
  if (constant) {
    out->push_back({origin, values[0], nullptr, nullptr});
    return;
  }
  guard.countLeafPair();
  auto upper = std::make_unique<LeafT>(origin, 0.0f, false);
  auto lower = std::make_unique<LeafT>(origin, kNeverInside, false);
  for (openvdb::Index n = 0; n < LeafT::SIZE; ++n) {
    if (isBackground(values[n])) continue;
    upper->setValueOn(n, values[n].upper);
    lower->setValueOn(n, values[n].lower);
  }
  out->push_back({origin, {}, std::move(upper), std::move(lower)});
}

// A 32³ super-block: one bounds test first, 64 leaf blocks when that fails.
void buildSuperBlock(const BlockSampler& s, const Coord& origin, const CoordBBox& box, BuildGuard& guard,
                     std::vector<Block>* out) {
  guard.checkTime();
  AlphaLevels v;
  const CoordBBox super = CoordBBox::createCube(origin, kSuperDim);
  const bool uniform = s.uniformOver(super, &v);
  if (uniform && isBackground(v)) return;
  std::vector<Coord> leaves;
  for (int i = 0; i < kSuperDim; i += kLeafDim)
    for (int j = 0; j < kSuperDim; j += kLeafDim)
      for (int k = 0; k < kSuperDim; k += kLeafDim) {
        const Coord o = origin.offsetBy(i, j, k);
        if (!box.hasOverlap(CoordBBox::createCube(o, kLeafDim))) continue;
        if (uniform)
          out->push_back({o, v, nullptr, nullptr});
        else
          leaves.push_back(o);
      }
  if (leaves.empty()) return;
  // The 8³ blocks of an undecided super-block are tasks of their own: the cost of a block varies
  // by orders of magnitude (a fuzzy part's hardest voxels cluster where the band is thin), so
  // super-blocks alone left cores idle behind the one that held them (the part with all fourteen
  // values fuzzy at N = 40: 1 -> 2 cores 1.69x with super-block tasks, 1.94x with block tasks).
  // Tasks of four blocks took that back to 1.70x (hard blocks sit next to one another).
  std::vector<std::vector<Block>> perLeaf(leaves.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leaves.size(), 1),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        buildLeafBlock(s, leaves[i], guard, &perLeaf[i]);
                    });
  for (auto& list : perLeaf)
    for (Block& b : list) out->push_back(std::move(b));
}

openvdb::math::Transform::Ptr cellCentredTransform(double h) {
  auto xform = openvdb::math::Transform::createLinearTransform(h);
  xform->postTranslate(openvdb::Vec3d(0.5 * h));  // index (i,j,k) ↦ ((i+½)h, (j+½)h, (k+½)h)
  return xform;
}

// Pruning above the leaves, on both grids at once (openvdb's tools::prune would treat each grid
// alone and break the shared topology): a 128³ node made only of equal active tiles in both
// grids becomes one tile.
void pruneNodesJointly(FloatTree& upper, FloatTree& lower) {
  std::vector<const Node1*> nodes;
  static_cast<const FloatTree&>(upper).getNodes(nodes);
  std::vector<std::pair<Coord, AlphaLevels>> collapse;
  for (const Node1* nu : nodes) {
    float u = 0.0f, l = 0.0f;
    bool onU = false, onL = false;
    if (!nu->isConstant(u, onU) || !onU) continue;
    const Node1* nl = lower.probeConstNode<Node1>(nu->origin());
    if (nl == nullptr || !nl->isConstant(l, onL) || !onL) continue;
    collapse.push_back({nu->origin(), {u, l}});
  }
  for (const auto& [origin, v] : collapse) {
    upper.addTile(kNodeTileLevel, origin, v.upper, true);
    lower.addTile(kNodeTileLevel, origin, v.lower, true);
  }
}

EnvelopeGridStats statsOf(const FloatGrid& upper, const FloatGrid& lower) {
  EnvelopeGridStats s;
  s.activeVoxels = upper.tree().activeLeafVoxelCount();
  s.activeTiles = upper.tree().activeTileCount();
  s.tileVoxels = upper.tree().activeVoxelCount() - s.activeVoxels;
  s.leafCount = upper.tree().leafCount();
  s.memoryBytes = static_cast<std::size_t>(upper.memUsage() + lower.memUsage());
  return s;
}

// Samples `s` over the index box `box` (inclusive): 128³ nodes first (serially; few), then the
// 32³ super-blocks of the undecided ones in parallel, each into its own block list, then the
// lists go into the trees serially (adding a leaf only moves a pointer). `limits` stop it by
// throwing; the block lists and the half-made grids are then freed on the way out.
std::shared_ptr<EnvelopeGrid::Impl> buildGrids(const BlockSampler& s, const CoordBBox& box,
                                               double h, const EnvelopeBuildLimits& limits = {}) {
  initializeOpenVdb();
  BuildGuard guard(limits);
  const auto start = std::chrono::steady_clock::now();
  auto impl = std::make_shared<EnvelopeGrid::Impl>();
  impl->voxelSize = h;
  impl->upper = FloatGrid::create(0.0f);
  impl->lower = FloatGrid::create(kNeverInside);
  auto xform = cellCentredTransform(h);
  impl->upper->setTransform(xform);
  impl->lower->setTransform(xform->copy());
  impl->upper->setName("upper");
  impl->lower->setName("lower");
  impl->upper->setGridClass(openvdb::GRID_FOG_VOLUME);  // u in [0,1], 0 outside: a fog volume
  FloatTree& upper = impl->upper->tree();
  FloatTree& lower = impl->lower->tree();

  std::vector<Coord> supers;
  if (!box.empty()) {
    const Coord lo(floorTo(box.min().x(), kNodeDim), floorTo(box.min().y(), kNodeDim),
                   floorTo(box.min().z(), kNodeDim));
    for (int x = lo.x(); x <= box.max().x(); x += kNodeDim)
      for (int y = lo.y(); y <= box.max().y(); y += kNodeDim)
        for (int z = lo.z(); z <= box.max().z(); z += kNodeDim) {
          guard.checkTime();
          const Coord o(x, y, z);
          const CoordBBox node = CoordBBox::createCube(o, kNodeDim);
          AlphaLevels v;
          if (s.uniformOver(node, &v)) {
            if (!isBackground(v)) {
              upper.addTile(kNodeTileLevel, o, v.upper, true);
              lower.addTile(kNodeTileLevel, o, v.lower, true);
            }
            continue;
          }
          for (int i = 0; i < kNodeDim; i += kSuperDim)
            for (int j = 0; j < kNodeDim; j += kSuperDim)
              for (int k = 0; k < kNodeDim; k += kSuperDim) {
                const Coord so = o.offsetBy(i, j, k);
                if (box.hasOverlap(CoordBBox::createCube(so, kSuperDim))) supers.push_back(so);
              }
        }
  }
  std::vector<std::vector<Block>> results(supers.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, supers.size()),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        buildSuperBlock(s, supers[i], box, guard, &results[i]);
                    });
  for (auto& list : results)
    for (Block& b : list) {
      if (b.upper) {
        upper.addLeaf(b.upper.release());
        lower.addLeaf(b.lower.release());
      } else {
        upper.addTile(kLeafTileLevel, b.origin, b.tile.upper, true);
        lower.addTile(kLeafTileLevel, b.origin, b.tile.lower, true);
      }
    }
  pruneNodesJointly(upper, lower);
  impl->stats = statsOf(*impl->upper, *impl->lower);
  impl->stats.buildMillis =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return impl;
}

// The source, sampled at voxel centres; a block's bounds are asked over the box of its voxel
// centres, which is all the samples see (tighter than the box of the cells).
class SourceSampler : public BlockSampler {
 public:
  SourceSampler(const AlphaFieldSource& source, double h) : source_(source), h_(h) {}
  bool uniformOver(const CoordBBox& box, AlphaLevels* value) const override {
    const AlphaLevelBounds b = source_.boundsOver(centre(box.min()), centre(box.max()));
    if (!b.uniform()) return false;
    *value = {b.upperMin, b.lowerMin};
    return true;
  }
  void sampleLeaf(const Coord& origin, AlphaLevels* out, const std::function<void()>& checkpoint) const override {
    static_assert(BlockLattice::kDim == kLeafDim, "a block is one leaf");
    BlockLattice b;
    b.checkpoint = &checkpoint;
    for (int n = 0; n < kLeafDim; ++n) {
      const Vec3 c = centre(origin.offsetBy(n));
      b.x[n] = c.x;
      b.y[n] = c.y;
      b.z[n] = c.z;
    }
    source_.sampleBlock(b, out);
  }

 private:
  Vec3 centre(const Coord& c) const {
    return {(c.x() + 0.5) * h_, (c.y() + 0.5) * h_, (c.z() + 0.5) * h_};
  }
  const AlphaFieldSource& source_;
  double h_;
};

// The Boolean of two grids. A block is uniform when neither side has a leaf there: each side is
// then one tile or background value over the block. Larger boxes are left to the block test.
class CombineSampler : public BlockSampler {
 public:
  CombineSampler(const EnvelopeGrid::Impl& a, const EnvelopeGrid::Impl& b, BooleanOp op)
      : a_(a), b_(b), op_(op) {}
  bool uniformOver(const CoordBBox& box, AlphaLevels* value) const override {
    if (box.dim() != Coord(kLeafDim)) return false;
    const Coord o = box.min();
    const FloatTree* trees[] = {&a_.upper->tree(), &a_.lower->tree(), &b_.upper->tree(),
                                &b_.lower->tree()};
    for (const FloatTree* t : trees)
      if (t->probeConstLeaf(o) != nullptr) return false;
    *value = apply({trees[0]->getValue(o), trees[1]->getValue(o)},
                   {trees[2]->getValue(o), trees[3]->getValue(o)});
    return true;
  }
  void sampleLeaf(const Coord& origin, AlphaLevels* out, const std::function<void()>&) const override {
    const Side a = side(a_, origin), b = side(b_, origin);
    for (openvdb::Index n = 0; n < LeafT::SIZE; ++n) out[n] = apply(a.at(n), b.at(n));
  }

 private:
  // One input over one block: a leaf per grid, or the constant value there.
  struct Side {
    const LeafT *upper, *lower;
    float upperValue, lowerValue;
    AlphaLevels at(openvdb::Index n) const {
      return {upper ? upper->getValue(n) : upperValue, lower ? lower->getValue(n) : lowerValue};
    }
  };
  static Side side(const EnvelopeGrid::Impl& g, const Coord& o) {
    const FloatTree& u = g.upper->tree();
    const FloatTree& l = g.lower->tree();
    return {u.probeConstLeaf(o), l.probeConstLeaf(o), u.getValue(o), l.getValue(o)};
  }
  AlphaLevels apply(AlphaLevels a, AlphaLevels b) const {
    switch (op_) {
      case BooleanOp::kUnion: return alphaUnion(a, b);
      case BooleanOp::kIntersection: return alphaIntersection(a, b);
      case BooleanOp::kDifference: return alphaDifference(a, b);
    }
    return a;
  }
  const EnvelopeGrid::Impl& a_;
  const EnvelopeGrid::Impl& b_;
  BooleanOp op_;
};

// Histogram of `count`-weighted values against sorted thresholds: bucket k holds the values
// that fall between thresholds k-1 and k (as `bucketOf` decides).
using Histogram = std::vector<std::uint64_t>;

template <class BucketOf>
Histogram histogram(const FloatTree& tree, std::size_t buckets, BucketOf bucketOf) {
  Histogram tiles(buckets, 0);
  // Tiles only: the iterator stops above the leaves.
  FloatTree::ValueOnCIter it = tree.cbeginValueOn();
  it.setMaxDepth(FloatTree::ValueOnCIter::LEAF_DEPTH - 1);
  for (; it; ++it) tiles[bucketOf(*it)] += it.getVoxelCount();
  openvdb::tree::LeafManager<const FloatTree> leaves(tree);
  // The identity starts every chunk, so it must be empty; the tiles are added at the end.
  Histogram h = tbb::parallel_reduce(
      leaves.leafRange(), Histogram(buckets, 0),
      [&](const openvdb::tree::LeafManager<const FloatTree>::LeafRange& r, Histogram h) {
        for (auto leaf = r.begin(); leaf; ++leaf)
          for (auto v = leaf->cbeginValueOn(); v; ++v) ++h[bucketOf(*v)];
        return h;
      },
      [](Histogram x, const Histogram& y) {
        for (std::size_t i = 0; i < x.size(); ++i) x[i] += y[i];
        return x;
      });
  for (std::size_t i = 0; i < buckets; ++i) h[i] += tiles[i];
  return h;
}

}  // namespace

std::uint64_t EnvelopeGrid::leafPairBytes() {
  // openvdb's count for one leaf with its voxel buffer allocated (what every leaf the build makes
  // has): the node (value mask, origin, buffer header) plus 8³ floats, times the two grids.
  // Heap bookkeeping of the allocator is not in it, nor the 128³ internal nodes above the leaves
  // (32 KiB each, one per 16³ leaves when full: under 1 % of a dense grid's leaves).
  static const std::uint64_t bytes = 2 * static_cast<std::uint64_t>(LeafT(Coord(0), 0.0f).memUsage());
  return bytes;
}

EnvelopeGrid EnvelopeGrid::build(const AlphaFieldSource& source, double voxelSize,
                                 const EnvelopeBuildLimits& limits) {
  if (!(std::isfinite(voxelSize) && voxelSize > 0.0))
    throw Error(errc::kInvalidParameter, "voxel size must be finite and positive", "voxel_size");
  Vec3 lo, hi;
  source.boundingBox(&lo, &hi);
  const double c[6] = {lo.x / voxelSize, lo.y / voxelSize, lo.z / voxelSize,
                       hi.x / voxelSize, hi.y / voxelSize, hi.z / voxelSize};
  for (double v : c)
    if (!(std::fabs(v) < kMaxIndex))
      throw Error(errc::kInvalidParameter,
                  "voxel size too small for the bounding box (index range exceeded)",
                  "voxel_size");
  // Voxels whose cells meet [lo, hi], padded by one voxel; an empty box (lo > hi) samples nothing.
  CoordBBox box;
  if (lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z)
    box = CoordBBox(Coord(static_cast<int>(std::floor(c[0])) - 1,
                          static_cast<int>(std::floor(c[1])) - 1,
                          static_cast<int>(std::floor(c[2])) - 1),
                    Coord(static_cast<int>(std::floor(c[3])) + 1,
                          static_cast<int>(std::floor(c[4])) + 1,
                          static_cast<int>(std::floor(c[5])) + 1));
  return EnvelopeGrid(buildGrids(SourceSampler(source, voxelSize), box, voxelSize, limits));
}

double EnvelopeGrid::voxelSize() const { return impl_->voxelSize; }
std::uint64_t EnvelopeGrid::activeVoxelCount() const { return impl_->stats.activeVoxels; }
const EnvelopeGridStats& EnvelopeGrid::stats() const { return impl_->stats; }

AlphaLevels EnvelopeGrid::levelsAt(const Vec3& p) const {
  const double h = impl_->voxelSize;
  const double i = std::floor(p.x / h), j = std::floor(p.y / h), k = std::floor(p.z / h);
  if (!(std::fabs(i) < kMaxIndex && std::fabs(j) < kMaxIndex && std::fabs(k) < kMaxIndex))
    return AlphaLevels{};
  const Coord ijk(static_cast<int>(i), static_cast<int>(j), static_cast<int>(k));
  return {impl_->upper->tree().getValue(ijk), impl_->lower->tree().getValue(ijk)};
}

std::vector<LevelVolume> EnvelopeGrid::volumes(const std::vector<double>& alphas) const {
  for (std::size_t i = 0; i < alphas.size(); ++i)
    if (!(alphas[i] >= 0.0 && alphas[i] <= 1.0))
      throw Error(errc::kInvalidParameter, "alpha must lie in [0, 1]",
                  "alphas[" + std::to_string(i) + "]");
  std::vector<double> sorted = alphas;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  // upper: a voxel with u > 0 counts for the thresholds α ≤ u, the first k = #{α ≤ u}; it goes
  // to bucket k, and count(j) = Σ_{k > j}. Buckets 0 (u = 0) count for nothing.
  const Histogram up = histogram(impl_->upper->tree(), n + 1, [&](float u) -> std::size_t {
    if (!(u > 0.0f)) return 0;
    return std::upper_bound(sorted.begin(), sorted.end(), static_cast<double>(u)) - sorted.begin();
  });
  // lower: a voxel counts for the thresholds α ≥ l, from k = #{α < l} on; count(j) = Σ_{k ≤ j}.
  const Histogram low = histogram(impl_->lower->tree(), n + 1, [&](float l) -> std::size_t {
    return std::lower_bound(sorted.begin(), sorted.end(), static_cast<double>(l)) - sorted.begin();
  });
  std::vector<std::uint64_t> upperCount(n), lowerCount(n);
  std::uint64_t acc = 0;
  for (std::size_t j = n; j-- > 0;) upperCount[j] = (acc += up[j + 1]);
  acc = 0;
  for (std::size_t j = 0; j < n; ++j) lowerCount[j] = (acc += low[j]);
  const double cell = impl_->voxelSize * impl_->voxelSize * impl_->voxelSize;
  std::vector<LevelVolume> out;
  out.reserve(n);
  for (double a : alphas) {
    // Any index of an equal threshold gives the same counts.
    const std::size_t j = std::lower_bound(sorted.begin(), sorted.end(), a) - sorted.begin();
    out.push_back({a, cell * static_cast<double>(lowerCount[j]),
                   cell * static_cast<double>(upperCount[j])});
  }
  return out;
}

EnvelopeGrid combine(const EnvelopeGrid& a, const EnvelopeGrid& b, BooleanOp op) {
  const double ha = a.voxelSize(), hb = b.voxelSize();
  if (std::fabs(ha - hb) > 1e-12 * std::max(ha, hb))
    throw Error(errc::kInvalidParameter,
                "Booleans need grids of one voxel size (" + std::to_string(ha) + " vs " +
                    std::to_string(hb) + "); resampling is not supported",
                "voxel_size");
  const CoordBBox boxA = a.impl().upper->evalActiveVoxelBoundingBox();
  const CoordBBox boxB = b.impl().upper->evalActiveVoxelBoundingBox();
  CoordBBox box;
  switch (op) {
    case BooleanOp::kUnion:
      box = boxA;
      box.expand(boxB);
      if (boxA.empty()) box = boxB;
      if (boxB.empty()) box = boxA;
      break;
    case BooleanOp::kIntersection:
      if (!boxA.empty() && !boxB.empty() && boxA.hasOverlap(boxB))
        box = CoordBBox(openvdb::Coord::maxComponent(boxA.min(), boxB.min()),
                        openvdb::Coord::minComponent(boxA.max(), boxB.max()));
      break;
    case BooleanOp::kDifference:  // u = min(uA, lB) ≤ uA: nothing outside a
      box = boxA;
      break;
  }
  return EnvelopeGrid(buildGrids(CombineSampler(a.impl(), b.impl(), op), box, ha));
}

}  // namespace fsdb
