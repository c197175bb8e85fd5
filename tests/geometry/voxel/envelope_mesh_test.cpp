// geometry/voxel/envelope_mesh: closed, outward-oriented meshes of lower(α) and upper(α), and .vdb bytes.
#include "geometry/voxel/envelope_mesh.h"

#include <gtest/gtest.h>
#include <openvdb/io/Stream.h>

#include <map>
#include <sstream>
#include <utility>

#include "geometry/voxel/envelope_grid_vdb.h"
#include "geometry/core/error.h"
#include "tests/geometry/fuzzy_ball.h"

namespace fsdb {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Signed volume by the divergence theorem: positive when the triangles face outwards.
double signedVolume(const TriangleMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles) v += dot(m.vertices[t[0]], cross(m.vertices[t[1]], m.vertices[t[2]])) / 6.0;
  return v;
}

// Closed and consistently oriented: every directed edge appears once and its reverse once.
bool closedAndOriented(const TriangleMesh& m) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  for (const auto& [e, n] : directed) {
    if (n != 1) return false;
    auto rev = directed.find({e.second, e.first});
    if (rev == directed.end() || rev->second != 1) return false;
  }
  return !m.triangles.empty();
}

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
