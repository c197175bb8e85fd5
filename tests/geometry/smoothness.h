#pragma once
// Finite-difference checks of C^k smoothness at a breakpoint b, shared by the tests of the
// smooth steps, absolutes, operators and blends.
//
// The one-sided estimate D^k_side(h) = Delta^k f / h^k over b, b +- h, ..., b +- k h is
// f^(k)(b+-) + (k/2) h f^(k+1)(b+-) + O(h^2) when f is smooth on that side. So the gap
// J(h) = |D^k_+(h) - D^k_-(h)| behaves like
//   - c h        when f^(k) is continuous at b: halving h halves the gap;
//   - |jump| + c h when f^(k) jumps at b:       halving h leaves the gap nearly unchanged.
// Comparing J(h) with J(h/2) tells the two apart without knowing the size of f^(k+1), and a
// test built on both checks (C^k holds, C^(k+1) does not) can fail either way. h must keep
// b +- (k+1) h inside the pieces next to b, and large enough that rounding (about
// 2^k eps |f| / h^k, counted as noise) stays well below the gaps.
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
double derivativeGap(const F& f, double b, int k, double h) {
  return std::fabs(oneSidedDerivative(f, b, k, h, +1) - oneSidedDerivative(f, b, k, h, -1));
}

// Rounding in derivativeGap: each estimate sums 2^k values of size |f| divided by h^k.
template <class F>
double derivativeNoise(const F& f, double b, int k, double h) {
  double scale = 0.0;
  for (int j = -k; j <= k; ++j) scale = std::max(scale, std::fabs(f(b + j * h)));
  return std::pow(2.0, k + 1) * 16.0 * std::numeric_limits<double>::epsilon() * scale /
         std::pow(h, k);
}

// f^(k) is continuous at b: the gap at h/2 is at most 0.7 of the gap at h (0.5 expected), or
// lost in rounding.
template <class F>
bool derivativeContinuousAt(const F& f, double b, int k, double h) {
  double coarse = derivativeGap(f, b, k, h), fine = derivativeGap(f, b, k, h / 2);
  double noise = derivativeNoise(f, b, k, h / 2);
  return fine <= 0.7 * coarse + noise;
}

// f^(k) jumps at b: the gap does not shrink with h (at h/2 it keeps more than 0.85 of it) and
// stands well clear of rounding.
template <class F>
bool derivativeJumpsAt(const F& f, double b, int k, double h) {
  double coarse = derivativeGap(f, b, k, h), fine = derivativeGap(f, b, k, h / 2);
  return fine > 0.85 * coarse && fine > 100.0 * derivativeNoise(f, b, k, h / 2);
}

// f is C^k at b and no smoother there.
template <class F>
bool exactlyCkAt(const F& f, double b, int k, double h) {
  for (int j = 0; j <= k; ++j)
    if (!derivativeContinuousAt(f, b, j, h)) return false;
  return derivativeJumpsAt(f, b, k + 1, h);
}

}  // namespace fsdb::testing
