// Parsing of POST /curves/fair bodies (query/document/fair_curve_json.h).
#include "query/document/fair_curve_json.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"

namespace fsdb {
namespace {

using nlohmann::json;

void expectError(const json& body, const std::string& code, const std::string& path, FairCurveLimits limits = {}) {
  try {
    parseFairCurveRequest(body, limits);
    ADD_FAILURE() << "accepted " << body.dump();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    EXPECT_EQ(e.path(), path) << e.what();
  }
}

TEST(FairCurveJson, ReadsEveryFieldAndDefaults) {
  const FairCurveRequest d = parseFairCurveRequest({{"points", {{0, 0}, {1, 2}}}});
  EXPECT_EQ(d.points.size(), 2u);
  EXPECT_EQ(d.points[1].y, 2);
  EXPECT_FALSE(d.closed);
  EXPECT_TRUE(d.relations.empty());
  EXPECT_EQ(d.samples, 32);
  EXPECT_EQ(d.options.angleSamples, 180);
  EXPECT_EQ(d.options.maxCandidates, 10u);
  EXPECT_EQ(d.options.behavior, FairBehavior::kNoInflection);
  const FairCurveRequest r = parseFairCurveRequest({{"points", {{0, 0}, {1, 2}, {3, 1}}},
                                                    {"closed", true},
                                                    {"relations", {"smoother", "sharper", "smoother"}},
                                                    {"behavior", "inflection"},
                                                    {"alpha_threshold", 0.25},
                                                    {"samples", 5},
                                                    {"angle_samples", 360},
                                                    {"max_candidates", 3}});
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.relations, (std::vector<Relation>{Relation::kSmoother, Relation::kSharper, Relation::kSmoother}));
  EXPECT_EQ(r.options.behavior, FairBehavior::kInflection);
  EXPECT_EQ(r.options.alphaThreshold, 0.25);
  EXPECT_EQ(r.samples, 5);
  EXPECT_EQ(r.options.angleSamples, 360);
  EXPECT_EQ(r.options.maxCandidates, 3u);
  EXPECT_STREQ(behaviorName(FairBehavior::kUndulant), "undulant");
  EXPECT_STREQ(behaviorName(r.options.behavior), "inflection");
}

TEST(FairCurveJson, ErrorsNameThePathAndTheLimit) {
  expectError({{"points", {{0, 0}, {1, true}}}}, errc::kInvalidDocument, "points[1][1]");
  expectError({{"points", {{0, 0}, {0, 0}}}}, errc::kInvalidParameter, "points[1]");
  expectError({{"points", {{0, 0}, {1, 1}}}, {"relations", {1}}}, errc::kInvalidDocument, "relations[0]");
  expectError({{"points", {{0, 0}, {1, 1}}}, {"angle_samples", 3}}, errc::kInvalidParameter, "angle_samples");
  expectError({{"points", {{0, 0}, {1, 1}}}, {"extra", 1}}, errc::kInvalidDocument, "extra");
  FairCurveLimits small;
  small.maxPoints = 2;
  expectError({{"points", {{0, 0}, {1, 1}, {2, 2}}}}, errc::kLimitExceeded, "points", small);
  expectError({{"points", {{0, 0}, {1, 1}}}, {"angle_samples", 40000}}, errc::kLimitExceeded, "angle_samples");
  expectError({{"points", {{0, 0}, {1, 1}}}, {"max_candidates", 101}}, errc::kLimitExceeded, "max_candidates");
  small = {};
  small.maxCurvePoints = 100;
  expectError({{"points", {{0, 0}, {1, 1}}}, {"samples", 20}}, errc::kLimitExceeded, "samples", small);
}

}  // namespace
}  // namespace fsdb
