#pragma once
// Test helper: a gtest fixture whose suite shares one real `fsdb serve` (ServerProcess), started
// once before the suite's first test and stopped after its last. A suite derives
// `class Name : public SharedServerTest<Name>` and, for extra arguments, defines
// `static std::vector<std::string> serverArgs()`; its tests reach the server as `server`.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/server/server_process.h"

namespace fsdb::test {

template <class Suite>
class SharedServerTest : public ::testing::Test {
 protected:
  static std::vector<std::string> serverArgs() { return {}; }
  static void SetUpTestSuite() { server = new ServerProcess(Suite::serverArgs()); }
  static void TearDownTestSuite() {
    delete server;
    server = nullptr;
  }
  static inline ServerProcess* server = nullptr;
};

}  // namespace fsdb::test
