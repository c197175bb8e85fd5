#include "geometry/operators/bezier_operator.h"

#include "geometry/core/parameter_check.h"

namespace fsdb {

namespace {

// b^n by repeated squaring (std::pow takes the slow general path for an integer exponent).
double integerPower(double b, int n) {
  double result = 1.0;
  for (; n > 0; n >>= 1, b *= b)
    if (n & 1) result *= b;
  return result;
}

}  // namespace

void bernsteinBasis(int n, double t, double* out) {
  // Walk the ratio b_{k+1}/b_k = (n-k)/(k+1) * t/(1-t) from the end nearer t, so the ratio
  // stays <= (n-k)/(k+1) * 1 and the starting power (1-t)^n >= 2^-n never underflows.
  bool mirrored = t > 0.5;
  double s = mirrored ? 1.0 - t : t;
  double ratio = s / (1.0 - s);
  double b = integerPower(1.0 - s, n);
  for (int k = 0; k <= n; ++k) {
    out[mirrored ? n - k : k] = b;
    b *= ratio * (n - k) / (k + 1);
  }
}

// Li & Tian, eq. 4. Its double sum is sum_{i,j} min(i,j)/n B_i(x) B_j(y), and
// min(i, j) = #{k = 1..n : k <= i and k <= j}, so it factors into
//   (1/n) sum_{k=1..n} T_k(x) T_k(y),   T_k(t) = sum_{i >= k} B_i(t),
// which needs the tail sums only: O(n) instead of O(n^2).
double bezierOperator(int n, double x, double y) {
  requireDegree("n", n, 1, kMaxBezierDegree);
  double bx[kMaxBezierDegree + 1], by[kMaxBezierDegree + 1];
  bernsteinBasis(n, x, bx);
  bernsteinBasis(n, y, by);
  double tailX = 0.0, tailY = 0.0, sum = 0.0;
  for (int k = n; k >= 1; --k) {
    tailX += bx[k];
    tailY += by[k];
    sum += tailX * tailY;
  }
  return sum / n;
}

// Li & Tian, eq. 4, literally: the diagonal sum plus the two off-diagonal sums.
double bezierOperatorLiteral(int n, double x, double y) {
  requireDegree("n", n, 1, kMaxBezierDegree);
  double bx[kMaxBezierDegree + 1], by[kMaxBezierDegree + 1];
  bernsteinBasis(n, x, bx);
  bernsteinBasis(n, y, by);
  double sum = 0.0;
  for (int k = 1; k <= n; ++k) sum += double(k) / n * bx[k] * by[k];
  for (int j = 1; j <= n; ++j)
    for (int i = j + 1; i <= n; ++i) sum += double(j) / n * (bx[i] * by[j] + by[i] * bx[j]);
  return sum;
}

}  // namespace fsdb
