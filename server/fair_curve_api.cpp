// POST /curves/fair: fair interpolating curves of seed 002, one per local maximum of the points'
// fuzzy sets, best first (SPEC §6; geometry/fair_candidates.h, query/fair_curve_json.h).
#include "geometry/fair_candidates.h"
#include "geometry/fair_curve.h"
#include "query/fair_curve_json.h"
#include "server/api.h"
#include "server/http_server.h"

namespace fsdb {
namespace {

nlohmann::json pointsJson(const std::vector<Vec2>& points) {
  nlohmann::json out = nlohmann::json::array();
  for (const Vec2& p : points) out.push_back({p.x, p.y});
  return out;
}

ApiResponse fairCurves(const ApiRequest& req) {
  const FairCurveRequest r = parseFairCurveRequest(req.body);
  const std::vector<double> magnitudes = radiusMagnitudes(r.points, r.relations, r.closed);
  nlohmann::json candidates = nlohmann::json::array();
  for (const FairCandidate& c : fairCandidates(r.points, r.closed, r.options)) {
    const FairCurve curve = buildFairCurve(r.points, c.anglesDeg, magnitudes, r.closed);
    candidates.push_back({{"score", c.score},
                          {"point", c.point},
                          {"membership", c.membership},
                          {"angles_deg", c.anglesDeg},
                          {"curve", pointsJson(sampleFairCurve(curve, r.samples))}});
  }
  return ApiResponse{200,
                     {{"candidates", std::move(candidates)},
                      {"first_estimation_deg", firstEstimationAngles(r.points, r.closed)},
                      {"radii", magnitudes},
                      {"behavior", behaviorName(r.options.behavior)}}};
}

}  // namespace

void registerFairCurveRoutes(HttpServer& server) {
  server.addRoute("POST", "/curves/fair", [](const ApiRequest& req) { return fairCurves(req); });
}

}  // namespace fsdb
