// geometry/voxel/envelope_mesh: closed, outward-oriented meshes of lower(α) and upper(α), and .vdb bytes.
#include "geometry/voxel/envelope_mesh.h"

#include <gtest/gtest.h>
#include <openvdb/io/Stream.h>

#include <cmath>
#include <map>
#include <sstream>
#include <utility>

#include "geometry/voxel/envelope_grid_vdb.h"
#include "geometry/core/error.h"
#include "tests/geometry/mesh_checks.h"
#include "tests/geometry/fuzzy_ball.h"

namespace fsdb {
namespace {

constexpr double kPi = 3.14159265358979323846;

using testing::closedAndOriented;
using testing::signedVolume;

class EnvelopeMesh : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    grid = new EnvelopeGrid(EnvelopeGrid::build(FuzzyBall({0.1, 0, 0}, 0.6, 0.8, 1.0), 0.025));
  }
  static void TearDownTestSuite() { delete grid; }
  static EnvelopeGrid* grid;
};
EnvelopeGrid* EnvelopeMesh::grid = nullptr;

TEST_F(EnvelopeMesh, UpperAndLowerSurfacesAreClosedOutwardAndEncloseTheirVolume) {
  for (double alpha : {0.0, 0.5, 1.0}) {
    for (EnvelopeBound bound : {EnvelopeBound::kLower, EnvelopeBound::kUpper}) {
      const TriangleMesh mesh = extractMesh(*grid, alpha, bound);
      EXPECT_TRUE(closedAndOriented(mesh)) << "alpha " << alpha;
      const double r = bound == EnvelopeBound::kUpper ? 1.0 - 0.2 * alpha : 0.6 + 0.2 * alpha;
      const double expect = 4.0 / 3.0 * kPi * r * r * r;
      EXPECT_NEAR(signedVolume(mesh), expect, 0.03 * expect) << "alpha " << alpha << " bound " << int(bound);
    }
  }
}

TEST_F(EnvelopeMesh, AnEmptySetHasAnEmptyMeshAndBadLevelsAreRefused) {
  // Two disjoint balls have nothing in common at any level.
  const EnvelopeGrid other = EnvelopeGrid::build(FuzzyBall({3, 0, 0}, 0.6, 0.8, 1.0), 0.025);
  const EnvelopeGrid empty = combine(*grid, other, BooleanOp::kIntersection);
  EXPECT_TRUE(extractMesh(empty, 1.0, EnvelopeBound::kLower).triangles.empty());
  EXPECT_TRUE(extractMesh(empty, 0.5, EnvelopeBound::kUpper).triangles.empty());
  try {
    extractMesh(*grid, 1.5, EnvelopeBound::kUpper);
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.path(), "alpha");
  }
}

TEST_F(EnvelopeMesh, VdbBytesReadBackAsTheTwoGrids) {
  std::istringstream in(vdbBytes(*grid), std::ios_base::binary);
  openvdb::io::Stream stream(in);
  openvdb::GridPtrVecPtr grids = stream.getGrids();
  ASSERT_EQ(grids->size(), 2u);
  std::map<std::string, openvdb::FloatGrid::Ptr> byName;
  for (auto& g : *grids) byName[g->getName()] = openvdb::gridPtrCast<openvdb::FloatGrid>(g);
  ASSERT_TRUE(byName.count("upper") && byName.count("lower"));
  EXPECT_EQ(byName["upper"]->activeVoxelCount(), upperGrid(*grid)->activeVoxelCount());
  EXPECT_EQ(byName["lower"]->background(), kNeverInside);
}

}  // namespace
}  // namespace fsdb

namespace fsdb {
namespace {

// vertexNormals: the area-weighted mean of a vertex's triangle normals, unit length; zero for a
// vertex of no triangle.
TEST(VertexNormals, AreAreaWeightedUnitMeans) {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {5, 5, 5}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};  // a tetrahedron, outward
  const std::vector<Vec3> n = vertexNormals(m);
  ASSERT_EQ(n.size(), 5u);
  // At the origin: the three axis faces, -x, -y, -z, equal areas.
  const double s = 1 / std::sqrt(3.0);
  EXPECT_NEAR(n[0].x, -s, 1e-12);
  EXPECT_NEAR(n[0].y, -s, 1e-12);
  EXPECT_NEAR(n[0].z, -s, 1e-12);
  // At (1, 0, 0): -z and -y (area 1/2 each) and the slanted face (1, 1, 1)/√3 (area √3/2): sum (1, 0, 0)/2.
  EXPECT_NEAR(n[1].x, 1, 1e-12);
  EXPECT_NEAR(n[1].y, 0, 1e-12);
  EXPECT_NEAR(n[1].z, 0, 1e-12);
  EXPECT_EQ(n[4].x, 0);
  EXPECT_EQ(norm(n[4]), 0);
}

}  // namespace
}  // namespace fsdb
