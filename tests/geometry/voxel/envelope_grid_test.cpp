// geometry/voxel/envelope_grid.h: the voxel envelopes of fuzzy balls (tests/geometry/fuzzy_ball.h)
// against closed forms. Volumes per level (docs/api.md §3: the fuzzy volume), Booleans against the
// volume of two intersecting spheres, sparsity (surface-like growth, interior tiles), nesting,
// the per-voxel Booleans against alpha_field.h, and the parameter errors.
#include "geometry/voxel/envelope_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "geometry/core/error.h"
#include "tests/geometry/expect_error.h"
#include "tests/geometry/fuzzy_ball.h"
#include "tests/geometry/sphere_volumes.h"

namespace fsdb {
namespace {

using testing::ballVolume;
using testing::lensVolume;

// A radius of 1 spans 60 voxels. The centres are off the lattice so nothing lines up.
constexpr double kH = 1.0 / 60.0;
const Vec3 kCentreA{0.013, -0.021, 0.007};
const Vec3 kCentreB{0.913, 0.019, -0.011};  // d = |B − A|
const FuzzyBall kBallA(kCentreA, 0.6, 0.8, 1.0);
const FuzzyBall kBallB(kCentreB, 0.5, 0.7, 0.9);
const std::vector<double> kAlphas{0.0, 0.5, 1.0};

double distanceAB() { return norm(kCentreB - kCentreA); }

const EnvelopeGrid& gridA() {
  static const EnvelopeGrid g = EnvelopeGrid::build(kBallA, kH);
  return g;
}
const EnvelopeGrid& gridB() {
  static const EnvelopeGrid g = EnvelopeGrid::build(kBallB, kH);
  return g;
}

void expectNear(double got, double want, double scale, const char* what, double alpha) {
  // 1% of the volume, and 0.2% of ball A's for the small volumes of a difference.
  EXPECT_NEAR(got, want, 0.01 * want + 0.002 * scale) << what << " at alpha " << alpha;
}

TEST(EnvelopeGrid, BallVolumesPerLevel) {
  const std::vector<LevelVolume> v = gridA().volumes(kAlphas);
  ASSERT_EQ(v.size(), kAlphas.size());
  for (std::size_t i = 0; i < kAlphas.size(); ++i) {
    const double a = kAlphas[i];
    EXPECT_EQ(v[i].alpha, a);
    EXPECT_NEAR(v[i].upper_volume, ballVolume(kBallA.upperRadius(a)),
                0.01 * ballVolume(kBallA.upperRadius(a)))
        << a;
    EXPECT_NEAR(v[i].lower_volume, ballVolume(kBallA.lowerRadius(a)),
                0.01 * ballVolume(kBallA.lowerRadius(a)))
        << a;
  }
  EXPECT_DOUBLE_EQ(gridA().voxelSize(), kH);
}

TEST(EnvelopeGrid, VolumesAnswerInTheGivenOrderWithRepeats) {
  const std::vector<double> alphas{1.0, 0.25, 0.5, 0.25};
  const std::vector<LevelVolume> v = gridA().volumes(alphas);
  const std::vector<LevelVolume> one = gridA().volumes({0.25});
  ASSERT_EQ(v.size(), 4u);
  EXPECT_EQ(v[1].upper_volume, one[0].upper_volume);
  EXPECT_EQ(v[3].lower_volume, one[0].lower_volume);
  EXPECT_EQ(v[0].alpha, 1.0);
  EXPECT_TRUE(gridA().volumes({}).empty());
}

TEST(EnvelopeGrid, UnionAndDifferenceAgainstIntersectingSpheres) {
  const double d = distanceAB();
  const double scale = ballVolume(1.0);
  const EnvelopeGrid u = combine(gridA(), gridB(), BooleanOp::kUnion);
  const EnvelopeGrid n = combine(gridA(), gridB(), BooleanOp::kIntersection);
  const EnvelopeGrid m = combine(gridA(), gridB(), BooleanOp::kDifference);
  const auto vu = u.volumes(kAlphas), vn = n.volumes(kAlphas), vm = m.volumes(kAlphas);
  for (std::size_t i = 0; i < kAlphas.size(); ++i) {
    const double a = kAlphas[i];
    const double uA = kBallA.upperRadius(a), lA = kBallA.lowerRadius(a);
    const double uB = kBallB.upperRadius(a), lB = kBallB.lowerRadius(a);
    // docs/api.md §3: union (lower_A ∪ lower_B, upper_A ∪ upper_B), intersection likewise,
    // difference (lower_A − upper_B, upper_A − lower_B).
    expectNear(vu[i].upper_volume, ballVolume(uA) + ballVolume(uB) - lensVolume(uA, uB, d), scale,
               "union upper", a);
    expectNear(vu[i].lower_volume, ballVolume(lA) + ballVolume(lB) - lensVolume(lA, lB, d), scale,
               "union lower", a);
    expectNear(vn[i].upper_volume, lensVolume(uA, uB, d), scale, "intersection upper", a);
    expectNear(vn[i].lower_volume, lensVolume(lA, lB, d), scale, "intersection lower", a);
    expectNear(vm[i].upper_volume, ballVolume(uA) - lensVolume(uA, lB, d), scale,
               "difference upper", a);
    expectNear(vm[i].lower_volume, ballVolume(lA) - lensVolume(lA, uB, d), scale,
               "difference lower", a);
  }
}

TEST(EnvelopeGrid, DifferenceWithNothingKeepsEverything) {
  // B far away: over all of A the right side is background (u = 0, l = never).
  const FuzzyBall far({5.0, 5.0, 5.0}, 0.2, 0.3, 0.4);
  const EnvelopeGrid b = EnvelopeGrid::build(far, kH);
  const EnvelopeGrid m = combine(gridA(), b, BooleanOp::kDifference);
  const auto want = gridA().volumes(kAlphas), got = m.volumes(kAlphas);
  for (std::size_t i = 0; i < kAlphas.size(); ++i) {
    EXPECT_EQ(got[i].upper_volume, want[i].upper_volume);
    EXPECT_EQ(got[i].lower_volume, want[i].lower_volume);
  }
  EXPECT_EQ(m.activeVoxelCount(), gridA().activeVoxelCount());
  const EnvelopeGrid n = combine(gridA(), b, BooleanOp::kIntersection);
  EXPECT_EQ(n.activeVoxelCount(), 0u);
  EXPECT_EQ(n.volumes({0.0})[0].upper_volume, 0.0);
}

TEST(EnvelopeGrid, SparseLikeTheSurfaceWithInteriorTiles) {
  // A crisp ball: only blocks across its surface hold voxels, so doubling the resolution
  // multiplies them by about 4; a fuzzy ball's shell r1..r3 is a volume and would give 8.
  const FuzzyBall crisp({0.013, -0.021, 0.007}, 0.75, 0.75, 0.75);
  const EnvelopeGrid coarse = EnvelopeGrid::build(crisp, 1.0 / 32.0);
  const EnvelopeGrid fine = EnvelopeGrid::build(crisp, 1.0 / 64.0);
  const double ratio = static_cast<double>(fine.activeVoxelCount()) / coarse.activeVoxelCount();
  EXPECT_GT(ratio, 3.0);
  EXPECT_LT(ratio, 5.0);
  for (const EnvelopeGrid* g : {&coarse, &fine}) {
    EXPECT_GT(g->stats().activeTiles, 0u);
    EXPECT_GT(g->stats().tileVoxels, g->activeVoxelCount() / 4);
    EXPECT_GT(g->stats().leafCount, 0u);
    EXPECT_GT(g->stats().memoryBytes, 0u);
    const auto v = g->volumes({0.5});
    EXPECT_NEAR(v[0].upper_volume, ballVolume(0.75), 0.02 * ballVolume(0.75));
    EXPECT_EQ(v[0].upper_volume, v[0].lower_volume);  // crisp: one shape at every level
  }
  // The fuzzy ball: voxels only in the shell r1 < d < r3 (plus the rest of its leaves), and
  // the core d ≤ r1 as tiles.
  const EnvelopeGridStats& s = gridA().stats();
  const double shell = (ballVolume(1.0) - ballVolume(0.6)) / (kH * kH * kH);
  EXPECT_GT(s.activeVoxels, 0.9 * shell);
  EXPECT_LT(s.activeVoxels, 1.5 * shell);
  EXPECT_GT(s.tileVoxels, 0.3 * ballVolume(0.6) / (kH * kH * kH));
}

TEST(EnvelopeGrid, LowerInsideUpperAndNestedInAlpha) {
  const EnvelopeGrid u = combine(gridA(), gridB(), BooleanOp::kUnion);
  const EnvelopeGrid m = combine(gridA(), gridB(), BooleanOp::kDifference);
  const double levels[] = {0.0, 0.25, 0.5, 0.75, 1.0};
  for (const EnvelopeGrid* g : {&gridA(), &u, &m}) {
    // Every voxel centre of a slab through both balls, every 2nd voxel across.
    for (double x = -1.1; x < 2.0; x += 2 * kH)
      for (double y = -1.1; y < 1.1; y += 2 * kH)
        for (double z = -0.1; z < 0.1; z += kH) {
          const AlphaLevels v = g->levelsAt({x, y, z});
          ASSERT_TRUE(v.upper >= 0.0f && v.upper <= 1.0f);
          for (double a : levels)
            ASSERT_TRUE(!inLower(v, a) || inUpper(v, a)) << x << " " << y << " " << z;
        }
    std::vector<double> alphas;
    for (int i = 0; i <= 20; ++i) alphas.push_back(i / 20.0);
    const auto vol = g->volumes(alphas);
    for (std::size_t i = 0; i < vol.size(); ++i) {
      EXPECT_LE(vol[i].lower_volume, vol[i].upper_volume);
      if (i == 0) continue;
      EXPECT_GE(vol[i].lower_volume, vol[i - 1].lower_volume);  // lower grows with α
      EXPECT_LE(vol[i].upper_volume, vol[i - 1].upper_volume);  // upper shrinks
    }
  }
}

TEST(EnvelopeGrid, VoxelsHoldTheSourceAndTheBooleansOfAlphaField) {
  const EnvelopeGrid u = combine(gridA(), gridB(), BooleanOp::kUnion);
  const EnvelopeGrid n = combine(gridA(), gridB(), BooleanOp::kIntersection);
  const EnvelopeGrid m = combine(gridA(), gridB(), BooleanOp::kDifference);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> x(-1.2, 2.0), yz(-1.2, 1.2);
  auto same = [](AlphaLevels p, AlphaLevels q) {
    return p.upper == q.upper && p.lower == q.lower;
  };
  int inside = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 p{x(rng), yz(rng), yz(rng)};
    const Vec3 centre{(std::floor(p.x / kH) + 0.5) * kH, (std::floor(p.y / kH) + 0.5) * kH,
                      (std::floor(p.z / kH) + 0.5) * kH};
    const AlphaLevels a = gridA().levelsAt(p), b = gridB().levelsAt(p);
    ASSERT_TRUE(same(a, kBallA.levelsAt(centre))) << p.x << " " << p.y << " " << p.z;
    ASSERT_TRUE(same(b, kBallB.levelsAt(centre))) << p.x << " " << p.y << " " << p.z;
    ASSERT_TRUE(same(u.levelsAt(p), alphaUnion(a, b)));
    ASSERT_TRUE(same(n.levelsAt(p), alphaIntersection(a, b)));
    ASSERT_TRUE(same(m.levelsAt(p), alphaDifference(a, b)));
    inside += a.upper > 0.0f && b.upper > 0.0f;
  }
  EXPECT_GT(inside, 500);  // the overlap was sampled
}

TEST(EnvelopeGrid, ParameterErrors) {
  expectInvalidParameter([] { EnvelopeGrid::build(kBallA, 0.0); }, "voxel_size");
  expectInvalidParameter([] { EnvelopeGrid::build(kBallA, -0.1); }, "voxel_size");
  expectInvalidParameter([] { EnvelopeGrid::build(kBallA, std::nan("")); }, "voxel_size");
  expectInvalidParameter([] { EnvelopeGrid::build(kBallA, 1e-12); }, "voxel_size");
  const EnvelopeGrid other = EnvelopeGrid::build(kBallB, 2 * kH);
  expectInvalidParameter([&] { combine(gridA(), other, BooleanOp::kUnion); }, "voxel_size");
  expectInvalidParameter([] { gridA().volumes({0.5, 1.5}); }, "alphas[1]");
  expectInvalidParameter([] { gridA().volumes({std::nan("")}); }, "alphas[0]");
}

}  // namespace
}  // namespace fsdb
