// Fuzzy Bézier curves and surfaces over HTTP (docs/api.md §6; Sarwar & Akram;
// geometry/curves/fuzzy_bezier.h):
//   POST /curves/bezier/evaluate     points of the lower, crisp and upper curves at level alpha
//   POST /curves/bezier/elevate      degree-elevated fuzzy control points (the same curve)
//   POST /curves/bezier/defuzzify    crisp control points (or a crisp control grid)
//   POST /surfaces/bezier/evaluate   points of the lower, crisp and upper surfaces
//   POST /surfaces/bezier/elevate    degree elevation in u and v (the same surface)
//   POST /surfaces/bezier/iso        an iso-parametric curve's fuzzy control points
//   GET  /curves/{id}/svg            a stored Bézier curve's three polylines at level alpha, or a
//                                    stored fair curve's candidates (server/service/svg_format.h)
//   GET  /surfaces/{id}/mesh         a stored surface's lower / crisp / upper uv grid as OBJ or STL
// The /curves/bezier/... routes have one more segment than /curves/{id} and another method than
// /curves/{id}/svg, so the two families never match the same request.
// Limits: control points per curve or grid (max_control_points) and evaluation points per
// request or export (max_curve_points), 413 naming the limit.
#include <algorithm>
#include <cmath>

#include "db/store.h"
#include "geometry/core/error.h"
#include "geometry/core/number_format.h"
#include "geometry/curves/fuzzy_bezier.h"
#include "query/document/bezier_json.h"
#include "query/document/curve_document.h"
#include "query/document/fair_curve_json.h"
#include "query/json/json_body.h"
#include "server/http/api.h"
#include "server/http/http_server.h"
#include "server/http/response_encoding.h"
#include "server/service/mesh_format.h"
#include "server/service/svg_format.h"

namespace fsdb {
namespace {

using nlohmann::json;

constexpr int kDefaultSvgSamples = 101;
constexpr int kDefaultMeshResolution = 32;

double alphaOf(const json& body) { return body.contains("alpha") ? parseUnitNumber(body["alpha"], "alpha") : 0.0; }

json pointJson(const FuzzyBezierPoint& p) { return {{"lower", p.lower}, {"crisp", p.crisp}, {"upper", p.upper}}; }

ApiResponse evaluateCurveRoute(const ApiRequest& req, const BezierJsonLimits& limits) {
  const json& body = requireObject(req.body, "");
  rejectUnknownKeys(body, "", {"control_points", "weights", "u", "alpha"});
  const FuzzyBezierCurve curve = parseBezierCurve(body, "", limits);
  const std::vector<double> us = parseParameterList(requireField(body, "u", ""), "u", limits);
  const double alpha = alphaOf(body);
  const BezierCurveCut cut = cutCurve(curve, alpha);
  json points = json::array();
  for (double u : us) {
    json p = pointJson(evaluateCut(cut, u));
    p["u"] = u;
    points.push_back(std::move(p));
  }
  return ApiResponse{200, {{"alpha", alpha}, {"degree", curve.degree()}, {"rational", curve.isRational()},
                           {"points", std::move(points)}}};
}

// times, times_u, times_v: the shared integer rule (json_body.h optionalInteger); a value that is
// not a number at all stays invalid_document.
int integerField(const json& body, const char* key, int fallback) {
  if (body.contains(key)) requireNumber(body[key], key);
  return static_cast<int>(optionalInteger(body, "", key, fallback, 0, 1000000));
}

ApiResponse elevateCurveRoute(const ApiRequest& req, const BezierJsonLimits& limits) {
  const json& body = requireObject(req.body, "");
  rejectUnknownKeys(body, "", {"control_points", "weights", "times"});
  const FuzzyBezierCurve curve = parseBezierCurve(body, "", limits);
  const int times = integerField(body, "times", 1);
  if (curve.controlPoints.size() + static_cast<std::size_t>(times) > limits.maxControlPoints)
    throw Error(errc::kLimitExceeded,
                "the elevated curve would have " + std::to_string(curve.controlPoints.size() + times) +
                    " control points, over max_control_points=" + std::to_string(limits.maxControlPoints),
                "times");
  const FuzzyBezierCurve elevated = elevateCurve(curve, times);
  json out = curveToJson(elevated);
  out["degree"] = elevated.degree();
  return ApiResponse{200, std::move(out)};
}

ApiResponse defuzzifyRoute(const ApiRequest& req, const BezierJsonLimits& limits) {
  const json& body = requireObject(req.body, "");
  rejectUnknownKeys(body, "", {"control_points", "weights", "control_grid", "method"});
  const Defuzzifier method = body.contains("method") ? parseDefuzzifier(body["method"], "method") : Defuzzifier::kCentroid;
  json out = {{"method", body.contains("method") ? body["method"] : json("centroid")}};
  if (body.contains("control_grid")) {
    if (body.contains("control_points") || body.contains("weights"))
      throw Error(errc::kInvalidDocument, "give control_points (a curve) or control_grid (a surface), not both",
                  "control_grid");
    out["control_grid"] = defuzzifySurface(parseBezierSurface(body, "", limits), method);
  } else {
    const CrispBezierCurve crisp = defuzzifyCurve(parseBezierCurve(body, "", limits), method);
    out["control_points"] = crisp.controlPoints;
    if (!crisp.weights.empty()) out["weights"] = crisp.weights;
  }
  return ApiResponse{200, std::move(out)};
}

ApiResponse evaluateSurfaceRoute(const ApiRequest& req, const BezierJsonLimits& limits) {
  const json& body = requireObject(req.body, "");
  rejectUnknownKeys(body, "", {"control_grid", "uv", "alpha"});
  const FuzzyBezierSurface surface = parseBezierSurface(body, "", limits);
  const std::vector<std::array<double, 2>> uvs = parseUvList(requireField(body, "uv", ""), "uv", limits);
  const double alpha = alphaOf(body);
  const BezierSurfaceCut cut = cutSurface(surface, alpha);
  json points = json::array();
  for (const auto& uv : uvs) {
    json p = pointJson(evaluateCut(cut, uv[0], uv[1]));
    p["u"] = uv[0];
    p["v"] = uv[1];
    points.push_back(std::move(p));
  }
  return ApiResponse{200, {{"alpha", alpha}, {"degree", {surface.controlGrid.size() - 1, surface.controlGrid[0].size() - 1}},
                           {"points", std::move(points)}}};
}

json gridToJson(const FuzzyBezierSurface& surface) {
  json rows = json::array();
  for (const auto& row : surface.controlGrid) rows.push_back(controlPointsToJson(row));
  return rows;
}

ApiResponse elevateSurfaceRoute(const ApiRequest& req, const BezierJsonLimits& limits) {
  const json& body = requireObject(req.body, "");
  rejectUnknownKeys(body, "", {"control_grid", "times_u", "times_v"});
  const FuzzyBezierSurface surface = parseBezierSurface(body, "", limits);
  const int timesU = integerField(body, "times_u", 1), timesV = integerField(body, "times_v", 1);
  const std::size_t rows = surface.controlGrid.size() + timesU, columns = surface.controlGrid[0].size() + timesV;
  if (rows * columns > limits.maxControlPoints)
    throw Error(errc::kLimitExceeded,
                "the elevated grid would have " + std::to_string(rows * columns) + " control points, over " +
                    limits.controlPointsLimitName + "=" + std::to_string(limits.maxControlPoints),
                "times_u");
  const FuzzyBezierSurface elevated = elevateSurface(surface, timesU, timesV);
  return ApiResponse{200, {{"control_grid", gridToJson(elevated)}, {"degree", {rows - 1, columns - 1}}}};
}

// {"control_grid", "u": a} gives the v-curve S(a, ·); {"control_grid", "v": b} the u-curve S(·, b).
ApiResponse isoCurveRoute(const ApiRequest& req, const BezierJsonLimits& limits) {
  const json& body = requireObject(req.body, "");
  rejectUnknownKeys(body, "", {"control_grid", "u", "v"});
  const FuzzyBezierSurface surface = parseBezierSurface(body, "", limits);
  if (body.contains("u") == body.contains("v"))
    throw Error(errc::kInvalidDocument, "give exactly one of u (a v-curve S(u, ·)) and v (a u-curve S(·, v))",
                body.contains("u") ? "v" : "u");
  const bool fixU = body.contains("u");
  const double at = parseUnitNumber(body[fixU ? "u" : "v"], fixU ? "u" : "v");
  const FuzzyBezierCurve iso = fixU ? isoCurveV(surface, at) : isoCurveU(surface, at);
  json out = curveToJson(iso);
  out["degree"] = iso.degree();
  out["fixed"] = {{fixU ? "u" : "v", at}};
  return ApiResponse{200, std::move(out)};
}

// An integer query parameter in [minimum, max] (max is a server limit: 413 beyond it).
int countParam(const ApiRequest& req, const std::string& name, double fallback, int minimum, std::size_t max,
               const std::string& limitName) {
  const double x = numberParam(req, name, fallback);
  if (x != std::floor(x) || x < minimum)
    throw Error(errc::kInvalidParameter, name + " must be an integer of at least " + std::to_string(minimum), name);
  if (x > static_cast<double>(max))
    throw Error(errc::kLimitExceeded, name + " " + std::to_string(static_cast<long long>(x)) + " exceeds " + limitName +
                                          "=" + std::to_string(max),
                name);
  return static_cast<int>(x);
}

double alphaParam(const ApiRequest& req) {
  const double alpha = numberParam(req, "alpha", 0.0);
  if (alpha < 0.0 || alpha > 1.0) throw Error(errc::kInvalidParameter, "alpha lies in [0, 1]", "alpha");
  return alpha;
}

// The 2-D picture of a curve point: (x, y); a curve of one coordinate is drawn as (u, x).
std::array<double, 2> project(const CrispPoint& p, double u) {
  return p.size() == 1 ? std::array<double, 2>{u, p[0]} : std::array<double, 2>{p[0], p[1]};
}

// Lower, crisp and upper polylines of a Bézier curve at level alpha (u = 0 .. 1, samples points).
std::string svgOfBezierCurve(const FuzzyBezierCurve& curve, double alpha, int samples) {
  SvgPolyline lines[3] = {{"lower", "#1f77b4", {}}, {"crisp", "#000000", {}}, {"upper", "#d62728", {}}};
  const BezierCurveCut cut = cutCurve(curve, alpha);
  for (int i = 0; i < samples; ++i) {
    const double u = static_cast<double>(i) / (samples - 1);  // samples >= 2
    const FuzzyBezierPoint p = evaluateCut(cut, u);
    lines[0].points.push_back(project(p.lower, u));
    lines[1].points.push_back(project(p.crisp, u));
    lines[2].points.push_back(project(p.upper, u));
  }
  return toSvg("fuzzy Bezier curve at alpha " + formatNumber(alpha), {lines[0], lines[1], lines[2]});
}

// Every candidate of a fair curve in grey, candidate `chosen` (0: the best) on top in black and
// thicker, and the given points as dots (only those when R_alpha left no candidate).
std::string svgOfFairCurve(const FairCurveRequest& request, const FairCurveAnswer& answer, std::size_t chosen) {
  std::vector<SvgPolyline> lines;
  auto polyline = [&](std::size_t k, const char* colour, double width) {
    SvgPolyline l{"candidate-" + std::to_string(k), colour, {}, width};
    for (const Vec2& p : answer.curves[k]) l.points.push_back({p.x, p.y});
    lines.push_back(std::move(l));
  };
  for (std::size_t k = 0; k < answer.curves.size(); ++k)
    if (k != chosen) polyline(k, "#a0a0a0", 1.0);
  std::vector<std::array<double, 2>> dots;
  for (const Vec2& p : request.points) dots.push_back({p.x, p.y});
  if (answer.curves.empty()) return toSvg("fair curve: no candidate reaches alpha_threshold", lines, dots);
  polyline(chosen, "#000000", 2.0);
  return toSvg("fair curve, candidate " + std::to_string(chosen) + " of " + std::to_string(answer.curves.size()) +
                   " (score " + formatNumber(answer.candidates[chosen].score) + ")",
               lines, dots);
}

TriangleMesh meshOfSurface(const FuzzyBezierSurface& surface, double alpha, const std::string& bound, int n) {
  TriangleMesh mesh;
  const BezierSurfaceCut cut = cutSurface(surface, alpha);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const FuzzyBezierPoint p = evaluateCut(cut, static_cast<double>(i) / n, static_cast<double>(j) / n);
      const CrispPoint& q = bound == "lower" ? p.lower : bound == "upper" ? p.upper : p.crisp;
      mesh.vertices.push_back({q[0], q.size() > 1 ? q[1] : 0.0, q.size() > 2 ? q[2] : 0.0});
    }
  auto at = [n](int i, int j) { return static_cast<std::uint32_t>(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

ApiResponse download(std::string bytes, const std::string& contentType, const std::string& filename) {
  ApiResponse out{200, nullptr, std::move(bytes), contentType};
  out.headers.emplace_back("Content-Disposition", contentDisposition("attachment", filename));
  return out;
}

}  // namespace

BezierJsonLimits bezierLimits(const ServerLimits& limits) {
  BezierJsonLimits out;
  out.maxControlPoints = limits.maxControlPoints;
  out.maxPoints = limits.maxCurvePoints;
  return out;
}

void registerBezierRoutes(HttpServer& server, const Store& store) {
  const BezierJsonLimits limits = bezierLimits(server.options().limits);
  const FairCurveLimits fair = server.options().limits.fairCurve;

  server.addRoute("POST", "/curves/bezier/evaluate", [limits](const ApiRequest& req) {
    return evaluateCurveRoute(req, limits);
  });
  server.addRoute("POST", "/curves/bezier/elevate", [limits](const ApiRequest& req) {
    return elevateCurveRoute(req, limits);
  });
  server.addRoute("POST", "/curves/bezier/defuzzify", [limits](const ApiRequest& req) {
    return defuzzifyRoute(req, limits);
  });
  server.addRoute("POST", "/surfaces/bezier/evaluate", [limits](const ApiRequest& req) {
    return evaluateSurfaceRoute(req, limits);
  });
  server.addRoute("POST", "/surfaces/bezier/elevate", [limits](const ApiRequest& req) {
    return elevateSurfaceRoute(req, limits);
  });
  server.addRoute("POST", "/surfaces/bezier/iso", [limits](const ApiRequest& req) {
    return isoCurveRoute(req, limits);
  });

  // A Bézier curve takes alpha and samples; a fair curve takes candidate (its samples per piece
  // are its document's). A parameter of the other form is 422 invalid_parameter naming it.
  server.addRoute("GET", "/curves/{id}/svg", [limits, fair, &store](const ApiRequest& req) {
    const StoredObject object = store.get("curve", positiveInteger(req.pathParams[0], "id"), versionParam(req));
    const CurveDocument curve = parseCurveDocument(json::parse(object.documentJson), "", limits, fair);
    auto reject = [&req](const char* name, const char* form) {
      if (req.hasQueryParam(name))
        throw Error(errc::kInvalidParameter, std::string(name) + " applies to " + form + " curves only", name);
    };
    if (curve.fair) {
      reject("alpha", "Bezier");
      reject("samples", "Bezier");
      const FairCurveAnswer answer = answerFairCurve(*curve.fair);
      // R_alpha may leave no candidate: the picture then shows the points only.
      // By default the designer's choice (the document's chosen_candidate), else the best.
      const double k = numberParam(req, "candidate", static_cast<double>(curve.chosenCandidate.value_or(0)));
      const std::size_t n = answer.curves.size();
      if (k != std::floor(k) || k < 0 || (n > 0 && k >= static_cast<double>(n)) || (n == 0 && req.hasQueryParam("candidate")))
        throw Error(errc::kInvalidParameter,
                    n == 0 ? "the curve has no candidate (none reaches alpha_threshold)"
                           : "candidate is an index 0 .. " + std::to_string(n - 1) + " (0: the best), got " +
                                 req.queryParam("candidate"),
                    "candidate");
      const auto chosen = static_cast<std::size_t>(k);
      return download(svgOfFairCurve(*curve.fair, answer, chosen), "image/svg+xml",
                      object.name + "-candidate-" + std::to_string(chosen) + ".svg");
    }
    reject("candidate", "fair");
    const double alpha = alphaParam(req);
    const int samples = countParam(req, "samples", std::min<double>(kDefaultSvgSamples, limits.maxPoints), 2,
                                   limits.maxPoints, limits.pointsLimitName);
    return download(svgOfBezierCurve(*curve.bezier, alpha, samples), "image/svg+xml",
                    object.name + "-" + formatNumber(alpha) + ".svg");
  });

  server.addRoute("GET", "/surfaces/{id}/mesh", [limits, &store](const ApiRequest& req) {
    const double alpha = alphaParam(req);
    const std::string bound = req.hasQueryParam("bound") ? req.queryParam("bound") : "crisp";
    if (bound != "lower" && bound != "crisp" && bound != "upper")
      throw Error(errc::kInvalidParameter, "bound must be lower, crisp or upper, got \"" + bound + "\"", "bound");
    const std::string format = req.hasQueryParam("format") ? req.queryParam("format") : "obj";
    if (format != "obj" && format != "stl")
      throw Error(errc::kInvalidParameter, "format must be obj or stl, got \"" + format + "\"", "format");
    // (resolution + 1)^2 surface points: the square root of max_curve_points bounds it.
    const auto maxResolution = static_cast<std::size_t>(std::sqrt(static_cast<double>(limits.maxPoints))) - 1;
    const int resolution = countParam(req, "resolution", std::max<double>(1, std::min<double>(kDefaultMeshResolution, maxResolution)), 1,
                                      maxResolution,
                                      "floor(sqrt(" + limits.pointsLimitName + ")) - 1");
    const StoredObject object = store.get("surface", positiveInteger(req.pathParams[0], "id"), versionParam(req));
    const FuzzyBezierSurface surface = parseSurfaceDocument(json::parse(object.documentJson), "", limits);
    const TriangleMesh mesh = meshOfSurface(surface, alpha, bound, resolution);
    return download(format == "obj" ? toObj(mesh) : toBinaryStl(mesh), format == "obj" ? "model/obj" : "model/stl",
                    object.name + "-" + bound + "-" + formatNumber(alpha) + "." + format);
  });
}

}  // namespace fsdb
