#include "geometry/core/closest_names.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace fsdb {
namespace {

TEST(ClosestNames, EditDistance) {
  EXPECT_EQ(editDistance("", ""), 0u);
  EXPECT_EQ(editDistance("bent", "bent"), 0u);
  EXPECT_EQ(editDistance("bnet", "bent"), 2u);
  EXPECT_EQ(editDistance("cylindr", "cylinder"), 1u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
}

// The unbanded table, as editDistance was before it had a limit.
size_t fullEditDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
    }
  }
  return row[b.size()];
}

TEST(ClosestNames, BandedDistanceIsExactUpToItsLimit) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 3000; ++trial) {
    auto word = [&rng]() {
      std::string w(rng() % 14, 'a');
      for (char& c : w) c = static_cast<char>('a' + rng() % 4);  // few letters: many near pairs
      return w;
    };
    const std::string a = word(), b = word();
    const size_t limit = rng() % 8;
    const size_t full = fullEditDistance(a, b);
    EXPECT_EQ(editDistance(a, b, limit), std::min(full, limit + 1)) << a << " " << b << " limit " << limit;
    EXPECT_EQ(editDistance(a, b), full) << a << " " << b;
    EXPECT_EQ(editDistance(a, b, static_cast<size_t>(-1)), full) << a << " " << b;
  }
}

// A 5 MB word against a vocabulary took 14 s of full tables; the band answers at once.
TEST(ClosestNames, AHugeWordIsComparedInLinearTime) {
  const std::string huge(5'000'000, 'q');
  const std::vector<std::string> known = {"bent", "cylinder", "sphere", "round"};
  EXPECT_EQ(editDistance(huge, "bent"), kEditDistanceLimit + 1);
  EXPECT_EQ(editDistance("bent", huge), kEditDistanceLimit + 1);
  // Within the limit in length, still within the band: 500 KB × 129 cells, not 500 KB × 500 KB.
  const std::string long1(500'000, 'q');
  const std::string almost = long1.substr(0, long1.size() - 3) + "abc";
  EXPECT_EQ(editDistance(long1, almost), 3u);
  EXPECT_EQ(closestNames(huge, known), "bent, cylinder, round");  // all equally far: alphabetical
}

TEST(ClosestNames, QuotedWordsAreCut) {
  EXPECT_EQ(quotedWord("bent"), "bent");
  EXPECT_EQ(quotedWord(std::string(100, 'x')), std::string(100, 'x'));
  EXPECT_EQ(quotedWord(std::string(5'000'000, 'x')), std::string(100, 'x') + "... (5000000 characters)");
  // Never inside a UTF-8 character: 99 x then a two-byte u-umlaut straddling byte 100.
  std::string utf8 = std::string(99, 'x');
  for (int i = 0; i < 50; ++i) utf8 += "\xC3\xBC";
  EXPECT_EQ(quotedWord(utf8), std::string(99, 'x') + "... (149 characters)");
}

TEST(ClosestNames, NearestFirstTiesAlphabetical) {
  const std::vector<std::string> known = {"round", "bent", "best", "sphere", "bent"};
  EXPECT_EQ(closestNames("bnet", known), "bent, best, round");
  EXPECT_EQ(closestNames("bnet", known, 1), "bent");
  EXPECT_EQ(closestNames("x", {}), "");
}

}  // namespace
}  // namespace fsdb
