// Li & Tian, eq. 4-7: the Bézier operator against its closed forms, its literal double sum, the
// four properties listed after eq. 7 and the chain B_1 <= B_2 <= ... <= min.
#include "geometry/operators/bezier_operator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/core/error.h"

namespace fsdb {
namespace {

std::vector<double> grid(int steps) {
  std::vector<double> g;
  for (int i = 0; i <= steps; ++i) g.push_back(double(i) / steps);
  return g;
}

TEST(BernsteinBasis, PartitionOfUnityAndValues) {
  double b[kMaxBezierDegree + 1];
  for (int n : {1, 2, 5, 17, 64}) {
    for (double t : grid(50)) {
      bernsteinBasis(n, t, b);
      double sum = 0.0;
      for (int k = 0; k <= n; ++k) {
        EXPECT_GE(b[k], 0.0);
        sum += b[k];
      }
      EXPECT_NEAR(sum, 1.0, 1e-13) << n << " " << t;
    }
  }
  bernsteinBasis(3, 0.25, b);  // C(3,k) 0.75^(3-k) 0.25^k
  EXPECT_DOUBLE_EQ(b[0], 0.421875);
  EXPECT_DOUBLE_EQ(b[1], 0.421875);
  EXPECT_DOUBLE_EQ(b[2], 0.140625);
  EXPECT_DOUBLE_EQ(b[3], 0.015625);
  bernsteinBasis(4, 1.0, b);
  EXPECT_EQ(b[4], 1.0);
  EXPECT_EQ(b[0], 0.0);
}

TEST(BezierOperator, ClosedFormsEq5To7) {
  for (double x : grid(20)) {
    for (double y : grid(20)) {
      double xb = 1 - x, yb = 1 - y;
      EXPECT_NEAR(bezierOperator(1, x, y), x * y, 1e-15);                                  // eq. 5
      EXPECT_NEAR(bezierOperator(2, x, y), x * y * (1 + xb * yb), 1e-15);                  // eq. 6
      EXPECT_NEAR(bezierOperator(3, x, y), x * y * (1 + xb * yb * (1 + x * y + xb * yb)),  // eq. 7
                  1e-15);
    }
  }
}

TEST(BezierOperator, FastFormEqualsLiteralDoubleSum) {
  for (int n : {1, 2, 3, 4, 7, 12, 30, 64})
    for (double x : grid(15))
      for (double y : grid(15))
        EXPECT_NEAR(bezierOperator(n, x, y), bezierOperatorLiteral(n, x, y), 1e-14) << n;
}

TEST(BezierOperator, PropertiesAfterEq7) {
  for (int n : {1, 2, 3, 5, 10, 64}) {
    EXPECT_EQ(bezierOperator(n, 0.0, 0.0), 0.0);
    EXPECT_NEAR(bezierOperator(n, 1.0, 1.0), 1.0, 1e-15);
    for (double x : grid(40)) {
      EXPECT_NEAR(bezierOperator(n, x, 0.0), 0.0, 1e-15);  // property 1
      EXPECT_NEAR(bezierOperator(n, 0.0, x), 0.0, 1e-15);
      EXPECT_NEAR(bezierOperator(n, x, 1.0), x, 1e-14);  // property 2
      EXPECT_NEAR(bezierOperator(n, 1.0, x), x, 1e-14);
      for (double y : grid(40)) {
        double v = bezierOperator(n, x, y);
        EXPECT_LE(v, std::min(x, y) + 1e-14);   // property 3
        EXPECT_EQ(v, bezierOperator(n, y, x));  // property 4
      }
    }
  }
}

TEST(BezierOperator, IncreasesWithDegreeTowardsMin) {
  double previousGap = 1.0;
  for (int n = 1; n <= 64; ++n) {
    double gap = 0.0;
    for (double x : grid(25)) {
      for (double y : grid(25)) {
        if (n > 1) {
          EXPECT_LE(bezierOperator(n - 1, x, y), bezierOperator(n, x, y) + 1e-14) << n;
        }
        gap = std::max(gap, std::min(x, y) - bezierOperator(n, x, y));
      }
    }
    EXPECT_LT(gap, previousGap) << n;
    previousGap = gap;
  }
  EXPECT_LT(previousGap, 0.036);  // the figure quoted for the cap in bezier_operator.h
}

TEST(BezierOperator, DegreeOutsideRangeThrows) {
  for (int n : {0, -1, kMaxBezierDegree + 1}) {
    try {
      bezierOperator(n, 0.5, 0.5);
      FAIL() << n;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), errc::kInvalidParameter);
      EXPECT_EQ(e.path(), "n");
    }
    EXPECT_THROW(bezierOperatorLiteral(n, 0.5, 0.5), Error);
  }
}

}  // namespace
}  // namespace fsdb
