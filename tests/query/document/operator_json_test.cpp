// query/document/operator_json: parsing, defaults, paths and the JSON form of operators.
#include "query/document/operator_json.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"

namespace fsdb {
namespace {

using nlohmann::json;

Error parseError(const json& j) {
  try {
    parseOperatorConfig(j, "operator");
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "no error for " << j.dump();
  return Error("", "");
}

TEST(OperatorJson, FillsDefaultsAndRoundTrips) {
  OperatorConfig c = parseOperatorConfig(json{{"name", "smooth_and"}}, "operator");
  EXPECT_EQ(c.name, "smooth_and");
  EXPECT_EQ(c.params.count("n"), 1u);
  EXPECT_EQ(c.params.count("delta"), 1u);
  json out = operatorConfigToJson(c);
  EXPECT_TRUE(out["n"].is_number_integer()) << out.dump();
  OperatorConfig again = parseOperatorConfig(out, "operator");
  EXPECT_EQ(again.params, c.params);
}

TEST(OperatorJson, ParsesTheNestedStepOfABlend) {
  OperatorConfig c = parseOperatorConfig(
      json{{"name", "ext_max"}, {"delta", 0.4}, {"step", {{"name", "bspline"}, {"m", 4}}}}, "operator");
  ASSERT_EQ(c.step.size(), 1u);
  EXPECT_EQ(c.step[0].name, "bspline");
  EXPECT_EQ(c.step[0].params.at("m"), 4);
  EXPECT_EQ(operatorConfigToJson(c)["step"]["m"], 4);
}

TEST(OperatorJson, ErrorsNameTheJsonPath) {
  EXPECT_EQ(parseError(json::array()).path(), "operator");
  EXPECT_EQ(parseError(json::object()).path(), "operator.name");
  EXPECT_EQ(parseError(json{{"name", 3}}).path(), "operator.name");
  EXPECT_EQ(parseError(json{{"name", "hamacher"}, {"a", "x"}}).path(), "operator.a");
  EXPECT_EQ(parseError(json{{"name", "hamacher"}, {"a", 1.0}}).path(), "operator.a");
  EXPECT_EQ(parseError(json{{"name", "zadeh"}, {"step", {{"name", "bspline"}}}}).path(), "operator.step");
  EXPECT_EQ(parseError(json{{"name", "int_max"}, {"step", {{"name", "bspline"}, {"m", 2.5}}}}).path(),
            "operator.step.m");
  Error unknown = parseError(json{{"name", "zadehh"}});
  EXPECT_EQ(unknown.code(), errc::kUnknownName);
  EXPECT_NE(std::string(unknown.what()).find("zadeh"), std::string::npos) << unknown.what();
}

TEST(OperatorJson, CombinationsByName) {
  EXPECT_EQ(parseCombine("union", "op"), Combine::Union);
  EXPECT_EQ(parseCombine("intersection", "op"), Combine::Intersection);
  EXPECT_EQ(parseCombine("difference", "op"), Combine::Difference);
  EXPECT_STREQ(combineName(Combine::Difference), "difference");
  EXPECT_THROW(parseCombine("xor", "op"), Error);
  EXPECT_THROW(parseCombine(1, "op"), Error);
}

TEST(OperatorJson, SpecJsonHasNullForUnboundedRanges) {
  json yager = operatorSpecToJson(*findOperator("yager"));
  ASSERT_EQ(yager["params"].size(), 1u);
  EXPECT_EQ(yager["params"][0]["name"], "k");
  EXPECT_TRUE(yager["params"][0]["max"].is_null());
  EXPECT_EQ(yager["params"][0]["min"], 1.0);
  EXPECT_FALSE(yager["params"][0]["min_inclusive"]);
}

}  // namespace
}  // namespace fsdb
