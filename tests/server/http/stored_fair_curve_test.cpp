// Stored fair curves ({"kind":"curve","fair":{POST /curves/fair request}}) against the real
// `fsdb serve`: create, new versions by PUT, lookup by name, GET /curves/{id}/candidates (what
// POST /curves/fair answers), the SVG of the candidates, errors with their paths, and the
// --max-fair-* options answering 413 by name.
#include <gtest/gtest.h>

#include <string>

#include "tests/server/shared_server.h"

using fsdb::test::ServerProcess;
using fsdb::test::SharedServerTest;
using nlohmann::json;

namespace {

// Bernardes, Wu & D'Ottaviano, Figure 7's four points, closed: several ranked candidates.
json figure7() {
  return {{"points", {{0, 0}, {-5, -1}, {-3, -4}, {1, -1}}}, {"closed", true}, {"behavior", "undulant"}, {"samples", 5}};
}

void expectError(const ServerProcess::Reply& r, int status, const std::string& code, const std::string& path) {
  EXPECT_EQ(r.status, status) << r.body;
  EXPECT_EQ(r.json["error"]["code"], code) << r.body;
  EXPECT_EQ(r.json["error"]["path"], path) << r.body;
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

class StoredFairCurve : public SharedServerTest<StoredFairCurve> {};

TEST_F(StoredFairCurve, CreatesVersionsAndFindsByName) {
  auto c = server->post("/curves", json{{"kind", "curve"}, {"name", "loop"}, {"fair", figure7()}});
  ASSERT_EQ(c.status, 201) << c.body;
  const std::string base = "/curves/" + std::to_string(c.json["id"].get<int64_t>());
  EXPECT_EQ(c.json["document"]["fair"], figure7());
  json open = figure7();
  open["closed"] = false;
  open["relations"] = {"smoother", "sharper", "smoother"};
  auto v2 = server->put(base, json{{"fair", open}});
  ASSERT_EQ(v2.status, 200) << v2.body;
  EXPECT_EQ(v2.json["version"], 2);
  EXPECT_EQ(v2.json["name"], "loop");
  auto byName = server->get("/curves?name=loop");
  ASSERT_EQ(byName.json["items"].size(), 1u);
  EXPECT_EQ(byName.json["items"][0]["document"]["fair"]["closed"], false);
  EXPECT_EQ(server->get(base + "?version=1").json["document"]["fair"]["closed"], true);
  // A fair curve can become a Bézier curve in a new version, and back.
  auto v3 = server->put(base, json{{"bezier", {{"control_points", {{0, 0}, {1, 1}}}}}});
  ASSERT_EQ(v3.status, 200) << v3.body;
  EXPECT_EQ(v3.json["version"], 3);
}

// The designer picks a candidate: a new version (PUT with If-Match) whose chosen_candidate GET
// shows and GET /curves/{id}/svg highlights by default; an index the curve has not is 422.
TEST_F(StoredFairCurve, StoresTheDesignersChosenCandidateAsANewVersion) {
  auto c = server->post("/curves", json{{"name", "fig7-chosen"}, {"fair", figure7()}});
  ASSERT_EQ(c.status, 201) << c.body;
  const std::string base = "/curves/" + std::to_string(c.json["id"].get<int64_t>());
  const size_t n = server->get(base + "/candidates").json["candidates"].size();
  ASSERT_GE(n, 2u);
  auto client = server->client();
  const json chosen = {{"fair", figure7()}, {"chosen_candidate", 1}};
  auto v2 = client.Put(base.c_str(), httplib::Headers{{"If-Match", "\"1\""}}, chosen.dump(), "application/json");
  ASSERT_EQ(v2->status, 200) << v2->body;
  EXPECT_EQ(v2->get_header_value("ETag"), "\"2\"");
  auto got = server->get(base);
  EXPECT_EQ(got.json["version"], 2);
  EXPECT_EQ(got.json["document"]["chosen_candidate"], 1);
  EXPECT_FALSE(server->get(base + "?version=1").json["document"].contains("chosen_candidate"));
  // The SVG highlights the choice unless ?candidate= asks for another; version 1 the best.
  EXPECT_NE(server->get(base + "/svg").body.find("<polyline id=\"candidate-1\" stroke=\"#000000\""), std::string::npos);
  EXPECT_NE(server->get(base + "/svg?candidate=0").body.find("<polyline id=\"candidate-0\" stroke=\"#000000\""),
            std::string::npos);
  EXPECT_NE(server->get(base + "/svg?version=1").body.find("<polyline id=\"candidate-0\" stroke=\"#000000\""),
            std::string::npos);
  // A second client that read version 1 cannot overwrite the choice.
  auto stale = client.Put(base.c_str(), httplib::Headers{{"If-Match", "\"1\""}},
                          json{{"fair", figure7()}, {"chosen_candidate", 0}}.dump(), "application/json");
  EXPECT_EQ(stale->status, 412) << stale->body;
  expectError(server->put(base, json{{"fair", figure7()}, {"chosen_candidate", n}}), 422, "invalid_document",
              "chosen_candidate");
  expectError(server->post("/curves", json{{"name", "line-chosen"},
                                           {"bezier", {{"control_points", {{0, 0}, {1, 1}}}}},
                                           {"chosen_candidate", 0}}),
              422, "invalid_document", "chosen_candidate");
  EXPECT_EQ(server->get(base).json["version"], 2);
}

TEST_F(StoredFairCurve, CandidatesAreWhatPostCurvesFairAnswers) {
  auto c = server->post("/curves", json{{"name", "fig7"}, {"fair", figure7()}});
  ASSERT_EQ(c.status, 201) << c.body;
  const std::string base = "/curves/" + std::to_string(c.json["id"].get<int64_t>());
  auto stored = server->get(base + "/candidates");
  ASSERT_EQ(stored.status, 200) << stored.body;
  auto direct = server->post("/curves/fair", figure7());
  ASSERT_EQ(direct.status, 200) << direct.body;
  EXPECT_EQ(stored.json, direct.json);
  EXPECT_GE(stored.json["candidates"].size(), 2u);
  // ?version= reads an older version; a Bézier curve has no candidates.
  auto bez = server->post("/curves", json{{"name", "line"}, {"bezier", {{"control_points", {{0, 0}, {1, 1}}}}}});
  ASSERT_EQ(bez.status, 201) << bez.body;
  expectError(server->get("/curves/" + std::to_string(bez.json["id"].get<int64_t>()) + "/candidates"), 422,
              "invalid_parameter", "id");
  expectError(server->get(base + "/candidates?version=9"), 404, "not_found", "");
  expectError(server->get("/curves/999999/candidates"), 404, "not_found", "");
}

TEST_F(StoredFairCurve, SvgDrawsEveryCandidateAndHighlightsOne) {
  auto c = server->post("/curves", json{{"name", "fig7-svg"}, {"fair", figure7()}});
  ASSERT_EQ(c.status, 201) << c.body;
  const std::string base = "/curves/" + std::to_string(c.json["id"].get<int64_t>());
  const json answer = server->get(base + "/candidates").json;
  const size_t n = answer["candidates"].size();
  ASSERT_GE(n, 2u);
  auto best = server->get(base + "/svg");
  ASSERT_EQ(best.status, 200) << best.body;
  EXPECT_EQ(best.contentType, "image/svg+xml");
  EXPECT_EQ(best.body.rfind("<svg", 0), 0u);
  EXPECT_EQ(count(best.body, "<polyline "), n) << best.body;
  EXPECT_EQ(count(best.body, "<circle class=\"point\""), 4u) << best.body;
  // The best candidate is black, thicker and drawn last (on top).
  const size_t last = best.body.rfind("<polyline ");
  const std::string top = "<polyline id=\"candidate-0\" stroke=\"#000000\" points=\"";
  EXPECT_EQ(best.body.compare(last, top.size(), top), 0) << best.body.substr(last, 80);
  EXPECT_NE(best.body.find("stroke-width", last), std::string::npos);
  EXPECT_EQ(count(best.body, "stroke=\"#000000\""), 1u);
  auto second = server->get(base + "/svg?candidate=1");
  ASSERT_EQ(second.status, 200) << second.body;
  EXPECT_NE(second.body.find("<polyline id=\"candidate-1\" stroke=\"#000000\""), std::string::npos);
  EXPECT_NE(second.body.find("<polyline id=\"candidate-0\" stroke=\"#a0a0a0\""), std::string::npos);
  expectError(server->get(base + "/svg?candidate=" + std::to_string(n)), 422, "invalid_parameter", "candidate");
  expectError(server->get(base + "/svg?candidate=-1"), 422, "invalid_parameter", "candidate");
  expectError(server->get(base + "/svg?candidate=0.5"), 422, "invalid_parameter", "candidate");
  expectError(server->get(base + "/svg?alpha=0.5"), 422, "invalid_parameter", "alpha");
  expectError(server->get(base + "/svg?samples=9"), 422, "invalid_parameter", "samples");
  // R_alpha = 1 leaves no candidate: the picture shows the points only, and no candidate is chosen.
  json none = figure7();
  none["alpha_threshold"] = 1;
  auto empty = server->post("/curves", json{{"name", "fig7-none"}, {"fair", none}});
  ASSERT_EQ(empty.status, 201) << empty.body;
  const std::string emptyBase = "/curves/" + std::to_string(empty.json["id"].get<int64_t>());
  EXPECT_EQ(server->get(emptyBase + "/candidates").json["candidates"], json::array());
  auto dots = server->get(emptyBase + "/svg");
  ASSERT_EQ(dots.status, 200) << dots.body;
  EXPECT_EQ(count(dots.body, "<polyline "), 0u);
  EXPECT_EQ(count(dots.body, "<circle class=\"point\""), 4u);
  expectError(server->get(emptyBase + "/svg?candidate=0"), 422, "invalid_parameter", "candidate");
  auto bez = server->post("/curves", json{{"name", "line-svg"}, {"bezier", {{"control_points", {{0, 0}, {1, 1}}}}}});
  ASSERT_EQ(bez.status, 201) << bez.body;
  expectError(server->get("/curves/" + std::to_string(bez.json["id"].get<int64_t>()) + "/svg?candidate=0"), 422,
              "invalid_parameter", "candidate");
}

TEST_F(StoredFairCurve, BadDocumentsNameTheirPathAndWriteNothing) {
  const int before = server->get("/health").json["curves"];
  expectError(server->post("/curves", json{{"name", "both"}, {"fair", figure7()}, {"bezier", {{"control_points", {{0, 0}}}}}}),
              422, "invalid_document", "fair");
  expectError(server->post("/curves", json{{"name", "neither"}}), 422, "invalid_document", "bezier");
  expectError(server->post("/curves", json{{"name", "p"}, {"fair", {{"points", {{0, 0}, {1, "x"}}}}}}), 422,
              "invalid_document", "fair.points[1][1]");
  expectError(server->post("/curves", json{{"name", "r"}, {"fair", {{"points", {{0, 0}, {1, 1}}}, {"relations", {"round"}}}}}),
              422, "invalid_parameter", "fair.relations[0]");
  expectError(server->post("/curves", json{{"name", "k"}, {"fair", {{"points", {{0, 0}, {1, 1}}}, {"colour", 1}}}}), 422,
              "invalid_document", "fair.colour");
  expectError(server->post("/curves", json{{"name", "d"}, {"fair", {{"points", {{0, 0}, {0, 0}}}}}}), 422,
              "invalid_parameter", "fair.points[1]");
  auto bulk = server->post("/curves/bulk",
                           "{\"name\":\"bf1\",\"fair\":{\"points\":[[0,0],[1,1],[2,0]]}}\n"
                           "{\"name\":\"bf2\",\"fair\":{\"points\":[[0,0]],\"closed\":true}}\n",
                           "application/x-ndjson");
  ASSERT_EQ(bulk.status, 200) << bulk.body;
  EXPECT_EQ(bulk.json["imported"], 1);
  ASSERT_EQ(bulk.json["errors"].size(), 1u);
  EXPECT_EQ(bulk.json["errors"][0]["error"]["path"], "fair.points");
  EXPECT_EQ(server->get("/health").json["curves"], before + 1);
}

// Each --max-fair-* option: a server started with a small value answers 413 naming it, both for
// POST /curves/fair and for a stored fair curve.
TEST(FairCurveLimitOptions, EachOptionAnswers413ByName) {
  ServerProcess small({"--max-fair-points", "3", "--max-fair-samples", "4", "--max-fair-angle-samples", "10",
                       "--max-fair-candidates", "2", "--max-fair-curve-points", "12"});
  const json four = {{0, 0}, {1, 1}, {2, 0}, {3, 1}}, three = {{0, 0}, {1, 1}, {2, 0}};
  struct Case {
    json request;
    std::string path, limit;
  };
  const Case cases[] = {
      {{{"points", four}}, "points", "max_fair_points=3"},
      {{{"points", three}, {"samples", 5}, {"max_candidates", 1}}, "samples", "max_fair_samples=4"},
      {{{"points", three}, {"angle_samples", 11}, {"max_candidates", 1}}, "angle_samples", "max_fair_angle_samples=10"},
      {{{"points", three}, {"max_candidates", 3}}, "max_candidates", "max_fair_candidates=2"},
      // 2 candidates x (2 pieces x (4 - 1) + 1) = 14 curve points > 12.
      {{{"points", three}, {"samples", 4}, {"max_candidates", 2}}, "samples", "max_fair_curve_points=12"},
  };
  for (const Case& c : cases) {
    for (const bool stored : {false, true}) {
      auto r = stored ? small.post("/curves", json{{"name", "f"}, {"fair", c.request}}) : small.post("/curves/fair", c.request);
      SCOPED_TRACE(c.limit + (stored ? " (stored)" : ""));
      expectError(r, 413, "limit_exceeded", stored ? "fair." + c.path : c.path);
      EXPECT_NE(r.json["error"]["message"].get<std::string>().find(c.limit), std::string::npos) << r.body;
    }
  }
  // Within every limit (2 x (2 x 2 + 1) = 10 curve points) both answer.
  const json ok = {{"points", three}, {"samples", 3}, {"max_candidates", 2}, {"angle_samples", 10}};
  EXPECT_EQ(small.post("/curves/fair", ok).status, 200);
  EXPECT_EQ(small.post("/curves", json{{"name", "ok"}, {"fair", ok}}).status, 201);
}

}  // namespace
