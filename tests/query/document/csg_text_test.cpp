// query/document/csg_text: the "C = A + (B - D) * E" form, precedence, n-ary chains, errors with columns.
#include "query/document/csg_text.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"

namespace fsdb {
namespace {

using nlohmann::json;

// Names starting with "s" are shapes, others parts; "missing" is unknown.
std::string kindOf(const std::string& name, size_t column) {
  if (name == "missing") throw Error("unknown_reference", "no " + name + " at " + std::to_string(column), "csg");
  return name[0] == 's' ? "shape" : "part";
}

json parse(const std::string& text) { return parseCsgText(text, kindOf, "csg").tree; }

TEST(CsgText, ParsesTheSpecExampleWithPrecedence) {
  CsgText t = parseCsgText("C = A + (B - D) * E", kindOf, "csg");
  EXPECT_EQ(t.name, "C");
  const json expected = {
      {"op", "union"},
      {"children",
       {{{"part", "A"}},
        {{"op", "intersection"},
         {"children", {{{"op", "difference"}, {"children", {{{"part", "B"}}, {{"part", "D"}}}}}, {{"part", "E"}}}}}}}};
  EXPECT_EQ(t.tree, expected) << t.tree.dump();
}

// Parentheses nest at most 64 deep: 100000 of them overflowed the stack (a crash of the server
// on POST /shapes, found by fuzzing); 64 still parse, and sequences of groups are not nesting.
TEST(CsgText, ParenthesesNestAtMost64Deep) {
  EXPECT_EQ(parse(std::string(64, '(') + "A" + std::string(64, ')')), json({{"part", "A"}}));
  std::string groups;
  for (int i = 0; i < 200; ++i) groups += i ? " + (B)" : "(A)";
  EXPECT_EQ(parse(groups)["children"].size(), 200u);
  for (int n : {65, 100000}) {
    try {
      parse(std::string(n, '(') + "A" + std::string(n, ')'));
      ADD_FAILURE() << n << " levels parsed";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), errc::kLimitExceeded);
      EXPECT_EQ(e.path(), "csg");
      EXPECT_NE(std::string(e.what()).find("deeper than 64 levels at column 65"), std::string::npos) << e.what();
    }
  }
}

TEST(CsgText, IntersectionBindsTighterThanUnion) {
  EXPECT_EQ(parse("A + B * C"),
            json({{"op", "union"},
                  {"children",
                   {{{"part", "A"}}, {{"op", "intersection"}, {"children", {{{"part", "B"}}, {{"part", "C"}}}}}}}}));
}

TEST(CsgText, ChainsBecomeNaryNodesButDifferenceKeepsItsOrder) {
  EXPECT_EQ(parse("A + B + C")["children"].size(), 3u);
  EXPECT_EQ(parse("A * (B * C)")["children"].size(), 3u);
  const json leftChain = parse("A - B - C");  // (A − B) − C
  EXPECT_EQ(leftChain["op"], "difference");
  ASSERT_EQ(leftChain["children"].size(), 3u);
  EXPECT_EQ(leftChain["children"][2], json({{"part", "C"}}));
  const json rightNested = parse("A - (B - C)");  // not the same set: stays nested
  ASSERT_EQ(rightNested["children"].size(), 2u);
  EXPECT_EQ(rightNested["children"][1]["op"], "difference");
}

// A long chain is one node with every operand in order (its operands are moved at each link, not
// copied: bench/bench_csg_query_text times it); parenthesised operands change nothing.
TEST(CsgText, LongChainsKeepEveryOperandInOrder) {
  std::string text = "P0";
  for (int i = 1; i < 5000; ++i)
    text += (i % 2 ? " + " : " + (") + std::string("P") + std::to_string(i) + (i % 2 ? "" : ")");
  const json tree = parse(text);
  EXPECT_EQ(tree["op"], "union");
  ASSERT_EQ(tree["children"].size(), 5000u);
  for (int i = 0; i < 5000; ++i) EXPECT_EQ(tree["children"][size_t(i)], json({{"part", "P" + std::to_string(i)}})) << i;
}

TEST(CsgText, ResolvesNamesToPartsOrShapesAndAcceptsQuotedNames) {
  EXPECT_EQ(parse("sWheel + bolt"), json({{"op", "union"}, {"children", {{{"ref", "sWheel"}}, {{"part", "bolt"}}}}}));
  EXPECT_EQ(parse("\"bent-rod\" - cap.v2"),
            json({{"op", "difference"}, {"children", {{{"part", "bent-rod"}}, {{"part", "cap.v2"}}}}}));
  EXPECT_EQ(parse("  lone  "), json({{"part", "lone"}}));
  EXPECT_EQ(parseCsgText("X=A*B", kindOf, "csg").name, "X");
}

std::string errorMessage(const std::string& text) {
  try {
    parse(text);
  } catch (const Error& e) {
    EXPECT_EQ(e.path(), "csg");
    return e.what();
  }
  ADD_FAILURE() << "no error for " << text;
  return "";
}

TEST(CsgText, ErrorsGiveTheColumnAndWhatWasExpected) {
  EXPECT_EQ(errorMessage("A + * B"), "csg: expected a name or '(' at column 5, found '*'");
  EXPECT_EQ(errorMessage("A + (B - C"), "csg: expected ')' at column 11, found the end of the text");
  EXPECT_EQ(errorMessage("A B"), "csg: expected '+', '-', '*' or the end at column 3, found 'B'");
  EXPECT_EQ(errorMessage(""), "csg: expected a name or '(' at column 1, found the end of the text");
  EXPECT_EQ(errorMessage("A + \"open"), "csg: unterminated quoted name at column 5, found '\"'");
  EXPECT_EQ(errorMessage("C = = A"), "csg: expected a name or '(' at column 5, found '='");
  EXPECT_EQ(errorMessage("A + missing"), "no missing at 5");  // the resolver's own error passes through
}

}  // namespace
}  // namespace fsdb
