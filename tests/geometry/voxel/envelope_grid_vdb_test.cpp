// geometry/voxel/envelope_grid_vdb.h: the openvdb grids behind an EnvelopeGrid, as mesh and .vdb
// export will see them: named, cell-centred in world space, one shared topology, backgrounds
// 0 and kNeverInside (envelope_grid.h).
#include "geometry/voxel/envelope_grid_vdb.h"

#include <gtest/gtest.h>

#include "tests/geometry/fuzzy_ball.h"

namespace fsdb {
namespace {

TEST(EnvelopeGridVdb, GridsAreCellCentredWithOneTopology) {
  const double h = 1.0 / 40.0;
  const FuzzyBall ball({0.1, 0.2, -0.3}, 0.5, 0.7, 0.9);
  const EnvelopeGrid g = EnvelopeGrid::build(ball, h);
  const auto upper = upperGrid(g), lower = lowerGrid(g);
  ASSERT_TRUE(upper && lower);
  EXPECT_EQ(upper->getName(), "upper");
  EXPECT_EQ(lower->getName(), "lower");
  EXPECT_EQ(upper->background(), 0.0f);
  EXPECT_EQ(lower->background(), kNeverInside);
  EXPECT_TRUE(upper->tree().hasSameTopology(lower->tree()));
  // Voxel (i, j, k) has its centre at ((i+½)h, (j+½)h, (k+½)h).
  const openvdb::Vec3d w = upper->indexToWorld(openvdb::Coord(3, -2, 7));
  EXPECT_NEAR(w.x(), 3.5 * h, 1e-12);
  EXPECT_NEAR(w.y(), -1.5 * h, 1e-12);
  EXPECT_NEAR(w.z(), 7.5 * h, 1e-12);
  EXPECT_NEAR(lower->voxelSize().x(), h, 1e-15);
  // The openvdb values are the ones levelsAt answers.
  const openvdb::Coord ijk(10, 8, -12);
  const AlphaLevels v = g.levelsAt({10.5 * h, 8.5 * h, -11.5 * h});
  EXPECT_EQ(upper->tree().getValue(ijk), v.upper);
  EXPECT_EQ(lower->tree().getValue(ijk), v.lower);
  EXPECT_EQ(upper->tree().activeLeafVoxelCount(), g.activeVoxelCount());
}

}  // namespace
}  // namespace fsdb
