// The family's members (geometry/superquadric/fuzzy_part_members.h): every value at an end of its
// α-cut, the pattern of ends, crisp values kept, and the membership of a crisp member.
#include "geometry/superquadric/fuzzy_part_members.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"

namespace fsdb {
namespace {

FuzzyPart fuzzyPart() {
  FuzzyPart p;
  p.a1 = FuzzyNumber::triangular(0.8, 1.0, 1.2);
  p.a3 = FuzzyNumber::trapezoidal(1.0, 2.0, 3.0, 5.0);
  p.kv = FuzzyNumber::triangular(0.0, 0.1, 0.2);
  p.tx = FuzzyNumber::triangular(2.0, 3.0, 4.0);
  p.eps2 = FuzzyNumber::crisp(0.5);
  return p;
}

TEST(FuzzyPartMembers, EveryFuzzyValueAtAnEndOfItsCut) {
  const FuzzyPart p = fuzzyPart();
  const FuzzyPart m1 = memberAt(p, 0.5, 1), m2 = memberAt(p, 0.5, 2);
  for (const FuzzyPart* m : {&m1, &m2})
    for (const FuzzyNumber* v : {&m->eps1, &m->eps2, &m->a1, &m->a2, &m->a3, &m->kx, &m->ky, &m->kv, &m->t, &m->tx,
                                 &m->ty, &m->tz, &m->deg, &m->scale})
      EXPECT_TRUE(v->isCrisp());
  // a1 is value 2: low at k = 1 (2 + 1 odd? no: 3 is odd, so high), the other end at k = 2.
  EXPECT_DOUBLE_EQ(m1.a1.core().lo, 1.1);
  EXPECT_DOUBLE_EQ(m2.a1.core().lo, 0.9);
  // a3 (value 4): the trapezoid's 0.5-cut is [1.5, 4].
  EXPECT_DOUBLE_EQ(m1.a3.core().lo, 4.0);
  EXPECT_DOUBLE_EQ(m2.a3.core().lo, 1.5);
  // Crisp values stay, whatever the pattern.
  EXPECT_DOUBLE_EQ(m1.eps2.core().lo, 0.5);
  EXPECT_DOUBLE_EQ(m2.eps2.core().lo, 0.5);
  EXPECT_EQ(m1.axis.z, p.axis.z);
  // Numbering from `first` shifts the pattern: a second part of a shape leans the other way.
  EXPECT_DOUBLE_EQ(memberAt(p, 0.5, 1, 1).a1.core().lo, 0.9);
}

TEST(FuzzyPartMembers, MembershipIsTheLeastOfTheValues) {
  const FuzzyPart p = fuzzyPart();
  EXPECT_DOUBLE_EQ(memberMembership(p, FuzzyPart::fromCrisp(p.coreRepresentative())), 1.0);
  for (double a : {0.0, 0.25, 0.5, 0.75, 1.0})
    for (size_t k : {1, 2, 3}) EXPECT_NEAR(memberMembership(p, memberAt(p, a, k)), a == 1.0 ? 1.0 : a, 1e-12) << a;
  FuzzyPart outside = FuzzyPart::fromCrisp(p.coreRepresentative());
  outside.tx = FuzzyNumber::crisp(10.0);
  EXPECT_DOUBLE_EQ(memberMembership(p, outside), 0.0);
}

TEST(FuzzyPartMembers, LevelOutsideZeroOneIsRefused) {
  EXPECT_THROW(memberAt(fuzzyPart(), 1.5, 1), Error);
  EXPECT_THROW(memberAt(fuzzyPart(), -0.1, 1), Error);
}

}  // namespace
}  // namespace fsdb
