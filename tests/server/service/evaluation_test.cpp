#include "server/service/evaluation.h"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <thread>
#include <vector>

#include "geometry/core/error.h"
#include "query/document/part_json.h"
#include "query/document/shape_json.h"
#include "tests/testing/fuzzy_bench_part.h"

namespace fsdb {
namespace {

// The bench part with all fourteen values fuzzy: its grid takes long enough (about a second at
// resolution 16) that requests started together all arrive while the first one builds.
ParsedShape slowPart() {
  return parseShapeField(partToJson(testing::allValuesFuzzyPart()), "", 10000, {});
}

// The tests of build sharing are not about time: under the sanitizers the slow part's concurrent
// builds take about a minute, as long as the default max_eval_ms, so they run without a deadline.
EvaluationLimits noTimeLimit() {
  EvaluationLimits limits;
  limits.maxEvalMs = 0;
  return limits;
}

// Runs `body` on a thread of its own; an error it throws becomes this test's failure (an
// exception that leaves a std::thread would abort the whole test binary).
std::thread testThread(std::function<void()> body) {
  return std::thread([body = std::move(body)] {
    try {
      body();
    } catch (const std::exception& e) {
      ADD_FAILURE() << "the thread threw: " << e.what();
    }
  });
}

// Requests for the same shape (one content key) at the same resolution at the same moment (a
// thumbnail, a mesh and the chart of a part just made) share one grid build: the grid, the field
// it sampled and the exhausted-search count are the first request's.
TEST(EvaluationTest, ConcurrentBuildsOfOneKeyRunOnce) {
  const ParsedShape shape = slowPart();
  const EvaluationLimits limits = noTimeLimit();
  const nlohmann::json request = {{"resolution", 16}, {"alphas", {0.5}}};
  constexpr int kRequests = 4;
  std::vector<Evaluation> got(kRequests);
  std::vector<std::thread> threads;
  for (int i = 0; i < kRequests; ++i)
    threads.push_back(testThread([&, i] { got[i] = evaluateParsedShape(request, shape, limits, "same-content"); }));
  for (std::thread& t : threads) t.join();
  for (int i = 1; i < kRequests; ++i) {
    EXPECT_EQ(got[i].grid.get(), got[0].grid.get()) << i;
    EXPECT_EQ(got[i].result["alphas"], got[0].result["alphas"]);
    EXPECT_EQ(got[i].result["exhausted_searches"], got[0].result["exhausted_searches"]);
  }
  // Once the build is over nothing is kept: the next request builds again.
  const Evaluation later = evaluateParsedShape(request, shape, limits, "same-content");
  EXPECT_NE(later.grid.get(), got[0].grid.get());
  EXPECT_EQ(later.result["alphas"], got[0].result["alphas"]);
}

// The mesh of an evaluation is held to max_eval_ms counted from the request's start, the grid's
// time included: 413 naming the option, in the request's terms.
TEST(EvaluationTest, MeshesAreHeldToTheEvaluationTimeLimit) {
  const ParsedShape sphere = parseShapeField({{"kind", "part"}, {"params", {{"a1", 1}}}}, "", 100, {});
  EvaluationLimits limits;
  limits.maxEvalMs = 1000;
  const Evaluation e = evaluateParsedShape({{"resolution", 16}, {"alphas", {0.5}}}, sphere, limits);
  try {
    evaluationMesh(e, 0.5, EnvelopeBound::kUpper, limits, std::chrono::steady_clock::now() - std::chrono::seconds(2));
    ADD_FAILURE() << "no limit_exceeded";
  } catch (const Error& err) {
    EXPECT_EQ(err.code(), errc::kLimitExceeded);
    EXPECT_EQ(err.path(), "resolution");
    EXPECT_NE(std::string(err.what()).find("max_eval_ms=1000"), std::string::npos) << err.what();
  }
  EXPECT_FALSE(evaluationMesh(e, 0.5, EnvelopeBound::kUpper, limits, std::chrono::steady_clock::now()).triangles.empty());
  limits.maxEvalMs = 0;  // no limit
  EXPECT_FALSE(
      evaluationMesh(e, 0.5, EnvelopeBound::kUpper, limits, std::chrono::steady_clock::now() - std::chrono::hours(1))
          .triangles.empty());
}

TEST(EvaluationTest, DifferentKeysOrResolutionsBuildApart) {
  const ParsedShape shape = slowPart();
  const EvaluationLimits limits = noTimeLimit();
  Evaluation a, b, c;
  std::thread ta = testThread([&] { a = evaluateParsedShape({{"resolution", 16}}, shape, limits, "content-a"); });
  std::thread tb = testThread([&] { b = evaluateParsedShape({{"resolution", 16}}, shape, limits, "content-b"); });
  std::thread tc = testThread([&] { c = evaluateParsedShape({{"resolution", 12}}, shape, limits, "content-a"); });
  ta.join();
  tb.join();
  tc.join();
  EXPECT_NE(a.grid.get(), b.grid.get());
  EXPECT_NE(a.grid.get(), c.grid.get());
  EXPECT_EQ(a.result["resolution"], 16);
  EXPECT_EQ(c.result["resolution"], 12);
}

// A build that fails (here: past max_eval_ms) fails every request that waited for it, with the
// same error, and leaves nothing behind.
TEST(EvaluationTest, AnErrorOfTheSharedBuildReachesEveryRequest) {
  const ParsedShape shape = slowPart();
  EvaluationLimits limits;
  limits.maxEvalMs = 1;
  constexpr int kRequests = 3;
  std::vector<std::string> errors(kRequests);
  std::vector<std::thread> threads;
  for (int i = 0; i < kRequests; ++i)
    threads.emplace_back([&, i] {
      try {
        evaluateParsedShape({{"resolution", 64}}, shape, limits, "failing");
      } catch (const Error& e) {
        errors[i] = e.code();
      }
    });
  for (std::thread& t : threads) t.join();
  for (const std::string& e : errors) EXPECT_EQ(e, errc::kLimitExceeded);
}

}  // namespace
}  // namespace fsdb
