// EnvelopeBuildLimits (geometry/voxel/envelope_grid.h): the leaf memory limit, the deadline, and the
// budget exhaustion counts of AlphaFieldSource that a build's caller reports (alpha_field.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <vector>

#include "geometry/field/csg_field.h"
#include "geometry/voxel/envelope_grid.h"
#include "geometry/core/error.h"
#include "geometry/field/fuzzy_part_field.h"
#include "geometry/field/smooth_csg_field.h"
#include "tests/geometry/expect_error.h"
#include "tests/geometry/fuzzy_ball.h"
#include "tests/testing/fuzzy_bench_part.h"
#include "tests/testing/sanitizer_slowdown.h"

namespace fsdb {
namespace {

using Clock = std::chrono::steady_clock;
using Field = std::shared_ptr<const AlphaFieldSource>;

const FuzzyBall kBall({0, 0, 0}, 0.6, 0.8, 1.0);
constexpr double kBallVoxel = 2.2 / 48;  // resolution 48 over the ball's box

std::shared_ptr<const FuzzyPartField> crispSphere(Vec3 at, double r) {
  PlacedSuperquadric s;
  s.placement.translate = at;
  s.placement.scale = r;
  return std::make_shared<FuzzyPartField>(FuzzyPart::fromCrisp(s));
}

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

TEST(EnvelopeBuildLimits, LeafPairBytesIsTwoAllocatedLeaves) {
  // Two buffers of 8³ floats and each leaf's own header; the grid's memory holds at least its leaves.
  EXPECT_GT(EnvelopeGrid::leafPairBytes(), 2u * 512u * sizeof(float));
  EXPECT_LT(EnvelopeGrid::leafPairBytes(), 2u * 512u * sizeof(float) + 512u);
  const EnvelopeGrid grid = EnvelopeGrid::build(kBall, kBallVoxel);
  ASSERT_GT(grid.stats().leafCount, 0u);
  EXPECT_GE(grid.stats().memoryBytes, grid.stats().leafCount * EnvelopeGrid::leafPairBytes());
}

TEST(EnvelopeBuildLimits, MemoryLimitCountsExactlyTheLeavesOfTheGrid) {
  const EnvelopeGrid free = EnvelopeGrid::build(kBall, kBallVoxel);
  const std::uint64_t need = free.stats().leafCount * EnvelopeGrid::leafPairBytes();
  EnvelopeBuildLimits limits;
  limits.maxLeafBytes = need;  // exactly enough
  const EnvelopeGrid fits = EnvelopeGrid::build(kBall, kBallVoxel, limits);
  EXPECT_EQ(fits.stats().leafCount, free.stats().leafCount);
  EXPECT_EQ(fits.volumes({0.5})[0].upper_volume, free.volumes({0.5})[0].upper_volume);
  limits.maxLeafBytes = need - 1;  // one byte short: the last leaf is refused, nothing is returned
  expectError([&] { EnvelopeGrid::build(kBall, kBallVoxel, limits); }, errc::kLimitExceeded, kMaxLeafBytesPath);
  limits.maxLeafBytes = 1;  // tiny: the first leaf already
  expectError([&] { EnvelopeGrid::build(kBall, kBallVoxel, limits); }, errc::kLimitExceeded, kMaxLeafBytesPath);
}

TEST(EnvelopeBuildLimits, ZeroMeansNoLimit) {
  EnvelopeBuildLimits limits;
  limits.maxLeafBytes = 0;
  EXPECT_EQ(EnvelopeGrid::build(kBall, kBallVoxel, limits).stats().leafCount,
            EnvelopeGrid::build(kBall, kBallVoxel).stats().leafCount);
}

// The fourteen-fuzzy part at resolution 64 takes seconds (about 2.3 s at 48 on one core); with a
// deadline the build gives control back long before.
class SlowPartDeadline : public ::testing::Test {
 protected:
  SlowPartDeadline() : field_(testing::allValuesFuzzyPart()) {
    Vec3 lo, hi;
    field_.boundingBox(&lo, &hi);
    voxel_ = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}) / 64;
  }
  FuzzyPartField field_;
  double voxel_ = 0;
};

TEST_F(SlowPartDeadline, PastDeadlineStopsAtOnce) {
  EnvelopeBuildLimits limits;
  limits.deadline = Clock::now() - std::chrono::milliseconds(1);
  const auto start = Clock::now();
  expectError([&] { EnvelopeGrid::build(field_, voxel_, limits); }, errc::kLimitExceeded, kDeadlinePath);
  EXPECT_LT(secondsSince(start), 0.5 * testing::kSlowdown);
}

TEST_F(SlowPartDeadline, DeadlineDuringTheBuildStopsItWithinASearch) {
  EnvelopeBuildLimits limits;
  const auto start = Clock::now();
  limits.deadline = start + std::chrono::milliseconds(150);
  expectError([&] { EnvelopeGrid::build(field_, voxel_, limits); }, errc::kLimitExceeded, kDeadlinePath);
  // The deadline is checked before each voxel's search (BlockLattice::checkpoint), so the build
  // stops about one search past it: 0.18-0.20 s here with two busy loops on both cores. It took
  // 1.7-2.2 s when only blocks checked it (one 8³ block of this part is seconds of searches).
  EXPECT_LT(secondsSince(start), 0.5 * testing::kSlowdown);
}

// A budget of one enclosure makes nearly every search of the fuzzy part run out.
std::shared_ptr<const FuzzyPartField> starvedPart() {
  FuzzyPartFieldOptions options;
  options.evaluationBudget = 1;
  return std::make_shared<FuzzyPartField>(testing::allValuesFuzzyPart(), options);
}

void probe(const AlphaFieldSource& f) {
  Vec3 lo, hi;
  f.boundingBox(&lo, &hi);
  for (int i = 0; i <= 10; ++i) {
    const double t = i / 10.0;
    f.levelsAt({lo.x + t * (hi.x - lo.x), lo.y + t * (hi.y - lo.y), lo.z + t * (hi.z - lo.z)});
  }
}

TEST(BudgetExhaustions, ExactSourcesAndCrispPartsReportNone) {
  probe(kBall);
  EXPECT_EQ(kBall.budgetExhaustions(), 0u);
  const auto sphere = crispSphere({0, 0, 0}, 1.0);
  EnvelopeGrid::build(*sphere, 0.1);
  EXPECT_EQ(sphere->budgetExhaustions(), 0u);
}

TEST(BudgetExhaustions, VirtualOnTheFuzzyPart) {
  const auto part = starvedPart();
  const AlphaFieldSource& asSource = *part;
  probe(asSource);
  EXPECT_GT(asSource.budgetExhaustions(), 0u);
  EXPECT_EQ(asSource.budgetExhaustions(), part->budgetExhaustions());
}

TEST(BudgetExhaustions, CsgNodesSumTheirChildren) {
  const auto a = starvedPart();
  const auto b = starvedPart();
  const auto zadeh = std::make_shared<CsgField>(CsgOp::kUnion, std::vector<Field>{a, crispSphere({3, 0, 0}, 0.5)});
  const Field smooth = makeSmoothCsgNode(CsgOp::kIntersection, OperatorConfig{"algebraic", {}, {}}, {},
                                         {zadeh, b});
  probe(*smooth);
  probe(*zadeh);
  EXPECT_GT(a->budgetExhaustions(), 0u);
  EXPECT_EQ(zadeh->budgetExhaustions(), a->budgetExhaustions());
  EXPECT_EQ(smooth->budgetExhaustions(), a->budgetExhaustions() + b->budgetExhaustions());
}

// A membership that says it ran out n times (no membership of the library searches today).
class CountingMembership : public MembershipField {
 public:
  explicit CountingMembership(std::uint64_t n) : n_(n) {}
  double membership(const Vec3&) const override { return 0.0; }
  MembershipRange membershipOver(const Vec3&, const Vec3&) const override { return {0.0, 0.0}; }
  void boundingBox(Vec3* lo, Vec3* hi) const override { *lo = {0, 0, 0}, *hi = {1, 1, 1}; }
  std::uint64_t budgetExhaustions() const override { return n_; }

 private:
  std::uint64_t n_;
};

TEST(BudgetExhaustions, MembershipNodesSumTheirChildren) {
  const MembershipCsgField node(CsgOp::kUnion, NodeOperator({"algebraic", {}, {}}),
                                {std::make_shared<CountingMembership>(7), std::make_shared<CountingMembership>(5)});
  EXPECT_EQ(node.budgetExhaustions(), 12u);
  // Crisp parts below a smooth node become exact memberships: such a node reports 0.
  const Field crispNode = makeSmoothCsgNode(CsgOp::kUnion, OperatorConfig{"algebraic", {}, {}}, {},
                                            {crispSphere({-0.5, 0, 0}, 1.0), crispSphere({0.5, 0, 0}, 1.0)});
  probe(*crispNode);
  EXPECT_EQ(crispNode->budgetExhaustions(), 0u);
}

}  // namespace
}  // namespace fsdb
