#include "query/document/bezier_json.h"

#include <cmath>

#include "geometry/core/error.h"
#include "query/json/fuzzy_json.h"
#include "query/json/json_body.h"
#include "query/json/json_path.h"

namespace fsdb {
namespace {

using nlohmann::json;

void checkCount(std::size_t n, std::size_t max, const std::string& limitName, const std::string& what,
                const std::string& path) {
  if (n > max)
    throw Error(errc::kLimitExceeded,
                std::to_string(n) + " " + what + " exceed " + limitName + "=" + std::to_string(max), path);
}

FuzzyPoint parsePoint(const json& j, const std::string& path) {
  requireArray(j, path);
  if (j.empty() || j.size() > 3)
    throw Error(errc::kInvalidDocument,
                "a control point is [x, y] or [x, y, z], got " + std::to_string(j.size()) + " coordinates", path);
  FuzzyPoint p;
  for (std::size_t c = 0; c < j.size(); ++c) p.push_back(parseFuzzyNumber(j[c], joinPath(path, c)));
  return p;
}

std::vector<FuzzyPoint> parsePolygon(const json& j, const std::string& path) {
  requireArray(j, path);
  std::vector<FuzzyPoint> out;
  for (std::size_t k = 0; k < j.size(); ++k) out.push_back(parsePoint(j[k], joinPath(path, k)));
  return out;
}

// Geometry checks name paths relative to the object ("control_points[1]"); here they become
// relative to the document.
template <class F>
void within(const std::string& path, F f) {
  try {
    f();
  } catch (const Error& e) {
    throw e.withPathPrefix(path);
  }
}

}  // namespace

FuzzyBezierCurve parseBezierCurve(const json& obj, const std::string& path, const BezierJsonLimits& limits) {
  requireObject(obj, path);
  const std::string cp = joinPath(path, "control_points");
  const json& points = requireArray(requireField(obj, "control_points", path), cp);
  checkCount(points.size(), limits.maxControlPoints, limits.controlPointsLimitName, "control points", cp);
  FuzzyBezierCurve curve;
  curve.controlPoints = parsePolygon(points, cp);
  if (obj.contains("weights")) {
    const std::string wp = joinPath(path, "weights");
    const json& weights = requireArray(obj["weights"], wp);
    for (std::size_t k = 0; k < weights.size(); ++k)
      curve.weights.push_back(parseFuzzyNumber(weights[k], joinPath(wp, k)));
    if (curve.weights.empty())
      throw Error(errc::kInvalidDocument, "weights must not be empty (leave it out for a polynomial curve)", wp);
  }
  within(path, [&] { validateCurve(curve); });
  return curve;
}

FuzzyBezierSurface parseBezierSurface(const json& obj, const std::string& path, const BezierJsonLimits& limits) {
  requireObject(obj, path);
  const std::string gp = joinPath(path, "control_grid");
  const json& grid = requireArray(requireField(obj, "control_grid", path), gp);
  std::size_t total = 0;
  for (std::size_t i = 0; i < grid.size(); ++i) total += requireArray(grid[i], joinPath(gp, i)).size();
  checkCount(total, limits.maxControlPoints, limits.controlPointsLimitName, "control points", gp);
  FuzzyBezierSurface surface;
  for (std::size_t i = 0; i < grid.size(); ++i) surface.controlGrid.push_back(parsePolygon(grid[i], joinPath(gp, i)));
  within(path, [&] { validateSurface(surface); });
  return surface;
}

FuzzyBezierSurface parseSurfaceDocument(const json& doc, const std::string& path, const BezierJsonLimits& limits) {
  requireObject(doc, path);  // before rejectUnknownKeys, which iterates keys (an array threw json's error)
  rejectUnknownKeys(doc, path, {"kind", "name", "bezier", "meta"}, " in a surface document");
  const std::string bp = joinPath(path, "bezier");
  const json& bezier = requireObject(requireField(doc, "bezier", path), bp);
  rejectUnknownKeys(bezier, bp, {"control_grid"});
  return parseBezierSurface(bezier, bp, limits);
}

double parseUnitNumber(const json& j, const std::string& path) {
  const double x = requireNumber(j, path);
  if (x < 0.0 || x > 1.0) throw Error(errc::kInvalidParameter, "must lie in [0, 1], got " + j.dump(), path);
  return x;
}

std::vector<double> parseParameterList(const json& j, const std::string& path, const BezierJsonLimits& limits) {
  requireArray(j, path);
  checkCount(j.size(), limits.maxPoints, limits.pointsLimitName, "parameter values", path);
  std::vector<double> out;
  for (std::size_t i = 0; i < j.size(); ++i) out.push_back(parseUnitNumber(j[i], joinPath(path, i)));
  return out;
}

std::vector<std::array<double, 2>> parseUvList(const json& j, const std::string& path, const BezierJsonLimits& limits) {
  requireArray(j, path);
  checkCount(j.size(), limits.maxPoints, limits.pointsLimitName, "parameter pairs", path);
  std::vector<std::array<double, 2>> out;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string p = joinPath(path, i);
    requireArray(j[i], p);
    if (j[i].size() != 2) throw Error(errc::kInvalidDocument, "a parameter pair is [u, v]", p);
    out.push_back({parseUnitNumber(j[i][0], joinPath(p, 0)), parseUnitNumber(j[i][1], joinPath(p, 1))});
  }
  return out;
}

Defuzzifier parseDefuzzifier(const json& j, const std::string& path) {
  const std::string& name = requireString(j, path);
  if (name == "centroid") return Defuzzifier::kCentroid;
  if (name == "bisector") return Defuzzifier::kBisector;
  if (name == "mean_of_maxima") return Defuzzifier::kMeanOfMaxima;
  if (name == "smallest_of_maxima") return Defuzzifier::kSmallestOfMaxima;
  if (name == "largest_of_maxima") return Defuzzifier::kLargestOfMaxima;
  throw Error(errc::kInvalidParameter,
              "unknown defuzzifier \"" + name +
                  "\"; expected one of: centroid, bisector, mean_of_maxima, smallest_of_maxima, largest_of_maxima",
              path);
}

json controlPointsToJson(const std::vector<FuzzyPoint>& points) {
  json out = json::array();
  for (const FuzzyPoint& p : points) {
    json q = json::array();
    for (const FuzzyNumber& c : p) q.push_back(toJson(c));
    out.push_back(std::move(q));
  }
  return out;
}

json curveToJson(const FuzzyBezierCurve& curve) {
  json out = {{"control_points", controlPointsToJson(curve.controlPoints)}};
  if (curve.isRational()) {
    json w = json::array();
    for (const FuzzyNumber& x : curve.weights) w.push_back(toJson(x));
    out["weights"] = std::move(w);
  }
  return out;
}

}  // namespace fsdb
