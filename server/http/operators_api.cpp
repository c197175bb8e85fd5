// GET /operators and POST /operators/evaluate: the catalogue of the operators of Li & Tian and of
// Li, and evaluation of one operator at many points (plots, client-side checks, tests).
#include <cmath>

#include "geometry/core/closest_names.h"
#include "geometry/core/error.h"
#include "geometry/operators/operator_catalog.h"
#include "query/document/operator_json.h"
#include "query/json/json_body.h"
#include "server/http/api.h"
#include "server/http/http_server.h"

namespace fsdb {
namespace {

nlohmann::json catalogueJson() {
  nlohmann::json list = nlohmann::json::array();
  for (const OperatorSpec& spec : operatorCatalog()) list.push_back(operatorSpecToJson(spec));
  return {{"operators", list}, {"combinations", {"intersection", "union", "difference"}}};
}

// A point's coordinates: `x` or `[x]` for unary functions, `[x, y]` for binary operators.
void readPoint(const nlohmann::json& p, int arity, bool unitInterval, const std::string& path, double* out) {
  if (arity == 1 && p.is_number()) {
    out[0] = requireNumber(p, path);
  } else {
    requireArray(p, path);
    if (static_cast<int>(p.size()) != arity)
      throw Error(errc::kInvalidDocument,
                  "expected " + std::to_string(arity) + " coordinate(s), got " + std::to_string(p.size()), path);
    for (int k = 0; k < arity; ++k) out[k] = requireNumber(p[k], joinPath(path, static_cast<std::size_t>(k)));
  }
  if (unitInterval)
    for (int k = 0; k < arity; ++k)
      if (out[k] < 0.0 || out[k] > 1.0)
        throw Error(errc::kInvalidDocument, "membership grades must lie in [0,1]; got " + std::to_string(out[k]),
                    arity == 1 && p.is_number() ? path : joinPath(path, static_cast<std::size_t>(k)));
}

ApiResponse evaluate(const ApiRequest& req, const ServerLimits& limits) {
  const nlohmann::json& body = requireObject(req.body, "");
  for (auto it = body.begin(); it != body.end(); ++it)
    if (it.key() != "operator" && it.key() != "op" && it.key() != "points")
      throw Error(errc::kInvalidDocument, "unknown field '" + quotedWord(it.key()) + "'; expected operator, op, points", it.key());
  const OperatorConfig config = parseOperatorConfig(requireField(body, "operator", ""), "operator");
  const OperatorSpec& spec = *findOperator(config.name);
  const nlohmann::json& points = requireArray(requireField(body, "points", ""), "points");
  if (points.size() > limits.maxPoints)
    throw Error(errc::kLimitExceeded,
                std::to_string(points.size()) + " points exceed max_points=" + std::to_string(limits.maxPoints),
                "points");

  nlohmann::json result = {{"operator", operatorConfigToJson(config)}};
  std::vector<double> values(points.size());
  if (spec.arity == 1) {
    if (body.contains("op")) throw Error(errc::kInvalidDocument, "'op' applies to binary operators only", "op");
    auto f = makeUnaryFunction(config);
    for (size_t i = 0; i < points.size(); ++i) {
      double x;
      readPoint(points[i], 1, false, joinPath("points", i), &x);
      values[i] = (*f)(x);
    }
  } else {
    // The default combination of a t-norm family is its intersection; of a blend, its union
    // (Ext_max and Int_max are smooth maxima, Li, eq. 21 and 25).
    Combine combine = spec.kind == "blend" ? Combine::Union : Combine::Intersection;
    if (body.contains("op")) combine = parseCombine(body["op"], "op");
    auto op = makeBinaryOperator(config);
    const bool unit = op->actsOnMemberships();
    for (size_t i = 0; i < points.size(); ++i) {
      double xy[2];
      readPoint(points[i], 2, unit, joinPath("points", i), xy);
      values[i] = op->apply(combine, xy[0], xy[1]);
    }
    result["op"] = combineName(combine);
  }
  for (size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw Error(errc::kDomainError, "the operator is not finite at this point", joinPath("points", i));
  result["values"] = std::move(values);
  return ApiResponse{200, std::move(result)};
}

}  // namespace

void registerOperatorRoutes(HttpServer& server) {
  static const nlohmann::json catalogue = catalogueJson();
  server.addRoute("GET", "/operators", [](const ApiRequest&) { return ApiResponse{200, catalogue}; });
  const ServerLimits limits = server.options().limits;
  server.addRoute("POST", "/operators/evaluate", [limits](const ApiRequest& req) { return evaluate(req, limits); });
}

}  // namespace fsdb
