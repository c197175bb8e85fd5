// The evaluator end to end in the geometry layer (fuzzy superquadric parts, CsgField, EnvelopeGrid
// at a resolution counted as the server counts it: voxels along the longest side of the bounding
// box) against closed forms: crisp volumes for several (eps1, eps2) pairs and
// with taper, twist and bend at resolution 128; a fuzzy ball per level; union and difference of
// two fuzzy balls against the two-sphere intersection formula; a fuzzy translation's capsule and
// lens.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "geometry/field/csg_field.h"
#include "geometry/superquadric/deformation.h"
#include "geometry/voxel/envelope_grid.h"
#include "geometry/field/fuzzy_part_field.h"
#include "geometry/superquadric/superquadric_volume.h"
#include "tests/geometry/random_superquadric.h"
#include "tests/geometry/sphere_volumes.h"

namespace fsdb {
namespace {

using testing::ballVolume;
using testing::lensVolume;
using testing::makeParams;

const std::vector<double> kAlphas{0.0, 0.5, 1.0};

// The server's grid (server/service/evaluation.cpp): voxel = longest side of the bounding box / resolution.
EnvelopeGrid gridAt(const AlphaFieldSource& field, int resolution) {
  Vec3 lo, hi;
  field.boundingBox(&lo, &hi);
  return EnvelopeGrid::build(field, std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}) / resolution);
}

// A crisp part's grid volume at every level is its closed-form volume, within 1%.
void expectCrispVolume(const PlacedSuperquadric& part, double exact, int resolution) {
  const FuzzyPartField field(FuzzyPart::fromCrisp(part));
  for (const LevelVolume& v : gridAt(field, resolution).volumes(kAlphas)) {
    EXPECT_NEAR(v.upper_volume / exact, 1.0, 0.01) << "alpha " << v.alpha;
    EXPECT_NEAR(v.lower_volume / exact, 1.0, 0.01) << "alpha " << v.alpha;
  }
}

TEST(EnvelopeClosedForms, CrispSuperquadricVolumesForSeveralExponentsAtResolution128) {
  const double pairs[][2] = {{0.5, 0.5}, {1, 1}, {1.5, 0.7}, {2, 2}, {0.3, 1}, {1, 0.3}, {0.7, 1.8}};
  for (const auto& e : pairs) {
    SCOPED_TRACE(::testing::Message() << "eps1 " << e[0] << " eps2 " << e[1]);
    PlacedSuperquadric part;
    part.params = makeParams(e[0], e[1], 1.0, 0.8, 1.3);  // A = 1, B = 0.8, C = 1.3
    expectCrispVolume(part, canonicalVolume(part.params), 128);  // Zhang, Pham & Chen, eq. 8 (beta functions)
  }
}

TEST(EnvelopeClosedForms, TaperedVolumesFollowTheTaperFactorAtResolution128) {
  const double cases[][4] = {{1, 1, 0.8, 0.6}, {0.5, 0.5, -1, 1}, {1.5, 0.7, 1, 1}, {0.3, 1, -0.7, -0.9}};
  for (const auto& c : cases) {
    SCOPED_TRACE(::testing::Message() << "eps " << c[0] << " " << c[1] << " taper " << c[2] << " " << c[3]);
    PlacedSuperquadric part;
    part.params = makeParams(c[0], c[1], 1.0, 0.9, 1.5);
    part.params.kx = c[2];
    part.params.ky = c[3];
    const double factor = taperVolumeFactor(part.params);
    ASSERT_NE(factor, 1.0);  // the taper changes the volume
    expectCrispVolume(part, canonicalVolume(part.params) * factor, 128);
  }
}

TEST(EnvelopeClosedForms, TwistAndBendPreserveTheVolumeAtResolution128) {
  const double cases[][4] = {{1, 1, 2.5, 0.4}, {0.5, 1.5, -3, -0.3}, {1.5, 0.7, 1.2, 0.25}};
  for (const auto& c : cases) {
    SCOPED_TRACE(::testing::Message() << "eps " << c[0] << " " << c[1] << " twist " << c[2] << " bend " << c[3]);
    PlacedSuperquadric part;
    part.params = makeParams(c[0], c[1], 1.0, 0.7, 2.0);
    part.params.t = c[2];
    part.params.kv = c[3];
    ASSERT_TRUE(bendIsInjectiveOnPart(part.params));
    part.placement.axis = {1, -2, 0.5};
    part.placement.deg = 35;
    part.placement.scale = 1.3;
    part.placement.translate = {0.3, -0.2, 0.1};
    // Twist and bend preserve volume: the placed volume is scale³ times the canonical one.
    expectCrispVolume(part, canonicalVolume(part.params) * 1.3 * 1.3 * 1.3, 128);
  }
}

// A fuzzy radius tri(0.8, 1, 1.2): lower(α) and upper(α) are the balls of the cut's ends.
TEST(EnvelopeClosedForms, FuzzyBallVolumesPerLevel) {
  FuzzyPart part;
  part.a1 = FuzzyNumber::triangular(0.8, 1.0, 1.2);
  const FuzzyPartField field(part);
  for (const LevelVolume& v : gridAt(field, 128).volumes(kAlphas)) {
    const double lower = ballVolume(0.8 + 0.2 * v.alpha), upper = ballVolume(1.2 - 0.2 * v.alpha);
    EXPECT_NEAR(v.lower_volume, lower, 0.01 * lower) << "alpha " << v.alpha;
    EXPECT_NEAR(v.upper_volume, upper, 0.01 * upper) << "alpha " << v.alpha;
  }
}

// Two fuzzy balls (fuzzy radii, centres d apart) under the zadeh Booleans of docs/api.md §3: union
// (lower_A ∪ lower_B, upper_A ∪ upper_B), difference (lower_A − upper_B, upper_A − lower_B), so
// each volume is two balls' volumes and a lens.
TEST(EnvelopeClosedForms, UnionAndDifferenceOfTwoFuzzyBallsAgainstTheTwoSphereFormula) {
  const double d = 0.9;
  FuzzyPart a, b;
  a.a1 = FuzzyNumber::triangular(0.6, 0.8, 1.0);
  b.a1 = FuzzyNumber::triangular(0.5, 0.7, 0.9);
  b.tx = FuzzyNumber::crisp(d);
  const std::vector<std::shared_ptr<const AlphaFieldSource>> balls{std::make_shared<FuzzyPartField>(a),
                                                                    std::make_shared<FuzzyPartField>(b)};
  const CsgField unite(CsgOp::kUnion, balls), subtract(CsgOp::kDifference, balls);
  const std::vector<LevelVolume> u = gridAt(unite, 128).volumes(kAlphas), m = gridAt(subtract, 128).volumes(kAlphas);
  const double scale = 0.002 * ballVolume(1.0);  // the small volumes of a difference
  for (size_t i = 0; i < kAlphas.size(); ++i) {
    const double alpha = kAlphas[i];
    const double uA = 1.0 - 0.2 * alpha, lA = 0.6 + 0.2 * alpha, uB = 0.9 - 0.2 * alpha, lB = 0.5 + 0.2 * alpha;
    const double unionUpper = ballVolume(uA) + ballVolume(uB) - lensVolume(uA, uB, d);
    const double unionLower = ballVolume(lA) + ballVolume(lB) - lensVolume(lA, lB, d);
    const double differenceUpper = ballVolume(uA) - lensVolume(uA, lB, d);
    const double differenceLower = ballVolume(lA) - lensVolume(lA, uB, d);
    EXPECT_NEAR(u[i].upper_volume, unionUpper, 0.01 * unionUpper + scale) << "alpha " << alpha;
    EXPECT_NEAR(u[i].lower_volume, unionLower, 0.01 * unionLower + scale) << "alpha " << alpha;
    EXPECT_NEAR(m[i].upper_volume, differenceUpper, 0.01 * differenceUpper + scale) << "alpha " << alpha;
    EXPECT_NEAR(m[i].lower_volume, differenceLower, 0.01 * differenceLower + scale) << "alpha " << alpha;
  }
}

// A unit ball whose x position is tri(−1, 0, 1): at level α it may sit anywhere in
// [−(1 − α), 1 − α], so upper(α) is the capsule swept along that segment and lower(α) the lens
// of its two end balls (2(1 − α) apart).
TEST(EnvelopeClosedForms, FuzzyTranslationIsTheSweptCapsuleAndTheLens) {
  FuzzyPart part;
  part.tx = FuzzyNumber::triangular(-1.0, 0.0, 1.0);
  const FuzzyPartField field(part);
  const double scale = 0.002 * ballVolume(1.0);
  for (const LevelVolume& v : gridAt(field, 128).volumes(kAlphas)) {
    const double length = 2.0 * (1.0 - v.alpha);
    const double capsule = ballVolume(1.0) + M_PI * length, lens = lensVolume(1.0, 1.0, length);
    EXPECT_NEAR(v.upper_volume, capsule, 0.01 * capsule) << "alpha " << v.alpha;
    EXPECT_NEAR(v.lower_volume, lens, 0.01 * lens + scale) << "alpha " << v.alpha;
  }
  EXPECT_EQ(field.budgetExhaustions(), 0u);
}

}  // namespace
}  // namespace fsdb
