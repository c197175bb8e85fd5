#include "query/json/fuzzy_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_arithmetic.h"
#include "tests/testing/random_fuzzy.h"

namespace fsdb {
namespace {

using nlohmann::json;

FuzzyNumber parse(const std::string& text, const std::string& path = "") {
  return parseFuzzyNumber(json::parse(text), path);
}

TEST(FuzzyJson, EveryAcceptedForm) {
  EXPECT_EQ(parse("2.5"), FuzzyNumber::crisp(2.5));
  EXPECT_EQ(parse("-3"), FuzzyNumber::crisp(-3));
  EXPECT_EQ(parse(R"({"tri":[0.8,1,1.2]})"), FuzzyNumber::triangular(0.8, 1, 1.2));
  EXPECT_EQ(parse(R"({"trap":[0,1,2,3]})"), FuzzyNumber::trapezoidal(0, 1, 2, 3));
  EXPECT_EQ(parse(R"({"about":3,"spread":0.5})"), FuzzyNumber::triangular(2.5, 3, 3.5));
  EXPECT_EQ(parse(R"({"about":3,"spread":0})"), FuzzyNumber::crisp(3));
  EXPECT_EQ(parse(R"({"about":3})"), parse(R"("about 3")"));
  EXPECT_EQ(parse(R"({"points":[[0,0],[1,1],[3,0]]})"), FuzzyNumber::triangular(0, 1, 3));
  EXPECT_EQ(parse(R"({"points":[[0,0],[1,0.5],[2,1],[4,0.2],[5,0]]})"),
            FuzzyNumber::fromPoints({{0, 0}, {1, 0.5}, {2, 1}, {4, 0.2}, {5, 0}}));
  EXPECT_EQ(parse(R"("about 3")"), FuzzyNumber::triangular(2.7, 3, 3.3));
  EXPECT_EQ(parse(R"("between 1 and 2")"), FuzzyNumber::trapezoidal(1, 1, 2, 2));
  EXPECT_EQ(parse(R"("exactly 7")"), FuzzyNumber::crisp(7));
  EXPECT_EQ(parse(R"("7")"), FuzzyNumber::crisp(7));
}

TEST(FuzzyJson, ToJsonPicksTheMostSpecificForm) {
  EXPECT_EQ(toJson(FuzzyNumber::crisp(2.5)), json(2.5));
  EXPECT_EQ(toJson(FuzzyNumber::triangular(1, 2, 3)), json::parse(R"({"tri":[1,2,3]})"));
  EXPECT_EQ(toJson(FuzzyNumber::triangular(1, 1, 3)), json::parse(R"({"tri":[1,1,3]})"));
  EXPECT_EQ(toJson(FuzzyNumber::trapezoidal(0, 1, 2, 3)), json::parse(R"({"trap":[0,1,2,3]})"));
  EXPECT_EQ(toJson(FuzzyNumber::trapezoidal(1, 2, 2, 3)), json::parse(R"({"tri":[1,2,3]})"));
  EXPECT_EQ(toJson(FuzzyNumber::fromPoints({{0, 0}, {1, 0.7}, {2, 1}, {3, 0}})),
            json::parse(R"({"points":[[0,0],[1,0.7],[2,1],[3,0]]})"));
}

// parse(toJson(x)) == x, also through JSON text, for every kind of number.
TEST(FuzzyJson, RoundTrip) {
  std::mt19937 rng(41);
  for (int i = 0; i < 500; ++i) {
    FuzzyNumber a;
    switch (i % 6) {
      case 0: a = FuzzyNumber::crisp(testing::uniform(rng, -1e6, 1e6)); break;
      case 1: a = testing::randomTriangular(rng, /*allowVertical=*/true); break;
      case 2: a = testing::randomTrapezoidal(rng); break;
      case 3: a = testing::randomConvexPoints(rng); break;
      case 4: a = testing::randomPoints(rng); break;
      default: a = testing::randomTriOrTrap(rng) * testing::randomTriOrTrap(rng); break;
    }
    EXPECT_EQ(parseFuzzyNumber(toJson(a), "x"), a);
    EXPECT_EQ(parseFuzzyNumber(json::parse(toJson(a).dump()), "x"), a);
  }
}

struct BadCase {
  const char* document;  // the value at "params.eps2"
  const char* path;      // the exact path of the bad value
  const char* says;      // a piece of the message
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << c.document; }

class FuzzyJsonRejects : public ::testing::TestWithParam<BadCase> {};

TEST_P(FuzzyJsonRejects, WithTheExactPath) {
  const BadCase& c = GetParam();
  try {
    parseFuzzyNumber(json::parse(c.document), "params.eps2");
    FAIL() << "accepted " << c.document;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidDocument);
    EXPECT_EQ(e.path(), c.path) << e.what();
    EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    BadInputs, FuzzyJsonRejects,
    ::testing::Values(
        BadCase{R"({"tri":[3,2,4]})", "params.eps2.tri[1]", "l <= m <= r, got l=3 > m=2"},
        BadCase{R"({"tri":[1,2,1.5]})", "params.eps2.tri[2]", "m=2 > r=1.5"},
        BadCase{R"({"tri":[1,2]})", "params.eps2.tri", "exactly 3 numbers"},
        BadCase{R"({"tri":[1,"2",3]})", "params.eps2.tri[1]", "must be a number, got string"},
        BadCase{R"({"tri":5})", "params.eps2.tri", "array of 3 numbers"},
        BadCase{R"({"trap":[0,2,1,3]})", "params.eps2.trap[2]", "a <= b <= c <= d"},
        BadCase{R"({"trap":[0,1,2,3,4]})", "params.eps2.trap", "exactly 4 numbers"},
        BadCase{R"({"trap":[0,1,null,3]})", "params.eps2.trap[2]", "got null"},
        BadCase{R"({"about":3,"spread":-1})", "params.eps2.spread", "spread must be >= 0"},
        BadCase{R"({"about":"3"})", "params.eps2.about", "must be a number"},
        BadCase{R"({"spread":1})", "params.eps2.spread", "spread goes with about"},
        BadCase{R"({"tri":[0,1,2],"spread":1})", "params.eps2.spread", "only with about"},
        BadCase{R"({"points":[[0,0],[1,1.5]]})", "params.eps2.points[1][1]", "mu must be in [0, 1]"},
        BadCase{R"({"points":[[0,0],[1,-0.5],[2,1]]})", "params.eps2.points[1][1]", "got -0.5"},
        BadCase{R"({"points":[[0,0],[1,0.8],[2,0]]})", "params.eps2.points", "normal"},
        BadCase{R"({"points":[[0,0],[2,1],[1,0]]})", "params.eps2.points[2][0]", "non-decreasing"},
        BadCase{R"({"points":[]})", "params.eps2.points", "non-empty"},
        BadCase{R"({"points":[[0,1],[1]]})", "params.eps2.points[1]", "exactly 2 numbers"},
        BadCase{R"({"points":[[0,1],{"x":1}]})", "params.eps2.points[1]", "array of 2 numbers"},
        BadCase{R"({"points":[[0,1],[true,0]]})", "params.eps2.points[1][0]", "got boolean"},
        BadCase{R"({"tri":[0,1,2],"trap":[0,1,2,3]})", "params.eps2.tri", "exactly one of"},
        BadCase{R"({"tri":[0,1,2],"mean":1})", "params.eps2.mean", "unknown key \"mean\""},
        BadCase{R"({})", "params.eps2", "empty object"},
        BadCase{R"("very round")", "params.eps2", "unknown number phrase \"very round\""},
        BadCase{R"("between 4 and 2")", "params.eps2", "A <= B"},
        BadCase{R"("about three")", "params.eps2", "\"three\""},
        BadCase{R"(null)", "params.eps2", "expected a fuzzy number"},
        BadCase{R"(true)", "params.eps2", "got boolean"},
        BadCase{R"([1,2,3])", "params.eps2", "{\"tri\":[l,m,r]}"}));

// nlohmann parses only finite numbers from text, but C++ callers can build NaN / Inf values.
TEST(FuzzyJson, RejectsNonFiniteNumbersFromCode) {
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  const std::pair<json, std::string> cases[] = {
      {json(nan), "params.a1"},
      {json(inf), "params.a1"},
      {json{{"tri", {0, nan, 1}}}, "params.a1.tri[1]"},
      {json{{"trap", {-inf, 0, 1, 2}}}, "params.a1.trap[0]"},
      {json{{"about", nan}}, "params.a1.about"},
      {json{{"about", 1}, {"spread", inf}}, "params.a1.spread"},
      {json{{"points", {{0, 1}, {inf, 0}}}}, "params.a1.points[1][0]"},
      {json{{"points", {{0, nan}, {1, 1}}}}, "params.a1.points[0][1]"},
  };
  for (const auto& [document, path] : cases) {
    try {
      parseFuzzyNumber(document, "params.a1");
      ADD_FAILURE() << "accepted " << document.dump();
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), errc::kInvalidDocument);
      EXPECT_EQ(e.path(), path) << e.what();
      EXPECT_NE(std::string(e.what()).find("finite"), std::string::npos) << e.what();
    }
  }
}

TEST(FuzzyJson, PathAtTheRoot) {
  try {
    parse(R"({"tri":[3,2,4]})");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.path(), "tri[1]");
  }
  try {
    parse(R"("nonsense")");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.path(), "");
  }
}

}  // namespace
}  // namespace fsdb
