// Fuzz target: stored curve and surface documents (query/document/curve_document.h: a fuzzy Bezier
// curve or a fair curve; query/document/bezier_json.h: a Bezier surface). A document whose "kind" is
// "surface" is read as a surface, any other as a curve. As prepareDocument
// (server/service/documents.h) does before either parser, a body that is not a JSON object is
// refused first. Limits are small so one input stays fast: 64 control points, fair curves of at
// most 12 points, 32 samples, 360 angle samples, 10 candidates and 4000 curve points.
// Properties of every accepted document:
//  * a Bezier curve prints back (curveToJson) to a value that parses to a curve that prints the
//    same; a surface's grid likewise (controlPointsToJson per row);
//  * evaluating it at a few u (and v) and alpha gives finite lower, crisp and upper points of the
//    curve's dimension with lower <= upper, and for a polynomial curve or a surface
//    lower <= crisp <= upper (up to rounding); an evaluation may refuse only with domain_error
//    (values beyond the double range, as fuzzy_bezier.h documents);
//  * a fair curve's answer (answerFairCurve) has one finite positive radius per point, at most
//    max_candidates candidates, each with score and membership in [0, 1], membership at least
//    alpha_threshold, one angle in [0, 180) per point and (samples - 1) * pieces + 1 finite curve
//    points.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "geometry/core/error.h"
#include "geometry/curves/fuzzy_bezier.h"
#include "query/document/bezier_json.h"
#include "query/document/curve_document.h"
#include "query/document/fair_curve_json.h"
#include "query/json/json_body.h"
#include "tests/fuzz/fuzz_check.h"

namespace {

constexpr int kDepth = 16;
constexpr double kParameters[] = {0.0, 0.37, 1.0};
constexpr double kLevels[] = {0.0, 0.5, 1.0};

fsdb::BezierJsonLimits bezierLimits() {
  fsdb::BezierJsonLimits limits;
  limits.maxControlPoints = 64;
  limits.maxPoints = 1000;
  return limits;
}

fsdb::FairCurveLimits fairLimits() {
  fsdb::FairCurveLimits limits;
  limits.maxPoints = 12;
  limits.maxSamples = 32;
  limits.maxAngleSamples = 360;
  limits.maxCandidates = 10;
  limits.maxCurvePoints = 4000;
  return limits;
}

bool near(double a, double b, double scale) { return a <= b || a - b <= 1e-9 * (1.0 + scale); }

// One evaluated point: finite, of the right dimension, ordered.
void checkPoint(const fsdb::FuzzyBezierPoint& p, size_t dimension, bool crispInside) {
  FUZZ_CHECK(p.lower.size() == dimension && p.crisp.size() == dimension && p.upper.size() == dimension,
             "an evaluated point has the curve's dimension");
  for (size_t c = 0; c < dimension; ++c) {
    FUZZ_CHECK(std::isfinite(p.lower[c]) && std::isfinite(p.crisp[c]) && std::isfinite(p.upper[c]),
               "an evaluation is finite");
    const double scale = std::fabs(p.lower[c]) + std::fabs(p.upper[c]);
    FUZZ_CHECK(near(p.lower[c], p.upper[c], scale), "lower <= upper");
    if (crispInside)
      FUZZ_CHECK(near(p.lower[c], p.crisp[c], scale) && near(p.crisp[c], p.upper[c], scale), "lower <= crisp <= upper");
  }
}

void domainErrorOnly(const fsdb::Error& e) {
  if (e.code() == fsdb::errc::kDomainError) return;
  std::fprintf(stderr, "evaluation: %s %s (%s)\n", e.code().c_str(), e.what(), e.path().c_str());
  FUZZ_CHECK(false, "evaluating an accepted curve or surface refuses only with domain_error");
}

void checkCurve(const fsdb::FuzzyBezierCurve& curve) {
  const nlohmann::json printed = fsdb::curveToJson(curve);
  try {
    FUZZ_CHECK(fsdb::curveToJson(fsdb::parseBezierCurve(printed, "bezier", bezierLimits())) == printed,
               "curveToJson parses to the same curve");
  } catch (const fsdb::Error& e) {
    std::fprintf(stderr, "printed %s: %s\n", printed.dump().c_str(), e.what());
    FUZZ_CHECK(false, "the printed form of an accepted curve is accepted");
  }
  const size_t dimension = curve.controlPoints.front().size();
  for (double u : kParameters)
    for (double alpha : kLevels) {
      try {
        checkPoint(fsdb::evaluateCurve(curve, u, alpha), dimension, !curve.isRational());
      } catch (const fsdb::Error& e) {
        domainErrorOnly(e);
      }
    }
}

void checkSurface(const fsdb::FuzzyBezierSurface& surface) {
  nlohmann::json grid = nlohmann::json::array();
  for (const auto& row : surface.controlGrid) grid.push_back(fsdb::controlPointsToJson(row));
  const nlohmann::json printed = {{"control_grid", grid}};
  try {
    const fsdb::FuzzyBezierSurface again = fsdb::parseBezierSurface(printed, "bezier", bezierLimits());
    nlohmann::json grid2 = nlohmann::json::array();
    for (const auto& row : again.controlGrid) grid2.push_back(fsdb::controlPointsToJson(row));
    FUZZ_CHECK(grid2 == grid, "the printed grid parses to the same surface");
  } catch (const fsdb::Error& e) {
    std::fprintf(stderr, "printed %s: %s\n", printed.dump().c_str(), e.what());
    FUZZ_CHECK(false, "the printed form of an accepted surface is accepted");
  }
  const size_t dimension = surface.controlGrid.front().front().size();
  for (double u : kParameters)
    for (double v : kParameters) {
      try {
        checkPoint(fsdb::evaluateSurface(surface, u, v, 0.5), dimension, true);
      } catch (const fsdb::Error& e) {
        domainErrorOnly(e);
      }
    }
}

void checkFair(const fsdb::FairCurveRequest& request) {
  fsdb::FairCurveAnswer answer;
  try {
    answer = fsdb::answerFairCurve(request);
  } catch (const fsdb::Error&) {
    return;  // points whose magnitudes leave the double range are refused (fair_curve.h)
  }
  const size_t n = request.points.size();
  FUZZ_CHECK(answer.radii.size() == n, "one radius per point");
  for (double r : answer.radii) FUZZ_CHECK(std::isfinite(r) && r > 0.0, "radii are finite and positive");
  FUZZ_CHECK(answer.candidates.size() <= request.options.maxCandidates, "at most max_candidates candidates");
  FUZZ_CHECK(answer.curves.size() == answer.candidates.size(), "one curve per candidate");
  const size_t pieces = request.closed ? n : n - 1;
  for (size_t k = 0; k < answer.candidates.size(); ++k) {
    const fsdb::FairCandidate& c = answer.candidates[k];
    FUZZ_CHECK(c.score >= 0.0 && c.score <= 1.0, "a score lies in [0, 1]");
    FUZZ_CHECK(c.membership >= 0.0 && c.membership <= 1.0, "a membership lies in [0, 1]");
    FUZZ_CHECK(c.membership >= request.options.alphaThreshold, "maxima below alpha_threshold are no candidates");
    FUZZ_CHECK(c.point < n && c.anglesDeg.size() == n, "one angle per point");
    for (double a : c.anglesDeg) FUZZ_CHECK(a >= 0.0 && a < 180.0, "an angle lies in [0, 180)");
    FUZZ_CHECK(answer.curves[k].size() == pieces * static_cast<size_t>(request.samples - 1) + 1,
               "(samples - 1) * pieces + 1 curve points");
    for (const fsdb::Vec2& p : answer.curves[k])
      FUZZ_CHECK(std::isfinite(p.x) && std::isfinite(p.y), "curve points are finite");
  }
  (void)fsdb::fairCurveAnswerJson(request, answer);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 64 * 1024) return 0;
  const std::string body(reinterpret_cast<const char*>(data), size);
  nlohmann::json doc;
  try {
    doc = fsdb::parseJsonBody(body, kDepth);
    fsdb::requireObject(doc, "");  // as prepareDocument, before the parsers
  } catch (const fsdb::Error&) {
    return 0;
  }
  const bool surface = doc.contains("kind") && doc["kind"] == "surface";
  if (surface) {
    fsdb::FuzzyBezierSurface s;
    try {
      s = fsdb::parseSurfaceDocument(doc, "", bezierLimits());
    } catch (const fsdb::Error&) {
      return 0;
    }
    FUZZ_CHECK(!s.controlGrid.empty() && !s.controlGrid.front().empty(), "an accepted grid is not empty");
    checkSurface(s);
    return 0;
  }
  fsdb::CurveDocument curve;
  try {
    curve = fsdb::parseCurveDocument(doc, "", bezierLimits(), fairLimits());
  } catch (const fsdb::Error&) {
    return 0;
  }
  FUZZ_CHECK(curve.bezier.has_value() != curve.fair.has_value(), "a curve document is one of the two forms");
  if (curve.bezier) {
    FUZZ_CHECK(!curve.bezier->controlPoints.empty(), "an accepted curve has control points");
    checkCurve(*curve.bezier);
  } else {
    FUZZ_CHECK(curve.fair->points.size() >= 2 && curve.fair->points.size() <= fairLimits().maxPoints,
               "an accepted fair curve has 2 to max_fair_points points");
    checkFair(*curve.fair);
  }
  return 0;
}
