#include "geometry/fuzzy/fuzzy_number.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "geometry/core/error.h"
#include "geometry/core/number_format.h"

namespace fsdb {

namespace {

// Interior breakpoints whose mu is within this of their neighbours' line are dropped.
constexpr double kCollinearTolerance = 1e-12;

std::string index(size_t i) { return "[" + std::to_string(i) + "]"; }

Error invalidArgument(const std::string& message, const std::string& path) {
  return Error(errc::kInvalidDocument, message, path);
}

// The x where the segment from a (below the level) to b (above it) reaches height alpha,
// a.mu <= alpha <= b.mu, a.mu < b.mu. Endpoints come back exactly, so the cut at a breakpoint's
// level is that breakpoint's x.
double crossing(const Breakpoint& a, const Breakpoint& b, double alpha) {
  if (alpha == b.mu || a.x == b.x) return b.x;
  if (alpha == a.mu) return a.x;
  const double t = (alpha - a.mu) / (b.mu - a.mu), span = b.x - a.x;
  // Breakpoints near -DBL_MAX and DBL_MAX: their span overflows to infinity, the weighted mean
  // of the two does not (found by fuzz_fuzzy_number: {"tri":[-1e308,1e308,1e308]}).
  return std::isfinite(span) ? a.x + t * span : (1 - t) * a.x + t * b.x;
}

// Keeps (left limit, value, right limit) of each run of breakpoints sharing an x.
bool collapseRuns(std::vector<Breakpoint>& p) {
  std::vector<Breakpoint> out;
  out.reserve(p.size());
  for (size_t i = 0; i < p.size();) {
    size_t j = i;
    double top = p[i].mu;
    while (j + 1 < p.size() && p[j + 1].x == p[i].x) top = std::max(top, p[++j].mu);
    const Breakpoint first = p[i], last = p[j];
    out.push_back(first);
    if (top != first.mu && top != last.mu) out.push_back({first.x, top});
    if (last.mu != out.back().mu) out.push_back(last);
    i = j + 1;
  }
  const bool changed = out.size() != p.size();
  p = std::move(out);
  return changed;
}

// Drops leading and trailing mu == 0 pieces, so the list spans exactly the support.
bool trimZeros(std::vector<Breakpoint>& p) {
  size_t begin = 0, end = p.size();
  while (end - begin >= 2 && p[begin].mu == 0 && p[begin + 1].mu == 0) ++begin;
  while (end - begin >= 2 && p[end - 1].mu == 0 && p[end - 2].mu == 0) --end;
  if (begin == 0 && end == p.size()) return false;
  p = std::vector<Breakpoint>(p.begin() + begin, p.begin() + end);
  return true;
}

// Drops interior breakpoints on the line through their neighbours. A point at mu 0 or 1 is
// kept unless its neighbours share its mu: dropping it could lose normality or move the support.
bool dropCollinear(std::vector<Breakpoint>& p) {
  if (p.size() < 3) return false;
  std::vector<Breakpoint> out;
  out.reserve(p.size());
  out.push_back(p[0]);
  for (size_t i = 1; i + 1 < p.size(); ++i) {
    const Breakpoint& a = out.back();
    const Breakpoint& b = p[i];
    const Breakpoint& c = p[i + 1];
    bool drop = false;
    if (a.x < b.x && b.x < c.x) {
      const double onLine = a.mu + (c.mu - a.mu) * ((b.x - a.x) / (c.x - a.x));
      const bool extreme = b.mu == 0 || b.mu == 1;
      drop = std::abs(b.mu - onLine) <= kCollinearTolerance && (!extreme || (a.mu == b.mu && c.mu == b.mu));
    }
    if (!drop) out.push_back(b);
  }
  out.push_back(p.back());
  const bool changed = out.size() != p.size();
  p = std::move(out);
  return changed;
}

std::vector<Breakpoint> canonical(std::vector<Breakpoint> p) {
  if (p.front().mu > 0) p.insert(p.begin(), Breakpoint{p.front().x, 0.0});
  if (p.back().mu > 0) p.push_back(Breakpoint{p.back().x, 0.0});
  // Each step can enable another; iterate to the fixed point so canonical() is idempotent.
  for (bool changed = true; changed;) {
    changed = collapseRuns(p);
    changed = trimZeros(p) || changed;
    changed = dropCollinear(p) || changed;
  }
  return p;
}

void checkAlpha(double alpha, bool allowZero, bool allowOne) {
  const bool ok = std::isfinite(alpha) && (allowZero ? alpha >= 0 : alpha > 0) && (allowOne ? alpha <= 1 : alpha < 1);
  if (!ok) {
    throw Error(errc::kInvalidParameter,
                "alpha must be in " + std::string(allowZero ? "[0" : "(0") + ", " + (allowOne ? "1]" : "1)") +
                    ", got " + formatNumber(alpha),
                "alpha");
  }
}

// Hull of the cut at alpha: strong ? {mu > alpha} : {mu >= alpha}. The lower end is where the
// first breakpoint above the level is reached, along the segment leading to it.
Interval cutHull(const std::vector<Breakpoint>& p, double alpha, bool strong) {
  auto above = [alpha, strong](double mu) { return strong ? mu > alpha : mu >= alpha; };
  size_t i = 0;
  while (!above(p[i].mu)) ++i;
  size_t j = p.size() - 1;
  while (!above(p[j].mu)) --j;
  // Canonical lists start and end at mu 0, so for alpha > 0 (or strong cuts) i > 0, j < last.
  const double lo = i == 0 ? p[0].x : crossing(p[i - 1], p[i], alpha);
  const double hi = j + 1 == p.size() ? p[j].x : crossing(p[j + 1], p[j], alpha);
  return {lo, hi};
}

}  // namespace

FuzzyNumber::FuzzyNumber() : FuzzyNumber(crisp(0.0)) {}

FuzzyNumber FuzzyNumber::crisp(double x) {
  if (!std::isfinite(x)) throw invalidArgument("a crisp number must be finite, got " + formatNumber(x), "");
  return FuzzyNumber({{x, 0.0}, {x, 1.0}, {x, 0.0}});
}

FuzzyNumber FuzzyNumber::triangular(double l, double m, double r) {
  const double v[3] = {l, m, r};
  const char* names[3] = {"l", "m", "r"};
  for (size_t i = 0; i < 3; ++i) {
    if (!std::isfinite(v[i])) {
      throw invalidArgument(
          std::string("triangular number needs finite l, m, r; got ") + names[i] + "=" + formatNumber(v[i]), index(i));
    }
  }
  for (size_t i = 1; i < 3; ++i) {
    if (v[i - 1] > v[i]) {
      throw invalidArgument(std::string("triangular number needs l <= m <= r, got ") + names[i - 1] + "=" +
                                formatNumber(v[i - 1]) + " > " + names[i] + "=" + formatNumber(v[i]),
                            index(i));
    }
  }
  return FuzzyNumber(canonical({{l, 0.0}, {m, 1.0}, {r, 0.0}}));
}

FuzzyNumber FuzzyNumber::trapezoidal(double a, double b, double c, double d) {
  const double v[4] = {a, b, c, d};
  const char* names[4] = {"a", "b", "c", "d"};
  for (size_t i = 0; i < 4; ++i) {
    if (!std::isfinite(v[i])) {
      throw invalidArgument(std::string("trapezoidal number needs finite a, b, c, d; got ") + names[i] + "=" +
                                formatNumber(v[i]),
                            index(i));
    }
  }
  for (size_t i = 1; i < 4; ++i) {
    if (v[i - 1] > v[i]) {
      throw invalidArgument(std::string("trapezoidal number needs a <= b <= c <= d, got ") + names[i - 1] + "=" +
                                formatNumber(v[i - 1]) + " > " + names[i] + "=" + formatNumber(v[i]),
                            index(i));
    }
  }
  return FuzzyNumber(canonical({{a, 0.0}, {b, 1.0}, {c, 1.0}, {d, 0.0}}));
}

FuzzyNumber FuzzyNumber::fromPoints(const std::vector<Breakpoint>& points) {
  if (points.empty()) {
    throw invalidArgument("points must hold at least one [x, mu] pair with mu = 1", "");
  }
  double top = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    const Breakpoint& p = points[i];
    if (!std::isfinite(p.x)) {
      throw invalidArgument("point " + std::to_string(i) + ": x must be finite, got " + formatNumber(p.x),
                            index(i) + "[0]");
    }
    if (!(p.mu >= 0 && p.mu <= 1)) {
      throw invalidArgument("point " + std::to_string(i) + ": mu must be in [0, 1], got " + formatNumber(p.mu),
                            index(i) + "[1]");
    }
    if (i > 0 && p.x < points[i - 1].x) {
      throw invalidArgument("points need non-decreasing x: point " + std::to_string(i) + " has x=" + formatNumber(p.x) +
                                " < previous x=" + formatNumber(points[i - 1].x),
                            index(i) + "[0]");
    }
    top = std::max(top, p.mu);
  }
  if (top != 1.0) {
    throw invalidArgument("points must be normal (reach mu = 1 somewhere); the largest mu is " + formatNumber(top), "");
  }
  return FuzzyNumber(canonical(points));
}

FuzzyNumber FuzzyNumber::fromAlphaCuts(const std::vector<double>& alphas, const std::vector<Interval>& cuts) {
  auto fail = [](const std::string& message, const std::string& path) {
    return Error(errc::kInvalidParameter, message, path);
  };
  if (alphas.empty() || alphas.size() != cuts.size()) {
    throw fail("alphas and cuts must be non-empty and of the same length, got " + std::to_string(alphas.size()) +
                   " and " + std::to_string(cuts.size()),
               "alphas");
  }
  double scale = 1.0;
  for (size_t k = 0; k < alphas.size(); ++k) {
    if (!(alphas[k] >= 0 && alphas[k] <= 1)) {
      throw fail("alpha levels must be in [0, 1], got " + formatNumber(alphas[k]), "alphas" + index(k));
    }
    if (k > 0 && alphas[k] < alphas[k - 1]) {
      throw fail("alpha levels must be non-decreasing", "alphas" + index(k));
    }
    if (k > 1 && alphas[k] == alphas[k - 2]) {
      throw fail("an alpha level may appear at most twice (closed and strong cut)", "alphas" + index(k));
    }
    if (!std::isfinite(cuts[k].lo) || !std::isfinite(cuts[k].hi) || cuts[k].lo > cuts[k].hi) {
      throw fail("cut " + std::to_string(k) + " must be finite with lo <= hi, got [" + formatNumber(cuts[k].lo) + ", " +
                     formatNumber(cuts[k].hi) + "]",
                 "cuts" + index(k));
    }
    scale = std::max({scale, std::abs(cuts[k].lo), std::abs(cuts[k].hi)});
  }
  if (alphas.back() != 1.0) {
    throw fail("the last alpha level must be 1 (a fuzzy number is normal), got " + formatNumber(alphas.back()),
               "alphas" + index(alphas.size() - 1));
  }
  // Up the left side (lo at rising alpha), then down the right side (hi at falling alpha).
  std::vector<Breakpoint> points;
  std::vector<size_t> cutOf;
  points.reserve(2 * cuts.size());
  for (size_t k = 0; k < cuts.size(); ++k) {
    points.push_back({cuts[k].lo, alphas[k]});
    cutOf.push_back(k);
  }
  for (size_t k = cuts.size(); k-- > 0;) {
    points.push_back({cuts[k].hi, alphas[k]});
    cutOf.push_back(k);
  }
  // Nested cuts give non-decreasing x; rounding in the caller's arithmetic may break that by
  // an ulp or so, which is clamped. Anything larger is a caller error.
  const double tolerance = 1e-9 * scale;
  for (size_t i = 1; i < points.size(); ++i) {
    if (points[i].x < points[i - 1].x) {
      if (points[i - 1].x - points[i].x > tolerance) {
        throw fail("cuts must be nested (each inside the cut of the level below it)",
                   "cuts" + index(std::max(cutOf[i], cutOf[i - 1])));
      }
      points[i].x = points[i - 1].x;
    }
  }
  return fromPoints(points);
}

double FuzzyNumber::membership(double x) const { return valueAt(points_, x); }

Interval FuzzyNumber::alphaCut(double alpha) const {
  checkAlpha(alpha, /*allowZero=*/true, /*allowOne=*/true);
  if (alpha == 0) return support();
  return cutHull(points_, alpha, /*strong=*/false);
}

Interval FuzzyNumber::strongAlphaCut(double alpha) const {
  checkAlpha(alpha, /*allowZero=*/true, /*allowOne=*/false);
  return cutHull(points_, alpha, /*strong=*/true);
}

Interval FuzzyNumber::support() const { return {points_.front().x, points_.back().x}; }

Interval FuzzyNumber::core() const { return alphaCut(1.0); }

bool FuzzyNumber::isCrisp() const { return points_.front().x == points_.back().x; }

bool FuzzyNumber::isConvex() const {
  // Quasi-concave: along the breakpoints mu never rises again once it has fallen.
  bool falling = false;
  for (size_t i = 1; i < points_.size(); ++i) {
    if (points_[i].mu < points_[i - 1].mu) falling = true;
    if (falling && points_[i].mu > points_[i - 1].mu) return false;
  }
  return true;
}

double FuzzyNumber::cardinality() const { return area(points_); }

bool operator==(const FuzzyNumber& a, const FuzzyNumber& b) { return a.breakpoints() == b.breakpoints(); }
bool operator!=(const FuzzyNumber& a, const FuzzyNumber& b) { return !(a == b); }

}  // namespace fsdb
