// geometry/node_operator: the (possibility, necessity) algebra of smooth CSG nodes.
#include "geometry/node_operator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "block_lattice.h"
#include "geometry/expect_error.h"

namespace fsdb {
namespace {

const CsgOp kOps[] = {CsgOp::kUnion, CsgOp::kIntersection, CsgOp::kDifference};

// Every binary operator of the catalogue, with its defaults.
std::vector<std::string> binaryOperatorNames() {
  std::vector<std::string> names;
  for (const OperatorSpec& spec : operatorCatalog())
    if (spec.kind == "fuzzy_operator" || spec.kind == "blend") names.push_back(spec.name);
  return names;
}

// A valid point of an alpha field (N = 1 − l <= Π = u), with the special values 0, 1 and
// kNeverInside drawn often.
AlphaLevels randomLevels(std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::uniform_int_distribution<int> pick(0, 3);
  for (;;) {
    const int ku = pick(rng), kl = pick(rng);
    const float u = ku == 0 ? 0.0f : ku == 1 ? 1.0f : unit(rng);
    const float l = kl == 0 ? 0.0f : kl == 1 ? 1.0f : kl == 2 ? kNeverInside : unit(rng);
    if (necessityOf({u, l}) <= u) return {u, l};
  }
}

TEST(NodeOperator, PossibilityAndNecessityOfLevels) {
  EXPECT_EQ(possibilityOf({0.25f, 0.5f}), 0.25);
  EXPECT_EQ(necessityOf({1.0f, 0.25f}), 0.75);
  EXPECT_EQ(necessityOf({1.0f, kNeverInside}), 0.0);
  const AlphaLevels back = levelsFromPossibility(0.75, 0.75);
  EXPECT_EQ(back.upper, 0.75f);
  EXPECT_EQ(back.lower, 0.25f);
  EXPECT_EQ(levelsFromPossibility(0.3, 0.0).lower, kNeverInside);
  EXPECT_EQ(levelsFromPossibility(1.5, 0.0).upper, 1.0f);
  // Rounding: u down, l up, and 1 − l <= u kept, also next to 1 where float ulps differ.
  for (double m : {0.99999997, 0.9999, 1.0 - 1e-12, 0.3 + 1e-12}) {
    const AlphaLevels v = levelsFromPossibility(m, m);
    EXPECT_LE(double(v.upper), m) << m;
    EXPECT_GE(double(v.lower), 1.0 - m) << m;
    EXPECT_LE(necessityOf(v), possibilityOf(v)) << m;
  }
  EXPECT_LT(levelsFromPossibility(1.0 - 1e-12, 0.0).upper, 1.0f);
}

// With T = min the pair rules are alpha_field.h's Booleans, except l = 1 → kNeverInside (the
// measure-zero caveat at α = 1).
TEST(NodeOperator, ZadehIsExactlyTheAlphaCutBooleans) {
  const NodeOperator op({"zadeh", {}, {}});
  std::mt19937 rng(11);
  int lowerOne = 0, never = 0;
  for (int i = 0; i < 200000; ++i) {
    const AlphaLevels a = randomLevels(rng), b = randomLevels(rng);
    for (CsgOp c : kOps) {
      const AlphaLevels ours = op.combine(c, a, b), exact = alphaCombine(c, a, b);
      ASSERT_EQ(ours.upper, exact.upper) << int(c) << " " << a.upper << "," << a.lower << " " << b.upper << "," << b.lower;
      if (exact.lower == 1.0f) {
        ASSERT_EQ(ours.lower, kNeverInside);
        ++lowerOne;
      } else {
        ASSERT_EQ(ours.lower, exact.lower) << int(c) << " " << a.upper << "," << a.lower << " " << b.upper << "," << b.lower;
      }
      never += exact.lower == kNeverInside;
    }
  }
  EXPECT_GT(lowerOne, 1000);  // the special cases were drawn
  EXPECT_GT(never, 1000);
}

// The dip of combine below monotonicity over a grid of [0,1]² (0: monotone on the grid).
double monotonicityDip(const NodeOperator& op, CsgOp c) {
  const int n = 200;
  double dip = 0.0;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = double(i) / n, y0 = double(j) / n, y1 = double(j + 1) / n;
      const double inB = op.combine(c, x, y1) - op.combine(c, x, y0);
      dip = std::max(dip, c == CsgOp::kDifference ? inB : -inB);
      dip = std::max(dip, op.combine(c, y0, x) - op.combine(c, y1, x));
    }
  return dip;
}

TEST(NodeOperator, EveryOperatorFlaggedMonotoneIsMonotoneAndTheOthersDip) {
  for (const std::string& name : binaryOperatorNames()) {
    const NodeOperator op({name, {}, {}});
    double worst = 0.0;
    for (CsgOp c : kOps) worst = std::max(worst, monotonicityDip(op, c));
    if (op.monotone())
      EXPECT_LE(worst, 1e-12) << name;  // rounding only (below the 1e-9 bound margin)
    else
      EXPECT_GT(worst, 1e-6) << name << " is monotone after all: flag it so its bounds prune";
  }
}

TEST(NodeOperator, NecessityNeverExceedsPossibilityForEveryOperator) {
  std::mt19937 rng(5);
  for (const std::string& name : binaryOperatorNames()) {
    const NodeOperator op({name, {}, {}});
    for (int i = 0; i < 20000; ++i) {
      const AlphaLevels a = randomLevels(rng), b = randomLevels(rng);
      for (CsgOp c : kOps) {
        const AlphaLevels r = op.combine(c, a, b);
        ASSERT_LE(necessityOf(r), possibilityOf(r)) << name;
        ASSERT_GE(r.upper, 0.0f);
        ASSERT_LE(r.upper, 1.0f);
      }
    }
  }
}

TEST(NodeOperator, BlendsKeepTheTNormBoundaryValues) {
  for (const char* name : {"ext_max", "int_max"}) {
    const NodeOperator op({name, {}, {}});
    EXPECT_EQ(op.combine(CsgOp::kUnion, 0.0, 0.0), 0.0) << name;
    EXPECT_EQ(op.combine(CsgOp::kUnion, 1.0, 0.3), 1.0) << name;
    EXPECT_EQ(op.combine(CsgOp::kIntersection, 0.0, 0.7), 0.0) << name;
    EXPECT_EQ(op.combine(CsgOp::kIntersection, 1.0, 1.0), 1.0) << name;
    EXPECT_EQ(op.combine(CsgOp::kDifference, 0.0, 0.2), 0.0) << name;
    EXPECT_EQ(op.combine(CsgOp::kDifference, 0.6, 1.0), 0.0) << name;
    EXPECT_EQ(op.combine(CsgOp::kDifference, 1.0, 0.0), 1.0) << name;
  }
  // Without them Ext_max(x, x) = x + delta/4 would fill space: here it is the blend on μ − 1/2.
  const NodeOperator ext({"ext_max", {{"delta", 0.2}, {"epsilon", 0.1}}, {}});
  EXPECT_NEAR(ext.combine(CsgOp::kUnion, 0.3, 0.3), 0.3 + 0.2 / 4, 1e-12);  // seed 001 eq. 18-21
}

TEST(NodeOperator, BlendsActOnMembershipMinusOneHalf) {
  // Int_max(x, x) = x (seed 001 eq. 24): equal memberships pass through; far apart it is max.
  const NodeOperator in({"int_max", {{"epsilon", 0.1}}, {}});
  EXPECT_NEAR(in.combine(CsgOp::kUnion, 0.4, 0.4), 0.4, 1e-12);
  EXPECT_NEAR(in.combine(CsgOp::kUnion, 0.2, 0.9), 0.9, 1e-12);
  // Ext_max is exactly max once |a − b| >= delta + epsilon (seed 001 eq. 19).
  const NodeOperator ext({"ext_max", {{"delta", 0.1}, {"epsilon", 0.05}}, {}});
  EXPECT_NEAR(ext.combine(CsgOp::kUnion, 0.5, 0.2), 0.5, 1e-12);
  EXPECT_NEAR(ext.combine(CsgOp::kIntersection, 0.5, 0.2), 0.2, 1e-12);
  EXPECT_NEAR(ext.combine(CsgOp::kDifference, 0.5, 0.2), 0.5, 1e-12);  // min(0.5, 1 − 0.2)
}

TEST(NodeOperator, BoundsHoldEveryCombinationOfPointsInside) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const std::string& name : binaryOperatorNames()) {
    const NodeOperator op({name, {}, {}});
    for (int box = 0; box < 300; ++box) {
      const AlphaLevels a0 = randomLevels(rng), a1 = randomLevels(rng), b0 = randomLevels(rng), b1 = randomLevels(rng);
      auto boundsOf = [](AlphaLevels x, AlphaLevels y) {
        return AlphaLevelBounds{std::min(x.upper, y.upper), std::max(x.upper, y.upper), std::min(x.lower, y.lower),
                                std::max(x.lower, y.lower)};
      };
      const AlphaLevelBounds ba = boundsOf(a0, a1), bb = boundsOf(b0, b1);
      auto inside = [&](const AlphaLevelBounds& b) {
        for (;;) {
          const float u = float(b.upperMin + unit(rng) * (b.upperMax - b.upperMin));
          const float lo = std::min(b.lowerMin, 1.0f), hi = std::min(b.lowerMax, 1.0f);
          float l = unit(rng) < 0.2 ? b.lowerMax : float(lo + unit(rng) * (hi - lo));
          if (l > 1.0f) l = kNeverInside;
          if (l < b.lowerMin || l > b.lowerMax) continue;
          if (necessityOf({u, l}) <= u) return AlphaLevels{u, l};
        }
      };
      for (CsgOp c : kOps) {
        const AlphaLevelBounds r = op.combine(c, ba, bb);
        for (int k = 0; k < 20; ++k) {
          // Only pairs that are valid levels (N <= Π) are drawn; skip boxes that hold none.
          if (necessityOf({ba.upperMax, ba.lowerMin}) > ba.upperMax || necessityOf({bb.upperMax, bb.lowerMin}) > bb.upperMax)
            break;
          const AlphaLevels v = op.combine(c, inside(ba), inside(bb));
          ASSERT_TRUE(levelsWithin(v, r)) << name;
        }
      }
    }
  }
}

TEST(NodeOperator, BoundsAreExactWhereTheChildrenAreEmpty) {
  const AlphaLevelBounds empty{0.0f, 0.0f, kNeverInside, kNeverInside}, any{};
  for (const std::string& name : binaryOperatorNames()) {
    const NodeOperator op({name, {}, {}});
    EXPECT_TRUE(op.combine(CsgOp::kUnion, empty, empty).uniform()) << name;
    EXPECT_EQ(op.combine(CsgOp::kUnion, empty, empty).upperMax, 0.0f) << name;
    EXPECT_EQ(op.combine(CsgOp::kIntersection, empty, any).upperMax, 0.0f) << name;
    EXPECT_EQ(op.combine(CsgOp::kDifference, empty, any).upperMax, 0.0f) << name;
    EXPECT_EQ(op.combine(CsgOp::kDifference, empty, any).lowerMin, kNeverInside) << name;
  }
}

TEST(NodeOperator, RefusesUnaryFunctionsAndBadParameters) {
  expectInvalidParameter([] { NodeOperator({"polynomial", {}, {}}); }, "name");
  expectInvalidParameter([] { NodeOperator({"bezier", {{"n", 0.0}}, {}}); }, "n");
  expectInvalidParameter([] { NodeOperator({"ext_max", {{"delta", -1.0}}, {}}); }, "delta");
  EXPECT_EQ(NodeOperator({"bezier", {}, {}}).config().params.at("n"), 3.0);  // defaults filled
}

}  // namespace
}  // namespace fsdb
