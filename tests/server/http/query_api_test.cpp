// POST /query/linguistic (docs/api.md §4) through the real `fsdb serve`, and `fsdb query`:
// ranking, limit, threshold, kind, scan, the index kept in step by PUT, DELETE and bulk import,
// a database made before the descriptor index, and every error of the request.
#include <gtest/gtest.h>

#include "db/migrations.h"
#include "db/sqlite.h"
#include "tests/server/server_process.h"

using fsdb::test::runFsdb;
using fsdb::test::ServerProcess;
using fsdb::test::TempDir;
using nlohmann::json;

namespace {

// bendness = min(1, |kv|·2C/π) with C = a1·a3 = 3 (query/linguistic/descriptors.h): kv 0.1 gives 0.19
// (slightly bent: 1), kv 0.05 gives 0.095 (slightly bent: 0.955), kv 0 gives 0.
json part(const std::string& name, double kv) {
  return {{"name", name}, {"params", {{"a1", 1}, {"a3", 3}, {"kv", kv}}}};
}

json query(const ServerProcess& server, json body, int status = 200) {
  auto r = server.post("/query/linguistic", body);
  EXPECT_EQ(r.status, status) << body.dump() << " -> " << r.body;
  return r.json;
}

std::vector<std::string> names(const json& answer) { return fsdb::test::resultNames(answer); }

int64_t create(const ServerProcess& server, const std::string& kind, const json& doc) {
  auto r = server.post("/" + kind + "s", doc);
  EXPECT_EQ(r.status, 201) << r.body;
  return r.json.value("id", int64_t{0});
}

TEST(QueryApi, RanksFiltersAndExplains) {
  ServerProcess server;
  create(server, "part", part("bent-rod", 0.1));
  const int64_t bitBent = create(server, "part", part("bit-bent", 0.05));
  create(server, "part", part("straight", 0));

  const json answer = query(server, {{"text", "find a slightly bent part"}});
  EXPECT_EQ(names(answer), (std::vector<std::string>{"bent-rod", "bit-bent"}));
  EXPECT_EQ(answer["parsed"]["subject"], "part");
  const json& best = answer["results"][0];
  EXPECT_EQ(best["kind"], "part");
  EXPECT_DOUBLE_EQ(best["score"].get<double>(), 1.0);
  EXPECT_GT(answer["results"][1]["score"].get<double>(), 0.9);
  EXPECT_LT(answer["results"][1]["score"].get<double>(), 1.0);
  ASSERT_FALSE(best["explain"].empty());
  EXPECT_TRUE(best["explain"][0].contains("text"));
  EXPECT_EQ(answer["scan"], false);

  // The full scan answers the same.
  json scanned = query(server, {{"text", "find a slightly bent part"}, {"scan", true}});
  EXPECT_EQ(scanned["results"], answer["results"]);
  EXPECT_EQ(scanned["scan"], true);
  EXPECT_LE(answer["candidates"].get<int>(), scanned["candidates"].get<int>());

  EXPECT_EQ(names(query(server, {{"text", "find a slightly bent part"}, {"limit", 1}})),
            std::vector<std::string>{"bent-rod"});
  EXPECT_EQ(names(query(server, {{"text", "find a slightly bent part"}, {"threshold", 0.99}})),
            std::vector<std::string>{"bent-rod"});
  EXPECT_TRUE(query(server, {{"text", "find a slightly bent part"}, {"kind", "shape"}})["results"].empty());
  // Nothing satisfies: 200 with no results.
  EXPECT_TRUE(query(server, {{"text", "find an extremely twisted part"}})["results"].empty());

  // DELETE takes it out of the index.
  EXPECT_EQ(server.del("/parts/" + std::to_string(bitBent)).status, 200);
  EXPECT_EQ(names(query(server, {{"text", "find a slightly bent part"}})), std::vector<std::string>{"bent-rod"});
}

TEST(QueryApi, ShapesFollowTheirReferencedParts) {
  ServerProcess server;
  const int64_t straight = create(server, "part", part("straight", 0));
  const int64_t frame = create(server, "shape", {{"name", "frame"},
                                                 {"tree", {{"op", "union"}, {"children", {{{"part", "straight"}},
                                                  {{"part", {{"params", {{"a1", 1}}}}}, {"transform", {{"translate", {3, 0, 0}}}}}}}}}});
  const json bentShapes = {{"text", "find a slightly bent shape"}, {"kind", "shape"}};
  EXPECT_TRUE(query(server, bentShapes)["results"].empty());
  // A new version of the referenced part bends the frame's first component.
  auto put = server.put("/parts/" + std::to_string(straight), part("straight", 0.1));
  ASSERT_EQ(put.status, 200) << put.body;
  const json answer = query(server, bentShapes);
  ASSERT_EQ(answer["results"].size(), 1u) << answer.dump();
  EXPECT_EQ(answer["results"][0]["id"], frame);
  EXPECT_EQ(answer["results"][0]["kind"], "shape");
  EXPECT_DOUBLE_EQ(answer["results"][0]["score"].get<double>(), 1.0);
  // Without a kind, the part itself and the shape (ties by id: the part was created first).
  EXPECT_EQ(names(query(server, {{"text", "find a slightly bent shape"}})),
            (std::vector<std::string>{"straight", "frame"}));
  EXPECT_EQ(query(server, {{"text", "find a slightly bent shape"}, {"scan", true}})["results"],
            query(server, {{"text", "find a slightly bent shape"}})["results"]);
}

TEST(QueryApi, BulkImportedPartsAreIndexed) {
  ServerProcess server;
  const std::string body = part("b1", 0.1).dump() + "\n" + part("b2", 0.05).dump() + "\n" + part("s", 0).dump() + "\n";
  auto r = server.post("/parts/bulk", body, "application/x-ndjson");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(names(query(server, {{"text", "find a slightly bent part"}})), (std::vector<std::string>{"b1", "b2"}));
  // Upserting new versions replaces the rows.
  const std::string again = part("b1", 0).dump() + "\n" + part("s", 0.1).dump() + "\n";
  ASSERT_EQ(server.post("/parts/bulk?mode=upsert", again, "application/x-ndjson").status, 200);
  EXPECT_EQ(names(query(server, {{"text", "find a slightly bent part"}})), (std::vector<std::string>{"s", "b2"}));
}

TEST(QueryApi, ADatabaseFromBeforeTheIndexIsBackfilled) {
  TempDir dir;
  const std::string db = dir.file("old.sqlite");
  {
    fsdb::sqlite::Connection c(db);
    ASSERT_EQ(fsdb::applyMigrations(c, {fsdb::embeddedMigrations().front()}), 1);
    c.exec("INSERT INTO objects (kind, name, latest_version) VALUES ('part', 'old-bent', 1)");
    auto s = c.prepare("INSERT INTO versions VALUES (1, 1, ?1, 'h', '2026-01-01T00:00:00.000Z')");
    s->bind(1, json{{"kind", "part"}, {"name", "old-bent"}, {"params", {{"a1", 1}, {"a3", 3}, {"kv", 0.1}}}}.dump());
    s->run();
  }
  ServerProcess server({"--db", db});
  EXPECT_EQ(names(query(server, {{"text", "find a slightly bent part"}})), std::vector<std::string>{"old-bent"});
  EXPECT_EQ(server.get("/health").json["schema_version"], fsdb::embeddedMigrations().back().first);
  fsdb::sqlite::Connection c(db);
  auto pending = c.prepare("SELECT COUNT(*) FROM descriptor_pending");
  ASSERT_TRUE(pending->step());
  EXPECT_EQ(pending->columnInt(0), 0);  // the backfill at startup cleared it
}

// A database indexed before the section descriptors (schema version 2): migration 003 marks its
// objects pending, and the startup backfill gives them rows for every descriptor.
TEST(QueryApi, ADatabaseFromBeforeTheSectionDescriptorsIsBackfilled) {
  TempDir dir;
  const std::string db = dir.file("v2.sqlite");
  {
    fsdb::sqlite::Connection c(db);
    const auto all = fsdb::embeddedMigrations();
    ASSERT_EQ(fsdb::applyMigrations(c, {all[0], all[1]}), 2);
    // Written by a version-2 server after its own backfill: not pending, and no section rows.
    c.exec("INSERT INTO objects (kind, name, latest_version) VALUES ('part', 'old-box', 1)");
    auto s = c.prepare("INSERT INTO versions VALUES (1, 1, ?1, 'h', '2026-01-01T00:00:00.000Z')");
    s->bind(1, json{{"kind", "part"}, {"name", "old-box"}, {"params", {{"a1", 1}, {"eps1", 0.1}, {"eps2", 0.1}}}}.dump());
    s->run();
  }
  ServerProcess server({"--db", db});
  EXPECT_EQ(names(query(server, {{"text", "find parts with a squarish cross-section"}})),
            std::vector<std::string>{"old-box"});
  fsdb::sqlite::Connection c(db);
  auto rows = c.prepare("SELECT COUNT(*) FROM descriptor_index WHERE descriptor = 'section-squariness'");
  ASSERT_TRUE(rows->step());
  EXPECT_EQ(rows->columnInt(0), 1);
  auto pending = c.prepare("SELECT COUNT(*) FROM descriptor_pending");
  ASSERT_TRUE(pending->step());
  EXPECT_EQ(pending->columnInt(0), 0);
}

// A stored document that no longer parses (here: a part without a1, written around the API) is
// skipped, with a warning on the log; the query still answers with every other object.
TEST(QueryApi, AnUnparsableStoredDocumentIsSkippedNotFatal) {
  TempDir dir;
  const std::string db = dir.file("bad.sqlite");
  {
    fsdb::sqlite::Connection c(db);
    ASSERT_EQ(fsdb::applyMigrations(c, fsdb::embeddedMigrations()), int(fsdb::embeddedMigrations().size()));
    c.exec("INSERT INTO objects (kind, name, latest_version) VALUES ('part', 'no-size', 1)");
    auto s = c.prepare("INSERT INTO versions VALUES (1, 1, ?1, 'h', '2026-01-01T00:00:00.000Z')");
    s->bind(1, json{{"kind", "part"}, {"name", "no-size"}, {"params", {{"kv", 0.1}}}}.dump());
    s->run();
  }
  ServerProcess server({"--db", db});
  ASSERT_EQ(server.post("/parts", part("bent", 0.1)).status, 201);
  for (const bool scan : {false, true})
    EXPECT_EQ(names(query(server, {{"text", "find a slightly bent part"}, {"scan", scan}})),
              std::vector<std::string>{"bent"});
}

TEST(QueryApi, Errors) {
  ServerProcess server;
  auto expectError = [&server](const std::string& body, int status, const std::string& code, const std::string& path) {
    auto r = server.post("/query/linguistic", body);
    EXPECT_EQ(r.status, status) << body << " -> " << r.body;
    EXPECT_EQ(r.json["error"]["code"], code) << body << " -> " << r.body;
    EXPECT_EQ(r.json["error"]["path"], path) << body << " -> " << r.body;
    return r.json["error"].value("message", "");
  };
  expectError("{}", 422, "invalid_document", "text");
  expectError(R"({"text":3})", 422, "invalid_document", "text");
  expectError(R"({"text":"find a part","limit":0})", 422, "invalid_parameter", "limit");
  expectError(R"({"text":"find a part","limit":1001})", 422, "invalid_parameter", "limit");
  expectError(R"({"text":"find a part","limit":2.5})", 422, "invalid_parameter", "limit");
  expectError(R"({"text":"find a part","threshold":1.5})", 422, "invalid_parameter", "threshold");
  expectError(R"({"text":"find a part","threshold":-0.1})", 422, "invalid_parameter", "threshold");
  expectError(R"({"text":"find a part","kind":"curve"})", 422, "invalid_parameter", "kind");
  expectError(R"({"text":"find a part","scan":"yes"})", 422, "invalid_document", "scan");
  expectError(R"({"text":"find a part","order":"name"})", 422, "invalid_document", "order");
  // A parse error names the position and the closest words.
  const std::string message = expectError(R"({"text":"find a slighly bent part"})", 422, "invalid_parameter", "text");
  EXPECT_NE(message.find("slightly"), std::string::npos) << message;
  EXPECT_EQ(server.post("/query/linguistic", std::string("{\"text\":")).status, 400);
  EXPECT_EQ(server.get("/query/linguistic").status, 405);
}

// A 5 MB unknown word cost 14 s of edit distances and came back whole in the 422; the
// suggestions are banded (geometry/core/closest_names.h) and the message quotes 100 characters.
TEST(QueryApi, AHugeUnknownWordIsRefusedWithAShortMessage) {
  ServerProcess server;
  const std::string word(5'000'000, 'q');
  auto r = server.post("/query/linguistic", json{{"text", "find a " + word + " cylinder"}});
  EXPECT_EQ(r.status, 422) << r.body.substr(0, 300);
  const std::string message = r.json["error"].value("message", "");
  EXPECT_LT(message.size(), 600u) << message.substr(0, 300);
  EXPECT_NE(message.find(std::string(100, 'q') + "... (5000000 characters)"), std::string::npos) << message.substr(0, 300);
  // The search box reads around it, and quotes it as briefly.
  auto box = server.post("/query", json{{"text", "find a " + word + " cylinder"}});
  ASSERT_EQ(box.status, 200) << box.body.substr(0, 300);
  EXPECT_LT(box.body.size(), 20000u);
  EXPECT_EQ(box.json["read_text"], "find a cylinder");
  EXPECT_EQ(box.json["ignored"][0]["word"], std::string(100, 'q') + "... (5000000 characters)");
  EXPECT_TRUE(box.json["ignored"][0]["did_you_mean"].empty());
  EXPECT_EQ(server.get("/health").status, 200);
}

TEST(QueryApi, QueryTimeLimit) {
  ServerProcess server({"--max-query-ms", "1"});
  std::string body;
  for (int i = 0; i < 3000; ++i) body += part("p" + std::to_string(i), 0.001 * (i % 100)).dump() + "\n";
  ASSERT_EQ(server.post("/parts/bulk", body, "application/x-ndjson").status, 200);
  // Scoring 3000 parts takes longer than 1 ms: 413 naming the limit, and the server keeps serving.
  auto r = server.post("/query/linguistic", json{{"text", "find shapes that are not twisted"}, {"scan", true}});
  EXPECT_EQ(r.status, 413) << r.body;
  EXPECT_EQ(r.json["error"]["code"], "limit_exceeded");
  EXPECT_NE(r.json["error"]["message"].get<std::string>().find("max_query_ms=1"), std::string::npos) << r.body;
  EXPECT_EQ(server.get("/health").status, 200);
}

TEST(QueryCli, DatabaseFileAndServer) {
  TempDir dir;
  const std::string db = dir.file("cli.sqlite");
  {
    ServerProcess server({"--db", db});
    create(server, "part", part("bent-rod", 0.1));
    create(server, "part", part("bit-bent", 0.05));
    create(server, "part", part("straight", 0));
    // Through the server: the same table as from the file below.
    const auto viaServer = runFsdb({"query", "find a slightly bent part", "--server",
                                    "http://" + server.host() + ":" + std::to_string(server.port())});
    EXPECT_EQ(viaServer.exitCode, 0) << viaServer.out;
    EXPECT_NE(viaServer.out.find("bent-rod"), std::string::npos) << viaServer.out;
    server.terminate();
    const auto viaFile = runFsdb({"query", "find a slightly bent part", "--db", db});
    EXPECT_EQ(viaFile.out, viaServer.out);
  }
  const auto table = runFsdb({"query", "find a slightly bent part", "--db", db});
  EXPECT_EQ(table.exitCode, 0);
  // header, then rank 1 bent-rod, rank 2 bit-bent
  EXPECT_NE(table.out.find("rank"), std::string::npos) << table.out;
  const size_t first = table.out.find("bent-rod"), second = table.out.find("bit-bent");
  EXPECT_TRUE(first != std::string::npos && second != std::string::npos && first < second) << table.out;
  EXPECT_EQ(table.out.find("straight"), std::string::npos) << table.out;

  const auto one = runFsdb({"query", "find a slightly bent part", "--db", db, "--limit", "1", "--json"});
  EXPECT_EQ(one.exitCode, 0);
  const json answer = json::parse(one.out);
  ASSERT_EQ(answer["results"].size(), 1u);
  EXPECT_EQ(answer["results"][0]["name"], "bent-rod");

  const auto none = runFsdb({"query", "find an extremely twisted part", "--db", db});
  EXPECT_EQ(none.exitCode, 0);
  EXPECT_EQ(none.out, "read as: find a part that is extremely twisted\nno results\n");

  const auto refused = runFsdb({"query", "find a slighly bent part", "--db", db}, true);
  EXPECT_EQ(refused.exitCode, 1) << refused.out;
  EXPECT_NE(refused.out.find("invalid_parameter"), std::string::npos) << refused.out;

  EXPECT_EQ(runFsdb({"query", "find a part", "--db", dir.file("missing.sqlite")}).exitCode, 2);
  EXPECT_EQ(runFsdb({"query", "find a part", "--server", "http://127.0.0.1:1"}).exitCode, 2);
}

}  // namespace
