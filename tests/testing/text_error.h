#pragma once
// The message of the invalid_parameter error at path "text" that parsing a query text throws, for
// the parser tests (linguistic and CSG texts); a test failure when it throws none or another.
#include <gtest/gtest.h>

#include <string>

#include "geometry/core/error.h"

namespace fsdb::test {

template <class Parse>
std::string textErrorOf(const std::string& text, Parse parse) {
  try {
    parse(text);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter) << text;
    EXPECT_EQ(e.path(), "text") << text;
    return e.what();
  }
  ADD_FAILURE() << "no error for \"" << text << "\"";
  return "";
}

}  // namespace fsdb::test
