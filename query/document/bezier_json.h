#pragma once
// Fuzzy Bézier curves and surfaces in JSON (docs/api.md §6; geometry/curves/fuzzy_bezier.h):
//   "control_points": [[x, y], [x, y, z], ...]     each coordinate a fuzzy number (query/json/fuzzy_json.h)
//   "weights":        [w, ...]                      optional: a rational curve, one positive fuzzy
//                                                   number per control point
//   "control_grid":   [[[x, y, z], ...], ...]       rows along u, columns along v
//   "u": [u, ...], "uv": [[u, v], ...], "alpha": a  parameters in [0, 1]
//   "method": "centroid" | "bisector" | "mean_of_maxima" | "smallest_of_maxima" | "largest_of_maxima"
// Stored surface documents (kind "surface"; curve documents: query/document/curve_document.h):
//   {"kind":"surface","name":...,"bezier":{"control_grid":...},"meta":{...}}
//
// Errors: fsdb::Error invalid_document / invalid_parameter with the JSON path of the bad value
// prefixed by `path` ("bezier.control_points[2][1].tri[0]", "weights[1]", "uv[3][0]"); unknown
// keys are rejected (rejectUnknownKeys). More control points than maxControlPoints (a grid
// counts all its points) or more parameter values than maxPoints is 413 limit_exceeded naming
// the limit ("max_control_points=N"; `limitName` says which option the caller enforces).
#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/curves/fuzzy_bezier.h"

namespace fsdb {

struct BezierJsonLimits {
  std::size_t maxControlPoints = 1024;
  std::string controlPointsLimitName = "max_control_points";
  std::size_t maxPoints = 10000;
  std::string pointsLimitName = "max_curve_points";
};

// Reads "control_points" (and "weights" when present) of obj; other keys are the caller's.
FuzzyBezierCurve parseBezierCurve(const nlohmann::json& obj, const std::string& path, const BezierJsonLimits& limits);
// Reads "control_grid" of obj.
FuzzyBezierSurface parseBezierSurface(const nlohmann::json& obj, const std::string& path,
                                      const BezierJsonLimits& limits);

// A whole stored surface document's "bezier" member (kind and name are the caller's).
FuzzyBezierSurface parseSurfaceDocument(const nlohmann::json& doc, const std::string& path,
                                        const BezierJsonLimits& limits);

// A number in [0, 1] (alpha, u, v), invalid_parameter otherwise.
double parseUnitNumber(const nlohmann::json& j, const std::string& path);
std::vector<double> parseParameterList(const nlohmann::json& j, const std::string& path, const BezierJsonLimits& limits);
std::vector<std::array<double, 2>> parseUvList(const nlohmann::json& j, const std::string& path,
                                               const BezierJsonLimits& limits);
Defuzzifier parseDefuzzifier(const nlohmann::json& j, const std::string& path);

nlohmann::json controlPointsToJson(const std::vector<FuzzyPoint>& points);
nlohmann::json curveToJson(const FuzzyBezierCurve& curve);  // {"control_points", "weights"?}

}  // namespace fsdb
