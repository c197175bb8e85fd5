#pragma once
// TestDatabase: a fresh, empty database on one backend, for suites that run on both (db/store.h).
// - "sqlite": a file in a TempDir (removed at destruction).
// - "postgresql": a schema of its own, named after the process and a counter, on the cluster at
//   $FSDB_TEST_POSTGRES_URL (make test starts one with scripts/pg-test-cluster); the cluster is
//   thrown away with its schemas. Without that variable the PostgreSQL cases are skipped, except
//   under CI=true, where they fail: CI must never pass by not running them.
// kBackends lists both for INSTANTIATE_TEST_SUITE_P; FSDB_USE_BACKEND(backend) goes first in SetUp.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>

#include <unistd.h>

#include "db/postgres.h"
#include "db/sql.h"
#include "db/sqlite.h"
#include "tests/db/temp_dir.h"

namespace fsdb::test {

inline const std::string kBackends[] = {"sqlite", "postgresql"};

// The cluster's URL, or "" when none was given.
inline std::string postgresTestUrl() {
  const char* url = std::getenv("FSDB_TEST_POSTGRES_URL");
  return url ? url : "";
}

// Skips (or under CI fails) the current test when `backend` cannot run here.
#define FSDB_USE_BACKEND(backend)                                                                         \
  do {                                                                                                    \
    if (std::string(backend) == "postgresql" && ::fsdb::test::postgresTestUrl().empty()) {                \
      if (std::getenv("CI")) FAIL() << "FSDB_TEST_POSTGRES_URL is not set (make test starts a cluster)"; \
      GTEST_SKIP() << "FSDB_TEST_POSTGRES_URL is not set: run make test, or scripts/pg-test-cluster";      \
    }                                                                                                     \
  } while (0)

// A URL for a new schema on the test cluster (created by the store at open).
inline std::string freshPostgresLocation() {
  static std::atomic<int> counter{0};
  static const unsigned salt = std::random_device{}();
  const std::string url = postgresTestUrl();
  const std::string schema =
      "t" + std::to_string(::getpid()) + "_" + std::to_string(salt % 100000) + "_" + std::to_string(counter++);
  return url + (url.find('?') == std::string::npos ? "?" : "&") + "schema=" + schema;
}

class TestDatabase {
 public:
  explicit TestDatabase(std::string backend) : backend_(std::move(backend)) {
    location_ = backend_ == "postgresql" ? freshPostgresLocation() : dir_.file("fsdb.db");
  }
  const std::string& backend() const { return backend_; }
  // What Store::open and `fsdb serve --db` take.
  const std::string& location() const { return location_; }
  // A connection of its own, for checks beside the store (rows of a table, old schemas).
  std::unique_ptr<sql::Connection> connect() const {
    if (backend_ == "postgresql") return std::make_unique<postgres::Connection>(postgres::parseAddress(location_));
    return std::make_unique<sqlite::Connection>(location_);
  }

 private:
  std::string backend_;
  TempDir dir_;
  std::string location_;
};

}  // namespace fsdb::test
