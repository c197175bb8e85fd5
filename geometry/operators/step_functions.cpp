#include "geometry/operators/step_functions.h"

#include <cmath>
#include <limits>
#include <vector>

#include "geometry/core/parameter_check.h"

namespace fsdb {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

void requireRisingRange(const char* name, double r) {
  requireInRange(name, r, 0.0, false, kInf, false);
}

}  // namespace

// Li & Tian, eq. 2 (H_0); Li, eq. 4
double heaviside(double t) { return t < 0.0 ? 0.0 : (t > 0.0 ? 1.0 : 0.5); }

// Li & Tian, eq. 2, bottom-up. H_n(x) needs H_{n-1} at x - 1 and x + 1, so level m needs H_m at
// x + s for s = -(n-m), -(n-m)+2, ..., n-m: n - m + 1 values, O(n^2) in all. Where |y| >= m the
// value is exactly 0 or 1 (property (3) after eq. 2); inside, the recursion is a convex
// combination, so rounding errors never grow.
double liTianStep(int n, double x) {
  requireDegree("n", n, 0, kMaxPolynomialStepDegree);
  if (n == 0) return heaviside(x);
  if (x <= -n) return 0.0;
  if (x >= n) return 1.0;
  double h[kMaxPolynomialStepDegree + 1];
  for (int i = 0; i <= n; ++i) h[i] = heaviside(x + (2 * i - n));
  for (int m = 1; m <= n; ++m) {
    double halfInverseM = 0.5 / m;  // one division per level, not per entry
    for (int i = 0; i <= n - m; ++i) {
      double y = x + (2 * i - (n - m));  // h[i] holds H_{m-1}(y - 1), h[i+1] holds H_{m-1}(y + 1)
      if (y <= -m)
        h[i] = 0.0;
      else if (y >= m)
        h[i] = 1.0;
      else
        h[i] = 0.5 * (h[i + 1] + h[i]) + y * halfInverseM * (h[i + 1] - h[i]);
    }
  }
  return h[0];
}

// Li & Tian, eq. 3
double liTianStepRange(int n, double R, double x) {
  requireDegree("n", n, 1, kMaxPolynomialStepDegree);
  requireRisingRange("R", R);
  return liTianStep(n, n * x / R);
}

// Li, eq. 5, bottom-up over the shifted arguments t - j (the same scheme as liTianStep):
// f_m(t - j) needs f_{m-1} at t - j and t - j - 1.
double cardinalStep(int n, double t) {
  requireDegree("n", n, 0, kMaxPolynomialStepDegree);
  if (n == 0) return heaviside(t);
  if (t <= 0.0) return 0.0;
  if (t >= n) return 1.0;
  double f[kMaxPolynomialStepDegree + 1];
  for (int j = 0; j <= n; ++j) f[j] = heaviside(t - j);
  for (int m = 1; m <= n; ++m) {
    double inverseM = 1.0 / m;
    for (int j = 0; j <= n - m; ++j) {
      double u = t - j;  // f[j] holds f_{m-1}(u), f[j+1] holds f_{m-1}(u - 1)
      if (u <= 0.0)
        f[j] = 0.0;
      else if (u >= m)
        f[j] = 1.0;
      else
        f[j] = f[j + 1] + u * inverseM * (f[j] - f[j + 1]);
    }
  }
  return f[0];
}

// Li, eq. 6
double polynomialStep(int n, double t) {
  requireDegree("n", n, 1, kMaxPolynomialStepDegree);
  return cardinalStep(n, n * (t + 1.0) / 2.0);
}

// Li, eq. 7 in closed form. With M_m(u) = 1/(m-1)! sum_k (-1)^k C(m,k) (u-k)_+^(m-1) the
// order-m cardinal B-spline on [0, m], N_m(s) = M_m(m(s+1)/2) and delta = 2/m, so
//   B_m(t) = f(m(t+1)/2),  f(u) = 1/m! sum_{k=0}^{m} (-1)^k C(m,k) (u-k)_+^m,
// which for m = 3 is eq. 8. f(u) = 1 - f(m - u) (the B-spline is symmetric); evaluating the
// half with u <= m/2 keeps the alternating terms, and so the cancellation, smallest.
double bsplineStep(int m, double t) {
  requireDegree("m", m, 1, kMaxBSplineOrder);
  double u = m * (t + 1.0) / 2.0;
  if (u <= 0.0) return 0.0;
  if (u >= m) return 1.0;
  bool mirrored = u > m / 2.0;
  if (mirrored) u = m - u;
  double sum = 0.0, binomial = 1.0, sign = 1.0;  // binomial = C(m, k)
  for (int k = 0; k < u; ++k) {
    sum += sign * binomial * std::pow(u - k, m);
    binomial = binomial * (m - k) / (k + 1);
    sign = -sign;
  }
  double factorial = 1.0;
  for (int k = 2; k <= m; ++k) factorial *= k;
  double f = sum / factorial;
  return mirrored ? 1.0 - f : f;
}

// Li, eq. 16 unrolled: R_n(t) = R_1(s^(n-1)(t)) with s(t) = sin(pi t / 2), O(n).
double risingCutoff(int n, double t) {
  requireDegree("n", n, 1, kMaxRisingCutoffLevel);
  if (t <= -1.0) return 0.0;
  if (t >= 1.0) return 1.0;
  for (int k = 1; k < n; ++k) t = std::sin(kPi / 2.0 * t);
  return std::sin(kPi / 4.0 * (1.0 + t));
}

// Li, §2.1.3 (R_n^2 as a step)
double risingCutoffSquared(int n, double t) {
  double r = risingCutoff(n, t);
  return r * r;
}

// Li, eq. 17, in the form whose exponential cannot overflow.
double sigmoidStep(double alpha, double t) {
  requireInRange("alpha", alpha, 0.0, false, kInf, false);
  if (t >= 0.0) return 1.0 / (1.0 + std::exp(-alpha * t));
  double e = std::exp(alpha * t);
  return e / (1.0 + e);
}

// Li, after eq. 17
double sigmoidAlphaBound(double epsilon) {
  requireInRange("epsilon", epsilon, 0.0, false, 1.0, false);
  return std::log((1.0 - epsilon) / epsilon);
}

namespace reference {

namespace {

double liTianStepRecursive(int n, double x) {
  if (n == 0) return heaviside(x);
  return 0.5 * ((1.0 + x / n) * liTianStepRecursive(n - 1, x + 1.0) +
                (1.0 - x / n) * liTianStepRecursive(n - 1, x - 1.0));
}

double cardinalStepRecursive(int n, double t) {
  if (n == 0) return heaviside(t);
  return t / n * cardinalStepRecursive(n - 1, t) +
         (1.0 - t / n) * cardinalStepRecursive(n - 1, t - 1.0);
}

double cardinalBSplineRecursive(int m, double u) {
  if (m == 1) return (u >= 0.0 && u < 1.0) ? 1.0 : 0.0;
  return (u * cardinalBSplineRecursive(m - 1, u) +
          (m - u) * cardinalBSplineRecursive(m - 1, u - 1.0)) /
         (m - 1);
}

// Gauss-Legendre nodes and weights on [-1, 1] (Newton on the Legendre recurrence).
void gaussLegendre(int points, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.assign(points, 0.0);
  weights.assign(points, 0.0);
  for (int i = 0; i < (points + 1) / 2; ++i) {
    double z = std::cos(kPi * (i + 0.75) / (points + 0.5)), dp = 0.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = 0.0;
      for (int j = 1; j <= points; ++j) {
        double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * j - 1.0) * z * p1 - (j - 1.0) * p2) / j;
      }
      dp = points * (z * p0 - p1) / (z * z - 1.0);
      double step = p0 / dp;
      z -= step;
      if (std::fabs(step) < 1e-16) break;
    }
    nodes[i] = -z;
    nodes[points - 1 - i] = z;
    weights[i] = weights[points - 1 - i] = 2.0 / ((1.0 - z * z) * dp * dp);
  }
}

// integral_{-1}^{t} N_m(s) ds, N_m(s) = M_m(m(s+1)/2), piece by piece between the knots.
double integrateN(int m, double t) {
  std::vector<double> nodes, weights;
  gaussLegendre(m / 2 + 1, nodes, weights);  // exact for degree m - 1 < 2(m/2 + 1)
  double total = 0.0;
  for (int j = 0; j < m; ++j) {
    double a = -1.0 + 2.0 * j / m, b = std::fmin(-1.0 + 2.0 * (j + 1) / m, t);
    if (b <= a) break;
    for (size_t q = 0; q < nodes.size(); ++q) {
      double s = 0.5 * (a + b) + 0.5 * (b - a) * nodes[q];
      total += 0.5 * (b - a) * weights[q] * cardinalBSplineRecursive(m, m * (s + 1.0) / 2.0);
    }
  }
  return total;
}

// Li, eq. 15
double theta0(double t) { return t < -1.0 ? 0.0 : (t > 1.0 ? kPi / 2.0 : kPi / 4.0 * (1.0 + t)); }

// Li, eq. 14: theta_k = (pi/2) sin^2(theta_{k-1})
double theta(int k, double t) {
  if (k == 0) return theta0(t);
  double mu = std::sin(theta(k - 1, t));
  return kPi / 2.0 * mu * mu;
}

}  // namespace

double liTianStep(int n, double x) {
  requireDegree("n", n, 0, kMaxPolynomialStepDegree);
  return liTianStepRecursive(n, x);
}

double cardinalStep(int n, double t) {
  requireDegree("n", n, 0, kMaxPolynomialStepDegree);
  return cardinalStepRecursive(n, t);
}

double polynomialStep(int n, double t) {
  requireDegree("n", n, 1, kMaxPolynomialStepDegree);
  return cardinalStepRecursive(n, n * (t + 1.0) / 2.0);
}

double cardinalBSpline(int m, double u) {
  requireDegree("m", m, 1, kMaxBSplineOrder);
  return cardinalBSplineRecursive(m, u);
}

double bsplineStep(int m, double t) {
  requireDegree("m", m, 1, kMaxBSplineOrder);
  if (t <= -1.0) return 0.0;
  return integrateN(m, std::fmin(t, 1.0)) / integrateN(m, 1.0);
}

double risingCutoff(int n, double t) {
  requireDegree("n", n, 1, kMaxRisingCutoffLevel);
  return std::sin(theta(n - 1, t));  // R_n = mu_n = sin(theta_{n-1})
}

}  // namespace reference

}  // namespace fsdb
