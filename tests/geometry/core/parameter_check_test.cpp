// The shared parameter checks: message format, range edges, NaN.
#include "geometry/core/parameter_check.h"

#include <gtest/gtest.h>

#include <limits>

#include "geometry/core/error.h"

namespace fsdb {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ParameterCheck, FormatsNumbersAndRanges) {
  EXPECT_EQ(formatNumber(0.1), "0.1");
  EXPECT_EQ(formatNumber(-1.0), "-1");
  EXPECT_EQ(formatNumber(kInf), "inf");
  EXPECT_EQ(formatNumber(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(formatRange(0.0, false, 1.0, true), "(0, 1]");
  EXPECT_EQ(formatRange(1.0, true, 64.0, true), "[1, 64]");
  EXPECT_EQ(formatRange(-1.0, false, kInf, false), "(-1, inf)");
}

TEST(ParameterCheck, InRangeHonoursInclusivenessAndRejectsNaN) {
  EXPECT_TRUE(inRange(0.0, 0.0, true, 1.0, false));
  EXPECT_FALSE(inRange(0.0, 0.0, false, 1.0, false));
  EXPECT_TRUE(inRange(1.0, 0.0, false, 1.0, true));
  EXPECT_FALSE(inRange(1.0, 0.0, false, 1.0, false));
  EXPECT_FALSE(inRange(std::numeric_limits<double>::quiet_NaN(), -kInf, false, kInf, false));
  EXPECT_FALSE(inRange(kInf, 0.0, false, kInf, false));
}

TEST(ParameterCheck, RequireInRangeThrowsWithPathAndMessage) {
  EXPECT_NO_THROW(requireInRange("delta", 0.5, 0.0, false, kInf, false));
  try {
    requireInRange("delta", -2.0, 0.0, false, kInf, false);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter);
    EXPECT_EQ(e.path(), "delta");
    EXPECT_STREQ(e.what(), "delta must be in (0, inf); got -2");
  }
}

TEST(ParameterCheck, RequireDegreeThrowsWithPathAndMessage) {
  EXPECT_NO_THROW(requireDegree("n", 3, 1, 32));
  try {
    requireDegree("n", 33, 1, 32);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter);
    EXPECT_EQ(e.path(), "n");
    EXPECT_STREQ(e.what(), "n must be an integer in [1, 32]; got 33");
  }
}

}  // namespace
}  // namespace fsdb
