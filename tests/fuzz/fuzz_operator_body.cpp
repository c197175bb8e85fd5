// Fuzz target: the body of POST /operators/evaluate. The route's handler (server/http/operators_api.cpp)
// sits in an anonymous namespace, so this target repeats its steps with the same public pieces:
// parseJsonBody (max depth 64, the server's default), the keys operator / op / points,
// parseOperatorConfig (query/document/operator_json.h), findOperator, makeUnaryFunction or
// makeBinaryOperator and parseCombine (geometry/operators/operator_catalog.h), the same point
// reading, and the same refusal of a value that is not finite (domain_error). Bodies with more than
// 1000 points are skipped, so one input stays fast.
// Properties:
//  * an accepted operator prints back (operatorConfigToJson) to a value that parses to the same
//    configuration, and validating a validated configuration changes nothing;
//  * a fuzzy operator (t-norm family) evaluated on memberships in [0, 1] gives finite values in
//    [0, 1] (up to 1e-9) for every combination, and a step function finite values in [0, 1] (up to
//    1e-9) at every finite point: both are never refused;
//  * an accepted answer holds one finite value per point.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "geometry/core/error.h"
#include "geometry/operators/operator_catalog.h"
#include "query/document/operator_json.h"
#include "query/json/json_body.h"
#include "query/json/json_path.h"
#include "tests/fuzz/fuzz_check.h"

namespace {

constexpr int kDepth = 64;
constexpr size_t kMaxPoints = 1000;

// readPoint of server/http/operators_api.cpp.
void readPoint(const nlohmann::json& p, int arity, bool unitInterval, const std::string& path, double* out) {
  if (arity == 1 && p.is_number()) {
    out[0] = fsdb::requireNumber(p, path);
  } else {
    fsdb::requireArray(p, path);
    if (static_cast<int>(p.size()) != arity)
      throw fsdb::Error(fsdb::errc::kInvalidDocument, "wrong number of coordinates", path);
    for (int k = 0; k < arity; ++k)
      out[k] = fsdb::requireNumber(p[k], fsdb::joinPath(path, static_cast<std::size_t>(k)));
  }
  if (unitInterval)
    for (int k = 0; k < arity; ++k)
      if (out[k] < 0.0 || out[k] > 1.0)
        throw fsdb::Error(fsdb::errc::kInvalidDocument, "membership grades must lie in [0,1]", path);
}

bool inUnit(double v) { return std::isfinite(v) && v >= -1e-9 && v <= 1.0 + 1e-9; }

void checkConfig(const fsdb::OperatorConfig& config) {
  const nlohmann::json printed = fsdb::operatorConfigToJson(config);
  try {
    FUZZ_CHECK(fsdb::operatorConfigToJson(fsdb::parseOperatorConfig(printed, "operator")) == printed,
               "operatorConfigToJson parses to the same configuration");
    FUZZ_CHECK(fsdb::operatorConfigToJson(fsdb::validateOperator(config)) == printed,
               "validating a validated configuration changes nothing");
  } catch (const fsdb::Error& e) {
    std::fprintf(stderr, "printed %s: %s (%s)\n", printed.dump().c_str(), e.what(), e.path().c_str());
    FUZZ_CHECK(false, "the printed form of an accepted operator is accepted");
  }
}

// The route's answer, or an fsdb::Error as the route would throw it.
nlohmann::json evaluate(const nlohmann::json& req) {
  const nlohmann::json& body = fsdb::requireObject(req, "");
  for (auto it = body.begin(); it != body.end(); ++it)
    if (it.key() != "operator" && it.key() != "op" && it.key() != "points")
      throw fsdb::Error(fsdb::errc::kInvalidDocument, "unknown field", it.key());
  const fsdb::OperatorConfig config = fsdb::parseOperatorConfig(fsdb::requireField(body, "operator", ""), "operator");
  checkConfig(config);
  const fsdb::OperatorSpec* spec = fsdb::findOperator(config.name);
  FUZZ_CHECK(spec != nullptr, "an accepted operator is in the catalogue");
  const nlohmann::json& points = fsdb::requireArray(fsdb::requireField(body, "points", ""), "points");
  if (points.size() > kMaxPoints) throw fsdb::Error(fsdb::errc::kLimitExceeded, "too many points", "points");

  nlohmann::json result = {{"operator", fsdb::operatorConfigToJson(config)}};
  std::vector<double> values(points.size());
  if (spec->arity == 1) {
    if (body.contains("op"))
      throw fsdb::Error(fsdb::errc::kInvalidDocument, "'op' applies to binary operators only", "op");
    auto f = fsdb::makeUnaryFunction(config);
    for (size_t i = 0; i < points.size(); ++i) {
      double x;
      readPoint(points[i], 1, false, fsdb::joinPath("points", i), &x);
      values[i] = (*f)(x);
      if (spec->kind == "step") FUZZ_CHECK(inUnit(values[i]), "a smooth unit step lies in [0, 1]");
    }
  } else {
    fsdb::Combine combine = spec->kind == "blend" ? fsdb::Combine::Union : fsdb::Combine::Intersection;
    if (body.contains("op")) combine = fsdb::parseCombine(body["op"], "op");
    auto op = fsdb::makeBinaryOperator(config);
    const bool unit = op->actsOnMemberships();
    FUZZ_CHECK(unit == (spec->kind == "fuzzy_operator"), "fuzzy operators, and only they, act on memberships");
    for (size_t i = 0; i < points.size(); ++i) {
      double xy[2];
      readPoint(points[i], 2, unit, fsdb::joinPath("points", i), xy);
      values[i] = op->apply(combine, xy[0], xy[1]);
      if (unit)
        for (fsdb::Combine c : {fsdb::Combine::Intersection, fsdb::Combine::Union, fsdb::Combine::Difference})
          FUZZ_CHECK(inUnit(op->apply(c, xy[0], xy[1])), "a fuzzy operator on memberships lies in [0, 1]");
    }
    result["op"] = fsdb::combineName(combine);
  }
  for (size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw fsdb::Error(fsdb::errc::kDomainError, "the operator is not finite at this point",
                        fsdb::joinPath("points", i));
  result["values"] = std::move(values);
  return result;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 64 * 1024) return 0;
  const std::string body(reinterpret_cast<const char*>(data), size);
  nlohmann::json answer;
  try {
    answer = evaluate(fsdb::parseJsonBody(body, kDepth));
  } catch (const fsdb::Error&) {
    return 0;  // a refusal, as the route answers it
  }
  const nlohmann::json& values = answer["values"];
  FUZZ_CHECK(values.is_array(), "an answer has values");
  for (const nlohmann::json& v : values)
    FUZZ_CHECK(v.is_number() && std::isfinite(v.get<double>()), "values are finite");
  return 0;
}
