#pragma once
// expectInvalidParameter(f, path): f() must throw fsdb::Error with code invalid_parameter and
// exactly this path. Shared by every test of a parameter check.
#include <gtest/gtest.h>

#include <string>

#include "geometry/error.h"

namespace fsdb {

template <class F>
void expectInvalidParameter(F f, const std::string& path) {
  try {
    f();
    ADD_FAILURE() << "no error thrown; expected invalid_parameter at " << path;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter) << e.what();
    EXPECT_EQ(e.path(), path) << e.what();
  }
}

}  // namespace fsdb
