#pragma once
// Finite-difference checks of C^k smoothness at a breakpoint b, shared by the tests of the
// smooth steps, absolutes, operators and blends.
//
// The one-sided estimate D^k_side(h) = Delta^k f / h^k over b, b +- h, ..., b +- k h equals
// f^(k)(xi) for some xi within k h of b on that side (mean value theorem for divided
// differences) whenever f is C^k on that side. So if f^(k) is continuous at b,
//   |D^k_+(h) - D^k_-(h)| <= k h (sup|f^(k+1)| right + sup|f^(k+1)| left) + rounding,
// a bound that shrinks with h; if f^(k) jumps by J, the difference tends to |J| instead.
// continuityDefect returns |D^k_+ - D^k_-| divided by that bound (with the sups estimated by
// the one-sided (k+1)-th differences and a safety factor of 4): <= 1 means "continuous within
// what h can resolve"; a jump shows as a ratio that grows like 1/h.
#include <algorithm>
#include <cmath>
#include <limits>

namespace fsdb::testing {

template <class F>
double oneSidedDerivative(const F& f, double b, int k, double h, int side) {
  double sum = 0.0, binomial = 1.0;  // C(k, j)
  for (int j = 0; j <= k; ++j) {
    sum += ((k - j) % 2 ? -1.0 : 1.0) * binomial * f(b + side * j * h);
    binomial = binomial * (k - j) / (j + 1);
  }
  return sum / std::pow(side * h, k);
}

template <class F>
double continuityDefect(const F& f, double b, int k, double h) {
  double jump = std::fabs(oneSidedDerivative(f, b, k, h, +1) - oneSidedDerivative(f, b, k, h, -1));
  double next = std::fabs(oneSidedDerivative(f, b, k + 1, h, +1)) +
                std::fabs(oneSidedDerivative(f, b, k + 1, h, -1));
  double scale = 0.0;
  for (int j = -k - 1; j <= k + 1; ++j) scale = std::max(scale, std::fabs(f(b + j * h)));
  double rounding = std::pow(2.0, k + 1) * 8.0 * std::numeric_limits<double>::epsilon() *
                    (scale + 1e-300) / std::pow(h, k);
  return jump / (4.0 * k * h * next + rounding);
}

// f is C^k at b (defect <= 1) and its (k+1)-th derivative visibly jumps there (defect > 10),
// so a test using this can fail in both directions.
template <class F>
bool exactlyCkAt(const F& f, double b, int k, double h) {
  return continuityDefect(f, b, k, h) <= 1.0 && continuityDefect(f, b, k + 1, h) > 10.0;
}

}  // namespace fsdb::testing
