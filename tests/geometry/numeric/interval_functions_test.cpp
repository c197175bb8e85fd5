#include "geometry/numeric/interval_functions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace fsdb {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMaxFinite = std::numeric_limits<double>::max();

Interval randomInterval(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  const double a = u(rng), b = u(rng);
  return {std::min(a, b), std::max(a, b)};
}

// Samples the function densely (ends included) and checks: every sample lies in the
// enclosure (inclusion), and the enclosure's ends are within `slack` of the extreme samples
// (tightness; `slack` covers the sampling step).
void expectInclusionAndTightness(const std::string& name, const Interval& r, const Interval& a,
                                 const std::function<double(double)>& f, double slack) {
  double lo = f(a.lo), hi = lo;
  const int n = 400;
  for (int i = 0; i <= n; ++i) {
    const double x = i == n ? a.hi : a.lo + (a.hi - a.lo) * i / n;
    const double v = f(x);
    EXPECT_GE(v, r.lo - 1e-12 * (1 + std::fabs(v))) << name << " at " << x;
    EXPECT_LE(v, r.hi + 1e-12 * (1 + std::fabs(v))) << name << " at " << x;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_NEAR(r.lo, lo, slack) << name << " on [" << a.lo << ", " << a.hi << "]";
  EXPECT_NEAR(r.hi, hi, slack) << name << " on [" << a.lo << ", " << a.hi << "]";
}

TEST(IntervalFunctions, ScalarHelpers) {
  EXPECT_EQ(mul(2.0, {1, 3}), (Interval{2, 6}));
  EXPECT_EQ(mul(-2.0, {1, 3}), (Interval{-6, -2}));
  EXPECT_EQ(neg({1, 3}), (Interval{-3, -1}));
  EXPECT_EQ(mid({1, 3}), 2.0);
  EXPECT_EQ(mid({-kMaxFinite, kMaxFinite}), 0.0);  // no overflow
  // A point interval is its point, the smallest subnormal too (halving it first gave 0).
  EXPECT_EQ(mid({5e-324, 5e-324}), 5e-324);
  EXPECT_EQ(mid({kMaxFinite, kMaxFinite}), kMaxFinite);
  EXPECT_EQ(magnitude({-5, 3}), 5.0);
  EXPECT_EQ(mignitude({2, 5}), 2.0);
  EXPECT_EQ(mignitude({-5, -3}), 3.0);
  EXPECT_EQ(mignitude({-5, 3}), 0.0);
  EXPECT_TRUE(isPoint({0, 0}, 0.0));
  EXPECT_FALSE(isPoint({0, 1}, 0.0));
  EXPECT_FALSE(isPoint({1, 1}, 0.0));
  EXPECT_EQ(intersect({0, 3}, {1, 5}), (Interval{1, 3}));
  // Two enclosures that miss by rounding: the gap, never an inverted interval.
  EXPECT_EQ(intersect({0, 1}, {1.0 + 1e-16 * 2, 2}), (Interval{1, 1.0 + 1e-16 * 2}));
}

TEST(IntervalFunctions, AbsAndSqr) {
  EXPECT_EQ(abs({1, 2}), (Interval{1, 2}));
  EXPECT_EQ(abs({-3, -2}), (Interval{2, 3}));
  EXPECT_EQ(abs({-3, 2}), (Interval{0, 3}));
  EXPECT_EQ(sqr({-1, 1}), (Interval{0, 1}));  // not [−1, 1]
  EXPECT_EQ(sqr({-3, -2}), (Interval{4, 9}));
  EXPECT_EQ(sqrt({4, 9}), (Interval{2, 3}));
  EXPECT_EQ(sqrt({-1e-18, 4}), (Interval{0, 2}));
}

TEST(IntervalFunctions, PowUsesMonotonicityInBaseAndExponent) {
  // Bases below 1 shrink with the exponent, bases above 1 grow.
  EXPECT_EQ(pow({0.25, 0.5}, {1, 2}), (Interval{0.0625, 0.5}));
  EXPECT_EQ(pow({2, 4}, {1, 2}), (Interval{2, 16}));
  EXPECT_EQ(pow({0.5, 2}, {1, 2}), (Interval{0.25, 4}));
  EXPECT_EQ(pow({0, 0}, {0.5, 3}), (Interval{0, 0}));
  // Overflow saturates at the largest finite double, like the crisp inside-outside function.
  EXPECT_EQ(pow({1e200, 1e300}, {2, 2}).hi, kMaxFinite);
  EXPECT_EQ(pow({1e200, 1e300}, {2, 2}).lo, kMaxFinite);
}

TEST(IntervalFunctions, SinCosKnownRanges) {
  EXPECT_EQ(cos({0, kPi}), (Interval{-1, 1}));
  EXPECT_EQ(cos({-7, 7}), (Interval{-1, 1}));
  EXPECT_EQ(sin({-0.5 * kPi, 0.5 * kPi}).lo, -1.0);
  EXPECT_EQ(sin({-0.5 * kPi, 0.5 * kPi}).hi, 1.0);
  const Interval s = sin({0.1, 0.2});
  EXPECT_EQ(s.lo, std::sin(0.1));
  EXPECT_EQ(s.hi, std::sin(0.2));
  const Interval c = cos({2.0, 2.5});  // decreasing there
  EXPECT_EQ(c.lo, std::cos(2.5));
  EXPECT_EQ(c.hi, std::cos(2.0));
  EXPECT_EQ(cos({0.5, 0.5}).lo, std::cos(0.5));  // a point gives the crisp value
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(sin({-inf, inf}), (Interval{-1, 1}));
}

TEST(IntervalFunctions, Atan2KnownRanges) {
  // First quadrant box: corners give the arc.
  const Interval q = atan2({1, 2}, {1, 2});
  EXPECT_EQ(q.lo, std::atan2(1.0, 2.0));
  EXPECT_EQ(q.hi, std::atan2(2.0, 1.0));
  // Straddling the positive x axis is fine (no jump there).
  const Interval p = atan2({-1, 1}, {1, 2});
  EXPECT_EQ(p.lo, std::atan2(-1.0, 1.0));
  EXPECT_EQ(p.hi, std::atan2(1.0, 1.0));
  // Across the branch cut, or around the origin: everything.
  EXPECT_EQ(atan2({-1, 1}, {-2, -1}), (Interval{-kPi, kPi}));
  EXPECT_EQ(atan2({-1, 1}, {-1, 1}), (Interval{-kPi, kPi}));
  // Above the negative x axis, no cut: the arc towards π.
  const Interval n = atan2({1, 2}, {-2, -1});
  EXPECT_EQ(n.lo, std::atan2(2.0, -1.0));
  EXPECT_EQ(n.hi, std::atan2(1.0, -2.0));
}

TEST(IntervalFunctions, RandomInclusionAndTightnessOfOneArgumentFunctions) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 300; ++trial) {
    const Interval a = randomInterval(rng, -10, 10);
    const Interval small = {a.lo, a.lo + 0.3 * (a.hi - a.lo) / 10};  // exercises monotone pieces
    for (const Interval& x : {a, small}) {
      const double step = (x.hi - x.lo) / 400;
      // Sampling misses an extremum by at most step²/2 for sin/cos (curvature <= 1).
      expectInclusionAndTightness(
          "sin", sin(x), x, [](double t) { return std::sin(t); }, step * step + 1e-15);
      expectInclusionAndTightness(
          "cos", cos(x), x, [](double t) { return std::cos(t); }, step * step + 1e-15);
      expectInclusionAndTightness(
          "abs", abs(x), x, [](double t) { return std::fabs(t); }, step + 1e-15);
      expectInclusionAndTightness(
          "sqr", sqr(x), x, [](double t) { return t * t; }, 2 * 10 * step + 1e-12);
    }
    const Interval nonneg = randomInterval(rng, 0, 5);
    expectInclusionAndTightness(
        "sqrt", sqrt(nonneg), nonneg, [](double t) { return std::sqrt(t); }, 1e-12);
  }
}

TEST(IntervalFunctions, RandomInclusionAndTightnessOfTwoArgumentFunctions) {
  std::mt19937_64 rng(11);
  const int n = 30;
  // The i-th of n + 1 grid points of a, the last one exactly a.hi.
  const auto at = [n](const Interval& a, int i) { return i == n ? a.hi : a.lo + (a.hi - a.lo) * i / n; };
  for (int trial = 0; trial < 300; ++trial) {
    const Interval b = randomInterval(rng, 0, 3), e = randomInterval(rng, 0.05, 20);
    const Interval x = randomInterval(rng, -4, 4), y = randomInterval(rng, -4, 4);
    const Interval p = pow(b, e), h = hypot(x, y), t = atan2(y, x);
    double plo = 1e300, phi = -1e300, hlo = 1e300, hhi = -1e300;
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; j <= n; ++j) {
        const double bi = at(b, i), ej = at(e, j);
        const double v = std::pow(bi, ej);
        EXPECT_TRUE(contains(Interval{p.lo * (1 - 1e-12), p.hi * (1 + 1e-12)}, v));
        plo = std::min(plo, v);
        phi = std::max(phi, v);
        const double xi = at(x, i), yj = at(y, j);
        const double hv = std::hypot(xi, yj), tv = std::atan2(yj, xi);
        EXPECT_TRUE(contains(Interval{h.lo - 1e-12, h.hi + 1e-12}, hv));
        EXPECT_TRUE(contains(Interval{t.lo - 1e-12, t.hi + 1e-12}, tv)) << tv;
        hlo = std::min(hlo, hv);
        hhi = std::max(hhi, hv);
      }
    }
    // pow's ends are corners, which the grid holds.
    EXPECT_DOUBLE_EQ(p.lo, plo);
    EXPECT_DOUBLE_EQ(p.hi, phi);
    // hypot's smallest value may lie inside an edge (the box straddles an axis); the grid
    // step bounds how far the samples miss it.
    const double step = std::hypot(width(x), width(y)) / n;
    EXPECT_NEAR(h.lo, hlo, step);
    EXPECT_DOUBLE_EQ(h.hi, hhi);
  }
}

// atanc(w) = atan(w)/w and its derivative over intervals: inclusion and tightness against dense
// samples, on intervals through 0, across the derivative's extremes at ±0.8243 and far out; the
// derivative against central differences of the scalar atanc.
TEST(IntervalFunctions, AtancAndItsSlope) {
  std::mt19937_64 rng(41);
  // The derivative in long double (its cancellation near 0 costs 1e-19 relative, not 1e-16), by
  // the series below 1e-3.
  const auto derivative = [](double x) {
    const long double w = x, w2 = w * w;
    if (std::fabs(x) < 1e-3) return double(w * (-2.0L / 3 + w2 * (4.0L / 5 - w2 * (6.0L / 7 - w2 * 8.0L / 9))));
    return double((1.0L / (1.0L + w2) - std::atan(w) / w) / w);
  };
  EXPECT_EQ(atanc(0.0), 1.0);
  EXPECT_NEAR(atanc(1.0), std::atan(1.0), 1e-16);
  for (int k = 0; k < 300; ++k) {
    const double reach = k % 3 == 0 ? 0.1 : k % 3 == 1 ? 2.0 : 20.0;
    const Interval a = randomInterval(rng, -reach, reach);
    // Tightness up to the sampling step at an interior extreme (both have |f''| < 1 there).
    const double step = (a.hi - a.lo) / 400, slack = 1e-6 + step * step;
    expectInclusionAndTightness(
        "atanc", atanc(a), a, [](double w) { return atanc(w); }, slack);
    expectInclusionAndTightness("atancSlope", atancSlope(a), a, derivative, slack);
  }
  // The extremes: −0.29224806 at 0.8243, +0.29224806 at −0.8243.
  const Interval both = atancSlope({-1.0, 1.0});
  EXPECT_NEAR(both.lo, -0.29224806, 1e-7);
  EXPECT_NEAR(both.hi, 0.29224806, 1e-7);
  EXPECT_LE(both.lo, derivative(0.8243));
  // The slope range holds central differences of the scalar atanc too (the form the search uses).
  for (double w : {-3.0, -0.8243, -0.2, 0.03, 0.5, 0.8243, 4.0}) {
    const double h = 1e-6, fd = (atanc(w + h) - atanc(w - h)) / (2 * h);
    const Interval r = atancSlope({w - 1e-3, w + 1e-3});
    EXPECT_GE(fd, r.lo - 1e-8) << w;
    EXPECT_LE(fd, r.hi + 1e-8) << w;
  }
}

}  // namespace
}  // namespace fsdb
