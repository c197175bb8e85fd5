#include "geometry/superquadric/fuzzy_part.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/geometry/expect_error.h"
#include "geometry/core/error.h"

namespace fsdb {
namespace {

FuzzyNumber tri(double l, double m, double r) { return FuzzyNumber::triangular(l, m, r); }

TEST(FuzzyPartTest, DefaultsAreTheCrispUnitSphereAtTheOrigin) {
  const FuzzyPart part;
  part.validate();
  const PlacedSuperquadric core = part.coreRepresentative();
  EXPECT_EQ(core.params.eps1, 1.0);
  EXPECT_EQ(core.params.a1, 1.0);
  EXPECT_EQ(core.params.kv, 0.0);
  EXPECT_EQ(core.placement.scale, 1.0);
  EXPECT_EQ(core.placement.deg, 0.0);
  EXPECT_EQ(core.placement.translate, (Vec3{0, 0, 0}));
  EXPECT_EQ(core.insideOutside({1, 0, 0}), 1.0);
  const PartBox box = part.boxAt(0.0);
  EXPECT_EQ(box.params.a1, (Interval{1, 1}));
  EXPECT_EQ(box.placement.scale, (Interval{1, 1}));
  EXPECT_EQ(part.breakpointLevels(), (std::vector<double>{0.0, 1.0}));
}

TEST(FuzzyPartTest, FromCrispKeepsEveryValue) {
  PlacedSuperquadric crisp;
  crisp.params = {0.5, 1.5, 2, 0.5, 3, 0.2, -0.3, 0.1, 1.0};
  crisp.placement = {{1, 2, 3}, {1, 1, 0}, 30, 2};
  const FuzzyPart part = FuzzyPart::fromCrisp(crisp);
  part.validate();
  EXPECT_TRUE(contains(part.boxAt(0.0), crisp));
  EXPECT_TRUE(contains(part.boxAt(1.0), crisp));
  const PlacedSuperquadric back = part.coreRepresentative();
  EXPECT_EQ(back.params.eps2, 1.5);
  EXPECT_EQ(back.params.t, 1.0);
  EXPECT_EQ(back.placement.translate, (Vec3{1, 2, 3}));
  EXPECT_EQ(back.placement.scale, 2.0);
}

TEST(FuzzyPartTest, BoxAtIsTheAlphaCutOfEveryValue) {
  FuzzyPart part;
  part.a1 = tri(1, 2, 4);
  part.kv = FuzzyNumber::trapezoidal(-0.2, -0.1, 0.1, 0.2);
  part.tx = tri(-1, 0, 1);
  part.deg = tri(10, 20, 30);
  part.scale = tri(0.5, 1, 1.5);
  part.validate();
  const PartBox b0 = part.boxAt(0.0), b5 = part.boxAt(0.5), b1 = part.boxAt(1.0);
  EXPECT_EQ(b0.params.a1, (Interval{1, 4}));
  EXPECT_EQ(b5.params.a1, (Interval{1.5, 3}));
  EXPECT_EQ(b1.params.a1, (Interval{2, 2}));
  EXPECT_NEAR(b5.params.kv.lo, -0.15, 1e-15);
  EXPECT_NEAR(b5.params.kv.hi, 0.15, 1e-15);
  EXPECT_EQ(b1.params.kv, (Interval{-0.1, 0.1}));
  EXPECT_EQ(b5.placement.tx, (Interval{-0.5, 0.5}));
  EXPECT_EQ(b5.placement.deg, (Interval{15, 25}));
  EXPECT_EQ(b0.placement.scale, (Interval{0.5, 1.5}));
  // The core representative is the middle of P(1) (kv's core is [-0.1, 0.1]).
  const PlacedSuperquadric core = part.coreRepresentative();
  EXPECT_EQ(core.params.a1, 2.0);
  EXPECT_EQ(core.params.kv, 0.0);
  EXPECT_TRUE(contains(b1, core));
  expectInvalidParameter([&] { part.boxAt(1.5); }, "alpha");
  expectInvalidParameter([&] { part.boxAt(-0.1); }, "alpha");
}

TEST(FuzzyPartTest, BreakpointLevelsAreTheSortedUnionOfHeights) {
  FuzzyPart part;
  part.a1 = FuzzyNumber::fromPoints({{1, 0}, {1.5, 0.25}, {2, 1}, {3, 0}});
  part.eps1 = FuzzyNumber::fromPoints({{0.5, 0}, {0.8, 0.5}, {1, 1}, {1.2, 0.25}, {1.5, 0}});
  const std::vector<double> levels = part.breakpointLevels();
  EXPECT_EQ(levels, (std::vector<double>{0.0, 0.25, 0.5, 1.0}));
  // Between consecutive levels the cut ends are linear in α: check a midpoint of each piece.
  for (size_t i = 0; i + 1 < levels.size(); ++i) {
    const double a = levels[i], b = levels[i + 1], m = 0.5 * (a + b);
    const Interval ca = part.a1.alphaCut(a == 0 ? 1e-300 : a), cb = part.a1.alphaCut(b),
                   cm = part.a1.alphaCut(m);
    EXPECT_NEAR(cm.lo, 0.5 * (ca.lo + cb.lo), 1e-12);
    EXPECT_NEAR(cm.hi, 0.5 * (ca.hi + cb.hi), 1e-12);
  }
}

TEST(FuzzyPartTest, ValidationNamesTheBadValue) {
  const auto with = [](auto set) {
    FuzzyPart p;
    set(p);
    return [p] { p.validate(); };
  };
  expectInvalidParameter(with([](FuzzyPart& p) { p.eps1 = tri(0, 1, 2); }), "params.eps1");
  expectInvalidParameter(with([](FuzzyPart& p) { p.eps2 = tri(3, 3.5, 4.5); }), "params.eps2");
  expectInvalidParameter(with([](FuzzyPart& p) { p.a1 = tri(-1, 1, 2); }), "params.a1");
  expectInvalidParameter(with([](FuzzyPart& p) { p.a2 = FuzzyNumber::crisp(0); }), "params.a2");
  expectInvalidParameter(with([](FuzzyPart& p) { p.a3 = tri(0, 0.5, 1); }), "params.a3");
  expectInvalidParameter(with([](FuzzyPart& p) { p.kx = tri(0.5, 1, 1.1); }), "params.kx");
  expectInvalidParameter(with([](FuzzyPart& p) { p.ky = tri(-1.5, 0, 0); }), "params.ky");
  // |kv|·C < π over the whole box: the core alone (kv = 1, C = 2) is valid, the support is not.
  expectInvalidParameter(with([](FuzzyPart& p) {
                           p.a3 = tri(1, 2, 3.5);
                           p.kv = tri(0.5, 1, 1.2);
                         }),
                         "params.kv");
  expectInvalidParameter(with([](FuzzyPart& p) {
                           p.a2 = FuzzyNumber::crisp(1e300);
                           p.a1 = FuzzyNumber::crisp(1e10);
                         }),
                         "params.a2");
  // Fuzzy numbers are finite by construction, so of the placement only the axis and the scale can
  // be out of range.
  expectInvalidParameter(with([](FuzzyPart& p) { p.axis = {NAN, 0, 1}; }), "transform.rotate.axis");
  expectInvalidParameter(with([](FuzzyPart& p) { p.axis = {0, 0, 0}; }), "transform.rotate.axis");
  expectInvalidParameter(with([](FuzzyPart& p) { p.scale = tri(0, 1, 2); }), "transform.scale");
  // A valid fuzzy part passes.
  FuzzyPart ok;
  ok.eps1 = tri(0.1, 1, 4);
  ok.kx = tri(-1, 0, 1);
  ok.a3 = tri(1, 2, 3);
  ok.kv = tri(-1, 0, 1);  // max |kv|·C = 3 < π
  ok.deg = tri(-720, 0, 720);
  ok.validate();
}

}  // namespace
}  // namespace fsdb
