// Level answers through the real server: the parts and points an independent brute-force
// reference flagged (stored as parts, then GET /parts/{id}/membership, verbatim from the report),
// the bounding box POST /evaluate grids, and the exactness flags of membership and evaluate.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "query/document/part_json.h"
#include "tests/server/shared_server.h"
#include "tests/testing/fuzzy_bench_part.h"
#include "tests/testing/sanitizer_slowdown.h"

using fsdb::test::SharedServerTest;
using nlohmann::json;

namespace {

// All triangular: P(1) is one parameter set, where F = 304.5 at the point below.
const char* kThinBentRod =
    R"({"params":{"eps1":{"tri":[0.095,0.1,0.10500000000000001]},"eps2":{"tri":[0.95,1,1.05]},"a1":{"tri":[0.11399999999999999,0.12,0.126]},"a2":{"tri":[0.95,1,1.05]},"a3":{"tri":[6.65,7,7.35]},"kx":{"tri":[0.15000000000000002,0.2,0.25]},"ky":{"tri":[0.05,0.1,0.15000000000000002]},"kv":{"tri":[1.52,1.6,1.6800000000000002]},"t":{"tri":[0.45,0.5,0.55]}},"transform":{"translate":[{"tri":[0.27999999999999997,0.3,0.32]},{"tri":[-0.22,-0.2,-0.18000000000000002]},{"tri":[0.08,0.1,0.12000000000000001]}],"rotate":{"axis":[0,1,1],"deg":{"tri":[28.5,30,31.5]}},"scale":{"tri":[0.95,1,1.05]}}})";
// A parameter set of P(1) puts the point below inside (F = 0.858).
const char* kMixedPart =
    R"({"params":{"eps1":0.8909661874018617,"eps2":{"tri":[2.0378137158018914,2.21037716014386,2.382940604485829]},"a1":0.558004844827056,"a2":1.0946576860061445,"a3":{"tri":[2.628587500925802,2.8511780691394972,3.0737686373531923]},"kx":{"trap":[-0.639414694706711,-0.6019146947067109,-0.5644146947067109,-0.5394146947067109]},"ky":{"points":[[0.5021189133992847,0],[0.5271189133992847,0.6],[0.5521189133992848,1],[0.5687855800659515,0.5],[0.6021189133992848,0]]},"kv":{"points":[[0.4436919409514721,0],[0.46247800784356546,0.6],[0.48126407473565885,1],[0.4937881193303878,0.5],[0.5188362085198457,0]]},"t":2.4235007291755606},"transform":{"translate":[0.13943829571855448,{"trap":[-0.7644377505641476,-0.7229195069996466,-0.6814012634351454,-0.6537224343921447]},-0.6150730100633353],"rotate":{"axis":[-0.011521468038548173,-0.4435812229744192,1.1661277761902227],"deg":77.02302325401439},"scale":{"trap":[1.2247749592102648,1.302561038428238,1.3803471176462112,1.4322045037915265]}}})";

class MembershipExactness : public SharedServerTest<MembershipExactness> {
 public:
  // The default 60 s limit on an evaluation, times the sanitizer build's slowdown (the rod's grid
  // takes about 10 s in Release; under ASan, beside another test's evaluations, it passed 60 s).
  static std::vector<std::string> serverArgs() {
    return {"--max-eval-ms", std::to_string(static_cast<int>(60000 * fsdb::testing::kSlowdown))};
  }
  std::string storePart(const std::string& name, json doc) {
    doc["kind"] = "part";
    doc["name"] = name;
    auto r = server->post("/parts", doc);
    EXPECT_EQ(r.status, 201) << r.body;
    return "/parts/" + std::to_string(r.json.value("id", int64_t{0}));
  }
};

TEST_F(MembershipExactness, UpperOneOnlyWhereTheCorePutsThePointInside) {
  const std::string at = storePart("rod", json::parse(kThinBentRod));
  auto r = server->get(at + "/membership?x=0.9402043674143239&y=-0.1187008650745276&z=0.3760387797516726");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_LT(r.json["upper"].get<double>(), 1.0) << r.body;  // answered 1 before
  EXPECT_EQ(r.json["lower_from"], nullptr) << r.body;
  // The answer says whether it is exact: a count, and exact exactly when it is 0.
  ASSERT_TRUE(r.json["exhausted_searches"].is_number_unsigned()) << r.body;
  EXPECT_EQ(r.json["exact"], r.json["exhausted_searches"] == 0) << r.body;
}

TEST_F(MembershipExactness, PointsThatTheCorePutsInsideHaveUpperOne) {
  const std::string at = storePart("mixed", json::parse(kMixedPart));
  auto r = server->get(at + "/membership?x=0.8961905740017211&y=-0.11067796850933344&z=-0.6696945766274232");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json["upper"], 1.0) << r.body;  // answered 0.9998 before
}

// The rod's box was 3.3 on its longest side around an upper(0) whose mesh spans 1.65: the grid
// now spans at most 1.25 times that.
TEST_F(MembershipExactness, EvaluateGridsABoxNearUpperZero) {
  json part = json::parse(kThinBentRod);
  part["kind"] = "part";
  auto r = server->post("/evaluate", json{{"shape", part}, {"resolution", 32}, {"alphas", {0.5}}});
  ASSERT_EQ(r.status, 200) << r.body;
  const json& box = r.json["bounding_box"];
  double longest = 0.0;
  for (int i = 0; i < 3; ++i)
    longest = std::max(longest, box["max"][i].get<double>() - box["min"][i].get<double>());
  EXPECT_LE(longest, 1.25 * 1.65) << r.body;
  EXPECT_EQ(r.json["exact"], r.json["exhausted_searches"] == 0) << r.body;
}

TEST_F(MembershipExactness, CrispAnswersAreExact) {
  const std::string at = storePart("ball", json{{"params", {{"a1", 1}}}});
  auto m = server->get(at + "/membership?x=0.2&y=0&z=0");
  ASSERT_EQ(m.status, 200) << m.body;
  EXPECT_EQ(m.json["exhausted_searches"], 0);
  EXPECT_EQ(m.json["exact"], true);
  auto e = server->post("/evaluate", json{{"shape", {{"kind", "part"}, {"params", {{"a1", 1}}}}}, {"resolution", 16}});
  ASSERT_EQ(e.status, 200) << e.body;
  EXPECT_EQ(e.json["exact"], true);
}

// The part with all fourteen values fuzzy runs searches out of budget at this resolution: the
// answer says so.
TEST_F(MembershipExactness, EvaluateSaysWhenLevelsAreBounds) {
  auto e = server->post("/evaluate", json{{"shape", fsdb::partToJson(fsdb::testing::allValuesFuzzyPart())},
                                          {"resolution", 16}, {"alphas", {0.5}}});
  ASSERT_EQ(e.status, 200) << e.body;
  ASSERT_GT(e.json["exhausted_searches"].get<std::uint64_t>(), 0u) << e.body;
  EXPECT_EQ(e.json["exact"], false);
}

}  // namespace
