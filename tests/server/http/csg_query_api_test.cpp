// POST /query/csg (docs/api.md §4, §5) through the real `fsdb serve`, and `fsdb query` routing CSG
// texts: an exact tree ranks first with score 1; swapped union children still score 1, swapped
// difference children do not; a text query finds the tree it describes above trees with a straight
// cylinder, with a difference, or with unrelated parts; a tree containing the pattern outranks an
// unrelated one; weights change rankings as documented; graphs follow PUTs of the parts they use;
// pruned == unpruned; every error of the request.
#include <gtest/gtest.h>

#include "tests/server/server_process.h"

using fsdb::test::runFsdb;
using fsdb::test::ServerProcess;
using fsdb::test::TempDir;
using nlohmann::json;

namespace {

json words(const std::string& text) { return {{"part", {{"text", text}}}}; }
json node(const std::string& op, json children) { return {{"op", op}, {"children", std::move(children)}}; }

const json kBent = words("a very bent cylinder");
const json kSharp = words("a very sharp pyramid");

int64_t create(const ServerProcess& server, const std::string& kind, const json& doc) {
  auto r = server.post("/" + kind + "s", doc);
  EXPECT_EQ(r.status, 201) << r.body;
  return r.json.value("id", int64_t{0});
}

int64_t shape(const ServerProcess& server, const std::string& name, const json& tree) {
  return create(server, "shape", {{"name", name}, {"tree", tree}});
}

json query(const ServerProcess& server, json body, int status = 200) {
  auto r = server.post("/query/csg", body);
  EXPECT_EQ(r.status, status) << body.dump() << " -> " << r.body;
  return r.json;
}

std::vector<std::string> names(const json& answer) { return fsdb::test::resultNames(answer); }

double scoreOf(const json& answer, const std::string& name) {
  for (const json& r : answer["results"])
    if (r["name"] == name) return r["score"];
  return -1;
}

// The catalogue of the structural search's acceptance cases.
struct Catalogue {
  ServerProcess server;
  Catalogue() {
    shape(server, "exact", node("union", {kBent, kSharp}));
    shape(server, "straight", node("union", {words("a straight cylinder"), kSharp}));
    shape(server, "difference", node("difference", {kBent, kSharp}));
    shape(server, "unrelated", node("union", {words("a sphere"), words("a box")}));
    shape(server, "contains", node("difference", {node("union", {kBent, kSharp}), words("a sphere")}));
  }
};

TEST(CsgQueryApi, ExactTreeFirstWithScoreOneAndOrderRules) {
  Catalogue c;
  const json answer = query(c.server, {{"tree", node("union", {kBent, kSharp})}});
  ASSERT_FALSE(answer["results"].empty());
  const json& best = answer["results"][0];
  EXPECT_EQ(best["name"], "exact");
  EXPECT_DOUBLE_EQ(best["score"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(best["structure"].get<double>(), 1.0);
  EXPECT_EQ(best["complete"], true);
  EXPECT_EQ(best["mapping"].size(), 3u);
  for (const json& m : best["mapping"]) {
    EXPECT_TRUE(m.contains("query_path") && m.contains("stored_path") && m.contains("similarity")) << m;
    EXPECT_EQ(m["query_path"].get<std::string>().rfind("tree", 0), 0u);
  }
  EXPECT_EQ(answer["parsed"]["form"], "tree");
  // Descending scores, ties by id.
  for (size_t i = 1; i < answer["results"].size(); ++i) {
    const json &a = answer["results"][i - 1], &b = answer["results"][i];
    EXPECT_TRUE(a["score"] > b["score"] || (a["score"] == b["score"] && a["id"] < b["id"])) << answer.dump();
  }
  // Swapped union children: still 1. A whole shape document as the tree: the same.
  EXPECT_DOUBLE_EQ(scoreOf(query(c.server, {{"tree", node("union", {kSharp, kBent})}}), "exact"), 1.0);
  EXPECT_DOUBLE_EQ(
      scoreOf(query(c.server, {{"tree", {{"kind", "shape"}, {"name", "q"}, {"tree", node("union", {kSharp, kBent})}}}}),
              "exact"),
      1.0);
  // Difference: in order 1, swapped less.
  EXPECT_DOUBLE_EQ(scoreOf(query(c.server, {{"tree", node("difference", {kBent, kSharp})}}), "difference"), 1.0);
  const double swapped = scoreOf(query(c.server, {{"tree", node("difference", {kSharp, kBent})}}), "difference");
  EXPECT_LT(swapped, 1.0);
  // limit and threshold
  EXPECT_EQ(query(c.server, {{"tree", node("union", {kBent, kSharp})}, {"limit", 1}})["results"].size(), 1u);
  // Kept in a variable: a range-for over query(...)["results"] reads a destroyed temporary (ASan).
  const json above = query(c.server, {{"tree", node("union", {kBent, kSharp})}, {"threshold", 0.5}});
  for (const json& r : above["results"]) EXPECT_GE(r["score"].get<double>(), 0.5);
}

TEST(CsgQueryApi, TextFindsTheTreeItDescribes) {
  Catalogue c;
  const json answer = query(c.server, {{"text", "the union of a very bent cylinder and a very sharp pyramid"}});
  const std::vector<std::string> ranked = names(answer);
  ASSERT_FALSE(ranked.empty());
  EXPECT_EQ(ranked[0], "exact") << answer.dump();
  const double exact = scoreOf(answer, "exact");
  for (const char* other : {"straight", "difference", "unrelated"}) EXPECT_LT(scoreOf(answer, other), exact) << other;
  // The tree containing the pattern outranks the unrelated one.
  EXPECT_GT(scoreOf(answer, "contains"), scoreOf(answer, "unrelated"));
  EXPECT_EQ(answer["parsed"]["form"], "phrase");
  EXPECT_EQ(answer["parsed"]["tree"]["children"][0]["text"], "a very bent cylinder");
  // The formula form with quoted descriptions finds the same.
  const json formula = query(c.server, {{"text", "\"very bent cylinder\" + \"very sharp pyramid\""}});
  EXPECT_EQ(names(formula)[0], "exact");
  EXPECT_EQ(formula["parsed"]["form"], "formula");
  // "a cube minus ..." style: the difference tree first.
  EXPECT_EQ(names(query(c.server, {{"text", "a very bent cylinder minus a very sharp pyramid"}}))[0], "difference");
}

// Tree query union(p1 at x=0, p2 at x=5). "moved": the same parts, both elsewhere (components 1,
// structure 1, transforms 0); "other": p1 in place and a different second part (components 1/2,
// transforms 1/2, structure 2/3). Default weights prefer "moved", transforms alone "other".
TEST(CsgQueryApi, WeightsChangeRankingsAsDocumented) {
  ServerProcess server;
  const auto at = [](double a1, double x, double y) {
    return json{{"part", {{"params", {{"a1", a1}}}, {"transform", {{"translate", {x, y, 0}}}}}}};
  };
  shape(server, "moved", node("union", {at(1, 0, 20), at(2, 5, 20)}));
  shape(server, "other", node("union", {at(1, 0, 0), at(3, 5, 0)}));
  const json tree = node("union", {at(1, 0, 0), at(2, 5, 0)});
  const json byDefault = query(server, {{"tree", tree}});
  EXPECT_EQ(names(byDefault), (std::vector<std::string>{"moved", "other"}));
  EXPECT_NEAR(scoreOf(byDefault, "moved"), 0.5 * 1 + 0.2 * 0 + 0.3 * 1, 1e-9);
  EXPECT_NEAR(scoreOf(byDefault, "other"), 0.5 * 0.5 + 0.2 * 0.5 + 0.3 * 2 / 3, 1e-9);
  const json transforms =
      query(server, {{"tree", tree}, {"weights", {{"components", 0}, {"transforms", 1}, {"structure", 0}}}});
  EXPECT_EQ(names(transforms), std::vector<std::string>{"other"});  // "moved" scores 0 there
  const json structure =
      query(server, {{"tree", tree}, {"weights", {{"components", 0}, {"transforms", 0}, {"structure", 1}}}});
  EXPECT_EQ(names(structure), (std::vector<std::string>{"moved", "other"}));
  EXPECT_DOUBLE_EQ(scoreOf(structure, "moved"), 1.0);
}

TEST(CsgQueryApi, StoredPartsInFormulasAndGraphsFollowPuts) {
  ServerProcess server;
  const int64_t rod = create(server, "part", {{"name", "rod"}, {"params", {{"a1", 1}, {"a3", 3}}}});
  create(server, "part", {{"name", "cap"}, {"params", {{"a1", 1}}}});
  shape(server, "assembly", node("union", {{{"part", "rod"}}, {{"part", "cap"}}}));
  json answer = query(server, {{"text", "rod + cap"}});
  ASSERT_EQ(names(answer), std::vector<std::string>{"assembly"});
  EXPECT_DOUBLE_EQ(answer["results"][0]["score"].get<double>(), 1.0);
  // A new version of a part the tree uses: the cached graph is rebuilt, the query (which resolves
  // "rod" again) still matches exactly, and the old rod no longer does.
  ASSERT_EQ(
      server.put("/parts/" + std::to_string(rod), json{{"name", "rod"}, {"params", {{"a1", 2}, {"a3", 3}}}}).status,
      200);
  answer = query(server, {{"text", "rod + cap"}});
  EXPECT_DOUBLE_EQ(answer["results"][0]["score"].get<double>(), 1.0);
  answer =
      query(server, {{"tree", node("union", {{{"part", {{"params", {{"a1", 1}, {"a3", 3}}}}}}, {{"part", "cap"}}})}});
  EXPECT_LT(answer["results"][0]["score"].get<double>(), 1.0);
}

TEST(CsgQueryApi, PrunedEqualsUnpruned) {
  Catalogue c;
  for (const char* text : {"the union of a very bent cylinder and a very sharp pyramid", "a sphere and a box",
                           "a very bent cylinder minus a very sharp pyramid", "a sphere"})
    for (int limit : {1, 2, 10}) {
      const json pruned = query(c.server, {{"text", text}, {"limit", limit}});
      const json full = query(c.server, {{"text", text}, {"limit", limit}, {"prune", false}});
      EXPECT_EQ(pruned["results"], full["results"]) << text << " limit " << limit;
      EXPECT_LE(pruned["matched"].get<int>(), full["matched"].get<int>());
      EXPECT_EQ(full["matched"], full["candidates"]);
    }
}

TEST(CsgQueryApi, RequestErrors) {
  ServerProcess server;
  const auto expectError = [&](json body, int status, const std::string& code, const std::string& path) {
    const json e = query(server, body, status);
    EXPECT_EQ(e["error"]["code"], code) << body.dump();
    EXPECT_EQ(e["error"]["path"], path) << body.dump();
  };
  expectError({{"text", "a cube"}, {"bogus", 1}}, 422, "invalid_document", "bogus");
  expectError(json::object(), 422, "invalid_document", "text");
  expectError({{"text", "a cube"}, {"tree", node("union", {kBent, kSharp})}}, 422, "invalid_document", "tree");
  expectError({{"text", 3}}, 422, "invalid_document", "text");
  expectError({{"text", "the union of a cube"}}, 422, "invalid_parameter", "text");
  expectError({{"text", "a cube"}, {"limit", 0}}, 422, "invalid_parameter", "limit");
  expectError({{"text", "a cube"}, {"threshold", 2}}, 422, "invalid_parameter", "threshold");
  expectError({{"text", "a cube"}, {"leaf_threshold", -1}}, 422, "invalid_parameter", "leaf_threshold");
  expectError({{"text", "a cube"}, {"time_budget_ms", 1e9}}, 422, "invalid_parameter", "time_budget_ms");
  expectError({{"text", "a cube"}, {"prune", "yes"}}, 422, "invalid_document", "prune");
  expectError({{"text", "a cube"}, {"weights", {{"structure", -1}}}}, 422, "invalid_parameter", "weights.structure");
  expectError({{"text", "a cube"}, {"weights", {{"size", 1}}}}, 422, "invalid_document", "weights.size");
  expectError({{"text", "a cube"}, {"weights", {{"components", 0}, {"transforms", 0}, {"structure", 0}}}}, 422,
              "invalid_parameter", "weights");
  expectError({{"tree", node("union", {{{"part", "nothing-of-that-name"}}, kSharp})}}, 422, "unknown_reference",
              "tree.children[0].part");
  const json e = query(server, {{"text", "the union of a cube and a frobnicated sphere"}}, 422);
  EXPECT_NE(e["error"]["message"].get<std::string>().find("character 26"), std::string::npos) << e.dump();
  EXPECT_EQ(server.get("/health").status, 200);
}

TEST(CsgQueryApi, NodeAndTimeLimits) {
  ServerProcess server({"--max-nodes", "5", "--max-query-ms", "1"});
  std::string text = "a cube";
  for (int i = 0; i < 6; ++i) text += " and a sphere";
  json e = query(server, {{"text", text}}, 413);
  EXPECT_EQ(e["error"]["code"], "limit_exceeded");
  std::string body;
  for (int i = 0; i < 3000; ++i)
    body += json{{"name", "s" + std::to_string(i)}, {"tree", node("union", {kBent, kSharp})}}.dump() + "\n";
  ASSERT_EQ(server.post("/shapes/bulk", body, "application/x-ndjson").status, 200);
  e = query(server, {{"text", "the union of a cube and a sphere"}, {"prune", false}}, 413);
  EXPECT_EQ(e["error"]["code"], "limit_exceeded");
  EXPECT_NE(e["error"]["message"].get<std::string>().find("max_query_ms=1"), std::string::npos) << e.dump();
  EXPECT_EQ(server.get("/health").status, 200);
}

// Wide queries within --max-nodes: a union of thousands of children matched against small stored
// unions is an assignment of thousands against a few (it was padded to a square: hours); a phrase
// list of thousands of operands is one union (it was a left-deep chain copied at every "and": tens
// of seconds); a match of two wide unions that takes too long stops at --max-query-ms (it ran on
// past it inside one tree DP).
TEST(CsgQueryApi, WideQueriesAnswerOrStopAtTheTimeLimit) {
  // 5000 x 4000 leaf pairs below: over the default --max-csg-pairs, which this test is not about.
  ServerProcess server({"--max-query-ms", "1000", "--max-csg-pairs", "20000000"});
  shape(server, "pair", node("union", {kBent, kSharp}));
  json wide = json::array();
  for (int i = 0; i < 5000; ++i) wide.push_back(i % 2 ? kBent : kSharp);
  json a = query(server, {{"tree", node("union", wide)}});
  EXPECT_EQ(a["parsed"]["leaves"], 5000);
  EXPECT_EQ(names(a), (std::vector<std::string>{"pair"}));
  std::string text = "a very bent cylinder";
  for (int i = 0; i < 3000; ++i) text += " and a very sharp pyramid";
  a = query(server, {{"text", text}});
  EXPECT_EQ(a["parsed"]["leaves"], 3001);
  EXPECT_EQ(a["parsed"]["tree"]["children"].size(), 3001u) << "one n-ary union";
  EXPECT_EQ(names(a), (std::vector<std::string>{"pair"}));
  shape(server, "wide", node("union", json(wide.begin(), wide.begin() + 4000)));
  json e = query(server, {{"tree", node("union", wide)}}, 413);
  EXPECT_NE(e["error"]["message"].get<std::string>().find("max_query_ms=1000"), std::string::npos) << e.dump();
  EXPECT_EQ(server.get("/health").status, 200);
}

// --max-csg-pairs: a match of more query leaves x stored leaves would allocate two tables of that
// many doubles (10,000 x 10,000 leaves: 1.6 GB); it is 413 naming the limit before that, and the
// server keeps serving (the same query within the limit still answers).
TEST(CsgQueryApi, LeafPairLimit) {
  ServerProcess server({"--max-csg-pairs", "20"});
  json five = json::array();
  for (int i = 0; i < 5; ++i) five.push_back(i % 2 ? kBent : kSharp);
  shape(server, "five", node("union", five));
  json e = query(server, {{"tree", node("union", five)}}, 413);
  EXPECT_EQ(e["error"]["code"], "limit_exceeded");
  EXPECT_NE(e["error"]["message"].get<std::string>().find("max_csg_pairs=20"), std::string::npos) << e.dump();
  EXPECT_EQ(server.get("/health").status, 200);
  json four(five.begin(), five.begin() + 4);
  const json a = query(server, {{"tree", node("union", four)}});
  EXPECT_EQ(names(a), (std::vector<std::string>{"five"}));
  EXPECT_EQ(a["parsed"]["leaves"], 4);
}

TEST(CsgQueryCli, RoutesCsgTexts) {
  TempDir dir;
  const std::string db = dir.file("cli.sqlite");
  std::string viaServer;
  {
    ServerProcess server({"--db", db});
    shape(server, "exact", node("union", {kBent, kSharp}));
    shape(server, "unrelated", node("union", {words("a sphere"), words("a box")}));
    const auto r = runFsdb({"query", "the union of a very bent cylinder and a very sharp pyramid", "--server",
                            "http://" + server.host() + ":" + std::to_string(server.port())});
    EXPECT_EQ(r.exitCode, 0) << r.out;
    viaServer = r.out;
  }
  const auto r = runFsdb({"query", "the union of a very bent cylinder and a very sharp pyramid", "--db", db});
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_EQ(r.out, viaServer);
  const size_t exact = r.out.find("exact"), unrelated = r.out.find("unrelated");
  EXPECT_TRUE(exact != std::string::npos && (unrelated == std::string::npos || exact < unrelated)) << r.out;
  EXPECT_NE(r.out.find("shape"), std::string::npos);
  const auto formula = runFsdb({"query", "\"very bent cylinder\" + \"very sharp pyramid\"", "--db", db, "--json"});
  EXPECT_EQ(formula.exitCode, 0);
  EXPECT_EQ(json::parse(formula.out)["parsed"]["form"], "formula");
  // A list is a CSG query too; a linguistic text is not.
  EXPECT_EQ(json::parse(runFsdb({"query", "a sphere and a box", "--db", db, "--json"}).out)["parsed"]["form"],
            "phrase");
  EXPECT_TRUE(json::parse(runFsdb({"query", "find a sphere", "--db", db, "--json"}).out)["parsed"].contains("subject"));
  const auto refused = runFsdb({"query", "the union of a cube and", "--db", db}, true);
  EXPECT_EQ(refused.exitCode, 1) << refused.out;
  EXPECT_NE(refused.out.find("invalid_parameter"), std::string::npos) << refused.out;
  EXPECT_EQ(runFsdb({"query", "a cube minus a sphere", "--db", db, "--scan"}).exitCode, 1);
}

}  // namespace
