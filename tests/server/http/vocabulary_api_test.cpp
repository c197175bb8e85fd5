// GET /vocabulary and `fsdb serve --vocabulary FILE` on the real server; parts from words over
// HTTP use the active vocabulary.
#include <gtest/gtest.h>

#include <fstream>

#include "tests/db/temp_dir.h"
#include "tests/server/server_process.h"

using fsdb::test::ServerProcess;
using nlohmann::json;

namespace {

json schemaVocabulary() {
  std::ifstream in(std::string(FSDB_SOURCE_DIR) + "/schema/vocabulary.json");
  return json::parse(in);
}

TEST(VocabularyApi, ServesTheBuiltinVocabulary) {
  ServerProcess server;
  const auto r = server.get("/vocabulary");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json, schemaVocabulary());
  EXPECT_EQ(r.json["directions"]["primary"].size(), 6u);
  EXPECT_EQ(r.json["directions"]["secondary"].size(), 12u);
}

TEST(VocabularyApi, PartsFromWords) {
  ServerProcess server;
  auto r = server.post("/parts", json{{"kind", "part"}, {"name", "p"}, {"text", "a slightly bent cylinder"}});
  ASSERT_EQ(r.status, 201) << r.body;
  r = server.post("/evaluate", json{{"shape", {{"kind", "part"}, {"text", "a very round sphere"}}}, {"resolution", 16}});
  ASSERT_EQ(r.status, 200) << r.body;
  r = server.post("/parts", json{{"kind", "part"}, {"name", "q"}, {"text", "a slightly bnet cylinder"}});
  EXPECT_EQ(r.status, 422);
  EXPECT_EQ(r.json["error"]["path"], "text");
  EXPECT_NE(r.json["error"]["message"].get<std::string>().find("closest known words: bent"), std::string::npos)
      << r.body;
}

TEST(VocabularyApi, LeavesPlacedByWords) {
  ServerProcess server;
  json shape = {{"kind", "shape"},
                {"name", "ball-above"},
                {"tree",
                 {{"op", "union"},
                  {"children",
                   {{{"part", {{"name", "base"}, {"text", "a box"}}}},
                    {{"part", {{"text", "a sphere"}}},
                     {"transform", {{"place", {{"relative_to", "base"}, {"direction", "above"}, {"distance", "about 3"}}}}}}}}}}};
  auto r = server.post("/shapes", shape);
  ASSERT_EQ(r.status, 201) << r.body;
  r = server.post("/shapes/" + std::to_string(r.json["id"].get<int>()) + "/evaluate", json{{"resolution", 24}});
  ASSERT_EQ(r.status, 200) << r.body;
  shape["name"] = "ball-lost";
  shape["tree"]["children"][1]["transform"]["place"]["relative_to"] = "bse";
  r = server.post("/shapes", shape);
  EXPECT_EQ(r.status, 422);
  EXPECT_EQ(r.json["error"]["path"], "tree.children[1].transform.place.relative_to") << r.body;
}

// The built-in vocabulary with one more noun, "egg", written by a user.
json eggVocabulary() {
  json doc = schemaVocabulary();
  doc["nouns"]["egg"] = {{"plural", "eggs"},
                         {"conditions", {{"roundness", {{"trap", {0.7, 0.9, 1, 1}}}}}},
                         {"params", {{"eps1", 1}, {"eps2", 1}, {"a1", 1}, {"a3", 1.3}}}};
  return doc;
}

TEST(VocabularyApi, ExtendedVocabularyFile) {
  fsdb::TempDir dir;
  const json doc = eggVocabulary();
  const std::string file = dir.file("my-vocabulary.json");
  std::ofstream(file) << doc.dump();
  ServerProcess server({"--vocabulary", file});
  auto r = server.get("/vocabulary");
  ASSERT_EQ(r.status, 200);
  EXPECT_TRUE(r.json["nouns"].contains("egg"));
  r = server.post("/parts", json{{"kind", "part"}, {"name", "e"}, {"text", "a slightly twisted egg"}});
  EXPECT_EQ(r.status, 201) << r.body;
  // The built-in server does not know the word.
  ServerProcess plain;
  EXPECT_EQ(plain.post("/parts", json{{"kind", "part"}, {"name", "e"}, {"text", "an egg"}}).status, 422);
}

// `fsdb query --db` and `fsdb eval` parse words too, so they take the same --vocabulary FILE.
TEST(VocabularyApi, QueryAndEvalTakeTheVocabularyFile) {
  fsdb::TempDir dir;
  const json doc = eggVocabulary();
  const std::string file = dir.file("eggs.json"), db = dir.file("db.sqlite");
  std::ofstream(file) << doc.dump();
  {
    ServerProcess server({"--vocabulary", file, "--db", db});
    ASSERT_EQ(server.post("/parts", json{{"kind", "part"}, {"name", "e"}, {"text", "an egg"}}).status, 201);
  }
  const auto found = fsdb::test::runFsdb({"query", "find an egg", "--db", db, "--vocabulary", file, "--json"});
  ASSERT_EQ(found.exitCode, 0) << found.out;
  const json answer = json::parse(found.out);
  ASSERT_EQ(answer["results"].size(), 1u) << found.out;
  EXPECT_EQ(answer["results"][0]["name"], "e");
  EXPECT_EQ(fsdb::test::runFsdb({"query", "find an egg", "--db", db}, true).exitCode, 1);  // built-in: unknown word

  const std::string part = dir.file("egg.json");
  std::ofstream(part) << json{{"kind", "part"}, {"name", "e"}, {"text", "a slightly bent egg"}}.dump();
  EXPECT_EQ(fsdb::test::runFsdb({"eval", part, "--resolution", "16", "--vocabulary", file}).exitCode, 0);
  EXPECT_NE(fsdb::test::runFsdb({"eval", part, "--resolution", "16"}, true).exitCode, 0);
  EXPECT_EQ(fsdb::test::runFsdb({"eval", part, "--vocabulary", dir.file("missing.json")}, true).exitCode, 1);
}

TEST(VocabularyApi, BadVocabularyFileStopsTheStart) {
  fsdb::TempDir dir;
  json doc = schemaVocabulary();
  doc["adjectives"]["bent"]["descriptor"] = "bentness";
  const std::string file = dir.file("bad.json");
  std::ofstream(file) << doc.dump();
  const auto r = fsdb::test::runFsdb({"serve", "--port", "0", "--db", dir.file("db.sqlite"), "--vocabulary", file}, true);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.out.find("adjectives.bent.descriptor"), std::string::npos) << r.out;
  EXPECT_EQ(fsdb::test::runFsdb({"serve", "--port", "0", "--db", dir.file("db.sqlite"), "--vocabulary",
                                 dir.file("missing.json")})
                .exitCode,
            1);
}

}  // namespace
