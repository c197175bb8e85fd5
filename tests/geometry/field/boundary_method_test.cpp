// geometry/field/boundary_method: the corner shapes of Zhang, Pham & Chen, eq. 4 and the per-level
// crisp solids.
#include "geometry/field/boundary_method.h"

#include <gtest/gtest.h>

#include "geometry/superquadric/superquadric_volume.h"

namespace fsdb {
namespace {

FuzzyNumber tri(double l, double m, double r) { return FuzzyNumber::triangular(l, m, r); }

TEST(BoundaryMethod, CornerShapesHaveTheExtremeVolumesOfThePlacementBox) {
  FuzzyPart part;
  part.eps1 = tri(0.5, 1.0, 1.5);
  part.eps2 = tri(0.8, 1.0, 1.2);
  part.a1 = tri(0.9, 1.0, 1.1);
  part.a3 = tri(1.5, 2.0, 2.5);
  part.kx = tri(-0.2, 0.0, 0.3);
  part.scale = tri(0.9, 1.0, 1.1);
  part.tx = tri(-1, 0, 1);
  for (double alpha : {0.0, 0.5, 1.0}) {
    const PlacedSuperquadric lo = boundaryShape(part, alpha, false), hi = boundaryShape(part, alpha, true);
    // Brute force over a grid of the box (corners included): nothing is outside [lo, hi].
    const PartBox box = part.boxAt(alpha);
    for (int i = 0; i <= 4; ++i)
      for (int j = 0; j <= 4; ++j) {
        PlacedSuperquadric s = lo;
        s.params.eps1 = box.params.eps1.lo + i / 4.0 * (box.params.eps1.hi - box.params.eps1.lo);
        s.params.a1 = box.params.a1.lo + j / 4.0 * (box.params.a1.hi - box.params.a1.lo);
        s.params.kx = box.params.kx.hi;
        EXPECT_GE(placedVolume(s), placedVolume(lo) * (1 - 1e-12));
        EXPECT_LE(placedVolume(s), placedVolume(hi) * (1 + 1e-12));
      }
    EXPECT_EQ(lo.params.a1, box.params.a1.lo);
    EXPECT_EQ(hi.params.a1, box.params.a1.hi);
    EXPECT_EQ(hi.placement.scale, box.placement.scale.hi);
    // Volume-neutral values sit at the middle of their cut.
    EXPECT_DOUBLE_EQ(hi.placement.translate.x, 0.0);
  }
}

TEST(BoundaryMethod, DifferenceSubtractsTheOtherBound) {
  auto leaf = [](double l, double m, double r, double x) {
    auto t = std::make_shared<CsgTree>();
    t->part.a1 = tri(l, m, r);
    t->part.tx = FuzzyNumber::crisp(x);
    return t;
  };
  CsgTree diff;
  diff.leaf = false;
  diff.op = CsgOp::kDifference;
  diff.children = {leaf(0.8, 1.0, 1.2, 0), leaf(0.3, 0.5, 0.7, 0)};
  // At α = 0: lower = ball(0.8) − ball(0.7), upper = ball(1.2) − ball(0.3).
  auto lower = boundarySolid(diff, 0.0, false), upper = boundarySolid(diff, 0.0, true);
  EXPECT_EQ(lower->levelsAt({0.75, 0, 0}).lower, 0.0f);       // in ball(0.8), outside ball(0.7)
  EXPECT_EQ(lower->levelsAt({0.65, 0, 0}).lower, kNeverInside);  // removed by ball(0.7)
  EXPECT_EQ(upper->levelsAt({0.65, 0, 0}).lower, 0.0f);       // only ball(0.3) is removed
  EXPECT_EQ(upper->levelsAt({1.1, 0, 0}).lower, 0.0f);
  EXPECT_EQ(upper->levelsAt({0.2, 0, 0}).lower, kNeverInside);
}

}  // namespace
}  // namespace fsdb
