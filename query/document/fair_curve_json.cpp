#include "query/document/fair_curve_json.h"

#include <string>

#include "geometry/core/error.h"
#include "query/json/json_body.h"
#include "query/json/json_path.h"

namespace fsdb {
namespace {

// An integer field in [lo, +inf): invalid_parameter below lo, limit_exceeded above `limit`.
long long boundedInteger(const nlohmann::json& body, const char* key, long long fallback, long long lo,
                         long long limit, const char* limitName) {
  if (!body.contains(key)) return fallback;
  const nlohmann::json& v = body[key];
  const std::optional<int64_t> integral = integralNumber(v);  // 32 and 32.0, as every integer field
  if (!integral)
    throw Error(errc::kInvalidDocument, std::string(key) + " must be an integer, got " + v.dump(), key);
  const long long n = *integral;
  if (n < lo)
    throw Error(errc::kInvalidParameter, std::string(key) + " must be at least " + std::to_string(lo) + ", got " +
                                             std::to_string(n), key);
  if (n > limit)
    throw Error(errc::kLimitExceeded, std::string(key) + " " + std::to_string(n) + " exceeds " + limitName + "=" +
                                          std::to_string(limit), key);
  return n;
}

}  // namespace

const char* behaviorName(FairBehavior b) {
  switch (b) {
    case FairBehavior::kUndulant: return "undulant";
    case FairBehavior::kNoInflection: return "no_inflection";
    case FairBehavior::kInflection: return "inflection";
  }
  return "no_inflection";
}

FairCurveAnswer answerFairCurve(const FairCurveRequest& r) {
  FairCurveAnswer a;
  a.radii = radiusMagnitudes(r.points, r.relations, r.closed);
  a.candidates = fairCandidates(r.points, r.closed, r.options);
  for (const FairCandidate& c : a.candidates)
    a.curves.push_back(sampleFairCurve(buildFairCurve(r.points, c.anglesDeg, a.radii, r.closed), r.samples));
  return a;
}

nlohmann::json fairCurveAnswerJson(const FairCurveRequest& r, const FairCurveAnswer& a) {
  nlohmann::json candidates = nlohmann::json::array();
  for (size_t k = 0; k < a.candidates.size(); ++k) {
    const FairCandidate& c = a.candidates[k];
    nlohmann::json curve = nlohmann::json::array();
    for (const Vec2& p : a.curves[k]) curve.push_back({p.x, p.y});
    candidates.push_back({{"score", c.score},
                          {"point", c.point},
                          {"membership", c.membership},
                          {"angles_deg", c.anglesDeg},
                          {"curve", std::move(curve)}});
  }
  return {{"candidates", std::move(candidates)},
          {"first_estimation_deg", firstEstimationAngles(r.points, r.closed)},
          {"radii", a.radii},
          {"behavior", behaviorName(r.options.behavior)}};
}

FairCurveRequest parseFairCurveRequest(const nlohmann::json& body, const FairCurveLimits& limits) {
  requireObject(body, "");
  rejectUnknownKeys(body, "", {"points", "relations", "closed", "behavior", "alpha_threshold", "samples",
                               "angle_samples", "max_candidates"});
  FairCurveRequest r;
  const nlohmann::json& points = requireArray(requireField(body, "points", ""), "points");
  if (points.size() > limits.maxPoints)
    throw Error(errc::kLimitExceeded,
                std::to_string(points.size()) + " points exceed max_fair_points=" + std::to_string(limits.maxPoints),
                "points");
  for (size_t i = 0; i < points.size(); ++i) {
    const std::string path = joinPath("points", i);
    const nlohmann::json& p = requireArray(points[i], path);
    if (p.size() != 2)
      throw Error(errc::kInvalidDocument, "a point is [x, y], got " + std::to_string(p.size()) + " coordinates", path);
    r.points.push_back({requireNumber(p[0], joinPath(path, size_t{0})), requireNumber(p[1], joinPath(path, size_t{1}))});
  }
  if (body.contains("closed")) {
    if (!body["closed"].is_boolean())
      throw Error(errc::kInvalidDocument, "closed must be true or false, got " + body["closed"].dump(), "closed");
    r.closed = body["closed"].get<bool>();
  }
  if (body.contains("relations")) {
    const nlohmann::json& rel = requireArray(body["relations"], "relations");
    for (size_t k = 0; k < rel.size(); ++k) {
      const std::string& s = requireString(rel[k], joinPath("relations", k));
      if (s != "smoother" && s != "sharper")
        throw Error(errc::kInvalidParameter, "a relation is \"smoother\" or \"sharper\", got \"" + s + "\"",
                    joinPath("relations", k));
      r.relations.push_back(s == "smoother" ? Relation::kSmoother : Relation::kSharper);
    }
  }
  if (body.contains("behavior")) {
    const std::string& b = requireString(body["behavior"], "behavior");
    if (b == "undulant") r.options.behavior = FairBehavior::kUndulant;
    else if (b == "no_inflection") r.options.behavior = FairBehavior::kNoInflection;
    else if (b == "inflection") r.options.behavior = FairBehavior::kInflection;
    else
      throw Error(errc::kInvalidParameter,
                  "behavior is one of undulant, no_inflection, inflection; got \"" + b + "\"", "behavior");
  }
  if (body.contains("alpha_threshold")) {
    const double a = requireNumber(body["alpha_threshold"], "alpha_threshold");
    if (a < 0 || a > 1)
      throw Error(errc::kInvalidParameter, "alpha_threshold (R_alpha) must lie in [0, 1], got " + body["alpha_threshold"].dump(),
                  "alpha_threshold");
    r.options.alphaThreshold = a;
  }
  r.samples = static_cast<int>(boundedInteger(body, "samples", r.samples, 2, limits.maxSamples, "max_fair_samples"));
  r.options.angleSamples = static_cast<int>(
      boundedInteger(body, "angle_samples", r.options.angleSamples, 4, limits.maxAngleSamples, "max_fair_angle_samples"));
  r.options.maxCandidates = static_cast<size_t>(boundedInteger(
      body, "max_candidates", static_cast<long long>(r.options.maxCandidates), 1,
      static_cast<long long>(limits.maxCandidates), "max_fair_candidates"));
  // The answer's size: every returned candidate carries (samples - 1) * pieces + 1 points.
  const size_t pieces = r.points.size() < 2 ? 0 : (r.closed ? r.points.size() : r.points.size() - 1);
  const size_t curvePoints = r.options.maxCandidates * (pieces * static_cast<size_t>(r.samples - 1) + 1);
  if (curvePoints > limits.maxCurvePoints)
    throw Error(errc::kLimitExceeded,
                "max_candidates x pieces x samples = " + std::to_string(curvePoints) + " curve points exceed max_fair_curve_points=" +
                    std::to_string(limits.maxCurvePoints) + "; lower samples or max_candidates",
                "samples");
  checkFairPoints(r.points, r.closed);  // points[i] named (fair_curve.h)
  return r;
}

}  // namespace fsdb
