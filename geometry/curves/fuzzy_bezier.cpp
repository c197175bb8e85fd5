#include "geometry/curves/fuzzy_bezier.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "geometry/fuzzy/defuzzify.h"
#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_arithmetic.h"
#include "geometry/numeric/interval_functions.h"

namespace fsdb {
namespace {

std::string indexPath(const std::string& base, std::size_t i) { return base + "[" + std::to_string(i) + "]"; }

void checkUnit(double x, const char* name) {
  if (!std::isfinite(x) || x < 0.0 || x > 1.0)
    throw Error(errc::kInvalidParameter, std::string(name) + " must lie in [0, 1]", name);
}

void validatePolygon(const std::vector<FuzzyPoint>& points, const std::string& path, std::size_t dimension) {
  if (points.empty()) throw Error(errc::kInvalidDocument, "at least one control point is needed", path);
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].size() != dimension)
      throw Error(errc::kInvalidDocument,
                  "control points must all have " + std::to_string(dimension) + " coordinates, this one has " +
                      std::to_string(points[i].size()),
                  indexPath(path, i));
}

// interval_functions.h's mid halves first: no overflow for ends near ±1.8e308.
double coreMidpoint(const FuzzyNumber& a) { return mid(a.core()); }

// Coordinates near the double range can still overflow in the combinations (a rational curve's
// w·P, differences of the hull): an answer holds finite numbers or is refused, never null.
FuzzyBezierPoint finite(FuzzyBezierPoint p, const char* path) {
  for (const CrispPoint* q : {&p.lower, &p.crisp, &p.upper})
    for (double x : *q)
      if (!std::isfinite(x))
        throw Error(errc::kDomainError, "the curve's values overflow the double range here (coordinates or weights too large)",
                    path);
  return p;
}

// Per control point: the lower ends of the coordinates' cuts, then the core midpoints, then the
// upper ends (3 × dimension values). De Casteljau interpolates componentwise, so one run on
// these packed points evaluates the three curves at once.
CrispPoint packedEnds(const FuzzyPoint& p, double alpha) {
  const std::size_t d = p.size();
  CrispPoint out(3 * d);
  for (std::size_t c = 0; c < d; ++c) {
    const Interval cut = p[c].alphaCut(alpha);
    out[c] = cut.lo;
    out[d + c] = coreMidpoint(p[c]);
    out[2 * d + c] = cut.hi;
  }
  return out;
}

FuzzyBezierPoint unpack(const CrispPoint& packed, std::size_t d) {
  return {CrispPoint(packed.begin(), packed.begin() + d), CrispPoint(packed.begin() + d, packed.begin() + 2 * d),
          CrispPoint(packed.begin() + 2 * d, packed.end())};
}

// min over w_k in [lo_k, hi_k] of Σ w_k x_k / Σ w_k (all lo_k ≥ 0, Σ lo_k > 0): the minimiser
// gives hi to the s smallest x and lo to the rest for some split s (header: rational hull).
// `order` lists the indices by ascending x; `sign` −1 reads every x negated (the maximum).
double minWeightedMean(const std::vector<CrispPoint>& ends, std::size_t c, double sign,
                       const std::vector<std::size_t>& order, const std::vector<double>& lo,
                       const std::vector<double>& hi) {
  double num = 0, den = 0;
  for (std::size_t k : order) num += lo[k] * sign * ends[k][c], den += lo[k];
  double best = num / den;
  for (std::size_t k : order) {
    num += (hi[k] - lo[k]) * sign * ends[k][c];
    den += hi[k] - lo[k];
    best = std::min(best, num / den);
  }
  return best;
}

// The control points by ascending sign · ends[k][c] (the split order of minWeightedMean).
std::vector<std::size_t> splitOrder(const std::vector<CrispPoint>& ends, std::size_t c, double sign) {
  std::vector<std::size_t> order(ends.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return sign * ends[a][c] < sign * ends[b][c]; });
  return order;
}

// The rational point at u: crisp by the homogeneous de Casteljau and the projection Π, lower /
// upper as the hull over the cuts (header).
FuzzyBezierPoint evaluateRational(const BezierCurveCut& cut, double u) {
  const std::size_t n = cut.ends.size(), dim = cut.dimension;
  const CrispPoint h = deCasteljau(cut.homogeneous, u);  // Sarwar & Akram, §2: de Casteljau on (wP, w)
  FuzzyBezierPoint out;
  for (std::size_t c = 0; c < dim; ++c) out.crisp.push_back(h[c] / h[dim]);  // the projection Π

  std::vector<double> wlo(n), whi(n);
  const std::vector<double> basis = bernsteinBasis(n - 1, u);
  for (std::size_t k = 0; k < n; ++k) {
    wlo[k] = basis[k] * cut.weights[k].lo;
    whi[k] = basis[k] * cut.weights[k].hi;
  }
  for (std::size_t c = 0; c < dim; ++c) {
    out.lower.push_back(minWeightedMean(cut.ends, c, 1.0, cut.order[c], wlo, whi));
    // max of the mean = −min of the mean of the negated values
    out.upper.push_back(-minWeightedMean(cut.ends, 2 * dim + c, -1.0, cut.order[dim + c], wlo, whi));
  }
  return out;
}

// P'_k = k/(r+1) P_{k−1} + (1 − k/(r+1)) P_k for k = 0..r+1 (Sarwar & Akram, degree elevation).
std::vector<FuzzyPoint> elevateOnce(const std::vector<FuzzyPoint>& p) {
  const std::size_t r = p.size() - 1;
  std::vector<FuzzyPoint> out(r + 2);
  out[0] = p[0];
  out[r + 1] = p[r];
  for (std::size_t k = 1; k <= r; ++k) {
    const double a = static_cast<double>(k) / static_cast<double>(r + 1);
    for (std::size_t c = 0; c < p[k].size(); ++c) out[k].push_back(add(scale(p[k - 1][c], a), scale(p[k][c], 1 - a)));
  }
  return out;
}

// Rational, crisp weights: homogeneous elevation, points as convex combinations (header).
FuzzyBezierCurve elevateRationalOnce(const FuzzyBezierCurve& curve) {
  const std::size_t r = curve.controlPoints.size() - 1;
  std::vector<double> w(r + 1);
  for (std::size_t k = 0; k <= r; ++k) w[k] = coreMidpoint(curve.weights[k]);
  FuzzyBezierCurve out;
  out.controlPoints.resize(r + 2);
  out.weights.resize(r + 2);
  out.controlPoints[0] = curve.controlPoints[0];
  out.controlPoints[r + 1] = curve.controlPoints[r];
  out.weights[0] = FuzzyNumber::crisp(w[0]);
  out.weights[r + 1] = FuzzyNumber::crisp(w[r]);
  for (std::size_t k = 1; k <= r; ++k) {
    const double a = static_cast<double>(k) / static_cast<double>(r + 1);
    const double wk = a * w[k - 1] + (1 - a) * w[k];
    out.weights[k] = FuzzyNumber::crisp(wk);
    for (std::size_t c = 0; c < curve.controlPoints[k].size(); ++c)
      out.controlPoints[k].push_back(add(scale(curve.controlPoints[k - 1][c], a * w[k - 1] / wk),
                                         scale(curve.controlPoints[k][c], (1 - a) * w[k] / wk)));
  }
  return out;
}

void checkTimes(int times, const char* name) {
  if (times < 0) throw Error(errc::kInvalidParameter, std::string(name) + " must be at least 0", name);
}

}  // namespace

void validateCurve(const FuzzyBezierCurve& curve) {
  validatePolygon(curve.controlPoints, "control_points",
                  curve.controlPoints.empty() ? 0 : curve.controlPoints[0].size());
  if (curve.controlPoints[0].empty())
    throw Error(errc::kInvalidDocument, "a control point needs at least one coordinate", "control_points[0]");
  if (!curve.isRational()) return;
  if (curve.weights.size() != curve.controlPoints.size())
    throw Error(errc::kInvalidDocument,
                "one weight per control point is needed: " + std::to_string(curve.controlPoints.size()) +
                    " control points, " + std::to_string(curve.weights.size()) + " weights",
                "weights");
  for (std::size_t k = 0; k < curve.weights.size(); ++k)
    if (!(curve.weights[k].support().lo > 0.0))
      throw Error(errc::kInvalidDocument, "weights must be positive (the support must lie above 0)",
                  indexPath("weights", k));
}

void validateSurface(const FuzzyBezierSurface& surface) {
  const auto& grid = surface.controlGrid;
  if (grid.empty()) throw Error(errc::kInvalidDocument, "at least one row of control points is needed", "control_grid");
  const std::size_t columns = grid[0].size();
  const std::size_t dimension = columns == 0 ? 0 : grid[0][0].size();
  if (dimension == 0)
    throw Error(errc::kInvalidDocument, "a control point needs at least one coordinate", "control_grid[0]");
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (grid[i].size() != columns)
      throw Error(errc::kInvalidDocument,
                  "every row needs " + std::to_string(columns) + " control points, this one has " +
                      std::to_string(grid[i].size()),
                  indexPath("control_grid", i));
    validatePolygon(grid[i], indexPath("control_grid", i), dimension);
  }
}

double bernstein(std::size_t r, std::size_t k, double u) {
  if (k > r) return 0.0;
  double binomial = 1.0;
  for (std::size_t i = 1; i <= k; ++i) binomial = binomial * static_cast<double>(r - k + i) / static_cast<double>(i);
  return binomial * std::pow(u, static_cast<double>(k)) * std::pow(1.0 - u, static_cast<double>(r - k));
}

std::vector<double> bernsteinBasis(std::size_t r, double u) {
  std::vector<double> b(r + 1, 0.0);
  b[0] = 1.0;
  for (std::size_t j = 1; j <= r; ++j)
    for (std::size_t k = j + 1; k-- > 0;) b[k] = (1.0 - u) * b[k] + (k > 0 ? u * b[k - 1] : 0.0);
  return b;
}

CrispPoint deCasteljau(const std::vector<CrispPoint>& points, double u) {
  std::vector<CrispPoint> b = points;
  // Sarwar & Akram, Algorithm 1: b_k^j = (1 − u) b_k^{j−1} + u b_{k+1}^{j−1}.
  for (std::size_t level = 1; level < b.size(); ++level)
    for (std::size_t k = 0; k + level < b.size(); ++k)
      for (std::size_t c = 0; c < b[k].size(); ++c) b[k][c] = (1.0 - u) * b[k][c] + u * b[k + 1][c];
  return b.empty() ? CrispPoint{} : b[0];
}

BezierCurveCut cutCurve(const FuzzyBezierCurve& curve, double alpha) {
  validateCurve(curve);
  checkUnit(alpha, "alpha");
  BezierCurveCut cut;
  cut.dimension = curve.controlPoints[0].size();
  for (const FuzzyPoint& p : curve.controlPoints) cut.ends.push_back(packedEnds(p, alpha));  // Sarwar & Akram, eq. 3
  if (!curve.isRational()) return cut;
  const std::size_t dim = cut.dimension;
  for (std::size_t k = 0; k < curve.weights.size(); ++k) {
    cut.weights.push_back(curve.weights[k].alphaCut(alpha));
    const double w = coreMidpoint(curve.weights[k]);
    CrispPoint h;
    for (std::size_t c = 0; c < dim; ++c) h.push_back(w * cut.ends[k][dim + c]);
    h.push_back(w);
    cut.homogeneous.push_back(std::move(h));
  }
  for (std::size_t c = 0; c < dim; ++c) cut.order.push_back(splitOrder(cut.ends, c, 1.0));
  for (std::size_t c = 0; c < dim; ++c) cut.order.push_back(splitOrder(cut.ends, 2 * dim + c, -1.0));
  return cut;
}

FuzzyBezierPoint evaluateCut(const BezierCurveCut& cut, double u) {
  checkUnit(u, "u");
  if (!cut.weights.empty()) return finite(evaluateRational(cut, u), "control_points");
  return finite(unpack(deCasteljau(cut.ends, u), cut.dimension), "control_points");
}

FuzzyBezierPoint evaluateCurve(const FuzzyBezierCurve& curve, double u, double alpha) {
  return evaluateCut(cutCurve(curve, alpha), u);
}

BezierSurfaceCut cutSurface(const FuzzyBezierSurface& surface, double alpha) {
  validateSurface(surface);
  checkUnit(alpha, "alpha");
  BezierSurfaceCut cut;
  cut.dimension = surface.controlGrid[0][0].size();
  for (const auto& row : surface.controlGrid) {
    cut.ends.emplace_back();
    for (const FuzzyPoint& p : row) cut.ends.back().push_back(packedEnds(p, alpha));
  }
  return cut;
}

FuzzyBezierPoint evaluateCut(const BezierSurfaceCut& cut, double u, double v) {
  checkUnit(u, "u");
  checkUnit(v, "v");
  // Sarwar & Akram, Algorithm 2: de Casteljau along each row at v, then along the column at u.
  std::vector<CrispPoint> column;
  for (const auto& row : cut.ends) column.push_back(deCasteljau(row, v));
  return finite(unpack(deCasteljau(column, u), cut.dimension), "control_grid");
}

FuzzyBezierPoint evaluateSurface(const FuzzyBezierSurface& surface, double u, double v, double alpha) {
  return evaluateCut(cutSurface(surface, alpha), u, v);
}

FuzzyBezierCurve isoCurveU(const FuzzyBezierSurface& surface, double v) {
  validateSurface(surface);
  checkUnit(v, "v");
  const auto& grid = surface.controlGrid;
  const std::size_t q = grid[0].size() - 1;
  const std::vector<double> basis = bernsteinBasis(q, v);
  FuzzyBezierCurve out;
  for (const auto& row : grid) {
    FuzzyPoint p;
    for (std::size_t c = 0; c < row[0].size(); ++c) {
      FuzzyNumber sum = scale(row[0][c], basis[0]);
      for (std::size_t j = 1; j <= q; ++j) sum = add(sum, scale(row[j][c], basis[j]));
      p.push_back(sum);
    }
    out.controlPoints.push_back(std::move(p));
  }
  return out;
}

FuzzyBezierCurve isoCurveV(const FuzzyBezierSurface& surface, double u) {
  validateSurface(surface);
  FuzzyBezierSurface transposed;  // its rows are the columns: isoCurveU of it is S(u, ·)
  const auto& grid = surface.controlGrid;
  transposed.controlGrid.assign(grid[0].size(), std::vector<FuzzyPoint>(grid.size()));
  for (std::size_t i = 0; i < grid.size(); ++i)
    for (std::size_t j = 0; j < grid[i].size(); ++j) transposed.controlGrid[j][i] = grid[i][j];
  checkUnit(u, "u");
  return isoCurveU(transposed, u);
}

FuzzyBezierCurve elevateCurve(const FuzzyBezierCurve& curve, int times) {
  validateCurve(curve);
  checkTimes(times, "times");
  if (curve.isRational())
    for (std::size_t k = 0; k < curve.weights.size(); ++k)
      if (!curve.weights[k].isCrisp())
        throw Error(errc::kInvalidParameter,
                    "degree elevation of a rational curve needs crisp weights (fuzzy division would widen the curve)",
                    indexPath("weights", k));
  FuzzyBezierCurve out = curve;
  for (int t = 0; t < times; ++t) {
    if (out.isRational()) out = elevateRationalOnce(out);
    else out.controlPoints = elevateOnce(out.controlPoints);
  }
  return out;
}

FuzzyBezierSurface elevateSurface(const FuzzyBezierSurface& surface, int timesU, int timesV) {
  validateSurface(surface);
  checkTimes(timesU, "times_u");
  checkTimes(timesV, "times_v");
  FuzzyBezierSurface out = surface;
  for (auto& row : out.controlGrid)
    for (int t = 0; t < timesV; ++t) row = elevateOnce(row);
  if (timesU == 0) return out;
  const std::size_t columns = out.controlGrid[0].size();
  std::vector<std::vector<FuzzyPoint>> grid;
  for (std::size_t j = 0; j < columns; ++j) {
    std::vector<FuzzyPoint> column;
    for (const auto& row : out.controlGrid) column.push_back(row[j]);
    for (int t = 0; t < timesU; ++t) column = elevateOnce(column);
    if (grid.empty()) grid.assign(column.size(), std::vector<FuzzyPoint>(columns));
    for (std::size_t i = 0; i < column.size(); ++i) grid[i][j] = column[i];
  }
  out.controlGrid = std::move(grid);
  return out;
}

double defuzzifyNumber(const FuzzyNumber& a, Defuzzifier method) {
  switch (method) {
    case Defuzzifier::kCentroid: return centroid(a);
    case Defuzzifier::kBisector: return bisector(a);
    case Defuzzifier::kMeanOfMaxima: return meanOfMaxima(a);
    case Defuzzifier::kSmallestOfMaxima: return smallestOfMaxima(a);
    case Defuzzifier::kLargestOfMaxima: return largestOfMaxima(a);
  }
  return centroid(a);
}

CrispPoint defuzzifyPoint(const FuzzyPoint& p, Defuzzifier method) {
  CrispPoint q;
  for (const FuzzyNumber& c : p) q.push_back(defuzzifyNumber(c, method));
  return q;
}

CrispBezierCurve defuzzifyCurve(const FuzzyBezierCurve& curve, Defuzzifier method) {
  validateCurve(curve);
  CrispBezierCurve out;
  for (const FuzzyPoint& p : curve.controlPoints) out.controlPoints.push_back(defuzzifyPoint(p, method));
  for (const FuzzyNumber& w : curve.weights) out.weights.push_back(defuzzifyNumber(w, method));
  return out;
}

std::vector<std::vector<CrispPoint>> defuzzifySurface(const FuzzyBezierSurface& surface, Defuzzifier method) {
  validateSurface(surface);
  std::vector<std::vector<CrispPoint>> out;
  for (const auto& row : surface.controlGrid) {
    std::vector<CrispPoint> r;
    for (const FuzzyPoint& p : row) r.push_back(defuzzifyPoint(p, method));
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace fsdb
