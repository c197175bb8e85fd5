// kill -9 during a stream of bulk imports (SPEC §4 "atomic batches"; server/bulk_import.h): every
// batch the server acknowledged with 200 is there after a restart on the same file, no batch is
// there in part, and the SQLite file passes PRAGMA integrity_check.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <map>
#include <random>
#include <set>
#include <thread>

#include "db/store.h"
#include "tests/server/server_process.h"

using fsdb::test::ServerProcess;
using fsdb::test::TempDir;
using nlohmann::json;

namespace {

constexpr int kLinesPerBatch = 50;

std::string lineName(int round, int batch, int line) {
  return "r" + std::to_string(round) + "-b" + std::to_string(batch) + "-l" + std::to_string(line);
}

std::string batchBody(int round, int batch) {
  std::string body;
  for (int i = 0; i < kLinesPerBatch; ++i)
    body += json{{"kind", "part"}, {"name", lineName(round, batch, i)}, {"params", {{"a1", 1 + i % 5}}}}.dump() + "\n";
  return body;
}

// The names of one round present in the database, per batch: batch -> number of lines there.
std::map<int, int> presentLines(const ServerProcess& server, int round) {
  std::map<int, int> out;
  const std::string prefix = "r" + std::to_string(round) + "-b";
  std::string after;
  for (;;) {
    auto r = server.get("/parts?limit=1000" + (after.empty() ? "" : "&after=" + after));
    if (r.status != 200) throw std::runtime_error("list failed: " + r.body);
    for (const auto& item : r.json["items"]) {
      const std::string name = item["name"];
      if (name.rfind(prefix, 0) != 0) continue;
      ++out[std::stoi(name.substr(prefix.size()))];
    }
    if (r.json["next_after"].is_null()) break;
    after = std::to_string(r.json["next_after"].get<int64_t>());
  }
  return out;
}

TEST(Durability, KillNineDuringBulkImportsLosesNoAcknowledgedBatch) {
  TempDir dir;
  const std::string db = dir.file("durable.sqlite");
  std::mt19937 random(20261122);
  int totalAcknowledged = 0;
  for (int round = 0; round < 4; ++round) {
    ServerProcess server({"--db", db, "--threads", "4"});
    std::atomic<bool> stop{false};
    std::set<int> acknowledged;  // written by the client thread only, read after join
    std::set<int> sent;
    std::thread client([&] {
      httplib::Client c(server.host(), server.port());
      c.set_read_timeout(30, 0);
      for (int batch = 0; !stop.load(); ++batch) {
        sent.insert(batch);
        auto r = c.Post("/parts/bulk", batchBody(round, batch), "application/x-ndjson");
        if (!r) break;  // the server is gone
        if (r->status == 200) {
          const json report = json::parse(r->body);
          if (report["imported"] == kLinesPerBatch && report["failed"] == 0) acknowledged.insert(batch);
          else ADD_FAILURE() << "batch " << batch << ": " << r->body;
        } else {
          ADD_FAILURE() << "batch " << batch << " status " << r->status << ": " << r->body;
        }
      }
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(150 + random() % 400));
    server.kill9();
    stop = true;
    client.join();
    EXPECT_GT(acknowledged.size(), 0u) << "round " << round << ": no batch acknowledged before the kill";

    ServerProcess again({"--db", db});
    const std::map<int, int> present = presentLines(again, round);
    for (int batch : acknowledged) {
      auto it = present.find(batch);
      EXPECT_TRUE(it != present.end() && it->second == kLinesPerBatch)
          << "round " << round << " acknowledged batch " << batch << " has "
          << (it == present.end() ? 0 : it->second) << " lines";
      // Spot-check by name, as a client would.
      auto r = again.get("/parts?name=" + lineName(round, batch, kLinesPerBatch - 1));
      EXPECT_EQ(r.json["items"].size(), 1u) << r.body;
    }
    for (const auto& [batch, count] : present) {
      EXPECT_TRUE(sent.count(batch)) << "batch " << batch << " was never sent";
      EXPECT_EQ(count, kLinesPerBatch) << "round " << round << " batch " << batch << " is partial";
    }
    totalAcknowledged += static_cast<int>(acknowledged.size());
    EXPECT_EQ(again.terminate(), 0);
    auto store = fsdb::Store::open(db);
    EXPECT_EQ(store->integrityCheck(), "ok") << "round " << round;
  }
  std::cout << "[durability] acknowledged batches over all rounds: " << totalAcknowledged << std::endl;
}

TEST(Durability, KillNineWithoutCheckpointKeepsCommittedSinglesAndTheFileIsWhole) {
  TempDir dir;
  const std::string db = dir.file("wal.sqlite");
  std::vector<int64_t> ids;
  {
    ServerProcess server({"--db", db});
    for (int i = 0; i < 20; ++i) {
      auto r = server.post("/parts", json{{"kind", "part"}, {"name", "p" + std::to_string(i)}, {"params", {{"a1", 1}}}});
      ASSERT_EQ(r.status, 201) << r.body;
      ids.push_back(r.json["id"]);
    }
    server.kill9();  // no checkpoint: the rows live in the WAL
  }
  ServerProcess again({"--db", db});
  for (int64_t id : ids) EXPECT_EQ(again.get("/parts/" + std::to_string(id)).status, 200) << id;
  EXPECT_EQ(again.get("/health").json["parts"], 20);
}

}  // namespace
