// query/document/part_json: part documents to FuzzyPart, defaults, round trips and error paths.
#include "query/document/part_json.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"

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
  EXPECT_EQ(errorPath(json{{"text", "a slightly bnet cylinder"}}), "part.text");
  EXPECT_EQ(errorPath(json{{"text", 3}}), "part.text");
  EXPECT_EQ(errorPath(json{{"place", {{"relative_to", "a"}, {"direction", "top"}}}, {"params", {{"a1", 1}}}}), "part.place");
  EXPECT_EQ(errorPath(json{{"kind", "shape"}, {"params", {{"a1", 1}}}}), "part.kind");
  EXPECT_EQ(errorPath(json{{"params", {{"a1", 1}}}, {"colour", "red"}}), "part.colour");
}

// Parts from words (query/document/part_from_words.h): "text" gives the parameters, "params" entries
// override them, "transform" places the part.
TEST(PartJson, TextGivesTheParameters) {
  const FuzzyPart p = parsePart(json{{"kind", "part"}, {"name", "p"}, {"text", "a slightly bent cylinder"}}, "");
  EXPECT_EQ(p.eps1, FuzzyNumber::crisp(0.1));
  EXPECT_EQ(p.a3, FuzzyNumber::crisp(2));
  EXPECT_FALSE(p.kv.isCrisp());
  const FuzzyPart q = parsePart(json{{"text", "a slightly bent cylinder"}, {"params", {{"a1", 2}}},
                                     {"transform", {{"translate", {"about 3", 0, 0}}}}},
                                "");
  EXPECT_EQ(q.a1, FuzzyNumber::crisp(2));
  EXPECT_EQ(q.kv, p.kv);  // the words' bend stays; a1 alone is overridden
  EXPECT_EQ(q.tx, FuzzyNumber::triangular(2.7, 3, 3.3));
  try {
    parsePart(json{{"text", "a slightly bnet cylinder"}}, "part");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidDocument);
    EXPECT_NE(std::string(e.what()).find("closest known words: bent"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fsdb
