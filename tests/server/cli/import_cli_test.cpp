// `fsdb import FILE --db PATH | --server URL` and `fsdb eval ID --db PATH` (docs/api.md §1) on the
// real binary: the last stdout line "imported N, failed M", the exit status, the same counts
// through a running server, and volumes printed by eval. The databases are files, or PostgreSQL
// schemas in the suite's postgresql.* run (tests/db/test_database.h storeLocation).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <thread>

#include "tests/server/server_process.h"

using fsdb::test::runFsdb;
using fsdb::test::ServerProcess;
using fsdb::test::TempDir;
using nlohmann::json;

namespace {

std::string lastLine(const std::string& out) {
  std::string text = out;
  while (!text.empty() && text.back() == '\n') text.pop_back();
  const size_t nl = text.rfind('\n');
  return nl == std::string::npos ? text : text.substr(nl + 1);
}

void writeFile(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// Three parts, two shapes (one by csg text), and one bad line (an unknown reference).
std::string catalogue(bool withBadLine) {
  std::string s;
  s += json{{"kind", "part"}, {"name", "A"}, {"params", {{"a1", 1}}}}.dump() + "\n";
  s += json{{"kind", "part"},
            {"name", "B"},
            {"params", {{"a1", {{"tri", {0.4, 0.5, 0.6}}}}}},
            {"transform", {{"translate", {1, 0, 0}}}}}
           .dump() +
       "\n";
  s += "\n";
  if (withBadLine) s += json{{"kind", "shape"}, {"name", "bad"}, {"tree", {{"part", "missing"}}}}.dump() + "\n";
  s += json{{"kind", "shape"},
            {"name", "AB"},
            {"tree", {{"op", "union"}, {"children", {{{"part", "A"}}, {{"part", "B"}}}}}}}
           .dump() +
       "\n";
  s += json{{"kind", "part"}, {"name", "C"}, {"params", {{"a1", 0.5}}}}.dump() + "\n";
  s += json{{"kind", "shape"}, {"name", "D"}, {"csg", "D = AB - C"}}.dump() + "\n";
  return s;
}

TEST(ImportCli, IntoADatabaseFile) {
  TempDir dir;
  const std::string file = dir.file("catalogue.jsonl"), db = fsdb::test::storeLocation(dir, "cli.sqlite");
  writeFile(file, catalogue(true));
  auto withBad = runFsdb({"import", file, "--db", db});
  EXPECT_EQ(withBad.exitCode, 1) << withBad.out;
  EXPECT_EQ(lastLine(withBad.out), "imported 5, failed 1") << withBad.out;

  // Good lines only, into a fresh file: exit 0.
  const std::string good = dir.file("good.jsonl"), db2 = fsdb::test::storeLocation(dir, "cli2.sqlite");
  writeFile(good, catalogue(false));
  auto clean = runFsdb({"import", good, "--db", db2});
  EXPECT_EQ(clean.exitCode, 0) << clean.out;
  EXPECT_EQ(lastLine(clean.out), "imported 5, failed 0") << clean.out;
  // The same file again: every name is taken (mode create).
  auto again = runFsdb({"import", good, "--db", db2});
  EXPECT_EQ(again.exitCode, 1) << again.out;
  EXPECT_EQ(lastLine(again.out), "imported 0, failed 5") << again.out;
  // A file that does not exist.
  EXPECT_EQ(runFsdb({"import", dir.file("nope.jsonl"), "--db", db2}).exitCode, 2);

  // What was imported is served.
  ServerProcess server({"--db", db});
  auto h = server.get("/health");
  EXPECT_EQ(h.json["parts"], 3);
  EXPECT_EQ(h.json["shapes"], 2);
  EXPECT_TRUE(server.get("/shapes?name=bad").json["items"].empty());
}

TEST(ImportCli, MixedFilesTakeCurvesAndSurfaces) {
  TempDir dir;
  const std::string file = dir.file("curves.jsonl"), db = fsdb::test::storeLocation(dir, "curves.sqlite");
  std::string s = json{{"kind", "part"}, {"name", "A"}, {"params", {{"a1", 1}}}}.dump() + "\n";
  s += json{{"kind", "curve"}, {"name", "arc"}, {"bezier", {{"control_points", {{0, 0}, {{{"tri", {0, 1, 2}}}, 1}}}}}}
           .dump() +
       "\n";
  s += json{{"kind", "surface"}, {"name", "patch"}, {"bezier", {{"control_grid", {{{0, 0, 0}}}}}}}.dump() + "\n";
  s += json{{"kind", "volume"}, {"name", "x"}}.dump() + "\n";
  writeFile(file, s);
  auto r = runFsdb({"import", file, "--db", db});
  EXPECT_EQ(lastLine(r.out), "imported 3, failed 1") << r.out;
  ServerProcess server({"--db", db});
  EXPECT_EQ(server.get("/health").json["curves"], 1);
  EXPECT_EQ(server.get("/curves?name=arc").json["items"].size(), 1u);
  EXPECT_EQ(server.get("/surfaces?name=patch").json["items"].size(), 1u);
}

TEST(ImportCli, ThroughARunningServerGivesTheSameCounts) {
  TempDir dir;
  const std::string file = dir.file("catalogue.jsonl");
  writeFile(file, catalogue(true));
  ServerProcess server({"--db", fsdb::test::storeLocation(dir, "srv.sqlite"), "--token", "tok"});
  const std::string url = "http://" + server.host() + ":" + std::to_string(server.port());
  auto noToken = runFsdb({"import", file, "--server", url});
  EXPECT_NE(noToken.exitCode, 0) << noToken.out;
  EXPECT_EQ(server.get("/health").json["parts"], 0);
  auto r = runFsdb({"import", file, "--server", url, "--token", "tok"});
  EXPECT_EQ(r.exitCode, 1) << r.out;
  EXPECT_EQ(lastLine(r.out), "imported 5, failed 1") << r.out;
  auto h = server.get("/health");
  EXPECT_EQ(h.json["parts"], 3);
  EXPECT_EQ(h.json["shapes"], 2);
  EXPECT_EQ(runFsdb({"import", file, "--server", "http://127.0.0.1:1", "--token", "tok"}).exitCode, 2);
}

// --max-errors lists the first failed lines of a file and counts the rest, into a database and
// through a server alike; an array file through a server keeps its element numbers.
TEST(ImportCli, MaxErrorsListsTheFirstFailuresAndCountsTheRest) {
  TempDir dir;
  const std::string lines = dir.file("bad.jsonl"), array = dir.file("bad.json");
  std::string text;
  for (int i = 1; i <= 7; ++i)
    text += (i == 4 ? json{{"kind", "part"}, {"name", "ok"}, {"params", {{"a1", 1}}}}.dump() : "0") + "\n";
  writeFile(lines, text);
  writeFile(array, "[0,\n 0,\n {\"kind\":\"part\",\"name\":\"ok2\",\n  \"params\":{\"a1\":1}}, 0]");
  ServerProcess server({"--db", fsdb::test::storeLocation(dir, "srv.sqlite")});
  const std::string url = "http://" + server.host() + ":" + std::to_string(server.port());
  for (const std::vector<std::string>& target :
       {std::vector<std::string>{"--db", fsdb::test::storeLocation(dir, "direct.sqlite")},
        std::vector<std::string>{"--server", url}}) {
    std::vector<std::string> args = {"import", lines, "--max-errors", "2", "--batch", "2"};
    args.insert(args.end(), target.begin(), target.end());
    auto r = runFsdb(args, true);
    EXPECT_EQ(r.exitCode, 1) << r.out;
    EXPECT_EQ(lastLine(r.out), "imported 1, failed 6") << r.out;
    EXPECT_NE(r.out.find("bad.jsonl:1: invalid_document"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("bad.jsonl:2: invalid_document"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("bad.jsonl:3:"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("bad.jsonl: 4 more failed lines not listed"), std::string::npos) << r.out;
    args = {"import", array};
    args.insert(args.end(), target.begin(), target.end());
    r = runFsdb(args, true);
    EXPECT_EQ(lastLine(r.out), "imported 1, failed 3") << r.out;
    EXPECT_NE(r.out.find("bad.json:4: invalid_document"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("not listed"), std::string::npos) << r.out;
  }
}

// Curves and surfaces go to their own bulk routes through a server, as into a file (before, every
// line that was no shape went to /parts/bulk and failed there).
TEST(ImportCli, CurvesAndSurfacesThroughAServerAsIntoAFile) {
  TempDir dir;
  const std::string file = dir.file("mixed.jsonl");
  std::string lines;
  lines += json{{"kind", "part"}, {"name", "P"}, {"params", {{"a1", 1}}}}.dump() + "\n";
  lines += json{{"kind", "curve"},
                {"name", "wave"},
                {"bezier", {{"control_points", {{0, 0}, {1, {{"tri", {1.5, 2, 2.5}}}}, {3, 0}}}}}}
               .dump() +
           "\n";
  lines += json{{"kind", "surface"},
                {"name", "patch"},
                {"bezier", {{"control_grid", {{{0, 0, 0}, {1, 0, 1}}, {{0, 1, 0}, {1, 1, {{"tri", {0, 0.5, 1}}}}}}}}}}
               .dump() +
           "\n";
  lines += json{{"kind", "curve"}, {"name", "fair"}, {"fair", {{"points", {{0, 0}, {2, 1}, {4, 0}}}}}}.dump() + "\n";
  writeFile(file, lines);
  auto direct = runFsdb({"import", file, "--db", fsdb::test::storeLocation(dir, "direct.sqlite")});
  EXPECT_EQ(lastLine(direct.out), "imported 4, failed 0") << direct.out;
  ServerProcess server({"--db", fsdb::test::storeLocation(dir, "served.sqlite")});
  const std::string url = "http://" + server.host() + ":" + std::to_string(server.port());
  auto served = runFsdb({"import", file, "--server", url});
  EXPECT_EQ(served.exitCode, 0) << served.out;
  EXPECT_EQ(lastLine(served.out), "imported 4, failed 0") << served.out;
  const json health = server.get("/health").json;
  EXPECT_EQ(health["parts"], 1);
  EXPECT_EQ(health["curves"], 2);
  EXPECT_EQ(health["surfaces"], 1);
}

TEST(ImportCli, IntoTheFileOfARunningServerWhileItWrites) {
  TempDir dir;
  const std::string file = dir.file("many.jsonl"), db = fsdb::test::storeLocation(dir, "shared.sqlite");
  std::string lines;
  for (int i = 0; i < 300; ++i)
    lines += json{{"kind", "part"}, {"name", "imp" + std::to_string(i)}, {"params", {{"a1", 1}}}}.dump() + "\n";
  writeFile(file, lines);
  ServerProcess server({"--db", db});
  std::thread writer([&] {
    for (int i = 0; i < 30; ++i)
      EXPECT_EQ(
          server.post("/parts", json{{"kind", "part"}, {"name", "w" + std::to_string(i)}, {"params", {{"a1", 1}}}})
              .status,
          201);
  });
  auto r = runFsdb({"import", file, "--db", db, "--batch", "20"});
  writer.join();
  EXPECT_EQ(r.exitCode, 0) << r.out;
  EXPECT_EQ(lastLine(r.out), "imported 300, failed 0") << r.out;
  EXPECT_EQ(server.get("/health").json["parts"], 330);
}

TEST(EvalCli, PrintsTheVolumesOfAStoredShape) {
  TempDir dir;
  const std::string file = dir.file("catalogue.jsonl"), db = fsdb::test::storeLocation(dir, "eval.sqlite");
  writeFile(file, catalogue(false));
  ASSERT_EQ(runFsdb({"import", file, "--db", db}).exitCode, 0);
  int64_t id = 0;
  {
    ServerProcess server({"--db", db});
    auto s = server.get("/shapes?name=AB");
    ASSERT_EQ(s.json["items"].size(), 1u) << s.body;
    id = s.json["items"][0]["id"];
    EXPECT_EQ(server.terminate(), 0);
  }
  auto r = runFsdb({"eval", std::to_string(id), "--db", db, "--resolution", "32", "--alphas", "0,1"});
  ASSERT_EQ(r.exitCode, 0) << r.out;
  const json out = json::parse(r.out, nullptr, false);
  ASSERT_TRUE(out.is_object()) << r.out;
  ASSERT_EQ(out["alphas"].size(), 2u) << r.out;
  for (const auto& level : out["alphas"]) {
    const double lower = level["lower_volume"], upper = level["upper_volume"];
    EXPECT_GT(lower, 4.0) << level;  // at least the unit ball A (4.19)
    EXPECT_LE(lower, upper) << level;
  }
  EXPECT_LT(out["alphas"][0]["lower_volume"].get<double>(), out["alphas"][0]["upper_volume"].get<double>());
  EXPECT_NE(runFsdb({"eval", "999999", "--db", db}).exitCode, 0);
}

}  // namespace
