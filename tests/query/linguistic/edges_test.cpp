// A part's edges (query/linguistic/edges.h): a noun's exponents below 1 are its edges (both where
// none is), and the edge descriptor's set for a noun is the mean of the edge degree over its edges
// and its other exponents' degrees, checked against the descriptor of crisp parts.
#include "query/linguistic/edges.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_arithmetic.h"
#include "query/linguistic/descriptors.h"

namespace fsdb {
namespace {

const Vocabulary& v() { return Vocabulary::builtin(); }

TEST(Edges, TheExponentsBelowOneAreTheEdges) {
  const EdgeExponents box = edgeExponentsOf(v().noun("box"));
  EXPECT_TRUE(box.eps1 && box.eps2);
  const EdgeExponents cylinder = edgeExponentsOf(v().noun("cylinder"));
  EXPECT_TRUE(cylinder.eps1);
  EXPECT_FALSE(cylinder.eps2);  // the round section
  // None below 1 (a ball, a double pyramid) or no shape at all: both.
  for (const Noun* noun : {v().noun("sphere"), v().noun("double pyramid"), v().noun("shape"),
                           static_cast<const Noun*>(nullptr)}) {
    const EdgeExponents e = edgeExponentsOf(noun);
    EXPECT_TRUE(e.eps1 && e.eps2);
  }
}

// The set is what describePart gives a crisp part of the noun with its edges at each degree.
TEST(Edges, TheSetIsTheDescriptorOfTheNounWithThoseEdges) {
  const FuzzyNumber d = FuzzyNumber::trapezoidal(0.15, 0.25, 0.5, 0.65);
  EXPECT_EQ(edgeDescriptorSet(d, v().noun("box"), v()), d);
  const FuzzyNumber cylinder = edgeDescriptorSet(d, v().noun("cylinder"), v());
  const int roundness = descriptorIndex("roundness");
  for (double e : {0.15, 0.25, 0.4, 0.5, 0.65}) {
    // A cylinder (eps2 = 1) with rims of exponent e: roundness (ro(e) + ro(1)) / 2.
    const double degree = (exponentDegree(roundness, e) + exponentDegree(roundness, 1.0)) / 2.0;
    EXPECT_NEAR(cylinder.membership(degree), d.membership(e), 1e-12) << e;
  }
  EXPECT_EQ(cylinder.membership(0.55), 0.0);  // a plain cylinder's rims (0.1) are no rounded edges
}

TEST(Edges, ExponentDegreeIsEachExponentShapesFunction) {
  EXPECT_DOUBLE_EQ(exponentDegree(descriptorIndex("squariness"), 0.1), 0.9);
  EXPECT_DOUBLE_EQ(exponentDegree(descriptorIndex("roundness"), 0.3), 0.3);
  EXPECT_DOUBLE_EQ(exponentDegree(descriptorIndex("roundness"), 1.5), 0.5);
  EXPECT_DOUBLE_EQ(exponentDegree(descriptorIndex("bevelness"), 2.0), 1.0);
  EXPECT_DOUBLE_EQ(exponentDegree(descriptorIndex("pinchness"), 3.0), 0.5);
  EXPECT_THROW(exponentDegree(descriptorIndex("bendness"), 1.0), Error);
}

}  // namespace
}  // namespace fsdb
