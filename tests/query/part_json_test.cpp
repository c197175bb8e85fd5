// query/part_json: part documents to FuzzyPart, defaults, round trips and error paths.
#include "query/part_json.h"

#include <gtest/gtest.h>

#include "geometry/error.h"

namespace fsdb {
namespace {

using nlohmann::json;

std::string errorPath(const json& doc) {
  try {
    parsePart(doc, "part");
  } catch (const Error& e) {
    return e.path();
  }
  ADD_FAILURE() << "no error for " << doc.dump();
  return "";
}

TEST(PartJson, ParsesFuzzyParametersAndTransformWithDefaults) {
  json doc = json::parse(R"({"kind":"part","name":"bent-rod","descriptors":["slightly bent"],
    "params":{"eps1":1.0,"eps2":{"tri":[0.8,1,1.2]},"a1":2,"a3":3,"kv":{"tri":[0.05,0.1,0.15]}},
    "transform":{"translate":[1,"about 2",{"tri":[-1,0,1]}],"rotate":{"axis":[0,0,1],"deg":30},"scale":1.5}})");
  FuzzyPart p = parsePart(doc, "");
  EXPECT_EQ(p.eps2, FuzzyNumber::triangular(0.8, 1, 1.2));
  EXPECT_EQ(p.a1, FuzzyNumber::crisp(2));
  EXPECT_EQ(p.a2, FuzzyNumber::crisp(1));  // default
  EXPECT_EQ(p.kx, FuzzyNumber::crisp(0));  // default
  EXPECT_EQ(p.ty, FuzzyNumber::triangular(1.8, 2, 2.2));
  EXPECT_EQ(p.deg, FuzzyNumber::crisp(30));
  EXPECT_EQ(p.scale, FuzzyNumber::crisp(1.5));
  EXPECT_EQ(p.axis.z, 1.0);
}

TEST(PartJson, RoundTripsThroughItsJsonForm) {
  json doc = json::parse(R"({"params":{"a1":{"trap":[1,2,3,4]},"t":{"about":0.5,"spread":0.1}},
                             "transform":{"rotate":{"axis":[1,0,0],"deg":{"tri":[10,20,30]}}}})");
  FuzzyPart p = parsePart(doc, "");
  FuzzyPart q = parsePart(partToJson(p), "");
  EXPECT_EQ(q.a1, p.a1);
  EXPECT_EQ(q.t, p.t);
  EXPECT_EQ(q.deg, p.deg);
  EXPECT_EQ(q.axis.x, 1.0);
}

TEST(PartJson, ErrorsNameTheJsonPath) {
  EXPECT_EQ(errorPath(json::array()), "part");
  EXPECT_EQ(errorPath(json{{"params", {{"eps1", 1}}}}), "part.params.a1");
  EXPECT_EQ(errorPath(json{{"params", {{"a1", 1}, {"eps3", 1}}}}), "part.params.eps3");
  EXPECT_EQ(errorPath(json{{"params", {{"a1", {{"tri", {1, 0, 2}}}}}}}), "part.params.a1.tri[1]");
  EXPECT_EQ(errorPath(json{{"params", {{"a1", 1}, {"eps1", 5}}}}), "part.params.eps1");
  EXPECT_EQ(errorPath(json{{"params", {{"a1", 1}}}, {"transform", {{"translate", {1, 2}}}}}), "part.transform.translate");
  EXPECT_EQ(errorPath(json{{"params", {{"a1", 1}}}, {"transform", {{"rotate", {{"axis", {0, 0, 0}}, {"deg", 1}}}}}}),
            "part.transform.rotate.axis");
  EXPECT_EQ(errorPath(json{{"params", {{"a1", 1}}}, {"transform", {{"shear", 1}}}}), "part.transform.shear");
  EXPECT_EQ(errorPath(json{{"params", {{"a1", 1}}}, {"transform", {{"scale", -1}}}}), "part.transform.scale");
  EXPECT_EQ(errorPath(json{{"text", "a slightly bent cylinder"}}), "part.text");
  EXPECT_EQ(errorPath(json{{"kind", "shape"}, {"params", {{"a1", 1}}}}), "part.kind");
  EXPECT_EQ(errorPath(json{{"params", {{"a1", 1}}}, {"colour", "red"}}), "part.colour");
}

}  // namespace
}  // namespace fsdb
