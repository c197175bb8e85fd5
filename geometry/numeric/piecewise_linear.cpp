#include "geometry/numeric/piecewise_linear.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "geometry/core/error.h"
#include "geometry/core/number_format.h"

namespace fsdb {

namespace {

// Line through (x0, m0) and (x1, m1) at x, for x0 < x1. Returns the endpoint values exactly.
double lerp(double x0, double m0, double x1, double m1, double x) {
  if (x <= x0) return m0;
  if (x >= x1) return m1;
  return m0 + (m1 - m0) * ((x - x0) / (x1 - x0));
}

// Index of the first breakpoint with x_i >= x (f.size() if none).
size_t firstAtOrAfter(const std::vector<Breakpoint>& f, double x) {
  return std::lower_bound(f.begin(), f.end(), x,
                          [](const Breakpoint& b, double v) { return b.x < v; }) -
         f.begin();
}

// Index one past the last breakpoint with x_i <= x.
size_t pastLastAtOrBefore(const std::vector<Breakpoint>& f, double x) {
  return std::upper_bound(f.begin(), f.end(), x,
                          [](double v, const Breakpoint& b) { return v < b.x; }) -
         f.begin();
}

template <class Op>
std::vector<Breakpoint> combine(const std::vector<Breakpoint>& f, const std::vector<Breakpoint>& g,
                                Op op) {
  checkPiecewiseLinear(f);
  checkPiecewiseLinear(g);
  std::vector<double> xs;
  xs.reserve(f.size() + g.size());
  for (const auto& b : f) xs.push_back(b.x);
  for (const auto& b : g) xs.push_back(b.x);
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());

  std::vector<Breakpoint> out;
  auto emit = [&out](double x, double mu) {
    if (out.empty() || out.back().x != x || out.back().mu != mu) out.push_back({x, mu});
  };
  for (size_t j = 0; j < xs.size(); ++j) {
    const double x = xs[j];
    // At a shared x: left limit, value, right limit, so jumps of either input survive.
    emit(x, op(leftLimit(f, x), leftLimit(g, x)));
    emit(x, op(valueAt(f, x), valueAt(g, x)));
    const double rf = rightLimit(f, x), rg = rightLimit(g, x);
    emit(x, op(rf, rg));
    if (j + 1 == xs.size()) break;
    // On (x, x'), both are linear: they cross at most once, where f - g changes sign.
    const double x1 = xs[j + 1];
    const double lf = leftLimit(f, x1), lg = leftLimit(g, x1);
    const double d0 = rf - rg, d1 = lf - lg;
    if ((d0 < 0 && d1 > 0) || (d0 > 0 && d1 < 0)) {
      const double t = d0 / (d0 - d1);
      const double xc = x + t * (x1 - x);
      if (xc > x && xc < x1) emit(xc, rf + t * (lf - rf));
    }
  }
  return out;
}

}  // namespace

bool operator==(const Breakpoint& a, const Breakpoint& b) { return a.x == b.x && a.mu == b.mu; }
bool operator!=(const Breakpoint& a, const Breakpoint& b) { return !(a == b); }

void checkPiecewiseLinear(const std::vector<Breakpoint>& f) {
  for (size_t i = 0; i < f.size(); ++i) {
    auto at = [i] { return "[" + std::to_string(i) + "]"; };
    if (!std::isfinite(f[i].x) || !std::isfinite(f[i].mu)) {
      throw Error(errc::kInvalidParameter,
                  "breakpoint " + std::to_string(i) + " is not finite (x and mu must be numbers)",
                  at());
    }
    if (i > 0 && f[i].x < f[i - 1].x) {
      throw Error(errc::kInvalidParameter,
                  "breakpoints must have non-decreasing x: breakpoint " + std::to_string(i) +
                      " has x=" + formatNumber(f[i].x) + " < previous x=" +
                      formatNumber(f[i - 1].x),
                  at());
    }
  }
}

double valueAt(const std::vector<Breakpoint>& f, double x) {
  if (f.empty() || !(x >= f.front().x && x <= f.back().x)) return 0.0;
  const size_t first = firstAtOrAfter(f, x);
  const size_t past = pastLastAtOrBefore(f, x);
  if (first < past) {  // breakpoints at exactly x: the largest of them
    double best = f[first].mu;
    for (size_t i = first + 1; i < past; ++i) best = std::max(best, f[i].mu);
    return best;
  }
  return lerp(f[first - 1].x, f[first - 1].mu, f[first].x, f[first].mu, x);
}

double leftLimit(const std::vector<Breakpoint>& f, double x) {
  if (f.empty() || !(x > f.front().x && x <= f.back().x)) return 0.0;
  const size_t i = firstAtOrAfter(f, x);
  if (f[i].x == x) return f[i].mu;
  return lerp(f[i - 1].x, f[i - 1].mu, f[i].x, f[i].mu, x);
}

double rightLimit(const std::vector<Breakpoint>& f, double x) {
  if (f.empty() || !(x >= f.front().x && x < f.back().x)) return 0.0;
  const size_t i = pastLastAtOrBefore(f, x) - 1;
  if (f[i].x == x) return f[i].mu;
  return lerp(f[i].x, f[i].mu, f[i + 1].x, f[i + 1].mu, x);
}

double area(const std::vector<Breakpoint>& f) {
  double sum = 0.0;
  for (size_t i = 1; i < f.size(); ++i) {
    sum += 0.5 * (f[i].x - f[i - 1].x) * (f[i].mu + f[i - 1].mu);
  }
  return sum;
}

double height(const std::vector<Breakpoint>& f) {
  double h = 0.0;
  for (size_t i = 0; i < f.size(); ++i) h = i == 0 ? f[i].mu : std::max(h, f[i].mu);
  return h;
}

std::vector<Breakpoint> pointwiseMin(const std::vector<Breakpoint>& f,
                                     const std::vector<Breakpoint>& g) {
  return combine(f, g, [](double a, double b) { return std::min(a, b); });
}

std::vector<Breakpoint> pointwiseMax(const std::vector<Breakpoint>& f,
                                     const std::vector<Breakpoint>& g) {
  return combine(f, g, [](double a, double b) { return std::max(a, b); });
}

}  // namespace fsdb
