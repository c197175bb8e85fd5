// Placements from words in shape documents: {"transform":{"place":{...}}} against an earlier leaf.
#include "query/document/placement_words.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"
#include "query/linguistic/linguistic_query.h"
#include "query/document/part_json.h"
#include "query/document/shape_json.h"
#include "query/linguistic/vocabulary.h"

namespace fsdb {
namespace {

using nlohmann::json;

json place(const std::string& relativeTo, const std::string& direction, const json& distance = nullptr) {
  json p = {{"relative_to", relativeTo}, {"direction", direction}};
  if (!distance.is_null()) p["distance"] = distance;
  return {{"place", p}};
}

std::vector<ShapeComponent> componentsOf(const json& children) {
  const ParsedShape s = parseShapeField({{"kind", "shape"}, {"tree", {{"op", "union"}, {"children", children}}}}, "shape", 100);
  return shapeComponents(*s.tree);
}

std::string errorPath(const json& children, std::string* message = nullptr) {
  try {
    componentsOf(children);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidDocument) << e.what();
    if (message) *message = e.what();
    return e.path();
  }
  ADD_FAILURE() << "no error";
  return "";
}

TEST(PlacementWords, SphereAbout3AboveABox) {
  const auto comps = componentsOf(
      {{{"part", {{"name", "base"}, {"text", "a box"}}}, {"transform", {{"translate", {1, 0, 0}}}}},
       {{"part", {{"text", "a sphere"}}}, {"transform", place("base", "above", "about 3")}}});
  ASSERT_EQ(comps.size(), 2u);
  EXPECT_EQ(comps[1].part.tx, FuzzyNumber::crisp(1));
  EXPECT_EQ(comps[1].part.ty, FuzzyNumber::triangular(2.7, 3, 3.3));
  EXPECT_EQ(comps[1].part.tz, FuzzyNumber::crisp(0));
  // The words that placed it find it.
  const LinguisticQuery q = parseLinguisticQuery("find a sphere about 3 above a box", Vocabulary::builtin());
  EXPECT_DOUBLE_EQ(scoreShape(q, comps).score, 1.0);
}

TEST(PlacementWords, DirectionsDistancesAndChains) {
  const auto comps = componentsOf(
      {{{"part", {{"name", "a"}, {"params", {{"a1", 1}}}}}},
       {{"part", {{"name", "b"}, {"params", {{"a1", 1}}}}}, {"transform", place("a", "left", 4)}},
       {{"part", {{"params", {{"a1", 0.5}}}}}, {"transform", place("b", "TOP RIGHT", {{"tri", {1, 2, 3}}})}},
       {{"part", {{"params", {{"a1", 2}}}}}, {"transform", place("a", "in front of")}},
       {{"part", {{"params", {{"a1", 1}}}}}, {"transform", place("a", "right", "close")}}});
  EXPECT_EQ(comps[1].part.tx, FuzzyNumber::crisp(-4));
  EXPECT_EQ(comps[1].part.ty, FuzzyNumber::crisp(0));
  const double s = std::sqrt(0.5);
  EXPECT_NEAR(comps[2].part.tx.core().lo, -4 + 2 * s, 1e-12);  // relative to b, placed itself
  EXPECT_NEAR(comps[2].part.ty.support().lo, s, 1e-12);
  EXPECT_NEAR(comps[2].part.ty.support().hi, 3 * s, 1e-12);
  // Default distance: bounding spheres touching (radii 1 and 2).
  EXPECT_EQ(comps[3].part.tz, FuzzyNumber::crisp(3));
  EXPECT_EQ(comps[4].part.tx, *Vocabulary::builtin().distance("close"));
}

TEST(PlacementWords, ErrorsNameThePath) {
  std::string message;
  EXPECT_EQ(errorPath({{{"part", {{"name", "a"}, {"params", {{"a1", 1}}}}}},
                       {{"part", {{"params", {{"a1", 1}}}}}, {"transform", place("nope", "left")}}},
                      &message),
            "shape.tree.children[1].transform.place.relative_to");
  EXPECT_NE(message.find("known so far: a"), std::string::npos) << message;
  // Only earlier leaves: a later one is not known yet.
  EXPECT_EQ(errorPath({{{"part", {{"params", {{"a1", 1}}}}}, {"transform", place("b", "left")}},
                       {{"part", {{"name", "b"}, {"params", {{"a1", 1}}}}}}}),
            "shape.tree.children[0].transform.place.relative_to");
  EXPECT_EQ(errorPath({{{"part", {{"name", "a"}, {"params", {{"a1", 1}}}}}},
                       {{"part", {{"params", {{"a1", 1}}}}}, {"transform", place("a", "lfet")}}},
                      &message),
            "shape.tree.children[1].transform.place.direction");
  EXPECT_NE(message.find("closest: left"), std::string::npos) << message;
  EXPECT_EQ(errorPath({{{"part", {{"name", "a"}, {"params", {{"a1", 1}}}}}},
                       {{"part", {{"params", {{"a1", 1}}}}}, {"transform", place("a", "left", "about x")}}}),
            "shape.tree.children[1].transform.place.distance");
  json extra = place("a", "left");
  extra["translate"] = {1, 2, 3};
  EXPECT_EQ(errorPath({{{"part", {{"name", "a"}, {"params", {{"a1", 1}}}}}},
                       {{"part", {{"params", {{"a1", 1}}}}}, {"transform", extra}}}),
            "shape.tree.children[1].transform.translate");
  // The part's own transform is reported under the part.
  EXPECT_EQ(errorPath({{{"part", {{"name", "a"}, {"params", {{"a1", 1}}}}}},
                       {{"part", {{"params", {{"a1", 1}}}, {"transform", place("a", "up")}}}}}),
            "shape.tree.children[1].part.transform.place.direction");
  // A part on its own has nothing to be placed against.
  try {
    parsePart({{"params", {{"a1", 1}}}, {"transform", place("a", "left")}}, "part");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.path(), "part.transform.place");
  }
}

}  // namespace
}  // namespace fsdb
