#include "geometry/fuzzy/defuzzify.h"

#include <algorithm>
#include <cmath>

#include "geometry/core/error.h"
#include "geometry/core/number_format.h"

namespace fsdb {

namespace {

// The pieces [lo, hi] of the set where mu == 1, left to right.
std::vector<Interval> corePieces(const FuzzyNumber& a) {
  std::vector<Interval> pieces;
  const auto& p = a.breakpoints();
  for (size_t i = 0; i < p.size(); ++i) {
    if (p[i].mu != 1.0) continue;
    size_t j = i;
    while (j + 1 < p.size() && p[j + 1].mu == 1.0) ++j;
    pieces.push_back({p[i].x, p[j].x});
    i = j;
  }
  return pieces;
}

// Length t from the start of a linear piece (height m0 there, slope s) whose area is target:
// m0 t + s t^2 / 2 = target, in the form that stays accurate when s or m0 is 0.
double lengthForArea(double m0, double s, double target) {
  if (target <= 0) return 0.0;
  const double disc = std::max(0.0, m0 * m0 + 2 * s * target);
  const double denom = m0 + std::sqrt(disc);
  return denom > 0 ? 2 * target / denom : 0.0;
}

// The smallest x with area(front..x) = target, walking from the left.
double reachFromLeft(const std::vector<Breakpoint>& p, double target) {
  double sum = 0.0;
  for (size_t i = 1; i < p.size(); ++i) {
    const double dx = p[i].x - p[i - 1].x;
    const double piece = 0.5 * dx * (p[i].mu + p[i - 1].mu);
    if (dx > 0 && sum + piece >= target) {
      const double s = (p[i].mu - p[i - 1].mu) / dx;
      return p[i - 1].x + std::min(dx, lengthForArea(p[i - 1].mu, s, target - sum));
    }
    sum += piece;
  }
  return p.back().x;
}

// The largest x with area(x..back) = target, walking from the right.
double reachFromRight(const std::vector<Breakpoint>& p, double target) {
  double sum = 0.0;
  for (size_t i = p.size() - 1; i > 0; --i) {
    const double dx = p[i].x - p[i - 1].x;
    const double piece = 0.5 * dx * (p[i].mu + p[i - 1].mu);
    if (dx > 0 && sum + piece >= target) {
      const double s = (p[i - 1].mu - p[i].mu) / dx;
      return p[i].x - std::min(dx, lengthForArea(p[i].mu, s, target - sum));
    }
    sum += piece;
  }
  return p.front().x;
}

}  // namespace

double centroid(const FuzzyNumber& a) {
  const auto& p = a.breakpoints();
  // Moments about the left end of the support keep precision for numbers far from 0.
  const double origin = p.front().x;
  double mass = 0.0, moment = 0.0;
  for (size_t i = 1; i < p.size(); ++i) {
    const double x0 = p[i - 1].x - origin, x1 = p[i].x - origin;
    const double m0 = p[i - 1].mu, m1 = p[i].mu;
    mass += 0.5 * (x1 - x0) * (m0 + m1);
    // ∫ x mu dx over a linear piece = (x1 - x0)/6 * (x0 (2 m0 + m1) + x1 (m0 + 2 m1))
    moment += (x1 - x0) / 6.0 * (x0 * (2 * m0 + m1) + x1 * (m0 + 2 * m1));
  }
  if (mass <= 0) return meanOfMaxima(a);
  return origin + moment / mass;
}

double bisector(const FuzzyNumber& a) {
  const auto& p = a.breakpoints();
  const double half = 0.5 * area(p);
  if (half <= 0) return meanOfMaxima(a);
  // Both walks meet at the same x unless a run of mu = 0 straddles it; then its middle.
  return 0.5 * (reachFromLeft(p, half) + reachFromRight(p, half));
}

double smallestOfMaxima(const FuzzyNumber& a) { return corePieces(a).front().lo; }

double largestOfMaxima(const FuzzyNumber& a) { return corePieces(a).back().hi; }

double meanOfMaxima(const FuzzyNumber& a) {
  const std::vector<Interval> pieces = corePieces(a);
  double length = 0.0, weighted = 0.0, midSum = 0.0;
  for (const Interval& c : pieces) {
    length += width(c);
    weighted += width(c) * 0.5 * (c.lo + c.hi);
    midSum += 0.5 * (c.lo + c.hi);
  }
  return length > 0 ? weighted / length : midSum / static_cast<double>(pieces.size());
}

std::vector<RankedValue> localMaxima(const std::vector<Breakpoint>& membership, double threshold) {
  checkPiecewiseLinear(membership);
  if (!std::isfinite(threshold)) {
    throw Error(errc::kInvalidParameter,
                "threshold (R_alpha) must be a finite number, got " + formatNumber(threshold),
                "threshold");
  }
  if (membership.empty()) return {};

  // The graph as a path of vertices: a jump keeps (left limit, value, right limit), so the
  // path never dips inside a jump and a jump's top is a vertex of its own.
  std::vector<Breakpoint> path;
  path.reserve(membership.size());
  double scale = 1.0;
  for (size_t i = 0; i < membership.size();) {
    size_t j = i;
    double top = membership[i].mu;
    while (j + 1 < membership.size() && membership[j + 1].x == membership[i].x) {
      top = std::max(top, membership[++j].mu);
    }
    for (const Breakpoint& b : {membership[i], Breakpoint{membership[i].x, top}, membership[j]}) {
      if (path.empty() || path.back() != b) path.push_back(b);
    }
    scale = std::max(scale, std::abs(top));
    i = j + 1;
  }

  // Plateaus: maximal runs of path vertices whose consecutive mu differ by at most tolerance
  // (sampled functions carry rounding noise that must not split a flat top).
  const double tolerance = 1e-12 * scale;
  struct Plateau {
    double xFirst, xLast, top, firstMu, lastMu;
  };
  std::vector<Plateau> plateaus;
  plateaus.reserve(path.size());
  for (const Breakpoint& v : path) {
    if (!plateaus.empty() && std::abs(v.mu - plateaus.back().lastMu) <= tolerance) {
      Plateau& p = plateaus.back();
      p.xLast = v.x;
      p.lastMu = v.mu;
      p.top = std::max(p.top, v.mu);
    } else {
      plateaus.push_back({v.x, v.x, v.mu, v.mu, v.mu});
    }
  }

  // Bernardes, Wu & D'Ottaviano, §5: the candidates are the pairs whose grades of membership are
  // local maxima.
  std::vector<RankedValue> maxima;
  for (size_t k = 0; k < plateaus.size(); ++k) {
    const Plateau& p = plateaus[k];
    const bool higherThanLeft = k == 0 || plateaus[k - 1].lastMu < p.firstMu;
    const bool higherThanRight = k + 1 == plateaus.size() || plateaus[k + 1].firstMu < p.lastMu;
    // Bernardes, Wu & D'Ottaviano, §7: the threshold R_alpha discards improbable maxima.
    if (higherThanLeft && higherThanRight && p.top >= threshold) {
      maxima.push_back({0.5 * (p.xFirst + p.xLast), p.top});
    }
  }
  std::sort(maxima.begin(), maxima.end(), [](const RankedValue& a, const RankedValue& b) {
    return a.mu != b.mu ? a.mu > b.mu : a.x < b.x;
  });
  return maxima;
}

}  // namespace fsdb
