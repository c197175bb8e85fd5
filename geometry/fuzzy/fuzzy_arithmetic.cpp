#include "geometry/fuzzy/fuzzy_arithmetic.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/core/error.h"
#include "geometry/core/number_format.h"

namespace fsdb {

namespace {

// Which extra levels an operation needs between the operands' breakpoint levels.
enum class Extra {
  kNone,           // add, subtract: linear between breakpoint levels
  kMultiplicative, // multiply, divide: uniform refinement and zero crossings of the cut ends
  kCrossings,      // min, max: where the operands' cut ends cross
};

std::vector<double> breakpointLevels(const FuzzyNumber& a, const FuzzyNumber& b) {
  std::vector<double> levels = {0.0, 1.0};
  for (const auto& p : a.breakpoints()) levels.push_back(p.mu);
  for (const auto& p : b.breakpoints()) levels.push_back(p.mu);
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  return levels;
}

// Adds the level in (a0, a1) where a function linear on (a0, a1] goes from f0 (its limit at
// a0) to f1 (its value at a1) through 0, if it changes sign there.
void addZeroCrossing(double a0, double a1, double f0, double f1, std::vector<double>& out) {
  if ((f0 < 0 && f1 > 0) || (f0 > 0 && f1 < 0)) {
    const double level = a0 + (a1 - a0) * (f0 / (f0 - f1));
    if (level > a0 && level < a1) out.push_back(level);
  }
}

std::vector<double> levelsFor(const FuzzyNumber& a, const FuzzyNumber& b, Extra extra) {
  std::vector<double> levels = breakpointLevels(a, b);
  if (extra == Extra::kNone) return levels;
  std::vector<double> more;
  // Between consecutive breakpoint levels each cut end is linear in alpha, from its strong
  // cut value at the lower level to its closed cut value at the upper one.
  for (size_t k = 0; k + 1 < levels.size(); ++k) {
    const double a0 = levels[k], a1 = levels[k + 1];
    const Interval sa = a.strongAlphaCut(a0), sb = b.strongAlphaCut(a0);
    const Interval ca = a.alphaCut(a1), cb = b.alphaCut(a1);
    if (extra == Extra::kMultiplicative) {
      addZeroCrossing(a0, a1, sa.lo, ca.lo, more);
      addZeroCrossing(a0, a1, sa.hi, ca.hi, more);
      addZeroCrossing(a0, a1, sb.lo, cb.lo, more);
      addZeroCrossing(a0, a1, sb.hi, cb.hi, more);
    } else {
      addZeroCrossing(a0, a1, sa.lo - sb.lo, ca.lo - cb.lo, more);
      addZeroCrossing(a0, a1, sa.hi - sb.hi, ca.hi - cb.hi, more);
    }
  }
  if (extra == Extra::kMultiplicative) {
    for (int k = 1; k < kArithmeticRefinementLevels; ++k) {
      more.push_back(static_cast<double>(k) / kArithmeticRefinementLevels);
    }
  }
  levels.insert(levels.end(), more.begin(), more.end());
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  return levels;
}

// Zhang, Pham & Chen, §3.2 eq. 3-4: (A o B)(alpha) = {a o b | a in A(alpha), b in B(alpha)}, its
// ends the min / max of a o b over the cut ends. Per level: the closed cut, and the strong cut
// where it differs.
template <class IntervalOp>
FuzzyNumber combine(const FuzzyNumber& a, const FuzzyNumber& b, Extra extra, IntervalOp op) {
  const std::vector<double> levels = levelsFor(a, b, extra);
  std::vector<double> alphas;
  std::vector<Interval> cuts;
  alphas.reserve(2 * levels.size());
  cuts.reserve(2 * levels.size());
  for (double alpha : levels) {
    const Interval closed = op(a.alphaCut(alpha), b.alphaCut(alpha));
    alphas.push_back(alpha);
    cuts.push_back(closed);
    if (alpha < 1.0) {
      const Interval strong = op(a.strongAlphaCut(alpha), b.strongAlphaCut(alpha));
      if (strong != closed) {
        alphas.push_back(alpha);
        cuts.push_back(strong);
      }
    }
  }
  return FuzzyNumber::fromAlphaCuts(alphas, cuts);
}

}  // namespace

// cut_a(A + B) = [lo_A + lo_B, hi_A + hi_B]
FuzzyNumber add(const FuzzyNumber& a, const FuzzyNumber& b) {
  return combine(a, b, Extra::kNone, [](Interval x, Interval y) { return fsdb::add(x, y); });
}

// cut_a(A - B) = [lo_A - hi_B, hi_A - lo_B]
FuzzyNumber subtract(const FuzzyNumber& a, const FuzzyNumber& b) {
  return combine(a, b, Extra::kNone, [](Interval x, Interval y) { return fsdb::sub(x, y); });
}

// cut_a(A * B) = hull of the endpoint products
FuzzyNumber multiply(const FuzzyNumber& a, const FuzzyNumber& b) {
  return combine(a, b, Extra::kMultiplicative,
                 [](Interval x, Interval y) { return fsdb::mul(x, y); });
}

// cut_a(A / B) = cut_a(A) * [1/hi_B, 1/lo_B], defined when 0 is outside supp(B)
FuzzyNumber divide(const FuzzyNumber& a, const FuzzyNumber& b) {
  const Interval s = b.support();
  if (contains(s, 0.0)) {
    throw Error(errc::kDomainError,
                "division by a fuzzy number whose support [" + formatNumber(s.lo) + ", " +
                    formatNumber(s.hi) + "] contains 0",
                "divisor");
  }
  return combine(a, b, Extra::kMultiplicative,
                 [](Interval x, Interval y) { return fsdb::div(x, y); });
}

// cut_a(min(A, B)) = [min(lo_A, lo_B), min(hi_A, hi_B)]
FuzzyNumber min(const FuzzyNumber& a, const FuzzyNumber& b) {
  return combine(a, b, Extra::kCrossings, [](Interval x, Interval y) { return fsdb::min(x, y); });
}

// cut_a(max(A, B)) = [max(lo_A, lo_B), max(hi_A, hi_B)]
FuzzyNumber max(const FuzzyNumber& a, const FuzzyNumber& b) {
  return combine(a, b, Extra::kCrossings, [](Interval x, Interval y) { return fsdb::max(x, y); });
}

// mu_{kA}(x) = mu_A(x / k): the breakpoints scale (and reverse order for k < 0).
FuzzyNumber scale(const FuzzyNumber& a, double k) {
  if (!std::isfinite(k)) {
    throw Error(errc::kInvalidParameter, "scale factor must be finite, got " + formatNumber(k),
                "k");
  }
  if (k == 0) return FuzzyNumber::crisp(0.0);
  std::vector<Breakpoint> points = a.breakpoints();
  for (auto& p : points) p.x = k * p.x + 0.0;  // + 0.0 turns -0 into 0
  if (k < 0) std::reverse(points.begin(), points.end());
  return FuzzyNumber::fromPoints(points);
}

FuzzyNumber negate(const FuzzyNumber& a) { return scale(a, -1.0); }

FuzzyNumber operator+(const FuzzyNumber& a, const FuzzyNumber& b) { return add(a, b); }
FuzzyNumber operator-(const FuzzyNumber& a, const FuzzyNumber& b) { return subtract(a, b); }
FuzzyNumber operator*(const FuzzyNumber& a, const FuzzyNumber& b) { return multiply(a, b); }
FuzzyNumber operator/(const FuzzyNumber& a, const FuzzyNumber& b) { return divide(a, b); }
FuzzyNumber operator-(const FuzzyNumber& a) { return negate(a); }

}  // namespace fsdb
