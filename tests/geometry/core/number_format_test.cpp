#include "geometry/core/number_format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>

namespace fsdb {
namespace {

TEST(NumberFormat, ShortestText) {
  EXPECT_EQ(formatNumber(3), "3");
  EXPECT_EQ(formatNumber(-2.5), "-2.5");
  EXPECT_EQ(formatNumber(0.1), "0.1");
  EXPECT_EQ(formatNumber(1e300), "1e+300");
  // Fewest digits is not shortest text: 10 is "10", not "1e+01".
  EXPECT_EQ(formatNumber(10), "10");
  EXPECT_EQ(formatNumber(-200), "-200");
  EXPECT_EQ(formatNumber(123000), "123000");
  EXPECT_EQ(formatNumber(1e6), "1e+06");
  EXPECT_EQ(formatNumber(1.5e-5), "1.5e-05");
  EXPECT_EQ(formatNumber(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(formatNumber(std::nan("")), "nan");
}

TEST(NumberFormat, RoundTripsRandomDoubles) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1e6, 1e6);
  for (int i = 0; i < 1000; ++i) {
    const double x = u(rng);
    EXPECT_EQ(std::strtod(formatNumber(x).c_str(), nullptr), x);
  }
}

}  // namespace
}  // namespace fsdb
