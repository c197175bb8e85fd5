#include "geometry/numeric/affine_form.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

namespace fsdb {
namespace {

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// The form's value at the noise symbols eps and its accumulated error at e (both in [−1, 1]).
double valueAt(const AffineForm& f, const double (&eps)[kAffineSymbols], double e) {
  double v = f.centre + f.err * e;
  for (int i = 0; i < kAffineSymbols; ++i) v += f.dev[i] * eps[i];
  return v;
}

// The result holds the true value for the same symbols: |value − (x0 + Σ x_i·ε_i)| <= err.
void expectHolds(const AffineForm& r, const double (&eps)[kAffineSymbols], double truth) {
  ASSERT_TRUE(r.valid);
  const double linear = valueAt(r, eps, 0.0);
  EXPECT_LE(std::fabs(truth - linear), r.err + 1e-14 * (1.0 + std::fabs(truth)))
      << "truth " << truth << " linear " << linear << " err " << r.err;
  const Interval a = range(r);
  EXPECT_LE(a.lo, truth + 1e-14 * (1.0 + std::fabs(truth)));
  EXPECT_GE(a.hi, truth - 1e-14 * (1.0 + std::fabs(truth)));
}

// A random form on three symbols with a little accumulated error, centred in [lo, hi].
AffineForm randomForm(std::mt19937_64& rng, double lo, double hi, double spread) {
  AffineForm f;
  f.centre = uniform(rng, lo, hi);
  for (int i = 0; i < 3; ++i) f.dev[i] = uniform(rng, -spread, spread);
  f.err = uniform(rng, 0.0, 0.1 * spread);
  return f;
}

TEST(AffineForm, AffineFunctionsAreExact) {
  const AffineForm x = affineVariable({1.0, 3.0}, 0), y = affineVariable({-2.0, 0.0}, 1);
  // 2x − 3y + 1 over [1, 3] × [−2, 0]: [2 + 0 + 1, 6 + 6 + 1] = [3, 13].
  const Interval r = range(add(1.0, sub(mul(2.0, x), mul(3.0, y))));
  EXPECT_NEAR(r.lo, 3.0, 1e-13);
  EXPECT_NEAR(r.hi, 13.0, 1e-13);
  // x − x = 0: the correlation interval arithmetic loses ([1, 3] − [1, 3] = [−2, 2]).
  const Interval zero = range(sub(x, x));
  EXPECT_NEAR(zero.lo, 0.0, 1e-14);
  EXPECT_NEAR(zero.hi, 0.0, 1e-14);
  // A linear combination is exact too: 2x + 3y − (x − y) = x + 4y over the boxes: [1 − 8, 3 + 0].
  const Interval lin = range(combine(2.0, x, 3.0, y, -1.0, sub(x, y)));
  EXPECT_NEAR(lin.lo, -7.0, 1e-13);
  EXPECT_NEAR(lin.hi, 3.0, 1e-13);
  // Constants are exact and have no deviations.
  const AffineForm c = affineConstant(2.5);
  EXPECT_EQ(range(c).lo, 2.5);
  EXPECT_EQ(range(c).hi, 2.5);
  EXPECT_FALSE(affineConstant(INFINITY).valid);
}

TEST(AffineForm, VariableSpansItsInterval) {
  const AffineForm x = affineVariable({0.25, 0.75}, 5);
  EXPECT_EQ(x.centre, 0.5);
  EXPECT_EQ(x.dev[5], 0.25);
  const Interval r = range(x);
  EXPECT_LE(r.lo, 0.25);
  EXPECT_GE(r.hi, 0.75);
  EXPECT_NEAR(r.lo, 0.25, 1e-15);
  EXPECT_FALSE(affineVariable({0.0, INFINITY}, 0).valid);
}

// Every operation holds the true value at random symbols (the same symbols for the inputs and the
// result: the correlation is sound, not just the range).
TEST(AffineForm, OperationsHoldSampledValues) {
  std::mt19937_64 rng(11);
  struct Unary {
    const char* name;
    std::function<AffineForm(const AffineForm&)> form;
    std::function<double(double)> f;
    double lo, hi;  // range of centres (the spread keeps the domain)
  };
  const Unary unary[] = {
      {"sqr", [](const AffineForm& x) { return sqr(x); }, [](double x) { return x * x; }, -3, 3},
      {"recip", [](const AffineForm& x) { return recip(x); }, [](double x) { return 1 / x; }, 0.5, 4},
      {"recip-", [](const AffineForm& x) { return recip(x); }, [](double x) { return 1 / x; }, -4, -0.5},
      {"sqrt", [](const AffineForm& x) { return sqrt(x); }, [](double x) { return std::sqrt(x); }, 0.5, 9},
      {"exp", [](const AffineForm& x) { return exp(x); }, [](double x) { return std::exp(x); }, -5, 5},
      {"log", [](const AffineForm& x) { return log(x); }, [](double x) { return std::log(x); }, 0.5, 9},
      {"sin", [](const AffineForm& x) { return sin(x); }, [](double x) { return std::sin(x); }, -7, 7},
      {"cos", [](const AffineForm& x) { return cos(x); }, [](double x) { return std::cos(x); }, -7, 7},
      {"atan", [](const AffineForm& x) { return atan(x); }, [](double x) { return std::atan(x); }, -4, 4},
  };
  for (const Unary& u : unary) {
    for (int k = 0; k < 300; ++k) {
      const double spread = k % 3 == 0 ? 0.1 : 0.01;
      const AffineForm x = randomForm(rng, u.lo, u.hi, spread);
      const AffineForm r = u.form(x);
      for (int s = 0; s < 20; ++s) {
        double eps[kAffineSymbols] = {};
        for (int i = 0; i < 3; ++i) eps[i] = s == 0 ? 1.0 : uniform(rng, -1, 1);
        const double e = s == 1 ? -1.0 : uniform(rng, -1, 1);
        SCOPED_TRACE(u.name);
        expectHolds(r, eps, u.f(valueAt(x, eps, e)));
      }
    }
  }
  for (int k = 0; k < 500; ++k) {
    const AffineForm x = randomForm(rng, -3, 3, 0.5), y = randomForm(rng, -3, 3, 0.5);
    const AffineForm sum = add(x, y), diff = sub(x, y), prod = mul(x, y);
    const AffineForm shifted = add(1.5, x), scaled = mul(-2.0, y);
    const AffineForm two = combine(0.5, x, -3.0, y), three = combine(0.5, x, -3.0, y, 2.0, prod);
    for (int s = 0; s < 20; ++s) {
      double eps[kAffineSymbols] = {};
      for (int i = 0; i < 3; ++i) eps[i] = uniform(rng, -1, 1);
      const double ex = uniform(rng, -1, 1), ey = uniform(rng, -1, 1);
      const double a = valueAt(x, eps, ex), b = valueAt(y, eps, ey);
      expectHolds(sum, eps, a + b);
      expectHolds(diff, eps, a - b);
      expectHolds(prod, eps, a * b);
      expectHolds(shifted, eps, 1.5 + a);
      expectHolds(scaled, eps, -2.0 * b);
      expectHolds(two, eps, 0.5 * a - 3.0 * b);
      expectHolds(three, eps, 0.5 * a - 3.0 * b + 2.0 * a * b);
    }
  }
}

// x^q with both arguments forms on shared symbols holds the true value at random symbols, for
// bases near 0 and beyond 1 and exponents below and above 1 (where the Hessian changes sign).
TEST(AffineForm, PowerHoldsSampledValues) {
  std::mt19937_64 rng(12);
  for (int k = 0; k < 2000; ++k) {
    const double spread = k % 3 == 0 ? 0.05 : 0.01;
    AffineForm x = randomForm(rng, 0.1, 3.0, spread), q = randomForm(rng, 0.3, 4.0, spread);
    if (k % 4 == 0) q = affineConstant(uniform(rng, 0.3, 4.0));  // a crisp exponent
    if (!(range(x).lo > 0.0)) continue;
    const AffineForm r = pow(x, q);
    for (int s = 0; s < 20; ++s) {
      double eps[kAffineSymbols] = {};
      for (int i = 0; i < 3; ++i) eps[i] = s == 0 ? 1.0 : s == 1 ? -1.0 : uniform(rng, -1, 1);
      const double ex = uniform(rng, -1, 1), eq = uniform(rng, -1, 1);
      expectHolds(r, eps, std::pow(valueAt(x, eps, ex), valueAt(q, eps, eq)));
    }
  }
  // The base must stay above 0; invalid inputs give invalid results.
  EXPECT_FALSE(pow(affineVariable({-0.1, 0.5}, 0), affineConstant(2.0)).valid);
  EXPECT_FALSE(pow(affineVariable({0.0, 0.5}, 0), affineConstant(2.0)).valid);
  EXPECT_FALSE(pow(recip(affineVariable({-1.0, 1.0}, 0)), affineConstant(2.0)).valid);
}

// The direct power keeps far less accumulated error than exp(q·log x) (one remainder, not three):
// the reason the superquadric enclosure uses it.
TEST(AffineForm, PowerKeepsLessErrorThanExpOfLog) {
  for (const Interval& xr : {Interval{0.075, 0.11}, Interval{0.2, 0.22}, Interval{0.5, 0.9}}) {
    for (const Interval& qr : {Interval{1.54, 1.54}, Interval{1.5, 1.58}, Interval{2.7, 3.0}}) {
      const AffineForm x = affineVariable(xr, 0), q = affineVariable(qr, 1);
      const AffineForm direct = pow(x, q), viaLog = exp(mul(log(x), q));
      ASSERT_TRUE(direct.valid);
      EXPECT_LT(direct.err, viaLog.err) << xr.lo << " " << qr.lo;
      // Both are sound: each holds the true range's ends (x^q increases in x here; q's end
      // depends on x < 1).
      for (double xe : {xr.lo, xr.hi})
        for (double qe : {qr.lo, qr.hi}) {
          const double t = std::pow(xe, qe);
          EXPECT_LE(range(direct).lo, t + 1e-15);
          EXPECT_GE(range(direct).hi, t - 1e-15);
        }
    }
  }
  // Exact for a single value.
  const AffineForm p = pow(affineConstant(0.7), affineConstant(1.3));
  EXPECT_NEAR(range(p).lo, std::pow(0.7, 1.3), 1e-14);
  EXPECT_NEAR(range(p).hi, std::pow(0.7, 1.3), 1e-14);
}

// |x|^q over ranges that reach or straddle 0, for exponent intervals with q.lo >= 1, holds the
// true value at random symbols and exponents.
TEST(AffineForm, AbsPowHoldsSampledValues) {
  std::mt19937_64 rng(13);
  for (int k = 0; k < 2000; ++k) {
    const AffineForm x = randomForm(rng, -0.3, 1.5, k % 2 ? 0.2 : 0.02);
    const double q0 = uniform(rng, 1.0, 3.5);
    const Interval q{q0, q0 + (k % 3 ? uniform(rng, 0.0, 0.3) : 0.0)};
    const AffineForm r = absPow(x, q);
    for (int s = 0; s < 20; ++s) {
      double eps[kAffineSymbols] = {};
      for (int i = 0; i < 3; ++i) eps[i] = s == 0 ? 1.0 : s == 1 ? -1.0 : uniform(rng, -1, 1);
      const double e = s == 2 ? 1.0 : uniform(rng, -1, 1);
      const double qe = s % 2 ? q.lo : uniform(rng, q.lo, q.hi);
      expectHolds(r, eps, std::pow(std::fabs(valueAt(x, eps, e)), qe));
    }
  }
  EXPECT_FALSE(absPow(affineVariable({-0.1, 0.5}, 0), {0.9, 1.2}).valid);  // not convex
  EXPECT_FALSE(absPow(affineVariable({0.0, INFINITY}, 0), {2.0, 2.0}).valid);
}

// Near 0 the band is several times narrower than the interval range and keeps the correlation:
// x^1.54 on [0, b] has range [0, b^1.54]; the band's error is about 0.16·b^1.54 (the secant's gap
// to the curve), its deviation the secant slope.
TEST(AffineForm, AbsPowNearZeroIsNarrowerThanTheRange) {
  for (double b : {0.05, 0.2, 1.0}) {
    const AffineForm x = affineVariable({0.0, b}, 0);
    const AffineForm r = absPow(x, {1.54, 1.54});
    ASSERT_TRUE(r.valid);
    const double top = std::pow(b, 1.54);
    EXPECT_LT(r.err, 0.2 * top) << b;
    EXPECT_NEAR(r.dev[0], 0.5 * b * top / b, 1e-9 * top);  // secant slope × half width
    // Straddling 0: still sound at the ends and the bottom.
    const AffineForm s = absPow(affineVariable({-b, 0.5 * b}, 1), {1.54, 1.54});
    EXPECT_LE(range(s).lo, 0.0 + 1e-15);
    EXPECT_GE(range(s).hi, top - 1e-15);
  }
}

// The remainder of a nonlinear function shrinks quadratically with the form's radius: the error
// term over a tenth of the spread is about a hundredth.
TEST(AffineForm, RemainderIsSecondOrder) {
  for (double r : {0.1, 0.01}) {
    const AffineForm big = exp(affineVariable({1.0 - r, 1.0 + r}, 0));
    const AffineForm small = exp(affineVariable({1.0 - 0.1 * r, 1.0 + 0.1 * r}, 0));
    EXPECT_LT(small.err, 0.02 * big.err) << r;
    // The linear part's slope is the derivative somewhere in the range (min-range or centre).
    EXPECT_GE(big.dev[0], std::exp(1.0 - r) * r * (1 - 1e-12));
    EXPECT_LE(big.dev[0], std::exp(1.0) * r * (1 + 1e-12));
  }
}

TEST(AffineForm, DomainErrorsAreInvalid) {
  const AffineForm straddles = affineVariable({-1.0, 1.0}, 0);
  EXPECT_FALSE(recip(straddles).valid);
  EXPECT_FALSE(log(straddles).valid);
  EXPECT_FALSE(sqrt(straddles).valid);
  EXPECT_FALSE(sqrt(affineVariable({0.0, 1.0}, 0)).valid);
  EXPECT_FALSE(exp(affineConstant(800.0)).valid);
  // Invalid propagates through every operation.
  const AffineForm bad = recip(straddles);
  EXPECT_FALSE(add(bad, straddles).valid);
  EXPECT_FALSE(mul(straddles, bad).valid);
  EXPECT_FALSE(sin(bad).valid);
  EXPECT_FALSE(mul(2.0, bad).valid);
  EXPECT_FALSE(affineFromInterval({0.0, INFINITY}).valid);
  const AffineForm i = affineFromInterval({1.0, 2.0});
  EXPECT_LE(range(i).lo, 1.0);
  EXPECT_GE(range(i).hi, 2.0);
}

}  // namespace
}  // namespace fsdb
