// Printing linguistic queries back (query/linguistic/query_print.h): the canonical phrasing of
// each construction, and that it reads back to the same query.
#include "query/linguistic/query_print.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"
#include "query/linguistic/vocabulary.h"
#include "tests/testing/query_shapes.h"
#include "tests/testing/text_error.h"

namespace fsdb {
namespace {

const Vocabulary& v() { return Vocabulary::builtin(); }
std::string printed(const std::string& text) { return linguisticQueryText(parseLinguisticQuery(text, v()), v()); }

TEST(QueryPrint, CanonicalPhrasing) {
  EXPECT_EQ(printed("find a slightly bent shape"), "find a shape that is slightly bent");
  EXPECT_EQ(printed("slightly bent"), "find a shape that is slightly bent");
  EXPECT_EQ(printed("show me something twisted, please"), "find a shape that is twisted");
  EXPECT_EQ(printed("I need a very round part"), "find a part that is very round");
  // An intensity said after its adjective reads back before it, as its term, not a synonym.
  EXPECT_EQ(printed("a box twisted a lot"), "find a box that is very twisted");
  EXPECT_EQ(printed("a rod bent slightly"), "find a rod that is slightly bent");
  EXPECT_EQ(printed("retrieve the tapered cylinders"), "find a tapered cylinder");
  EXPECT_EQ(printed("a very bent cylinder"), "find a very bent cylinder");
  EXPECT_EQ(printed("a cylinder which is bent and twisted"), "find a cylinder that is bent and twisted");
  EXPECT_EQ(printed("a bent cylinder which is twisted"), "find a bent cylinder that is twisted");
  EXPECT_EQ(printed("find shapes that are not (bent or twisted) and very round at least 0.5"),
            "find a shape that is (not (bent or twisted)) and very round at least 0.5");
  EXPECT_EQ(printed("find parts with bendness at least 0.3 using product"),
            "find a part that is bendness at least 0.3 using product");
  EXPECT_EQ(printed("find a very sharp shape with squarish traverse section"),
            "find a very sharp shape that is squarish traverse section");
  EXPECT_EQ(printed("shapes with a square cross-section"), "find a shape that is square cross-section");
  EXPECT_EQ(printed("find a sphere about 3 units above a box"), "find a sphere about 3 to the top of a box");
  EXPECT_EQ(printed("find a cone close to the top right of a plate"), "find a cone close to the top right of a plate");
  EXPECT_EQ(printed("a ball between 2 and 4 behind shapes"), "find a sphere between 2 and 4 to the back of a shape");
  EXPECT_EQ(printed("anything"), "find a shape");
  // An outline word on a flat noun prints as written (it says the section only beside that noun).
  EXPECT_EQ(printed("a round plate"), "find a round plate");
  EXPECT_EQ(printed("plate round big thin"), "find a plate that is round and big and thin");
  EXPECT_EQ(printed("a plate with a round cross-section"), "find a plate that is round cross-section");
  // Edges print as written, after "with" when they name their edges.
  EXPECT_EQ(printed("a cube with round edges"), "find a cube with round edges");
  EXPECT_EQ(printed("a box which has very softened corners"), "find a box with very softened corners");
  EXPECT_EQ(printed("a rounded box"), "find a rounded box");
  EXPECT_EQ(printed("a cube with a rounded edge"), "find a cube with rounded edge");
  // Words in any case (a fuzz finding: a descriptor degree written "bEndness" was unprintable).
  EXPECT_EQ(printed("find shapes with bEndness at least 0.5"), "find a shape that is bendness at least 0.5");
  EXPECT_EQ(printed("a Slightly BENT shape"), "find a shape that is slightly bent");
  EXPECT_EQ(printed("shapes with a Square Cross-Section"), "find a shape that is square cross-section");
}

TEST(QueryPrint, PrintedTextsMeanTheQuery) {
  for (const char* text :
       {"find a slightly bent shape", "show me something twisted", "a (bent or twisted) very flat box",
        "find shapes that are not round and not (bent and tapered)", "find a cylinder with a very round cross-section",
        "a rod that is roundness about 1", "find a small sphere far in front of a large box at least 0.2 using mean",
        "find shapes with bendness between 0.2 and 0.4", "a cylinder about 10 long and 1 across",
        "a box 4 by 2 by 1", "a ball of radius 0.5", "a rod exactly 6 long that is slightly bent",
        "something between 3 and 4 wide", "a disc with a radius of about 1", "a disc of radius about 0.3",
        "ball small", "a box 4 x 2 x 1 and 3 tall", "rod 6 long thin with a round cross-section",
        "a square disc on a round plate", "a board that is not square", "a long flat board",
        "a cube with round edges", "a rounded box", "a bent box with very soft corners", "a box that is rounded"}) {
    const LinguisticQuery q = parseLinguisticQuery(text, v());
    const std::string once = linguisticQueryText(q, v());
    EXPECT_EQ(testing::queryMeaning(parseLinguisticQuery(once, v())), testing::queryMeaning(q))
        << text << " -> " << once;
    EXPECT_EQ(printed(once), once) << "a printed text prints as itself: " << once;
  }
}

TEST(QueryPrint, MeasuresPrintAsTheirNumbersAndWords) {
  EXPECT_EQ(printed("a cylinder about 10 long and 1 across"), "find a cylinder that is 10 long and 1 across");
  EXPECT_EQ(printed("a ball of radius 0.5"), "find a sphere that is 1 across");
  EXPECT_EQ(printed("a rod about 0.5 long"), "find a rod that is about 0.5 long");  // not within 10 %
  EXPECT_EQ(printed("a rod exactly 6 long"), "find a rod that is exactly 6 long");
  EXPECT_EQ(printed("a post height 3"), "find a column that is 3 tall");
  // A cylinder's length is along its axis (the height), and prints as the length it was said as.
  EXPECT_EQ(printed("a cylinder with diameter 2 and length 1"), "find a cylinder that is 2 across and 1 long");
  EXPECT_EQ(printed("a board 8 long"), "find a board that is 8 long");
}

TEST(QueryPrint, NumbersAndDistances) {
  // Numbers print in formatNumber's shortest form; 10 printed "1e+01" before (its '+' made the
  // printed structural query a formula that no longer parsed: found by fuzz_csg_query_text).
  EXPECT_EQ(distanceText(FuzzyNumber::crisp(10), v()), "10");
  EXPECT_EQ(distanceText(FuzzyNumber::crisp(100), v()), "100");
  EXPECT_EQ(distanceText(FuzzyNumber::crisp(1.0 / 3), v()), "0.3333333333333333");
  EXPECT_EQ(distanceText(FuzzyNumber::crisp(2.5), v()), "2.5");
  // Nor a '+' in an exponent (fuzz_csg_query_text again: "about 2.4444444444444445e+32").
  EXPECT_EQ(distanceText(FuzzyNumber::crisp(1e300), v()), "1e300");
  EXPECT_EQ(distanceText(FuzzyNumber::crisp(2e-7), v()), "2e-07");
  EXPECT_EQ(printed("a sphere about 244444444444444444444444444444444 units above a cube"),
            "find a sphere about 2.4444444444444445e32 to the top of a cube");
  EXPECT_EQ(distanceText(FuzzyNumber::triangular(2.7, 3, 3.3), v()), "about 3");
  EXPECT_EQ(distanceText(FuzzyNumber::trapezoidal(2, 2, 4, 4), v()), "between 2 and 4");
  EXPECT_EQ(distanceText(*v().distance("near"), v()), "close");  // the first word with that set
  EXPECT_THROW(distanceText(FuzzyNumber::triangular(1, 2, 5), v()), Error);
}

TEST(QueryPrint, WhatNoWordsSayIsAnError) {
  LinguisticQuery q;
  q.root.kind = QueryCondition::Kind::kDescriptor;
  q.root.descriptor = "bendness";
  q.root.set = FuzzyNumber::triangular(0.11, 0.12, 0.13);
  q.root.text = "made by hand";
  const std::string e = test::invalidParameterOf("query", "a hand-made set", [&] { linguisticQueryText(q, v()); });
  EXPECT_NE(e.find("bendness"), std::string::npos) << e;
}

}  // namespace
}  // namespace fsdb
