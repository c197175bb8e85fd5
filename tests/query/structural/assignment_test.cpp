// maxWeightAssignment against every partial matching of small random matrices.
#include "query/structural/assignment.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "geometry/core/error.h"

namespace fsdb {
namespace {

double bestByEnumeration(int rows, int cols, const std::vector<double>& w) {
  std::vector<char> used(size_t(cols), 0);
  std::function<double(int)> go = [&](int r) -> double {
    if (r == rows) return 0;
    double best = go(r + 1);
    for (int c = 0; c < cols; ++c)
      if (!used[size_t(c)]) {
        used[size_t(c)] = 1;
        best = std::max(best, w[size_t(r) * cols + c] + go(r + 1));
        used[size_t(c)] = 0;
      }
    return best;
  };
  return go(0);
}

TEST(Assignment, MaximalOnRandomRectangularMatrices) {
  std::mt19937 rng(77);
  for (int trial = 0; trial < 3000; ++trial) {
    const int rows = std::uniform_int_distribution<int>(0, 6)(rng), cols = std::uniform_int_distribution<int>(0, 6)(rng);
    std::vector<double> w;
    for (int i = 0; i < rows * cols; ++i) {
      const int k = std::uniform_int_distribution<int>(0, 3)(rng);
      w.push_back(k == 0 ? 0.0 : k == 1 ? 1.0 : std::uniform_real_distribution<double>(0, 5)(rng));
    }
    const Assignment a = maxWeightAssignment(rows, cols, w);
    ASSERT_NEAR(a.weight, bestByEnumeration(rows, cols, w), 1e-9) << "trial " << trial;
    ASSERT_EQ(a.columnOfRow.size(), size_t(rows));
    std::vector<char> used(size_t(cols), 0);
    double sum = 0;
    for (int r = 0; r < rows; ++r) {
      const int c = a.columnOfRow[size_t(r)];
      if (c < 0) continue;
      ASSERT_LT(c, cols);
      ASSERT_FALSE(used[size_t(c)]);
      used[size_t(c)] = 1;
      EXPECT_GT(w[size_t(r) * cols + c], 0);  // zero pairs stay unassigned
      sum += w[size_t(r) * cols + c];
    }
    EXPECT_NEAR(sum, a.weight, 1e-12);
  }
}

TEST(Assignment, ZeroWeightsAssignNothing) {
  const Assignment a = maxWeightAssignment(2, 3, std::vector<double>(6, 0.0));
  EXPECT_EQ(a.weight, 0);
  EXPECT_EQ(a.columnOfRow, (std::vector<int>{-1, -1}));
}

TEST(Assignment, PrefersTheBetterTotalOverTheGreedyPair) {
  // Greedy takes (0,0) = 3 and is left with (1,1) = 0; the optimum is 2 + 2.
  const Assignment a = maxWeightAssignment(2, 2, {3, 2, 2, 0});
  EXPECT_DOUBLE_EQ(a.weight, 4);
  EXPECT_EQ(a.columnOfRow, (std::vector<int>{1, 0}));
}

// A union of thousands of children against one of a few (POST /query/csg with a long list) is
// k²·n work, not n³: 20000 x 3 would be ~8e12 steps padded to a square.
TEST(Assignment, LongThinMatricesAugmentTheSmallerSide) {
  const int rows = 20000, cols = 3;
  std::vector<double> w(size_t(rows) * cols, 0.5);
  w[size_t(7) * cols + 0] = 2;      // the best rows of each column
  w[size_t(19999) * cols + 1] = 3;
  w[size_t(123) * cols + 2] = 4;
  int polls = 0;
  const Assignment a = maxWeightAssignment(rows, cols, w, [&] { ++polls; });
  EXPECT_DOUBLE_EQ(a.weight, 9);
  EXPECT_EQ(a.columnOfRow[7], 0);
  EXPECT_EQ(a.columnOfRow[19999], 1);
  EXPECT_EQ(a.columnOfRow[123], 2);
  EXPECT_EQ(polls, cols);  // once per augmented (smaller-side) vertex
  std::vector<double> t(size_t(rows) * cols);  // the transpose: 3 x 20000
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) t[size_t(c) * rows + r] = w[size_t(r) * cols + c];
  const Assignment b = maxWeightAssignment(cols, rows, t);
  EXPECT_DOUBLE_EQ(b.weight, 9);
  EXPECT_EQ(b.columnOfRow, (std::vector<int>{7, 19999, 123}));
}

TEST(Assignment, PollMayStopTheRun) {
  EXPECT_THROW(maxWeightAssignment(3, 3, std::vector<double>(9, 1.0), [] { throw Error(errc::kLimitExceeded, "stop"); }),
               Error);
}

TEST(Assignment, RejectsBadWeights) {
  EXPECT_THROW(maxWeightAssignment(2, 2, {1, 2, 3}), Error);
  EXPECT_THROW(maxWeightAssignment(1, 1, {-1}), Error);
  EXPECT_THROW(maxWeightAssignment(1, 1, {std::nan("")}), Error);
}

}  // namespace
}  // namespace fsdb
