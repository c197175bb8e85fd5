#include "query/linguistic/descriptors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry/superquadric/deformation.h"
#include "query/document/part_json.h"

namespace fsdb {
namespace {

constexpr double kPi = 3.14159265358979323846;

PlacedSuperquadric crispPart(double eps1, double eps2, double a1 = 1, double a2 = 1, double a3 = 1) {
  PlacedSuperquadric p;
  p.params.eps1 = eps1;
  p.params.eps2 = eps2;
  p.params.a1 = a1;
  p.params.a2 = a2;
  p.params.a3 = a3;
  return p;
}

double degreeOf(const std::string& name, const PlacedSuperquadric& p) { return descriptorDegree(descriptorIndex(name), p); }

TEST(Descriptors, NamesInIndexOrder) {
  EXPECT_EQ(descriptorNames(), (std::vector<std::string>{"squariness", "roundness", "bevelness", "pinchness",
                                                          "bendness", "taperness", "twistness", "size",
                                                          "elongation", "section-squariness", "section-roundness",
                                                          "length", "width", "thickness", "height",
                                                          "flatness", "slenderness"}));
  EXPECT_EQ(descriptorIndex("section-roundness"), 10);
  EXPECT_EQ(descriptorNames().size(), kDescriptorsBeforeSections + 2 + 4 + 2);
  EXPECT_EQ(kDescriptorsBeforeProportions, kDescriptorsBeforeMeasures + 4);
  EXPECT_EQ(kDescriptorsBeforeMeasures, kDescriptorsBeforeSections + 2);
  EXPECT_EQ(descriptorIndex("bendness"), 4);
  EXPECT_EQ(descriptorIndex("bentness"), -1);
}

TEST(Descriptors, ShapeWordsFromTheExponents) {
  const auto sphere = crispPart(1, 1), cube = crispPart(0.1, 0.1), octahedron = crispPart(2, 2),
             star = crispPart(4, 4), cylinder = crispPart(0.1, 1);
  EXPECT_DOUBLE_EQ(degreeOf("roundness", sphere), 1.0);
  EXPECT_DOUBLE_EQ(degreeOf("squariness", sphere), 0.0);
  EXPECT_DOUBLE_EQ(degreeOf("squariness", cube), 0.9);
  EXPECT_DOUBLE_EQ(degreeOf("roundness", cube), 0.1);
  EXPECT_DOUBLE_EQ(degreeOf("bevelness", octahedron), 1.0);
  // 0 by the function, read from 0.01 (roundness's degree domain: parts are made round to a degree
  // d with ε = d >= 0.01).
  EXPECT_DOUBLE_EQ(degreeOf("roundness", octahedron), 0.01);
  EXPECT_DOUBLE_EQ(degreeOf("pinchness", star), 1.0);
  EXPECT_DOUBLE_EQ(degreeOf("pinchness", octahedron), 0.0);
  EXPECT_DOUBLE_EQ(degreeOf("squariness", cylinder), 0.45);
  EXPECT_DOUBLE_EQ(degreeOf("roundness", cylinder), 0.55);
}

// Degree domains: within kLeastDegree of an end no part reaches, every degree reads as the end of
// the domain; inside, as the function gives it. Fuzzy values are clamped cut by cut.
TEST(Descriptors, DegreesAreClampedIntoTheirDomains) {
  const auto domain = [](const char* name) { return degreeDomain(descriptorIndex(name)); };
  EXPECT_EQ(domain("squariness").lo, 0.0);
  EXPECT_EQ(domain("squariness").hi, 1.0 - kLeastDegree);
  EXPECT_EQ(domain("section-squariness").hi, 1.0 - kLeastDegree);
  EXPECT_EQ(domain("roundness").lo, kLeastDegree);
  EXPECT_EQ(domain("roundness").hi, 1.0);
  for (const char* name : {"size", "elongation", "length", "width", "thickness", "height"}) {
    EXPECT_EQ(domain(name).lo, kLeastDegree) << name;
    EXPECT_EQ(domain(name).hi, 1.0 - kLeastDegree) << name;
  }
  for (const char* name : {"flatness", "slenderness"}) {
    EXPECT_EQ(domain(name).lo, 0.0) << name;
    EXPECT_EQ(domain(name).hi, 1.0 - kLeastDegree) << name;
  }
  for (const char* name : {"bevelness", "pinchness", "bendness", "taperness", "twistness"}) {
    EXPECT_EQ(domain(name).lo, 0.0) << name;
    EXPECT_EQ(domain(name).hi, 1.0) << name;
  }
  // ε = 0.005 is squariness 0.995 by the function: as square as any part is made.
  EXPECT_DOUBLE_EQ(degreeOf("squariness", crispPart(0.005, 0.005)), 0.99);
  EXPECT_DOUBLE_EQ(degreeOf("squariness", crispPart(0.02, 0.02)), 0.98);
  EXPECT_DOUBLE_EQ(degreeOf("roundness", crispPart(0.005, 0.005)), 0.01);
  EXPECT_DOUBLE_EQ(degreeOf("roundness", crispPart(0.5, 0.5)), 0.5);
  // A part 0.002 across (size 0.001 / 1.001) and one 2000 across.
  EXPECT_DOUBLE_EQ(degreeOf("size", crispPart(1, 1, 0.001)), 0.01);
  EXPECT_DOUBLE_EQ(degreeOf("length", crispPart(1, 1, 1000)), 0.99);
  EXPECT_DOUBLE_EQ(degreeOf("bendness", crispPart(1, 1)), 0.0);  // a [0, 1] domain: 0 stays 0
  // A fuzzy exponent reaching past ε = 0.01: its squariness cuts end at 0.99.
  FuzzyPart part;
  part.eps1 = part.eps2 = FuzzyNumber::triangular(0.002, 0.005, 0.05);
  part.validate();
  const FuzzyNumber square = describePart(part)[size_t(descriptorIndex("squariness"))].value;
  EXPECT_DOUBLE_EQ(square.support().lo, 0.95);
  EXPECT_DOUBLE_EQ(square.support().hi, 0.99);
  EXPECT_DOUBLE_EQ(square.core().lo, 0.99);
}

TEST(Descriptors, DeformationsSizeAndElongation) {
  auto p = crispPart(1, 1, 1, 1, 2);  // C = 2
  p.params.kv = kPi / 8;              // bend angle kv·2C = π/2
  EXPECT_DOUBLE_EQ(degreeOf("bendness", p), 0.5);
  p.params.kv = -kPi / 8;
  EXPECT_DOUBLE_EQ(degreeOf("bendness", p), 0.5);
  p.params.kx = -0.3;
  p.params.ky = 0.6;
  EXPECT_DOUBLE_EQ(degreeOf("taperness", p), 0.6);
  p.params.t = kPi / 2;
  EXPECT_DOUBLE_EQ(degreeOf("twistness", p), 0.5);
  EXPECT_DOUBLE_EQ(degreeOf("size", crispPart(1, 1)), 0.5);
  auto big = crispPart(1, 1, 3);
  EXPECT_DOUBLE_EQ(degreeOf("size", big), 0.75);
  big.placement.scale = 1.0 / 3.0;
  EXPECT_NEAR(degreeOf("size", big), 0.5, 1e-12);
  // The arithmetic mean of the half-lengths: a plate 6 across and 0.1 thick (L = 2.0167) is bigger
  // than a stub 2 across and 1 long (L = 5/6), as people see them.
  const double plate = degreeOf("size", crispPart(1, 1, 3, 1, 0.05 / 3));
  const double stub = degreeOf("size", crispPart(1, 1, 1, 1, 0.5));
  EXPECT_NEAR(plate, 2.0166666666666666 / 3.0166666666666666, 1e-12);
  EXPECT_NEAR(stub, (5.0 / 6.0) / (11.0 / 6.0), 1e-12);
  EXPECT_GT(plate, stub);
  EXPECT_NEAR(degreeOf("elongation", crispPart(1, 1, 1, 1, 1)), 0.5, 1e-15);
  EXPECT_NEAR(degreeOf("elongation", crispPart(1, 1, 1, 1, 5)), 0.9, 1e-15);    // a rod
  EXPECT_NEAR(degreeOf("elongation", crispPart(1, 1, 1, 1, 0.1)), 0.05, 1e-15);  // a plate
  EXPECT_NEAR(degreeOf("elongation", crispPart(1, 1, 1, 5, 1)), 0.9, 1e-15);    // long along y too
}

TEST(Descriptors, EveryDegreeInTheUnitInterval) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> eps(0.01, 4), len(0.01, 10), k(-1, 1), u(0, 1);
  for (int i = 0; i < 2000; ++i) {
    auto p = crispPart(eps(rng), eps(rng), len(rng), len(rng), len(rng));
    p.params.kx = k(rng);
    p.params.ky = k(rng);
    p.params.kv = k(rng) * u(rng) * kPi / p.params.C();
    p.params.t = 10 * k(rng);
    p.placement.scale = len(rng);
    for (size_t d = 0; d < descriptorNames().size(); ++d) {
      const double x = descriptorDegree(static_cast<int>(d), p);
      EXPECT_GE(x, 0.0) << descriptorNames()[d];
      EXPECT_LE(x, 1.0) << descriptorNames()[d];
    }
  }
}

TEST(Descriptors, CrispPartHasCrispValues) {
  FuzzyPart part = FuzzyPart::fromCrisp(crispPart(0.5, 1.5, 2, 1, 3));
  const auto values = describePart(part);
  ASSERT_EQ(values.size(), descriptorNames().size());
  for (size_t d = 0; d < values.size(); ++d) {
    EXPECT_EQ(values[d].descriptor, descriptorNames()[d]);
    EXPECT_TRUE(values[d].value.isCrisp()) << values[d].descriptor;
    EXPECT_DOUBLE_EQ(values[d].value.core().lo, descriptorDegree(static_cast<int>(d), part.coreRepresentative()));
  }
}

// The general path (levels and boxes) agrees with the crisp fast path: a fuzzy translation is
// read by no descriptor.
TEST(Descriptors, FuzzyPlacementOnlyGivesTheCrispValues) {
  FuzzyPart crisp = FuzzyPart::fromCrisp(crispPart(0.5, 1.5, 2, 1, 3));
  FuzzyPart moved = crisp;
  moved.tx = FuzzyNumber::triangular(-1, 0, 1);
  const auto a = describePart(crisp), b = describePart(moved);
  for (size_t d = 0; d < a.size(); ++d) EXPECT_EQ(a[d].value, b[d].value) << a[d].descriptor;
}

// The alpha-cut of a descriptor value is the image of P(α): it holds the degree of every crisp
// part sampled in the box, and its ends are reached (by the corners and critical values).
// The traverse section reads eps2 alone (Zhang, Pham & Chen, §2.1): a cylinder's section is round
// and a pyramid's or a box's square, whatever their profiles.
TEST(Descriptors, SectionDescriptorsReadTheTraverseSectionAlone) {
  const auto cylinder = crispPart(0.1, 1), box = crispPart(0.1, 0.1), sphere = crispPart(1, 1),
             squareBarrel = crispPart(1, 0.1), octahedron = crispPart(2, 2);
  EXPECT_DOUBLE_EQ(degreeOf("section-roundness", cylinder), 1.0);
  EXPECT_DOUBLE_EQ(degreeOf("section-squariness", cylinder), 0.0);
  EXPECT_DOUBLE_EQ(degreeOf("section-squariness", box), 0.9);
  EXPECT_DOUBLE_EQ(degreeOf("section-roundness", box), 0.1);
  EXPECT_DOUBLE_EQ(degreeOf("section-roundness", sphere), 1.0);
  // The profile (eps1) does not move them.
  EXPECT_DOUBLE_EQ(degreeOf("section-squariness", squareBarrel), degreeOf("section-squariness", box));
  EXPECT_DOUBLE_EQ(degreeOf("section-roundness", octahedron), 0.01);  // its degree domain's end
  // Fuzzy eps2 across the peak of ro at 1: the exact image, core 1.
  FuzzyPart part;
  part.eps2 = FuzzyNumber::triangular(0.5, 1.0, 1.5);
  part.validate();
  const auto values = describePart(part);
  const FuzzyNumber& round = values[size_t(descriptorIndex("section-roundness"))].value;
  EXPECT_NEAR(round.core().lo, 1.0, 1e-12);
  EXPECT_NEAR(round.support().lo, 0.5, 1e-12);
  EXPECT_NEAR(round.support().hi, 1.0, 1e-12);
}

TEST(Descriptors, FuzzyValuesAreTheImageOfTheParameterBox) {
  FuzzyPart part;
  part.eps1 = FuzzyNumber::triangular(0.5, 1.0, 2.5);  // crosses the critical values 1 and 2
  part.eps2 = FuzzyNumber::triangular(0.05, 0.2, 0.4);
  part.a1 = FuzzyNumber::triangular(0.8, 1, 1.2);
  part.a2 = FuzzyNumber::triangular(0.5, 1, 3);
  part.a3 = FuzzyNumber::triangular(0.8, 1.5, 2);  // a2 = a3 inside the box
  part.kv = FuzzyNumber::triangular(-0.2, 0.1, 0.3);
  part.kx = FuzzyNumber::triangular(-0.5, 0, 0.2);
  part.t = FuzzyNumber::triangular(0.5, 1, 2);
  part.scale = FuzzyNumber::triangular(0.5, 1, 2);
  part.validate();
  const auto values = describePart(part);
  std::mt19937 rng(3);
  for (double alpha : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const PartBox box = part.boxAt(alpha);
    // Each value at an end of its interval a third of the time each, so corners are sampled too.
    auto pick = [&rng](const Interval& i) {
      const int end = std::uniform_int_distribution<int>(0, 2)(rng);
      return end == 0 ? i.lo : end == 1 ? i.hi : std::uniform_real_distribution<double>(i.lo, i.hi)(rng);
    };
    for (size_t d = 0; d < values.size(); ++d) {
      const Interval cut = values[d].value.alphaCut(alpha);
      double seenLo = 1e9, seenHi = -1e9;
      for (int s = 0; s < 3000; ++s) {
        PlacedSuperquadric p;
        p.params = {pick(box.params.eps1), pick(box.params.eps2), pick(box.params.a1), pick(box.params.a2),
                    pick(box.params.a3),   pick(box.params.kx),   pick(box.params.ky), pick(box.params.kv),
                    pick(box.params.t)};
        p.placement.scale = pick(box.placement.scale);
        const double x = descriptorDegree(static_cast<int>(d), p);
        EXPECT_GE(x, cut.lo - 1e-9) << values[d].descriptor << " alpha " << alpha;
        EXPECT_LE(x, cut.hi + 1e-9) << values[d].descriptor << " alpha " << alpha;
        seenLo = std::min(seenLo, x);
        seenHi = std::max(seenHi, x);
      }
      // Sampling comes close to both ends: the cut is not wider than the image.
      EXPECT_NEAR(seenLo, cut.lo, 0.02) << values[d].descriptor << " alpha " << alpha;
      EXPECT_NEAR(seenHi, cut.hi, 0.02) << values[d].descriptor << " alpha " << alpha;
    }
  }
  // The critical values are found exactly: roundness reaches 1 where eps1 = 1 is in the box.
  EXPECT_DOUBLE_EQ(descriptorRange(1, part.boxAt(0)).hi, (1.0 + 0.4) / 2.0);
  EXPECT_DOUBLE_EQ(descriptorRange(4, part.boxAt(1)).lo, descriptorDegree(4, part.coreRepresentative()));
  EXPECT_DOUBLE_EQ(descriptorRange(4, part.boxAt(0)).lo, 0.0);  // kv = 0 inside the support
}

TEST(Descriptors, Deterministic) {
  FuzzyPart part;
  part.kv = FuzzyNumber::triangular(0.05, 0.1, 0.15);
  const auto a = describePart(part), b = describePart(part);
  for (size_t d = 0; d < a.size(); ++d) EXPECT_EQ(a[d].value, b[d].value);
}

}  // namespace
}  // namespace fsdb

namespace fsdb {
namespace {

// The measure descriptors: a part's extents in world units (2·scale·A, B, C), sorted for length,
// width and thickness, along z for height, as e / (1 + e); exact ranges over boxes at the corners.
TEST(Descriptors, MeasuresAreTheExtentsInWorldUnits) {
  PlacedSuperquadric rod;  // a1 0.5, a2 1, a3 10, scale 2: extents 2 x 2 x 20
  rod.params.a1 = 0.5;
  rod.params.a3 = 10;
  rod.placement.scale = 2;
  EXPECT_DOUBLE_EQ(degreeOf("length", rod), extentDegree(20));
  EXPECT_DOUBLE_EQ(degreeOf("width", rod), extentDegree(2));
  EXPECT_DOUBLE_EQ(degreeOf("thickness", rod), extentDegree(2));
  EXPECT_DOUBLE_EQ(degreeOf("height", rod), extentDegree(20));
  PlacedSuperquadric board;  // a1 4, a2 0.25, a3 0.05: extents 8 x 2 x 0.4; its height is along z
  board.params.a1 = 4;
  board.params.a2 = 0.25;
  board.params.a3 = 0.05;
  EXPECT_DOUBLE_EQ(degreeOf("length", board), extentDegree(8));
  EXPECT_DOUBLE_EQ(degreeOf("width", board), extentDegree(2));
  EXPECT_DOUBLE_EQ(degreeOf("thickness", board), extentDegree(0.4));
  EXPECT_DOUBLE_EQ(degreeOf("height", board), extentDegree(0.4));
  EXPECT_DOUBLE_EQ(extentDegree(3), 0.75);
  EXPECT_DOUBLE_EQ(extentDegree(0), 0.0);
  // Over a box the range is the corners' (the extents rise with every parameter): a3 in [1, 3]
  // crosses a2 = 2, where the sorted order swaps, and still the corners hold the extremes.
  PartBox box = crispPartBox(PlacedSuperquadric{});  // a1 1, scale 1
  box.params.a2 = Interval{2, 2};
  box.params.a3 = Interval{1, 3};
  const Interval width = descriptorRange(descriptorIndex("width"), box);
  EXPECT_DOUBLE_EQ(width.lo, extentDegree(2));  // a3 = 1: extents 2, 2, 4
  EXPECT_DOUBLE_EQ(width.hi, extentDegree(4));  // a3 = 3: extents 2, 4, 6
  const Interval length = descriptorRange(descriptorIndex("length"), box);
  EXPECT_DOUBLE_EQ(length.lo, extentDegree(4));
  EXPECT_DOUBLE_EQ(length.hi, extentDegree(6));
}

// The proportions: flatness = 1 − s1/s2 and slenderness = 1 − s2/s3 of the sorted half-lengths,
// whatever the axis order, the size or the scale. A board is both, where elongation puts it
// between a plate and a rod.
TEST(Descriptors, ProportionsSayFlatAndLong) {
  const auto part = [](double a1, double a2, double a3, double scale) {
    PlacedSuperquadric p;
    p.params.a1 = a1;
    p.params.a2 = a2;
    p.params.a3 = a3;
    p.placement.scale = scale;
    return p;
  };
  const PlacedSuperquadric board = part(4, 0.125, 0.025, 1);  // 8 x 1 x 0.2
  EXPECT_DOUBLE_EQ(degreeOf("flatness", board), 1 - 0.2 / 1.0);
  EXPECT_DOUBLE_EQ(degreeOf("slenderness", board), 1 - 1.0 / 8.0);
  EXPECT_NEAR(degreeOf("elongation", board), 0.5375, 1e-12);
  const PlacedSuperquadric rod = part(0.2, 1, 10, 3);  // a round section ten times shorter
  EXPECT_DOUBLE_EQ(degreeOf("flatness", rod), 0.0);
  EXPECT_DOUBLE_EQ(degreeOf("slenderness", rod), 0.9);
  const PlacedSuperquadric plate = part(1, 1, 0.1, 0.5);
  EXPECT_DOUBLE_EQ(degreeOf("flatness", plate), 0.9);
  EXPECT_DOUBLE_EQ(degreeOf("slenderness", plate), 0.0);
  const PlacedSuperquadric cube = part(2, 1, 1, 1);
  EXPECT_DOUBLE_EQ(degreeOf("flatness", cube), 0.0);
  EXPECT_DOUBLE_EQ(degreeOf("slenderness", cube), 0.0);
  // The same board along another axis order (its length on B, its thickness on A).
  const PlacedSuperquadric turned = part(0.1, 40, 5, 1);  // 0.2 x 8 x 1
  EXPECT_DOUBLE_EQ(degreeOf("flatness", turned), degreeOf("flatness", board));
  EXPECT_DOUBLE_EQ(degreeOf("slenderness", turned), degreeOf("slenderness", board));
  // Over a box where a2 and a3 pass each other and 1, the range is found exactly: slenderness
  // is 0 where a2 = a3 = 1 is in the box, and its largest where a3 is longest over a2 near 1.
  PartBox box = crispPartBox(PlacedSuperquadric{});
  box.params.a2 = Interval{0.5, 2};
  box.params.a3 = Interval{0.8, 4};
  const Interval slender = descriptorRange(descriptorIndex("slenderness"), box);
  EXPECT_DOUBLE_EQ(slender.lo, 0.0);
  EXPECT_DOUBLE_EQ(slender.hi, 1 - 1.0 / 4.0);
  const Interval flat = descriptorRange(descriptorIndex("flatness"), box);
  EXPECT_DOUBLE_EQ(flat.lo, 0.0);
  EXPECT_DOUBLE_EQ(flat.hi, 1 - 0.5 / 1.0);
}

// A fuzzy extent's set over the degrees: the image of its cuts, exact at each level.
TEST(Descriptors, ExtentDegreeSetMapsEveryCut) {
  const FuzzyNumber about10 = FuzzyNumber::triangular(9, 10, 11);
  const FuzzyNumber set = extentDegreeSet(about10);
  for (double a : {0.0, 0.25, 0.5, 1.0}) {
    const Interval cut = about10.alphaCut(a), image = set.alphaCut(a);
    EXPECT_NEAR(image.lo, extentDegree(cut.lo), 1e-12) << a;
    EXPECT_NEAR(image.hi, extentDegree(cut.hi), 1e-12) << a;
  }
  EXPECT_TRUE(extentDegreeSet(FuzzyNumber::crisp(3)).isCrisp());
  EXPECT_DOUBLE_EQ(extentDegreeSet(FuzzyNumber::crisp(3)).core().lo, 0.75);
}

}  // namespace
}  // namespace fsdb

namespace fsdb {
namespace {

// A taper widens the section the measures read: a sharp cone's width is its base's diameter, and
// its height stays its axis. A fuzzy taper through 0 gives the untapered width at the cut's low end.
// A part of the 1M bench catalogue stayed pending: the low corner of one measure's cut came out an
// ulp above the high corner's (the taper's factor is found by bisection), and the cut was refused.
TEST(Descriptors, MeasureCutsAreOrderedWhereTheCornersRoundApart) {
  // The catalogue part's document as stored (part-0051473).
  const FuzzyPart part = parsePart(nlohmann::json::parse(R"({"kind":"part","params":{
      "a1":1.8036378250230751,"a2":1.6380837991356665,"a3":1.8101651131858043,
      "eps1":1.9405747382606588,"eps2":2.436026147387037,
      "kv":{"tri":[0.07280637506245109,0.07898570607162232,0.08516503708079355]},
      "kx":{"tri":[0.3175102602423413,0.37088878626040495,0.4242673122784686]},"ky":0.0,"t":0.0}})"),
                                  "");
  std::vector<DescriptorValue> values;
  ASSERT_NO_THROW(values = describePart(part));
  for (const DescriptorValue& v : values) EXPECT_LE(v.value.support().lo, v.value.support().hi) << v.descriptor;
}

TEST(Descriptors, MeasuresReadTheTaperedSection) {
  PlacedSuperquadric cone;  // the catalogue's sharp cone: A 0.5, C 1.5, tapered to a point
  cone.params.eps1 = 0.1;
  cone.params.a1 = 0.5;
  cone.params.a3 = 3;
  cone.params.kx = cone.params.ky = -1;
  const double base = 2 * 0.5 * taperedHalfWidthFactor(0.1, -1);
  EXPECT_NEAR(base, 1.9075, 1e-4);
  EXPECT_DOUBLE_EQ(degreeOf("width", cone), extentDegree(base));
  EXPECT_DOUBLE_EQ(degreeOf("thickness", cone), extentDegree(base));
  EXPECT_DOUBLE_EQ(degreeOf("length", cone), extentDegree(3));
  EXPECT_DOUBLE_EQ(degreeOf("height", cone), extentDegree(3));
  // A wedge (tapered along x alone) is wider across x only.
  PlacedSuperquadric wedge = cone;
  wedge.params.ky = 0;
  wedge.params.a3 = 0.8;  // C 0.4: the base (0.95 by 0.5) is longer than the height
  EXPECT_DOUBLE_EQ(degreeOf("length", wedge), extentDegree(base));
  EXPECT_DOUBLE_EQ(degreeOf("width", wedge), extentDegree(1.0));
  EXPECT_DOUBLE_EQ(degreeOf("thickness", wedge), extentDegree(0.8));
  FuzzyPart fuzzy;
  fuzzy.eps1 = FuzzyNumber::crisp(0.1);
  fuzzy.kx = fuzzy.ky = FuzzyNumber::triangular(-0.5, 0, 0.5);
  const Interval width = descriptorRange(descriptorIndex("width"), fuzzy.boxAt(0));
  EXPECT_DOUBLE_EQ(width.lo, extentDegree(2));
  EXPECT_DOUBLE_EQ(width.hi, extentDegree(2 * taperedHalfWidthFactor(0.1, 0.5)));
}

}  // namespace
}  // namespace fsdb
