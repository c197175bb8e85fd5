// GET /parts/{id}/members and GET /shapes/{id}/members through the real server: the family's crisp
// members (Zhang, Pham & Chen, Figure 1) with their membership degrees, from the core outward;
// each member a document the server takes; the errors.
#include <gtest/gtest.h>

#include <string>

#include "tests/server/shared_server.h"

using fsdb::test::SharedServerTest;
using nlohmann::json;

namespace {

class FamilyMembers : public SharedServerTest<FamilyMembers> {};

const json kFuzzyPart = json::parse(
    R"({"kind":"part","name":"fuzzy-bent-rod","params":{"a1":{"tri":[0.18,0.2,0.22]},"a3":{"tri":[4,5,6]},"kv":{"tri":[0,0.1,0.2]}},"transform":{"translate":[{"tri":[-0.5,0,0.5]},0,0]}})");

TEST_F(FamilyMembers, APartsMembersFromTheCoreOutward) {
  auto stored = server->post("/parts", kFuzzyPart);
  ASSERT_EQ(stored.status, 201) << stored.body;
  const std::string id = std::to_string(stored.json["id"].get<int64_t>());
  auto r = server->get("/parts/" + id + "/members?count=5");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json["kind"], "part");
  EXPECT_EQ(r.json["count"], 5);
  const json& members = r.json["members"];
  ASSERT_EQ(members.size(), 5u);
  EXPECT_DOUBLE_EQ(members[0]["membership"].get<double>(), 1.0);
  for (size_t k = 1; k < members.size(); ++k) {
    EXPECT_LE(members[k]["membership"].get<double>(), members[k - 1]["membership"].get<double>());
    // Triangular values: a member at level 1 - k/5 has exactly that membership.
    EXPECT_NEAR(members[k]["membership"].get<double>(), 1.0 - k / 5.0, 1e-12);
    // Every value crisp, and the member is a part the server takes.
    const json& doc = members[k]["document"];
    EXPECT_EQ(doc["kind"], "part");
    for (const auto& [name, value] : doc["params"].items()) EXPECT_TRUE(value.is_number()) << name << ": " << value;
    EXPECT_EQ(server->post("/evaluate", json{{"shape", doc}, {"resolution", 8}}).status, 200) << doc;
  }
  // Members lean different ways: consecutive ones differ in every fuzzy value.
  EXPECT_NE(members[1]["document"]["params"]["a3"], members[2]["document"]["params"]["a3"]);
  // The default count.
  EXPECT_EQ(server->get("/parts/" + id + "/members").json["members"].size(), 9u);
}

TEST_F(FamilyMembers, AShapesMembersDrawEveryPartTogether) {
  json shape = json::parse(R"({"kind":"shape","name":"two-fuzzy-parts","tree":{"op":"difference","children":[
      {"part":{"params":{"a1":{"tri":[0.9,1,1.1]},"a3":{"tri":[1,1.5,2]}}}},
      {"part":{"params":{"a1":{"tri":[0.05,0.1,0.15]},"a3":3}}}]}})");
  auto stored = server->post("/shapes", shape);
  ASSERT_EQ(stored.status, 201) << stored.body;
  const std::string id = std::to_string(stored.json["id"].get<int64_t>());
  auto r = server->get("/shapes/" + id + "/members?count=4");
  ASSERT_EQ(r.status, 200) << r.body;
  const json& members = r.json["members"];
  ASSERT_EQ(members.size(), 4u);
  for (const json& m : members) {
    const json& tree = m["document"]["tree"];
    EXPECT_EQ(tree["op"], "difference");
    ASSERT_EQ(tree["children"].size(), 2u);
    EXPECT_TRUE(tree["children"][1]["part"]["params"]["a1"].is_number());
    EXPECT_EQ(server->post("/evaluate", json{{"shape", m["document"]}, {"resolution", 8}}).status, 200);
  }
  EXPECT_NEAR(members[3]["membership"].get<double>(), 0.25, 1e-12);
}

TEST_F(FamilyMembers, Errors) {
  auto stored = server->post("/parts", json{{"kind", "part"}, {"name", "crisp-ball"}, {"params", {{"a1", 1}}}});
  ASSERT_EQ(stored.status, 201) << stored.body;
  const std::string id = std::to_string(stored.json["id"].get<int64_t>());
  for (const char* count : {"0", "65", "2.5", "many"}) {
    auto r = server->get("/parts/" + id + "/members?count=" + count);
    EXPECT_EQ(r.status, 422) << count << ": " << r.body;
    EXPECT_EQ(r.json["error"]["path"], "count") << count;
  }
  EXPECT_EQ(server->get("/parts/999999/members").status, 404);
  // A crisp part is its own only member, at every level.
  auto crisp = server->get("/parts/" + id + "/members?count=3");
  ASSERT_EQ(crisp.status, 200);
  for (const json& m : crisp.json["members"]) EXPECT_DOUBLE_EQ(m["membership"].get<double>(), 1.0);
}

}  // namespace
