// Several `fsdb serve` processes on one database (db/store.h: SQLite file or PostgreSQL; this suite
// runs on both, tests/CMakeLists.txt): a write through one server is seen through the other at
// once, even by the structural search's in-memory graphs; ETag / If-Match prevent lost updates;
// and a soak of 2 servers, 4 writers and 4 readers (60 s on PostgreSQL, 15 s on SQLite;
// FSDB_MULTI_SERVER_SECONDS to change)
// ends with no 5xx, no lost or duplicated version, and every search answer true of the versions
// it names.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include "tests/server/server_process.h"

using fsdb::test::ServerProcess;
using nlohmann::json;

namespace {

// A part of half-height 1.5 that is bent (kv 1) or straight (kv 0: "bent" scores it 0); `mark` names the
// write in meta, so each stored version can be traced to the request that made it.
json rod(const std::string& name, bool bent, const std::string& mark = "") {
  json params = {{"eps1", 0.1}, {"eps2", 1}, {"a1", 0.3}, {"a3", 1.5}, {"kv", bent ? 1.0 : 0.0}};
  return {{"kind", "part"}, {"name", name}, {"params", params}, {"meta", {{"write", mark}}}};
}

json sphere(const std::string& name) {
  return {{"kind", "part"}, {"name", name}, {"params", {{"eps1", 1}, {"eps2", 1}, {"a1", 1}, {"a2", 1}, {"a3", 1}}}};
}

json cylinder(const std::string& name) {
  return {{"kind", "part"}, {"name", name}, {"params", {{"eps1", 0.1}, {"eps2", 1}, {"a1", 1}, {"a3", 1.5}}}};
}

json unionOf(const std::string& name, const std::string& a, const std::string& b) {
  return {{"kind", "shape"},
          {"name", name},
          {"tree",
           {{"op", "union"},
            {"children", json::array({{{"part", a}}, {{"part", b}, {"transform", {{"translate", {3, 0, 0}}}}}})}}}};
}

double scoreOf(const json& answer, const std::string& name) {
  for (const json& r : answer["results"])
    if (r["name"] == name) return r["score"].get<double>();
  return -1;
}

TEST(MultiServer, AWriteThroughOneServerIsSeenThroughTheOtherAtOnce) {
  ServerProcess a;
  ServerProcess b({"--db", a.db()});
  ASSERT_EQ(a.post("/parts", cylinder("left")).status, 201);
  const auto right = a.post("/parts", cylinder("right"));
  ASSERT_EQ(right.status, 201);
  ASSERT_EQ(a.post("/shapes", unionOf("pair", "left", "right")).status, 201);
  EXPECT_EQ(b.get("/shapes?name=pair").json["items"].size(), 1u);

  const json query = {{"text", "the union of a sphere and a cylinder"}, {"limit", 10}};
  const auto before = b.post("/query/csg", query);  // builds b's graph cache
  ASSERT_EQ(before.status, 200) << before.body;
  const double was = scoreOf(before.json, "pair");
  ASSERT_GT(was, 0);

  // Through a: the right leaf becomes a sphere. b's cached graph of "pair" is stale now.
  const int64_t id = right.json["id"];
  ASSERT_EQ(a.put("/parts/" + std::to_string(id), sphere("right")).status, 200);
  const auto after = b.post("/query/csg", query);
  ASSERT_EQ(after.status, 200) << after.body;
  EXPECT_GT(scoreOf(after.json, "pair"), was);
  // The same answer as a server that never saw the old version.
  ServerProcess c({"--db", a.db()});
  EXPECT_EQ(after.json["results"], c.post("/query/csg", query).json["results"]);

  // Deleted through a: gone from b's answers at once.
  ASSERT_EQ(a.del("/shapes/" + std::to_string(a.get("/shapes?name=pair").json["items"][0]["id"].get<int64_t>())).status,
            200);
  EXPECT_EQ(scoreOf(b.post("/query/csg", query).json, "pair"), -1);
  // And the linguistic search through b sees a new bent part written through a.
  ASSERT_EQ(a.post("/parts", rod("hook", true)).status, 201);
  const auto bent = b.post("/query/linguistic", json{{"text", "find a bent part"}});
  ASSERT_EQ(bent.status, 200) << bent.body;
  ASSERT_EQ(bent.json["results"].size(), 1u) << bent.body;  // the cylinders are straight
  EXPECT_EQ(bent.json["results"][0]["name"], "hook");
}

TEST(MultiServer, IfMatchRefusesAWriteBasedOnAnOldVersion) {
  ServerProcess a;
  ServerProcess b({"--db", a.db()});
  const auto created = a.post("/parts", rod("bar", false));
  ASSERT_EQ(created.status, 201);
  const std::string path = "/parts/" + std::to_string(created.json["id"].get<int64_t>());
  auto ca = a.client(), cb = b.client();
  auto got = cb.Get(path.c_str());
  ASSERT_TRUE(got);
  EXPECT_EQ(got->get_header_value("ETag"), "\"1\"");
  auto cached = cb.Get(path.c_str(), httplib::Headers{{"If-None-Match", "\"1\""}});
  EXPECT_EQ(cached->status, 304);

  // Two clients read version 1; the first PUT wins, the second is 412 and writes nothing.
  auto first =
      ca.Put(path.c_str(), httplib::Headers{{"If-Match", "\"1\""}}, rod("bar", true).dump(), "application/json");
  ASSERT_EQ(first->status, 200) << first->body;
  EXPECT_EQ(first->get_header_value("ETag"), "\"2\"");
  auto second =
      cb.Put(path.c_str(), httplib::Headers{{"If-Match", "\"1\""}}, rod("bar", false).dump(), "application/json");
  ASSERT_EQ(second->status, 412) << second->body;
  const json error = json::parse(second->body)["error"];
  EXPECT_EQ(error["code"], "precondition_failed");
  EXPECT_EQ(error["path"], "If-Match");
  EXPECT_NE(error["message"].get<std::string>().find("its ETag is now \"2\""), std::string::npos) << error;
  EXPECT_EQ(a.get(path).json["version"], 2);

  // Weak tags never match (strong comparison); "*" and a list holding the current tag do.
  EXPECT_EQ(
      cb.Put(path.c_str(), httplib::Headers{{"If-Match", "W/\"2\""}}, rod("bar", false).dump(), "application/json")
          ->status,
      412);
  EXPECT_EQ(
      cb.Put(path.c_str(), httplib::Headers{{"If-Match", "\"1\", \"2\""}}, rod("bar", false).dump(), "application/json")
          ->status,
      200);
  EXPECT_EQ(
      cb.Put(path.c_str(), httplib::Headers{{"If-Match", "*"}}, rod("bar", true).dump(), "application/json")->status,
      200);
  EXPECT_EQ(cb.Delete(path.c_str(), httplib::Headers{{"If-Match", "\"3\""}})->status, 412);
  EXPECT_EQ(cb.Delete(path.c_str(), httplib::Headers{{"If-Match", "\"4\""}})->status, 200);
  EXPECT_EQ(a.get(path).status, 404);
}

TEST(MultiServer, TwoServersFourWritersFourReaders) {
  // 60 s on PostgreSQL, the backend several servers are meant to share; 15 s on one SQLite file.
  const char* seconds = std::getenv("FSDB_MULTI_SERVER_SECONDS");
  const auto duration =
      std::chrono::seconds(seconds ? std::atoi(seconds) : fsdb::test::suiteBackend() == "postgresql" ? 60 : 15);
  ServerProcess a({"--threads", "8"});
  ServerProcess b({"--db", a.db(), "--threads", "8"});
  const ServerProcess* servers[2] = {&a, &b};
  constexpr int kWriters = 4, kReaders = 4;

  std::map<std::string, int64_t> ids;  // every part written, by name
  for (int w = 0; w < kWriters; ++w)
    for (const char* own : {"a", "b"}) {
      const std::string name = "w" + std::to_string(w) + "-" + own;
      ids[name] = a.post("/parts", rod(name, false, "create")).json["id"];
    }
  ids["contended"] = a.post("/parts", rod("contended", false, "create")).json["id"];
  for (const auto& [name, id] : ids) ASSERT_GT(id, 0) << name;

  std::mutex mutex;
  std::map<int64_t, std::map<int, std::string>> acknowledged;  // id -> version -> mark of the PUT
  std::set<std::pair<int64_t, int>> answered;                  // (id, version) a search called bent
  std::vector<std::string> failures;
  std::atomic<int> serverErrors{0}, requests{0}, preconditionFailed{0}, searches{0}, shapes{0};
  const auto fail = [&](const std::string& what) {
    std::lock_guard<std::mutex> lock(mutex);
    if (failures.size() < 20) failures.push_back(what);
  };
  // A request's answer, counted; nullptr (and a failure) for a transport error or a 5xx.
  const auto answer = [&](const httplib::Result& r, const std::string& what) -> const httplib::Response* {
    ++requests;
    if (!r) {
      fail(what + ": " + httplib::to_string(r.error()));
      return nullptr;
    }
    if (r->status >= 500) {
      ++serverErrors;
      fail(what + ": " + std::to_string(r->status) + " " + r->body);
      return nullptr;
    }
    return &*r;
  };
  const auto deadline = std::chrono::steady_clock::now() + duration;

  std::vector<std::thread> threads;
  for (int w = 0; w < kWriters; ++w)
    threads.emplace_back([&, w] {
      httplib::Client writes = servers[w % 2]->client(), reads = servers[(w + 1) % 2]->client();
      for (int i = 0; std::chrono::steady_clock::now() < deadline; ++i) {
        const bool contended = i % 3 == 2;
        const std::string name = contended ? "contended" : "w" + std::to_string(w) + (i % 2 ? "-b" : "-a");
        const std::string path = "/parts/" + std::to_string(ids[name]);
        const std::string mark = "w" + std::to_string(w) + "-" + std::to_string(i);
        // Read, then write on what was read (If-Match); a 412 means another writer came first.
        const auto read = reads.Get(path.c_str());
        const httplib::Response* current = answer(read, "GET " + path);
        if (!current) continue;
        const std::string tag = current->get_header_value("ETag");
        const auto put = writes.Put(path.c_str(), httplib::Headers{{"If-Match", tag}},
                                    rod(name, i % 4 < 2, mark).dump(), "application/json");
        const httplib::Response* written = answer(put, "PUT " + path);
        if (!written) continue;
        if (written->status == 412) {
          ++preconditionFailed;
          if (!contended) fail("412 on " + name + ", which only writer " + std::to_string(w) + " writes");
          continue;
        }
        if (written->status != 200) {
          fail("PUT " + path + ": " + std::to_string(written->status) + " " + written->body);
          continue;
        }
        const json body = json::parse(written->body, nullptr, false);
        if (!body.is_object() || !body.contains("version")) {
          fail("PUT " + path + " answered 200 with " + std::to_string(written->body.size()) +
               " bytes: " + written->body.substr(0, 80) + " (" + written->get_header_value("Content-Encoding") + ")");
          continue;
        }
        const int version = body["version"];
        {
          std::lock_guard<std::mutex> lock(mutex);
          if (!acknowledged[ids[name]].emplace(version, mark).second)
            failures.push_back("version " + std::to_string(version) + " of " + name + " acknowledged twice");
        }
        // Read-your-write through the other server, at once.
        const auto reread = reads.Get(path.c_str());
        const httplib::Response* seen = answer(reread, "GET " + path + " after PUT");
        if (seen && json::parse(seen->body, nullptr, false).value("version", 0) < version)
          fail("the other server read " + name + " older than the version just written");
        // Now and then a new shape through one server, found by name through the other.
        if (i % 10 == 0) {
          const std::string shape = "w" + std::to_string(w) + "-s" + std::to_string(i);
          const auto post = writes.Post(
              "/shapes", unionOf(shape, "w" + std::to_string(w) + "-a", "w" + std::to_string(w) + "-b").dump(),
              "application/json");
          const httplib::Response* made = answer(post, "POST /shapes");
          if (made && made->status == 201) {
            ++shapes;
            const auto byName = reads.Get(("/shapes?name=" + shape).c_str());
            const httplib::Response* found = answer(byName, "GET /shapes?name");
            if (found && json::parse(found->body, nullptr, false).value("items", json::array()).size() != 1)
              fail("shape " + shape + " not found through the other server");
          }
        }
      }
    });
  for (int r = 0; r < kReaders; ++r)
    threads.emplace_back([&, r] {
      httplib::Client client = servers[r % 2]->client();
      for (int i = 0; std::chrono::steady_clock::now() < deadline; ++i) {
        if (i % 4 == 3) {  // the structural search, whose graphs must follow the other server's writes
          const auto csg = client.Post(
              "/query/csg", json{{"text", "the union of a bent cylinder and a cylinder"}}.dump(), "application/json");
          const httplib::Response* found = answer(csg, "POST /query/csg");
          if (found && found->status != 200) fail("query/csg: " + std::to_string(found->status) + " " + found->body);
          continue;
        }
        const auto linguistic = client.Post(
            "/query/linguistic", json{{"text", "find a bent part"}, {"limit", 50}}.dump(), "application/json");
        const httplib::Response* found = answer(linguistic, "POST /query/linguistic");
        if (!found) continue;
        if (found->status != 200) {
          fail("query/linguistic: " + std::to_string(found->status) + " " + found->body);
          continue;
        }
        ++searches;
        std::lock_guard<std::mutex> lock(mutex);
        const json body = json::parse(found->body, nullptr, false);
        if (!body.contains("results")) {
          failures.push_back("query/linguistic answered 200 with " + found->body.substr(0, 80));
          continue;
        }
        for (const json& hit : body["results"]) answered.emplace(hit["id"], hit["version"]);
      }
    });
  for (std::thread& t : threads) t.join();

  EXPECT_EQ(serverErrors.load(), 0);
  for (const std::string& f : failures) ADD_FAILURE() << f;
  // No lost and no duplicated version: every object's versions 2..latest are exactly the PUTs that
  // were answered 200, each holding the document its PUT sent.
  for (const auto& [name, id] : ids) {
    const json latest = a.get("/parts/" + std::to_string(id)).json;
    const auto& versions = acknowledged[id];
    ASSERT_EQ(latest["version"].get<int>(), static_cast<int>(versions.size()) + 1) << name;
    for (const auto& [version, mark] : versions) {
      const json stored = b.get("/parts/" + std::to_string(id) + "?version=" + std::to_string(version)).json;
      EXPECT_EQ(stored["document"]["meta"]["write"], mark) << name << " version " << version;
    }
  }
  // Every search answer is true of the version it names (versions never change once written).
  for (const auto& [id, version] : answered) {
    const json stored = a.get("/parts/" + std::to_string(id) + "?version=" + std::to_string(version)).json;
    EXPECT_EQ(stored["document"]["params"]["kv"], 1.0)
        << "a search called part " << id << " version " << version << " bent";
  }
  EXPECT_GT(acknowledged[ids["contended"]].size(), 10u);
  EXPECT_GT(searches.load(), 10);
  std::cout << "multi-server: " << requests.load() << " requests in " << duration.count() << " s, "
            << preconditionFailed.load() << " writes refused by If-Match, " << searches.load() << " searches, "
            << shapes.load() << " shapes created, " << answered.size() << " (part, version) answers checked\n";
}

}  // namespace
