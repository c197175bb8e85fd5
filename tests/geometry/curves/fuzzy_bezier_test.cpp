// Fuzzy Bézier curves and surfaces: the properties Sarwar & Akram list, checked on random fuzzy
// control points (fixed seeds), and the rational hull against brute force.
#include "geometry/curves/fuzzy_bezier.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_arithmetic.h"
#include "tests/geometry/expect_error.h"
#include "tests/testing/random_fuzzy.h"

namespace fsdb {
namespace {

using testing::randomTriangular;
using testing::randomTriOrTrap;
using testing::uniform;

constexpr double kTol = 1e-9;

FuzzyBezierCurve randomCurve(std::mt19937& rng, std::size_t n, std::size_t dim, bool trapezoids = false) {
  FuzzyBezierCurve c;
  for (std::size_t k = 0; k < n; ++k) {
    FuzzyPoint p;
    for (std::size_t d = 0; d < dim; ++d) p.push_back(trapezoids ? randomTriOrTrap(rng) : randomTriangular(rng));
    c.controlPoints.push_back(p);
  }
  return c;
}

FuzzyBezierSurface randomSurface(std::mt19937& rng, std::size_t rows, std::size_t columns) {
  FuzzyBezierSurface s;
  for (std::size_t i = 0; i < rows; ++i) s.controlGrid.push_back(randomCurve(rng, columns, 3).controlPoints);
  return s;
}

FuzzyNumber randomWeight(std::mt19937& rng) {
  const double m = uniform(rng, 0.5, 3);
  return FuzzyNumber::triangular(m - uniform(rng, 0, 0.4), m, m + uniform(rng, 0, 1));
}

void expectNear(const CrispPoint& a, const CrispPoint& b, double tol, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t c = 0; c < a.size(); ++c) EXPECT_NEAR(a[c], b[c], tol) << what << " coordinate " << c;
}

void expectSamePoint(const FuzzyBezierPoint& a, const FuzzyBezierPoint& b, double tol, const std::string& what) {
  expectNear(a.lower, b.lower, tol, what + " lower");
  expectNear(a.crisp, b.crisp, tol, what + " crisp");
  expectNear(a.upper, b.upper, tol, what + " upper");
}

// Levels a1 <= a2 and the nesting lower(a1) <= lower(a2) <= crisp <= upper(a2) <= upper(a1).
std::pair<double, double> orderedLevels(std::mt19937& rng) {
  const double a = uniform(rng, 0, 1), b = uniform(rng, 0, 1);
  return {std::min(a, b), std::max(a, b)};
}

void expectNested(const FuzzyBezierPoint& p1, const FuzzyBezierPoint& p2) {
  for (std::size_t d = 0; d < p1.lower.size(); ++d) {
    EXPECT_LE(p1.lower[d], p2.lower[d] + kTol) << d;
    EXPECT_LE(p2.lower[d], p2.crisp[d] + kTol) << d;
    EXPECT_LE(p2.crisp[d], p2.upper[d] + kTol) << d;
    EXPECT_LE(p2.upper[d], p1.upper[d] + kTol) << d;
  }
}

// Ends near the double range: the crisp midpoint of a core [1e308, 1e308] is 1e308 (it was
// (lo + hi) / 2 = inf, shown as null), and values that do overflow are refused, never inf or NaN.
TEST(FuzzyBezier, HugeCoordinatesStayFiniteOrAreRefused) {
  FuzzyBezierCurve big;
  big.controlPoints = {{FuzzyNumber::crisp(1e308), FuzzyNumber::crisp(-1e308)},
                       {FuzzyNumber::crisp(1e308), FuzzyNumber::crisp(1e308)}};
  const FuzzyBezierPoint p = evaluateCurve(big, 0.5, 0.0);
  EXPECT_EQ(p.crisp, (CrispPoint{1e308, 0.0}));
  EXPECT_EQ(p.lower, p.crisp);
  FuzzyBezierCurve rational;
  for (int k = 0; k < 3; ++k) {
    rational.controlPoints.push_back({FuzzyNumber::triangular(-1e308, 0, 1e308), FuzzyNumber::crisp(1)});
    rational.weights.push_back(FuzzyNumber::triangular(1e-300, 1, 1e300));
  }
  try {
    evaluateCurve(rational, 0.5, 0.0);
    ADD_FAILURE() << "an overflowing hull was returned";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kDomainError);
    EXPECT_EQ(e.path(), "control_points");
  }
  EXPECT_NO_THROW(evaluateCurve(rational, 0.5, 1.0));  // the core is finite
}

TEST(FuzzyBezier, TriangularCutIsTheSeedFormula) {
  // Sarwar & Akram, eq. 3: [l + α(m − l), r − α(r − m)].
  const FuzzyNumber a = FuzzyNumber::triangular(1, 2, 4);
  FuzzyBezierCurve c{{{a}}, {}};
  const FuzzyBezierPoint p = evaluateCurve(c, 0.3, 0.25);
  EXPECT_NEAR(p.lower[0], 1 + 0.25 * (2 - 1), kTol);
  EXPECT_NEAR(p.upper[0], 4 - 0.25 * (4 - 2), kTol);
  EXPECT_NEAR(p.crisp[0], 2, kTol);
}

TEST(FuzzyBezier, InterpolatesTheEndControlPoints) {
  std::mt19937 rng(1);
  for (int trial = 0; trial < 20; ++trial) {
    const FuzzyBezierCurve c = randomCurve(rng, 2 + trial % 5, 2 + trial % 2, true);
    const double alpha = uniform(rng, 0, 1);
    for (double u : {0.0, 1.0}) {
      const FuzzyPoint& end = u == 0 ? c.controlPoints.front() : c.controlPoints.back();
      const FuzzyBezierPoint p = evaluateCurve(c, u, alpha);
      for (std::size_t d = 0; d < end.size(); ++d) {
        EXPECT_NEAR(p.lower[d], end[d].alphaCut(alpha).lo, kTol);
        EXPECT_NEAR(p.upper[d], end[d].alphaCut(alpha).hi, kTol);
        EXPECT_NEAR(p.crisp[d], 0.5 * (end[d].core().lo + end[d].core().hi), kTol);
      }
    }
  }
}

TEST(FuzzyBezier, DeCasteljauEqualsTheBernsteinForm) {
  std::mt19937 rng(2);
  for (int trial = 0; trial < 20; ++trial) {
    const FuzzyBezierCurve c = randomCurve(rng, 1 + trial % 8, 3, true);
    const double alpha = uniform(rng, 0, 1), u = uniform(rng, 0, 1);
    const FuzzyBezierPoint p = evaluateCurve(c, u, alpha);
    const std::size_t r = c.degree();
    for (std::size_t d = 0; d < 3; ++d) {
      double lo = 0, hi = 0;
      for (std::size_t k = 0; k <= r; ++k) {
        lo += bernstein(r, k, u) * c.controlPoints[k][d].alphaCut(alpha).lo;
        hi += bernstein(r, k, u) * c.controlPoints[k][d].alphaCut(alpha).hi;
      }
      EXPECT_NEAR(p.lower[d], lo, 1e-9);
      EXPECT_NEAR(p.upper[d], hi, 1e-9);
    }
  }
}

TEST(FuzzyBezier, BernsteinBasisIsAPartitionOfUnity) {
  for (std::size_t r : {0u, 1u, 3u, 10u})
    for (double u : {0.0, 0.2, 0.5, 1.0}) {
      double sum = 0;
      for (std::size_t k = 0; k <= r; ++k) {
        EXPECT_GE(bernstein(r, k, u), 0.0);
        sum += bernstein(r, k, u);
      }
      EXPECT_NEAR(sum, 1.0, 1e-12);
    }
  EXPECT_EQ(bernstein(3, 4, 0.5), 0.0);
  for (std::size_t r : {0u, 1u, 5u, 17u})
    for (double u : {0.0, 0.3, 1.0}) {
      const std::vector<double> basis = bernsteinBasis(r, u);
      ASSERT_EQ(basis.size(), r + 1);
      for (std::size_t k = 0; k <= r; ++k) EXPECT_NEAR(basis[k], bernstein(r, k, u), 1e-14) << r << " " << k;
    }
  // Degree 2000: the closed form's binomial overflows, the recurrence does not.
  const std::vector<double> high = bernsteinBasis(2000, 0.5);
  double sum = 0;
  for (double b : high) sum += b;
  EXPECT_NEAR(sum, 1.0, 1e-9);
}

TEST(FuzzyBezier, LiesInTheConvexHullOfTheCuts) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 30; ++trial) {
    const FuzzyBezierCurve c = randomCurve(rng, 2 + trial % 6, 2, true);
    const double alpha = uniform(rng, 0, 1), u = uniform(rng, 0, 1);
    const FuzzyBezierPoint p = evaluateCurve(c, u, alpha);
    for (std::size_t d = 0; d < 2; ++d) {
      double lo = 1e300, hi = -1e300;
      for (const FuzzyPoint& q : c.controlPoints) {
        lo = std::min(lo, q[d].alphaCut(alpha).lo);
        hi = std::max(hi, q[d].alphaCut(alpha).hi);
      }
      EXPECT_GE(p.lower[d], lo - kTol);
      EXPECT_LE(p.upper[d], hi + kTol);
    }
  }
}

TEST(FuzzyBezier, AffineMapsCommuteWithEvaluation) {
  // Sarwar & Akram, §2 affine invariance: mapping the fuzzy control points by x ↦ A x + b (fuzzy
  // arithmetic) and evaluating gives the interval image of the evaluated box.
  std::mt19937 rng(4);
  const double A[2][2] = {{0.8, -1.5}, {2.0, 0.3}};
  const double b[2] = {3.0, -1.0};
  for (int trial = 0; trial < 10; ++trial) {
    const FuzzyBezierCurve c = randomCurve(rng, 4, 2);
    FuzzyBezierCurve mapped;
    for (const FuzzyPoint& p : c.controlPoints) {
      FuzzyPoint q;
      for (int row = 0; row < 2; ++row)
        q.push_back(add(add(scale(p[0], A[row][0]), scale(p[1], A[row][1])), FuzzyNumber::crisp(b[row])));
      mapped.controlPoints.push_back(q);
    }
    const double alpha = uniform(rng, 0, 1), u = uniform(rng, 0, 1);
    const FuzzyBezierPoint p = evaluateCurve(c, u, alpha), m = evaluateCurve(mapped, u, alpha);
    for (int row = 0; row < 2; ++row) {
      double lo = b[row], hi = b[row], crisp = b[row];
      for (int col = 0; col < 2; ++col) {
        lo += std::min(A[row][col] * p.lower[col], A[row][col] * p.upper[col]);
        hi += std::max(A[row][col] * p.lower[col], A[row][col] * p.upper[col]);
        crisp += A[row][col] * p.crisp[col];
      }
      EXPECT_NEAR(m.lower[row], lo, 1e-9);
      EXPECT_NEAR(m.upper[row], hi, 1e-9);
      EXPECT_NEAR(m.crisp[row], crisp, 1e-9);
    }
  }
}

TEST(FuzzyBezier, EndTangentsAreTheFirstAndLastLegs) {
  // Sarwar & Akram, §2: C'(0) = r (P_1 − P_0), C'(1) = r (P_r − P_{r−1}), on every end curve.
  std::mt19937 rng(5);
  const double h = 1e-6;
  for (int trial = 0; trial < 10; ++trial) {
    const FuzzyBezierCurve c = randomCurve(rng, 2 + trial % 5, 2);
    const double alpha = uniform(rng, 0, 1), r = static_cast<double>(c.degree());
    const FuzzyBezierPoint p0 = evaluateCurve(c, 0, alpha), ph = evaluateCurve(c, h, alpha);
    const FuzzyBezierPoint p1 = evaluateCurve(c, 1, alpha), p1h = evaluateCurve(c, 1 - h, alpha);
    const auto& P = c.controlPoints;
    const std::size_t n = P.size() - 1;
    for (std::size_t d = 0; d < 2; ++d) {
      EXPECT_NEAR((ph.lower[d] - p0.lower[d]) / h, r * (P[1][d].alphaCut(alpha).lo - P[0][d].alphaCut(alpha).lo), 1e-3);
      EXPECT_NEAR((ph.upper[d] - p0.upper[d]) / h, r * (P[1][d].alphaCut(alpha).hi - P[0][d].alphaCut(alpha).hi), 1e-3);
      EXPECT_NEAR((p1.crisp[d] - p1h.crisp[d]) / h, r * (P[n][d].core().lo - P[n - 1][d].core().lo), 1e-3);
    }
  }
}

TEST(FuzzyBezier, AlphaCutsAreNested) {
  std::mt19937 rng(6);
  for (int trial = 0; trial < 30; ++trial) {
    const FuzzyBezierCurve c = randomCurve(rng, 2 + trial % 6, 3, true);
    const auto [a1, a2] = orderedLevels(rng);
    const double u = uniform(rng, 0, 1);
    expectNested(evaluateCurve(c, u, a1), evaluateCurve(c, u, a2));
  }
}

TEST(FuzzyBezier, SurfaceCutsAreNestedAndInterpolateTheCorners) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 10; ++trial) {
    const FuzzyBezierSurface s = randomSurface(rng, 2 + trial % 3, 2 + trial % 4);
    const auto [a1, a2] = orderedLevels(rng);
    const double u = uniform(rng, 0, 1), v = uniform(rng, 0, 1);
    expectNested(evaluateSurface(s, u, v, a1), evaluateSurface(s, u, v, a2));
    const auto& g = s.controlGrid;
    const FuzzyBezierPoint corner = evaluateSurface(s, 1, 0, a1);
    for (std::size_t d = 0; d < 3; ++d) {
      EXPECT_NEAR(corner.lower[d], g.back().front()[d].alphaCut(a1).lo, kTol);
      EXPECT_NEAR(corner.upper[d], g.back().front()[d].alphaCut(a1).hi, kTol);
    }
  }
}

TEST(FuzzyBezier, SurfaceEqualsTheTensorProductBernsteinForm) {
  std::mt19937 rng(8);
  const FuzzyBezierSurface s = randomSurface(rng, 3, 4);
  const double u = 0.3, v = 0.65, alpha = 0.4;
  const FuzzyBezierPoint p = evaluateSurface(s, u, v, alpha);
  for (std::size_t d = 0; d < 3; ++d) {
    double lo = 0, hi = 0;
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 4; ++j) {
        const double w = bernstein(2, i, u) * bernstein(3, j, v);
        lo += w * s.controlGrid[i][j][d].alphaCut(alpha).lo;
        hi += w * s.controlGrid[i][j][d].alphaCut(alpha).hi;
      }
    EXPECT_NEAR(p.lower[d], lo, 1e-9);
    EXPECT_NEAR(p.upper[d], hi, 1e-9);
  }
}

TEST(FuzzyBezier, IsoParametricCurvesLieOnTheSurface) {
  std::mt19937 rng(9);
  const FuzzyBezierSurface s = randomSurface(rng, 3, 4);
  for (double v : {0.0, 0.25, 1.0}) {
    const FuzzyBezierCurve iso = isoCurveU(s, v);
    ASSERT_EQ(iso.controlPoints.size(), 3u);
    for (double u : {0.0, 0.4, 0.9})
      for (double alpha : {0.0, 0.5, 1.0})
        expectSamePoint(evaluateCurve(iso, u, alpha), evaluateSurface(s, u, v, alpha), 1e-9, "u iso-curve");
  }
  // v = 0: the boundary curve of the first column of control points (Sarwar & Akram, §2).
  const FuzzyBezierCurve boundary = isoCurveU(s, 0);
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t d = 0; d < 3; ++d) EXPECT_EQ(boundary.controlPoints[i][d], s.controlGrid[i][0][d]);
  const FuzzyBezierCurve isoV = isoCurveV(s, 0.7);
  ASSERT_EQ(isoV.controlPoints.size(), 4u);
  for (double v : {0.0, 0.3, 1.0})
    expectSamePoint(evaluateCurve(isoV, v, 0.3), evaluateSurface(s, 0.7, v, 0.3), 1e-9, "v iso-curve");
}

TEST(FuzzyBezier, DegreeElevationKeepsTheCurve) {
  std::mt19937 rng(10);
  for (int trial = 0; trial < 10; ++trial) {
    const FuzzyBezierCurve c = randomCurve(rng, 1 + trial % 5, 2, true);
    const int times = 1 + trial % 3;
    const FuzzyBezierCurve e = elevateCurve(c, times);
    ASSERT_EQ(e.controlPoints.size(), c.controlPoints.size() + times);
    for (double u : {0.0, 0.17, 0.5, 0.83, 1.0})
      for (double alpha : {0.0, 0.3, 1.0})
        expectSamePoint(evaluateCurve(e, u, alpha), evaluateCurve(c, u, alpha), 1e-9, "elevated");
  }
}

TEST(FuzzyBezier, DegreeElevationOfAQuadraticFollowsTheSeedRatio) {
  // Sarwar & Akram, Example 3 pattern: P'_1 = 1/3 P_0 + 2/3 P_1, P'_2 = 2/3 P_1 + 1/3 P_2.
  const FuzzyNumber p0 = FuzzyNumber::triangular(0, 1, 2), p1 = FuzzyNumber::triangular(3, 4, 6),
                    p2 = FuzzyNumber::triangular(6, 7, 7.5);
  const FuzzyBezierCurve e = elevateCurve({{{p0}, {p1}, {p2}}, {}}, 1);
  ASSERT_EQ(e.controlPoints.size(), 4u);
  EXPECT_EQ(e.controlPoints[0][0], p0);
  const FuzzyNumber expected1 = FuzzyNumber::triangular(2, 3, 14.0 / 3);
  const Interval got = e.controlPoints[1][0].support();
  EXPECT_NEAR(got.lo, expected1.support().lo, 1e-12);
  EXPECT_NEAR(got.hi, expected1.support().hi, 1e-12);
  EXPECT_NEAR(e.controlPoints[2][0].core().lo, 2.0 / 3 * 4 + 1.0 / 3 * 7, 1e-12);
  EXPECT_EQ(e.controlPoints[3][0], p2);
}

TEST(FuzzyBezier, SurfaceDegreeElevationKeepsTheSurface) {
  std::mt19937 rng(11);
  const FuzzyBezierSurface s = randomSurface(rng, 2, 3);
  const FuzzyBezierSurface e = elevateSurface(s, 2, 1);
  ASSERT_EQ(e.controlGrid.size(), 4u);
  ASSERT_EQ(e.controlGrid[0].size(), 4u);
  for (double u : {0.0, 0.3, 1.0})
    for (double v : {0.0, 0.6, 1.0})
      for (double alpha : {0.0, 0.5, 1.0})
        expectSamePoint(evaluateSurface(e, u, v, alpha), evaluateSurface(s, u, v, alpha), 1e-9, "elevated surface");
}

TEST(FuzzyBezier, RationalWithEqualWeightsIsThePolynomialCurve) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 10; ++trial) {
    FuzzyBezierCurve c = randomCurve(rng, 2 + trial % 5, 2, true);
    const FuzzyBezierCurve polynomial = c;
    c.weights.assign(c.controlPoints.size(), FuzzyNumber::crisp(uniform(rng, 0.1, 5)));
    for (double u : {0.0, 0.2, 0.7, 1.0})
      for (double alpha : {0.0, 0.6, 1.0})
        expectSamePoint(evaluateCurve(c, u, alpha), evaluateCurve(polynomial, u, alpha), 1e-9, "equal weights");
  }
}

TEST(FuzzyBezier, RationalCrispCurveIsTheProjectedHomogeneousCurve) {
  std::mt19937 rng(13);
  FuzzyBezierCurve c = randomCurve(rng, 4, 2);
  for (int k = 0; k < 4; ++k) c.weights.push_back(randomWeight(rng));
  const double u = 0.37;
  const FuzzyBezierPoint p = evaluateCurve(c, u, 0.5);
  for (std::size_t d = 0; d < 2; ++d) {
    double num = 0, den = 0;
    for (std::size_t k = 0; k < 4; ++k) {
      const double w = bernstein(3, k, u) * c.weights[k].core().lo;
      num += w * c.controlPoints[k][d].core().lo;
      den += w;
    }
    EXPECT_NEAR(p.crisp[d], num / den, 1e-9);
  }
}

TEST(FuzzyBezier, RationalBoundsAreTheHullOverTheCuts) {
  // Brute force over every corner of the weight box (the extremes of a linear-fractional
  // function lie at corners) with the matching point ends.
  std::mt19937 rng(14);
  for (int trial = 0; trial < 20; ++trial) {
    const std::size_t n = 2 + trial % 4;
    FuzzyBezierCurve c = randomCurve(rng, n, 2);
    for (std::size_t k = 0; k < n; ++k) c.weights.push_back(randomWeight(rng));
    const double alpha = uniform(rng, 0, 1), u = uniform(rng, 0, 1);
    const FuzzyBezierPoint p = evaluateCurve(c, u, alpha);
    for (std::size_t d = 0; d < 2; ++d) {
      double lo = 1e300, hi = -1e300;
      for (unsigned mask = 0; mask < (1u << n); ++mask) {
        double numLo = 0, numHi = 0, den = 0;
        for (std::size_t k = 0; k < n; ++k) {
          const Interval w = c.weights[k].alphaCut(alpha);
          const double wk = bernstein(n - 1, k, u) * ((mask >> k) & 1 ? w.hi : w.lo);
          numLo += wk * c.controlPoints[k][d].alphaCut(alpha).lo;
          numHi += wk * c.controlPoints[k][d].alphaCut(alpha).hi;
          den += wk;
        }
        lo = std::min(lo, numLo / den);
        hi = std::max(hi, numHi / den);
      }
      EXPECT_NEAR(p.lower[d], lo, 1e-9);
      EXPECT_NEAR(p.upper[d], hi, 1e-9);
      EXPECT_LE(p.lower[d], p.crisp[d] + kTol);
      EXPECT_LE(p.crisp[d], p.upper[d] + kTol);
    }
  }
}

TEST(FuzzyBezier, RationalCutsAreNested) {
  std::mt19937 rng(15);
  for (int trial = 0; trial < 20; ++trial) {
    FuzzyBezierCurve c = randomCurve(rng, 3 + trial % 3, 2, true);
    for (std::size_t k = 0; k < c.controlPoints.size(); ++k) c.weights.push_back(randomWeight(rng));
    const auto [a1, a2] = orderedLevels(rng);
    const double u = uniform(rng, 0, 1);
    expectNested(evaluateCurve(c, u, a1), evaluateCurve(c, u, a2));
  }
}

TEST(FuzzyBezier, RationalElevationWithCrispWeightsKeepsTheCurve) {
  std::mt19937 rng(16);
  FuzzyBezierCurve c = randomCurve(rng, 4, 2);
  for (std::size_t k = 0; k < 4; ++k) c.weights.push_back(FuzzyNumber::crisp(uniform(rng, 0.5, 3)));
  const FuzzyBezierCurve e = elevateCurve(c, 2);
  ASSERT_EQ(e.weights.size(), 6u);
  for (double u : {0.0, 0.3, 0.8, 1.0})
    for (double alpha : {0.0, 0.5, 1.0})
      expectSamePoint(evaluateCurve(e, u, alpha), evaluateCurve(c, u, alpha), 1e-9, "elevated rational");
}

TEST(FuzzyBezier, DefuzzifiesTrianglesToTheirCentroid) {
  const FuzzyBezierCurve c{{{FuzzyNumber::triangular(0, 1, 5), FuzzyNumber::crisp(2)},
                            {FuzzyNumber::triangular(3, 3, 6), FuzzyNumber::triangular(-1, 0, 1)}},
                           {FuzzyNumber::triangular(1, 2, 3), FuzzyNumber::crisp(1)}};
  const CrispBezierCurve d = defuzzifyCurve(c, Defuzzifier::kCentroid);
  EXPECT_NEAR(d.controlPoints[0][0], 2.0, 1e-12);  // (l + m + r) / 3
  EXPECT_NEAR(d.controlPoints[0][1], 2.0, 1e-12);
  EXPECT_NEAR(d.controlPoints[1][0], 4.0, 1e-12);
  EXPECT_NEAR(d.weights[0], 2.0, 1e-12);
  EXPECT_NEAR(defuzzifyCurve(c, Defuzzifier::kMeanOfMaxima).controlPoints[0][0], 1.0, 1e-12);
  const FuzzyBezierSurface s{{c.controlPoints}};
  EXPECT_NEAR(defuzzifySurface(s, Defuzzifier::kLargestOfMaxima)[0][1][0], 3.0, 1e-12);
}

TEST(FuzzyBezier, CutsOnceEvaluatesAlike) {
  std::mt19937 rng(17);
  FuzzyBezierCurve c = randomCurve(rng, 5, 3, true);
  const FuzzyBezierSurface s = randomSurface(rng, 3, 2);
  const BezierCurveCut cut = cutCurve(c, 0.4);
  const BezierSurfaceCut surfaceCut = cutSurface(s, 0.4);
  for (double u : {0.0, 0.3, 1.0}) {
    expectSamePoint(evaluateCut(cut, u), evaluateCurve(c, u, 0.4), 0, "curve cut");
    expectSamePoint(evaluateCut(surfaceCut, u, 1 - u), evaluateSurface(s, u, 1 - u, 0.4), 0, "surface cut");
  }
  for (std::size_t k = 0; k < c.controlPoints.size(); ++k) c.weights.push_back(randomWeight(rng));
  expectSamePoint(evaluateCut(cutCurve(c, 0.7), 0.6), evaluateCurve(c, 0.6, 0.7), 0, "rational cut");
  expectInvalidParameter([&] { evaluateCut(cut, 1.01); }, "u");
  expectInvalidParameter([&] { evaluateCut(surfaceCut, 0.5, -0.5); }, "v");
  expectInvalidParameter([&] { cutCurve(c, 1.5); }, "alpha");
}

TEST(FuzzyBezier, RejectsMalformedInput) {
  auto expectDocumentError = [](auto f, const std::string& path) { expectError(f, errc::kInvalidDocument, path); };
  const FuzzyNumber one = FuzzyNumber::crisp(1);
  expectDocumentError([] { evaluateCurve({}, 0.5, 0.5); }, "control_points");
  expectDocumentError([&] { evaluateCurve({{{one, one}, {one}}, {}}, 0.5, 0.5); }, "control_points[1]");
  expectDocumentError([&] { evaluateCurve({{{one}, {one}}, {one}}, 0.5, 0.5); }, "weights");
  expectDocumentError([&] { evaluateCurve({{{one}, {one}}, {one, FuzzyNumber::triangular(0, 1, 2)}}, 0.5, 0.5); },
                      "weights[1]");
  expectDocumentError([&] { evaluateSurface({{{{one}, {one}}, {{one}}}}, 0.5, 0.5, 0.5); }, "control_grid[1]");
  expectInvalidParameter([&] { evaluateCurve({{{one}}, {}}, 1.5, 0.5); }, "u");
  expectInvalidParameter([&] { evaluateCurve({{{one}}, {}}, 0.5, -0.1); }, "alpha");
  expectInvalidParameter([&] { evaluateSurface({{{{one}}}}, 0.5, 2, 0.5); }, "v");
  expectInvalidParameter([&] { isoCurveV({{{{one}}}}, -1); }, "u");
  expectInvalidParameter([&] { elevateCurve({{{one}}, {}}, -1); }, "times");
  expectInvalidParameter([&] { elevateCurve({{{one}, {one}}, {one, FuzzyNumber::triangular(1, 2, 3)}}, 1); },
                         "weights[1]");
}

}  // namespace
}  // namespace fsdb
