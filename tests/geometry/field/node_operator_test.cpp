// geometry/field/node_operator: the (possibility, necessity) algebra of smooth CSG nodes.
#include "geometry/field/node_operator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "tests/geometry/block_lattice.h"
#include "tests/geometry/operator_names.h"
#include "tests/geometry/expect_error.h"

namespace fsdb {
namespace {

const CsgOp kOps[] = {CsgOp::kUnion, CsgOp::kIntersection, CsgOp::kDifference};

// A valid point of an alpha field (l <= 1 only where u = 1), with the special values 0, 1 and
// kNeverInside drawn often.
AlphaLevels randomLevels(std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::uniform_int_distribution<int> pick(0, 3);
  const int ku = pick(rng), kl = pick(rng);
  const float u = ku == 0 ? 0.0f : ku <= 2 ? 1.0f : unit(rng);
  if (u < 1.0f) return {u, kNeverInside};
  return {u, kl == 0 ? 0.0f : kl == 1 ? 1.0f : kl == 2 ? kNeverInside : unit(rng)};
}

// Any pair with N <= Π, also ones that break lower ⊆ upper (no source of fsdb makes them).
AlphaLevels randomBrokenLevels(std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (;;) {
    const AlphaLevels v{unit(rng), unit(rng)};
    if (necessityOf(v) <= v.upper) return v;
  }
}

TEST(NodeOperator, PossibilityAndNecessityOfLevels) {
  EXPECT_EQ(possibilityOf({0.25f, kNeverInside}), 0.25);
  EXPECT_EQ(necessityOf({1.0f, 0.25f}), 0.75);
  EXPECT_EQ(necessityOf({1.0f, kNeverInside}), 0.0);
  const AlphaLevels back = levelsFromPossibility(1.0, 0.75);
  EXPECT_EQ(back.upper, 1.0f);
  EXPECT_EQ(back.lower, 0.25f);
  EXPECT_EQ(levelsFromPossibility(0.3, 0.0).lower, kNeverInside);
  EXPECT_EQ(levelsFromPossibility(1.5, 0.0).upper, 1.0f);
  // N > 0 only where Π = 1: below it the point is in no lower(α) (lower only shrinks).
  EXPECT_EQ(levelsFromPossibility(0.75, 0.75).upper, 0.75f);
  EXPECT_EQ(levelsFromPossibility(0.75, 0.75).lower, kNeverInside);
  // Rounding: u down, l up; u = 1 only where Π >= 1, also next to 1 where float ulps differ.
  for (double m : {0.99999997, 0.9999, 1.0 - 1e-12, 0.3 + 1e-12}) {
    EXPECT_LE(double(levelsFromPossibility(m, 0.0).upper), m) << m;
    EXPECT_LT(levelsFromPossibility(m, m).upper, 1.0f) << m;
    EXPECT_EQ(levelsFromPossibility(m, m).lower, kNeverInside) << m;
    EXPECT_GE(double(levelsFromPossibility(1.0, m).lower), 1.0 - m) << m;
  }
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

// The axiom N > 0 ⇒ Π = 1 carries over through the boundary values for every operator, without
// the enforcement of levelsFromPossibility (the raw N', Π' are checked); and with children that
// break it, the enforcement still gives lower ⊆ upper.
TEST(NodeOperator, EveryOperatorKeepsLowerInsideUpper) {
  std::mt19937 rng(5);
  for (const std::string& name : binaryOperatorNames()) {
    const NodeOperator op({name, {}, {}});
    for (int i = 0; i < 20000; ++i) {
      const AlphaLevels a = randomLevels(rng), b = randomLevels(rng);
      for (CsgOp c : kOps) {
        const bool difference = c == CsgOp::kDifference;
        const double p = op.combine(c, possibilityOf(a), difference ? necessityOf(b) : possibilityOf(b));
        const double n = op.combine(c, necessityOf(a), difference ? possibilityOf(b) : necessityOf(b));
        ASSERT_TRUE(n <= 0.0 || p == 1.0) << name << " " << int(c) << ": N' = " << n << ", Π' = " << p;
        const AlphaLevels r = op.combine(c, a, b);
        ASSERT_TRUE(lowerInsideUpper(r)) << name;
        ASSERT_GE(r.upper, 0.0f);
        ASSERT_LE(r.upper, 1.0f);
      }
      for (CsgOp c : kOps) ASSERT_TRUE(lowerInsideUpper(op.combine(c, randomBrokenLevels(rng), randomBrokenLevels(rng)))) << name;
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
  EXPECT_NEAR(ext.combine(CsgOp::kUnion, 0.3, 0.3), 0.3 + 0.2 / 4, 1e-12);  // Li, eq. 18-21
}

TEST(NodeOperator, BlendsActOnMembershipMinusOneHalf) {
  // Int_max(x, x) = x (Li, eq. 24): equal memberships pass through; far apart it is max.
  const NodeOperator in({"int_max", {{"epsilon", 0.1}}, {}});
  EXPECT_NEAR(in.combine(CsgOp::kUnion, 0.4, 0.4), 0.4, 1e-12);
  EXPECT_NEAR(in.combine(CsgOp::kUnion, 0.2, 0.9), 0.9, 1e-12);
  // Ext_max is exactly max once |a − b| >= delta + epsilon (Li, eq. 19).
  const NodeOperator ext({"ext_max", {{"delta", 0.1}, {"epsilon", 0.05}}, {}});
  EXPECT_NEAR(ext.combine(CsgOp::kUnion, 0.5, 0.2), 0.5, 1e-12);
  EXPECT_NEAR(ext.combine(CsgOp::kIntersection, 0.5, 0.2), 0.2, 1e-12);
  EXPECT_NEAR(ext.combine(CsgOp::kDifference, 0.5, 0.2), 0.5, 1e-12);  // min(0.5, 1 − 0.2)
}

TEST(NodeOperator, BoundsHoldEveryCombinationOfPointsInside) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  long checked = 0;
  for (const std::string& name : binaryOperatorNames()) {
    const NodeOperator op({name, {}, {}});
    for (int box = 0; box < 300; ++box) {
      const AlphaLevels a0 = randomLevels(rng), a1 = randomLevels(rng), b0 = randomLevels(rng), b1 = randomLevels(rng);
      auto boundsOf = [](AlphaLevels x, AlphaLevels y) {
        return AlphaLevelBounds{std::min(x.upper, y.upper), std::max(x.upper, y.upper), std::min(x.lower, y.lower),
                                std::max(x.lower, y.lower)};
      };
      const AlphaLevelBounds ba = boundsOf(a0, a1), bb = boundsOf(b0, b1);
      // A valid pair (randomLevels' kind) within the bounds b; false when none was drawn.
      auto inside = [&](const AlphaLevelBounds& b, AlphaLevels* v) {
        for (int tries = 0; tries < 100; ++tries) {
          const float u = unit(rng) < 0.3 ? b.upperMax : float(b.upperMin + unit(rng) * (b.upperMax - b.upperMin));
          const float lo = std::min(b.lowerMin, 1.0f), hi = std::min(b.lowerMax, 1.0f);
          float l = unit(rng) < 0.3 ? b.lowerMax : float(lo + unit(rng) * (hi - lo));
          if (l > 1.0f) l = kNeverInside;
          if (l < b.lowerMin || l > b.lowerMax || (l <= 1.0f && u < 1.0f)) continue;
          *v = {u, l};
          return true;
        }
        return false;
      };
      for (CsgOp c : kOps) {
        const AlphaLevelBounds r = op.combine(c, ba, bb);
        for (int k = 0; k < 20; ++k) {
          AlphaLevels va, vb;
          if (!inside(ba, &va) || !inside(bb, &vb)) continue;
          const AlphaLevels v = op.combine(c, va, vb);
          ASSERT_TRUE(levelsWithin(v, r)) << name;
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 100000);
}

TEST(NodeOperator, MembershipBoundsHoldEveryCombinationInside) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto end = [&] {
    const double x = unit(rng);
    return x < 0.15 ? 0.0 : x > 0.85 ? 1.0 : unit(rng);
  };
  for (const std::string& name : binaryOperatorNames()) {
    const NodeOperator op({name, {}, {}});
    for (int box = 0; box < 2000; ++box) {
      const double a0 = end(), a1 = end(), b0 = end(), b1 = end();
      const MembershipRange a{std::min(a0, a1), std::max(a0, a1)}, b{std::min(b0, b1), std::max(b0, b1)};
      for (CsgOp c : kOps) {
        const MembershipRange r = op.combine(c, a, b);
        for (int k = 0; k < 10; ++k) {
          const double x = a.lo + unit(rng) * (a.hi - a.lo), y = b.lo + unit(rng) * (b.hi - b.lo);
          const double v = op.combine(c, k == 0 ? a.lo : k == 1 ? a.hi : x, k == 0 ? b.hi : k == 1 ? b.lo : y);
          ASSERT_GE(v, r.lo) << name << " " << int(c);
          ASSERT_LE(v, r.hi) << name << " " << int(c);
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
