// Printing structural queries back (query/structural/csg_query_print.h): the canonical phrase form
// of each construction, relations included, and that it reads back to the same query.
#include "query/structural/csg_query_print.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"
#include "query/linguistic/vocabulary.h"
#include "tests/testing/query_shapes.h"
#include "tests/testing/text_error.h"

namespace fsdb {
namespace {

const Vocabulary& v() { return Vocabulary::builtin(); }
CsgQuery parse(const std::string& text) { return parseCsgQuery(text, v(), {}, 1000); }
std::string printed(const std::string& text) { return csgQueryText(parse(text), v()); }

TEST(CsgQueryPrint, CanonicalPhrasing) {
  EXPECT_EQ(printed("find a shape which is the union of a very bent cylinder and a very sharp pyramid"),
            "find the union of the very bent cylinder and the very sharp pyramid");
  EXPECT_EQ(printed("a cube with a cylindrical hole"), "find the difference of the cube and the cylinder");
  EXPECT_EQ(printed("the part of a sphere inside a cube"), "find the intersection of the sphere and the cube");
  EXPECT_EQ(printed("a sphere, a box and a cylinder"), "find the union of the sphere and the box and the cylinder");
  EXPECT_EQ(printed("a sphere on top of a cylinder"), "find the union of the cylinder and the sphere to its top");
  EXPECT_EQ(printed("the union of a cube and a sphere about 2 units to its right"),
            "find the union of the cube and the sphere about 2 to its right");
  EXPECT_EQ(printed("a cone on top of a cylinder on top of a box"),
            "find the union of the box and the cylinder to its top and the cone to its top");
  // Below the root a chain keeps its subject first, for what is placed against it.
  EXPECT_EQ(printed("a cone on top of a cylinder on top of a box minus a sphere"),
            "find the difference of the cone to the top of the cylinder to the top of the box and the sphere");
  EXPECT_EQ(printed("a cube with a sphere on top and a cone"),
            "find the union of the cube and the sphere to its top and the cone");
  EXPECT_EQ(printed("a sphere on top of a cube intersected with a cone to its right"),
            "find the intersection of the sphere to the top of the cube and the cone to its right");
  EXPECT_EQ(printed("the difference of a cube and a sphere to its right"),
            "find the difference of the cube and the sphere to its right");
  EXPECT_EQ(printed("cube + \"very bent cylinder\""), "find the union of the cube and the very bent cylinder");
}

TEST(CsgQueryPrint, PrintedTextsMeanTheQuery) {
  for (const char* text :
       {"the union of a cube and the difference of a box and a cylinder", "(a cube plus a sphere) minus a cylinder",
        "a sphere intersected with a box minus a cone", "the union of a bent and twisted rod, a round box and a sphere",
        "the union of a box, a sphere in front of it and a cone to its left",
        "a cylinder with a cone about 3 units on top", "a sphere close to the top right of a cube",
        "a box without a cylinder with bendness at least 0.5", "C = sphere + (box - cylinder) * cone",
        // A fuzz finding: printed "about 2.4444444444444445e+32", whose '+' made the text a formula.
        "a cube and a sphere about 244444444444444444444444444444444 units to its right"}) {
    const CsgQuery q = parse(text);
    const std::string once = csgQueryText(q, v());
    EXPECT_EQ(testing::csgMeaning(parse(once)), testing::csgMeaning(q)) << text << " -> " << once;
    EXPECT_EQ(printed(once), once) << "a printed text prints as itself: " << once;
  }
}

TEST(CsgQueryPrint, StoredPartsAreTheFormulaFormsToName) {
  const ReferenceResolver resolver = [](const std::string& kind,
                                        const nlohmann::json& name) -> std::optional<ResolvedReference> {
    if (kind != "part" || name != "bolt") return std::nullopt;
    ResolvedReference r;
    r.id = 7;
    r.document = {{"kind", "part"}, {"name", "bolt"}, {"params", {{"a1", 1}}}};
    return r;
  };
  const CsgQuery q = parseCsgQuery("bolt + cube", v(), resolver, 100);
  const std::string e = test::invalidParameterOf("query", "bolt + cube", [&] { csgQueryText(q, v()); });
  EXPECT_NE(e.find("bolt"), std::string::npos) << e;
}

}  // namespace
}  // namespace fsdb
