#pragma once
// TestDatabase: a fresh, empty database on one backend, for suites that run on both (db/store.h).
// - "sqlite": a file in a TempDir (removed at destruction).
// - "postgresql": a schema of its own, named after the process and a counter, on the test cluster:
//   $FSDB_TEST_POSTGRES_URL, or the URL in the file FSDB_PG_TEST_URL_FILE (compiled in: ctest
//   starts a cluster there with scripts/pg-test-cluster as a fixture; tests/CMakeLists.txt).
//   The cluster is thrown away with its schemas. Without a URL the PostgreSQL cases are skipped,
//   except under CI=true, where they fail: CI must never pass by not running them.
// kBackends lists both for INSTANTIATE_TEST_SUITE_P; FSDB_USE_BACKEND(backend) goes first in SetUp.
// The server and service suites run once per backend instead (FSDB_TEST_BACKEND, set by ctest for
// their "postgresql." copies): storeLocation() gives their databases.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <random>
#include <stdexcept>
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
  if (const char* url = std::getenv("FSDB_TEST_POSTGRES_URL")) return url;
  std::string url;
#ifdef FSDB_PG_TEST_URL_FILE
  std::ifstream in(FSDB_PG_TEST_URL_FILE);
  std::getline(in, url);
#endif
  return url;
}

// Skips (or under CI fails) the current test when `backend` cannot run here.
#define FSDB_USE_BACKEND(backend)                                                                        \
  do {                                                                                                   \
    if (std::string(backend) == "postgresql" && ::fsdb::test::postgresTestUrl().empty()) {               \
      if (std::getenv("CI")) FAIL() << "FSDB_TEST_POSTGRES_URL is not set (make test starts a cluster)"; \
      GTEST_SKIP() << "FSDB_TEST_POSTGRES_URL is not set: run make test, or scripts/pg-test-cluster";    \
    }                                                                                                    \
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

// The backend of this run of a server or service suite: "sqlite" unless FSDB_TEST_BACKEND says.
inline std::string suiteBackend() {
  const char* backend = std::getenv("FSDB_TEST_BACKEND");
  return backend ? backend : "sqlite";
}

// A new database for a server or service test: the file `name` in `dir`, or a new schema on the
// test cluster when the suite runs on PostgreSQL (no URL there is an error, not a skip).
inline std::string storeLocation(const TempDir& dir, const std::string& name) {
  if (suiteBackend() != "postgresql") return dir.file(name);
  if (postgresTestUrl().empty())
    throw std::runtime_error("FSDB_TEST_BACKEND=postgresql, but no test cluster (FSDB_TEST_POSTGRES_URL)");
  return freshPostgresLocation();
}

}  // namespace fsdb::test
