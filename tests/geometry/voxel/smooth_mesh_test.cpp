// geometry/voxel/smooth_mesh: vertices on the true surface of lower(α) and upper(α). On crisp
// spheres, a superellipsoid and a fuzzy ball's lower and upper at three levels, every vertex
// lies within 10% of a voxel of the closed-form surface (mean under 2%), the mesh volume is
// within 1% of the closed form, and the mesh stays closed and outward.
#include "geometry/voxel/smooth_mesh.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <utility>

#include "geometry/core/error.h"
#include "geometry/field/fuzzy_part_field.h"
#include "geometry/voxel/envelope_grid.h"
#include "tests/geometry/fuzzy_ball.h"
#include "tests/geometry/mesh_checks.h"

namespace fsdb {
namespace {

constexpr double kPi = 3.14159265358979323846;

using testing::closedAndOriented;
using testing::signedVolume;

// Max and mean of distance(v) over the vertices, in voxels.
std::pair<double, double> distances(const TriangleMesh& m, double h,
                                    const std::function<double(const Vec3&)>& distance) {
  double worst = 0, sum = 0;
  for (const Vec3& v : m.vertices) {
    const double d = distance(v) / h;
    worst = std::max(worst, d);
    sum += d;
  }
  return {worst, sum / double(m.vertices.size())};
}

void expectOnSurface(const TriangleMesh& mesh, double h, const std::function<double(const Vec3&)>& distance,
                     double volume, const std::string& what) {
  ASSERT_TRUE(closedAndOriented(mesh)) << what;
  const auto [worst, mean] = distances(mesh, h, distance);
  EXPECT_LE(worst, 0.10) << what << ": worst vertex, in voxels";
  EXPECT_LE(mean, 0.02) << what << ": mean vertex distance, in voxels";
  EXPECT_NEAR(signedVolume(mesh), volume, 0.01 * volume) << what;
}

TEST(SmoothMesh, CrispSpheresLieOnTheirSurface) {
  for (const double radius : {1.0, 0.37}) {
    const Vec3 c{0.1, -0.2, 0.05};
    const FuzzyBall ball(c, radius, radius, radius);
    const double h = 2 * radius / 40;
    const EnvelopeGrid grid = EnvelopeGrid::build(ball, h);
    SmoothMeshStats stats;
    const TriangleMesh mesh = extractSmoothMesh(grid, ball, 0.5, EnvelopeBound::kUpper, &stats);
    expectOnSurface(
        mesh, h, [&](const Vec3& v) { return std::fabs(norm(v - c) - radius); },
        4.0 / 3.0 * kPi * radius * radius * radius, "sphere r=" + std::to_string(radius));
    EXPECT_EQ(stats.vertices, mesh.vertices.size());
    EXPECT_EQ(stats.unmoved, 0u);
    EXPECT_GT(stats.evaluations, stats.vertices);
    // The voxel mesh it starts from is off by up to half a voxel: the smooth one is far closer.
    const auto [voxelWorst, voxelMean] = distances(extractMesh(grid, 0.5, EnvelopeBound::kUpper), h,
                                                   [&](const Vec3& v) { return std::fabs(norm(v - c) - radius); });
    EXPECT_GT(voxelMean, 0.1) << "the terraced mesh";
    (void)voxelWorst;
  }
}

// A superellipsoid (eps1 = eps2 = 0.5, unit half-lengths: a rounded cube, F(p) = x⁴ + y⁴ + z⁴).
// F(s·p) = s^(2/eps1)·F(p), so the surface point on the ray through v is v·F(v)^(−eps1/2), and
// |v|·|1 − F(v)^(−eps1/2)| bounds v's distance to the surface from above.
// A deadline already past stops the mesh with limit_exceeded at kDeadlinePath; one far away
// changes nothing.
TEST(SmoothMesh, StopsAtItsDeadline) {
  const FuzzyBall ball({0, 0, 0}, 0.8, 1.0, 1.2);
  const EnvelopeGrid grid = EnvelopeGrid::build(ball, 0.1);
  try {
    extractSmoothMesh(grid, ball, 0.5, EnvelopeBound::kUpper, nullptr,
                      std::chrono::steady_clock::now() - std::chrono::seconds(1));
    ADD_FAILURE() << "no limit_exceeded";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kLimitExceeded);
    EXPECT_EQ(e.path(), kDeadlinePath);
  }
  const TriangleMesh later = extractSmoothMesh(grid, ball, 0.5, EnvelopeBound::kUpper, nullptr,
                                               std::chrono::steady_clock::now() + std::chrono::hours(1));
  const TriangleMesh never = extractSmoothMesh(grid, ball, 0.5, EnvelopeBound::kUpper);
  ASSERT_EQ(later.vertices.size(), never.vertices.size());
  for (size_t i = 0; i < never.vertices.size(); ++i) EXPECT_EQ(norm(later.vertices[i] - never.vertices[i]), 0.0);
}

TEST(SmoothMesh, ASuperellipsoidLiesOnItsSurface) {
  PlacedSuperquadric s;
  s.params.eps1 = 0.5;
  s.params.eps2 = 0.5;
  const FuzzyPartField part(FuzzyPart::fromCrisp(s));
  const double h = 2.0 / 40;
  const EnvelopeGrid grid = EnvelopeGrid::build(part, h);
  const TriangleMesh mesh = extractSmoothMesh(grid, part, 1.0, EnvelopeBound::kUpper);
  const auto distance = [&](const Vec3& v) {
    return norm(v) * std::fabs(1.0 - std::pow(insideOutside(s.params, v), -s.params.eps1 / 2));
  };
  // Volume of |x|^4 + |y|^4 + |z|^4 <= 1 (eps = 0.5): 8·Γ(1 + 1/4)³ / Γ(1 + 3/4).
  const double volume = 8 * std::pow(std::tgamma(1.25), 3) / std::tgamma(1.75);
  expectOnSurface(mesh, h, distance, volume, "superellipsoid eps 0.5");
}

TEST(SmoothMesh, AFuzzyBallsLowerAndUpperAtThreeLevels) {
  const Vec3 c{0.1, 0, 0};
  const FuzzyBall ball(c, 0.6, 0.8, 1.0);
  const double h = 0.025;
  const EnvelopeGrid grid = EnvelopeGrid::build(ball, h);
  for (double alpha : {0.0, 0.5, 1.0}) {
    for (EnvelopeBound bound : {EnvelopeBound::kLower, EnvelopeBound::kUpper}) {
      const double r = bound == EnvelopeBound::kUpper ? ball.upperRadius(alpha) : ball.lowerRadius(alpha);
      const TriangleMesh mesh = extractSmoothMesh(grid, ball, alpha, bound);
      expectOnSurface(
          mesh, h, [&](const Vec3& v) { return std::fabs(norm(v - c) - r); }, 4.0 / 3.0 * kPi * r * r * r,
          std::string(bound == EnvelopeBound::kUpper ? "upper" : "lower") + " at " + std::to_string(alpha));
    }
  }
}

TEST(SmoothMesh, BadLevelsAreRefused) {
  const FuzzyBall ball({0, 0, 0}, 1, 1, 1);
  const EnvelopeGrid grid = EnvelopeGrid::build(ball, 0.1);
  EXPECT_THROW(extractSmoothMesh(grid, ball, 1.5, EnvelopeBound::kUpper), Error);
}

}  // namespace
}  // namespace fsdb
