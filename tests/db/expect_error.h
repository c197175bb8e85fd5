#pragma once
// expectError(f, code, path): f() must throw fsdb::Error with this code (and exactly this path
// when one is given). Returns the error's message ("" when none was thrown), so a test can check
// what the message names. Shared by the tests of db/, whose errors carry many codes
// (tests/geometry/expect_error.h checks invalid_parameter only).
#include <gtest/gtest.h>

#include <string>

#include "geometry/core/error.h"

namespace fsdb {

template <class F>
std::string expectError(F f, const std::string& code, const std::string& path = "") {
  try {
    f();
    ADD_FAILURE() << "no error thrown; expected " << code;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    if (!path.empty()) {
      EXPECT_EQ(e.path(), path) << e.what();
    }
    return e.what();
  }
  return "";
}

// The message contains `fragment`.
#define FSDB_EXPECT_CONTAINS(message, fragment) \
  EXPECT_NE(std::string(message).find(fragment), std::string::npos) << (message)

}  // namespace fsdb
