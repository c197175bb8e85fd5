#include "query/json/number_phrases.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"
#include "tests/testing/random_fuzzy.h"

namespace fsdb {
namespace {

std::string errorOf(const std::string& text) {
  try {
    parseNumberPhrase(text);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidDocument);
    EXPECT_EQ(e.path(), "");
    return e.what();
  }
  ADD_FAILURE() << "no error for \"" << text << "\"";
  return "";
}

TEST(NumberPhrases, TableListsEveryForm) {
  std::vector<std::string> patterns;
  for (const auto& p : numberPhrases()) patterns.push_back(p.pattern);
  EXPECT_EQ(patterns, (std::vector<std::string>{"N", "exactly N", "about N", "around N",
                                                "approximately N", "roughly N",
                                                "between A and B"}));
  for (const auto& p : numberPhrases()) EXPECT_FALSE(p.description.empty());
}

TEST(NumberPhrases, ApproximateSpread) {
  EXPECT_DOUBLE_EQ(approximateSpread(3), 0.3);
  EXPECT_DOUBLE_EQ(approximateSpread(-50), 5);
  EXPECT_DOUBLE_EQ(approximateSpread(0), 0.1);
  EXPECT_DOUBLE_EQ(approximateSpread(0.5), 0.1);
}

TEST(NumberPhrases, Crisp) {
  EXPECT_EQ(parseNumberPhrase("3"), FuzzyNumber::crisp(3));
  EXPECT_EQ(parseNumberPhrase("  exactly   -2.5 "), FuzzyNumber::crisp(-2.5));
  EXPECT_EQ(parseNumberPhrase("+1e3"), FuzzyNumber::crisp(1000));
  EXPECT_EQ(parseNumberPhrase("Exactly 4"), FuzzyNumber::crisp(4));
}

TEST(NumberPhrases, Approximately) {
  for (const char* hedge : {"about", "around", "approximately", "roughly", "ABOUT"}) {
    EXPECT_EQ(parseNumberPhrase(std::string(hedge) + " 3"),
              FuzzyNumber::triangular(3 - 0.3, 3, 3 + 0.3));
  }
  EXPECT_EQ(parseNumberPhrase("about 0"), FuzzyNumber::triangular(-0.1, 0, 0.1));
}

TEST(NumberPhrases, Between) {
  EXPECT_EQ(parseNumberPhrase("between 2 and 4"), FuzzyNumber::trapezoidal(2, 2, 4, 4));
  EXPECT_EQ(parseNumberPhrase("between 2 and 2"), FuzzyNumber::crisp(2));
  EXPECT_NE(errorOf("between 5 and 2").find("A <= B"), std::string::npos);
}

TEST(NumberPhrases, ErrorsListTheAcceptedForms) {
  for (const char* bad : {"", "big", "about", "about three", "between 1 or 2", "nan", "inf",
                          "about inf", "0x10", "3 apples", "about 1e999"}) {
    const std::string message = errorOf(bad);
    EXPECT_NE(message.find("\"between A and B\""), std::string::npos) << message;
  }
  EXPECT_NE(errorOf("about three").find("\"three\""), std::string::npos);
  EXPECT_NE(errorOf("very big").find("unknown number phrase \"very big\""), std::string::npos);
}

}  // namespace
}  // namespace fsdb
