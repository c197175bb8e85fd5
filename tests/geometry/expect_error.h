#pragma once
// expectInvalidParameter(f, path): f() must throw fsdb::Error with code invalid_parameter and
// exactly this path. Shared by every test of a parameter check.
#include <gtest/gtest.h>

#include <string>

#include "geometry/core/error.h"

namespace fsdb {

// expectError(f, code, path): the same for any error code.
template <class F>
void expectError(F f, const std::string& code, const std::string& path) {
  try {
    f();
    ADD_FAILURE() << "no error thrown; expected " << code << " at " << path;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    EXPECT_EQ(e.path(), path) << e.what();
  }
}

template <class F>
void expectInvalidParameter(F f, const std::string& path) {
  expectError(f, errc::kInvalidParameter, path);
}

}  // namespace fsdb
