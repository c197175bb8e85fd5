// Fair interpolating curves of Bernardes, Wu & D'Ottaviano over HTTP (docs/api.md §6;
// query/document/fair_curve_json.h):
//   POST /curves/fair               the candidates of a request, best first
//   GET  /curves/{id}/candidates    the same for a stored fair curve ({"fair": request}; a
//                                   Bézier curve has none: 422 invalid_parameter naming "id")
// Limits: FairCurveLimits from `fsdb serve --max-fair-*` (413 naming the limit).
#include "db/store.h"
#include "geometry/core/error.h"
#include "query/document/bezier_json.h"
#include "query/document/curve_document.h"
#include "query/document/fair_curve_json.h"
#include "server/http/api.h"
#include "server/http/http_server.h"

namespace fsdb {

void registerFairCurveRoutes(HttpServer& server, const Store& store) {
  const ServerLimits& limits = server.options().limits;
  const FairCurveLimits fair = limits.fairCurve;
  const BezierJsonLimits bezier = bezierLimits(limits);

  server.addRoute("POST", "/curves/fair", [fair](const ApiRequest& req) {
    const FairCurveRequest r = parseFairCurveRequest(req.body, fair);
    return ApiResponse{200, fairCurveAnswerJson(r, answerFairCurve(r))};
  });

  server.addRoute("GET", "/curves/{id}/candidates", [fair, bezier, &store](const ApiRequest& req) {
    const StoredObject object = store.get("curve", positiveInteger(req.pathParams[0], "id"), versionParam(req));
    const CurveDocument curve = parseCurveDocument(nlohmann::json::parse(object.documentJson), "", bezier, fair);
    if (!curve.fair)
      throw Error(errc::kInvalidParameter, "curve " + std::to_string(object.id) + " is a Bezier curve; only fair curves have candidates",
                  "id");
    return ApiResponse{200, fairCurveAnswerJson(*curve.fair, answerFairCurve(*curve.fair))};
  });
}

}  // namespace fsdb
