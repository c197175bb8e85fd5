#pragma once
// The message of the invalid_parameter error at path "text" that parsing a query text throws, for
// the parser tests (linguistic and CSG texts; "query" for the printers); a test failure when it
// throws none or another.
#include <gtest/gtest.h>

#include <string>

#include "geometry/core/error.h"

namespace fsdb::test {

// The message of the invalid_parameter error at `path` that `run()` throws; `what` names the
// attempt in failures.
template <class Run>
std::string invalidParameterOf(const std::string& path, const std::string& what, Run run) {
  try {
    run();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter) << what;
    EXPECT_EQ(e.path(), path) << what;
    return e.what();
  }
  ADD_FAILURE() << "no error for \"" << what << "\"";
  return "";
}

template <class Parse>
std::string textErrorOf(const std::string& text, Parse parse) {
  return invalidParameterOf("text", text, [&] { parse(text); });
}

}  // namespace fsdb::test
