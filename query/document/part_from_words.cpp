#include "query/document/part_from_words.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>

#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_arithmetic.h"
#include "geometry/fuzzy/fuzzy_similarity.h"
#include "geometry/numeric/piecewise_linear.h"
#include "geometry/superquadric/deformation.h"
#include "query/linguistic/degree_sets.h"
#include "query/linguistic/descriptors.h"
#include "query/linguistic/edges.h"
#include "query/linguistic/linguistic_query.h"
#include "query/document/part_json.h"
#include "query/linguistic/vocabulary.h"
#include "query/linguistic/word_routes.h"

namespace fsdb {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The order in which adjectives act (see the header): the shape, then its size, its taper and
// extents, then the bend and twist (a bend's degree is its angle over the length the extents gave;
// the taper widens the section the extents measure, descriptors.h, so it comes before them).
const std::vector<std::string> kOrder = {"squariness", "roundness", "bevelness", "pinchness",
                                         "section-squariness", "section-roundness", "elongation",
                                         "slenderness", "flatness", "size",    "taperness", "length",
                                         "width",      "thickness", "height",   "bendness",  "twistness"};

bool isExtent(const std::string& descriptor) {
  return descriptor == "length" || descriptor == "width" || descriptor == "thickness" || descriptor == "height";
}

FuzzyNumber affine(const FuzzyNumber& d, double slope, double offset) {
  return add(scale(d, slope), FuzzyNumber::crisp(offset));
}

// The degrees a part made from words takes for a descriptor whose end is a size or a ratio no
// part has (d = L / (1 + L) is 1 only for L infinite): the set read over the descriptor's domain
// (degreeDomain, descriptors.h: within kLeastDegree of such an end), cut, not squeezed
// (withinDegrees, as the search reads the words), and a set whose core lies wholly beyond an end
// that end, crisp. The search reads the words' sets over the same domain, so the part satisfies
// its words fully. The price is an extreme part's size: an extremely large part is up to 99 units
// across, an extremely long one up to 100 times its width.
FuzzyNumber realizableDegrees(const std::string& descriptor, const FuzzyNumber& d) {
  const Interval domain = degreeDomain(descriptorIndex(descriptor));
  const Interval core = d.core();
  // A set wholly beyond an end (a vocabulary's create set crisp at 1) is that end, crisp.
  if (core.lo >= domain.hi) return FuzzyNumber::crisp(domain.hi);
  if (core.hi <= domain.lo) return FuzzyNumber::crisp(domain.lo);
  return withinDegrees(d, domain.lo, domain.hi);
}

// f increasing: the set's image under f, its pieces sampled at the levels describePart reads
// (every 1/kDescriptorLevels, and the part's breakpoint levels, which are the set's own: every
// piece is sampled at the levels of every breakpoint) as well as at its breakpoints. f is not
// affine (a size is d / (1 − d)), so the image of a piece is a curve; a number through the images
// of the breakpoints alone has alpha-cuts that, read back through f's inverse, bow away from the
// set (an extremely large part read 0.66 for its own words). Through these points the part's
// descriptor is the set at every level it is read at. (Without the breakpoint levels, "a slightly
// big ball", whose set is cut at size 0.01 where its membership is 0.1, read 0.999996 for its own
// words: the falling side was read at level 0.1 between two samples.)
template <typename F>
FuzzyNumber mapIncreasing(const FuzzyNumber& d, F f) {
  const std::vector<Breakpoint>& in = d.breakpoints();
  std::vector<double> levels;
  for (int k = 1; k < kDescriptorLevels; ++k) levels.push_back(static_cast<double>(k) / kDescriptorLevels);
  for (const Breakpoint& b : in) levels.push_back(b.mu);
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  std::vector<Breakpoint> points;
  for (size_t i = 0; i < in.size(); ++i) {
    if (i > 0 && in[i - 1].mu != in[i].mu && in[i - 1].x != in[i].x) {
      const Breakpoint& a = in[i - 1];
      const Breakpoint& b = in[i];
      const bool rising = b.mu > a.mu;
      for (size_t k = 0; k < levels.size(); ++k) {
        const double mu = rising ? levels[k] : levels[levels.size() - 1 - k];
        if (mu <= std::min(a.mu, b.mu) || mu >= std::max(a.mu, b.mu)) continue;
        points.push_back({a.x + (mu - a.mu) / (b.mu - a.mu) * (b.x - a.x), mu});
      }
    }
    points.push_back(in[i]);
  }
  for (Breakpoint& p : points) p.x = f(p.x);
  return FuzzyNumber::fromPoints(points);
}

// The exponent descriptors: ε = max(kMinExponent, slope·d + offset), the inverse of the
// descriptor's function (descriptors.h: squariness 1 − ε, roundness ε below 1, bevelness ε − 1,
// pinchness (ε − 2)/2), so a part made "moderately round" is exactly as round as the words say,
// except where ε would fall under the smallest exponent a part is made with, 0.01 (a box's
// edges, not a cube's corners of zero radius). Squariness 1 is ε = 0, which no part has, as a
// size's degree 1 is an infinite size (realizableDegrees): squariness is read up to 0.99 and
// roundness from 0.01 (degreeDomain), the degrees ε >= 0.01 gives, so an extremely square part
// satisfies its words fully. A
// whole-shape one sets ε1 and ε2; a section one sets ε2 alone, after the whole shape ("a round
// box with a square section"), by the rule of its whole-shape descriptor
// (Vocabulary::wholeShapeDescriptor).
struct ExponentRule {
  const char* descriptor;
  double slope, offset;
};
constexpr ExponentRule kExponentRules[] = {
    {"squariness", -1.0, 1.0}, {"roundness", 1.0, 0.0}, {"bevelness", 1.0, 1.0}, {"pinchness", 2.0, 2.0}};
constexpr double kMinExponent = kLeastDegree;  // squariness <= 0.99, roundness >= 0.01

// The rule of an exponent-shape descriptor, or nullptr for any other descriptor.
const ExponentRule* exponentRule(const std::string& descriptor) {
  for (const ExponentRule& rule : kExponentRules)
    if (descriptor == rule.descriptor) return &rule;
  return nullptr;
}

// The image of the degree d under ε = max(kMinExponent, slope·d + offset) by the extension
// principle: the affine image with the part under kMinExponent gathered at it (a breakpoint put
// where a segment crosses it, so the image is exact, not a chord over the kink).
FuzzyNumber exponentOf(const FuzzyNumber& d, double slope, double offset) {
  const FuzzyNumber e = affine(d, slope, offset);
  std::vector<Breakpoint> points;
  const std::vector<Breakpoint>& in = e.breakpoints();
  for (size_t i = 0; i < in.size(); ++i) {
    if (i > 0) {
      const Breakpoint& a = in[i - 1];
      const Breakpoint& b = in[i];
      if (a.x < kMinExponent - 1e-12 && b.x > kMinExponent + 1e-12) {
        const double t = (kMinExponent - a.x) / (b.x - a.x);
        points.push_back({kMinExponent, a.mu + t * (b.mu - a.mu)});
      }
    }
    // Within rounding of the smallest exponent is at it (1 − 0.99 is 0.010000000000000009).
    points.push_back({in[i].x < kMinExponent + 1e-12 ? kMinExponent : in[i].x, in[i].mu});
  }
  // Points gathered at kMinExponent keep the highest membership among them (the sup of the image).
  std::vector<Breakpoint> out;
  double gathered = -1.0;
  for (const Breakpoint& p : points) {
    if (p.x == kMinExponent) {
      gathered = std::max(gathered, p.mu);
      continue;
    }
    if (gathered >= 0.0) {
      out.push_back({kMinExponent, gathered});
      gathered = -1.0;
    }
    out.push_back(p);
  }
  if (gathered >= 0.0) out.push_back({kMinExponent, gathered});
  return FuzzyNumber::fromPoints(out);
}

// The edge exponents of `noun` (edgeExponentsOf) at degree `d` of the vocabulary's edge
// descriptor, through that descriptor's exponent rule; the others as they are.
void realizeEdges(const FuzzyNumber& d, const Noun& noun, const Vocabulary& vocabulary, FuzzyPart* part) {
  const ExponentRule* rule = exponentRule(vocabulary.edgeDescriptor());
  if (!rule) return;  // the vocabulary checks that its edge descriptor is an exponent shape
  const EdgeExponents edges = edgeExponentsOf(&noun);
  const FuzzyNumber e = exponentOf(d, rule->slope, rule->offset);
  if (edges.eps1) part->eps1 = e;
  if (edges.eps2) part->eps2 = e;
}

// A section descriptor is found through the vocabulary's sections map (section-squariness is
// squariness's), not by its name.
void realize(const std::string& descriptor, const FuzzyNumber& d, const Vocabulary& vocabulary, FuzzyPart* part) {
  const std::string* whole = vocabulary.wholeShapeDescriptor(descriptor);
  const std::string& shape = whole ? *whole : descriptor;
  if (const ExponentRule* rule = exponentRule(shape)) {
    part->eps2 = exponentOf(d, rule->slope, rule->offset);
    if (!whole) part->eps1 = part->eps2;
  }
  if (descriptor == "elongation") {
    part->a2 = FuzzyNumber::crisp(1.0);
    part->a3 = mapIncreasing(realizableDegrees(descriptor, d), [](double x) { return x < 0.5 ? 2.0 * x : 1.0 / (2.0 - 2.0 * x); });
  }
  // The proportions act on B and C (A = a1 is the unit they are measured in): flatness on the
  // shorter, slenderness on the longer (C on a tie, so "a flat sphere" is squashed along its z axis
  // and "a long sphere" stretched along it, the axis its bend and taper follow). With the half-lengths
  // 1 : a2 : a3, slenderness sets the longer to the middle of the three over (1 − d), and flatness
  // the shorter to (1 − d) times the middle. Slenderness goes first: it leaves the middle at 1 (A),
  // where flatness then measures from, so "a long flat board" is d_s slender and d_f flat at their
  // cores (flatness first would measure from a board's width, which slenderness then moves).
  if (descriptor == "flatness" || descriptor == "slenderness") {
    const SuperquadricParams now = part->coreRepresentative().params;
    const bool cLonger = now.a3 >= now.a2;
    FuzzyNumber* longer = cLonger ? &part->a3 : &part->a2;
    FuzzyNumber* shorter = cLonger ? &part->a2 : &part->a3;
    const double longerCore = cLonger ? now.a3 : now.a2, shorterCore = cLonger ? now.a2 : now.a3;
    if (descriptor == "flatness") {
      const double middle = std::min(1.0, longerCore);  // of 1, the longer, and the shorter set below it
      *shorter = mapIncreasing(negate(realizableDegrees(descriptor, d)), [middle](double x) { return middle * (1.0 + x); });
    } else {
      const double middle = std::max(1.0, shorterCore);
      *longer = mapIncreasing(realizableDegrees(descriptor, d), [middle](double x) { return middle / (1.0 - x); });
    }
  }
  const SuperquadricParams core = part->coreRepresentative().params;  // the size so far
  if (descriptor == "bendness") part->kv = scale(d, kPi / (2.0 * core.a1 * core.a3));
  if (descriptor == "taperness") part->kx = part->ky = negate(d);
  if (descriptor == "twistness") part->t = scale(d, kPi);
  if (descriptor == "size") {
    const double l = core.a1 * (1.0 + core.a2 + core.a3) / 3.0;  // descriptors.h: the mean half-length
    part->scale = mapIncreasing(realizableDegrees(descriptor, d), [l](double x) { return x / (1.0 - x) / l; });
  }
}

// The part's axes set to the extents asked for (world units: descriptors.h's length, width,
// thickness and height). The noun's axes at its core, sorted by half-length (ties in the order
// A, B, C), say which axis is the thickness, the width and the length; height is the z axis (C).
// An axis as long as a measured one (a round section, a square plate) takes the same extent
// unless it is measured itself. A = a1 and B, C = a1·a2, a1·a3: a1 takes A's extent and a2, a3
// are B's and C's divided by a1's core, so they are exact when a1 is crisp; A keeps its spread only
// when no other axis is measured (below). `keepProportions`: the words keep the noun's condition
// on its proportions (PartDescription::keepsProportions), so one extent asked for scales the whole
// part ("a wide rod" is a thicker rod, still a rod; widening its section alone made it a stub).
// The half-lengths compared and set are the extents' (descriptors.h): A and B widened by the taper
// at its core (fx, fy), so "a cone 2 across" has a base 2 across; a1 and a2 are divided by them.
void realizeExtents(const std::map<std::string, FuzzyNumber>& extents, bool keepProportions, FuzzyPart* part) {
  if (extents.empty()) return;
  const PlacedSuperquadric core = part->coreRepresentative();
  const double s = core.placement.scale;
  const double fx = taperedHalfWidthFactor(core.params.eps1, core.params.kx);
  const double fy = taperedHalfWidthFactor(core.params.eps1, core.params.ky);
  const double half[3] = {core.params.a1 * fx, core.params.a1 * core.params.a2 * fy, core.params.a1 * core.params.a3};
  // The roles follow the extents' order (a sharp cone's widened base is wider than its default
  // height). A measured height names the z axis itself, so the roles said beside it go to A and B:
  // "a cone 4 x 2 x 1" reads its axis as the height (turnAxialLength), 4, and its base as 2 by 1.
  const bool heightNamed = extents.count("height") > 0;
  int order[3] = {0, 1, 2};
  std::stable_sort(order, order + (heightNamed ? 2 : 3), [&](int a, int b) { return half[a] < half[b]; });
  std::optional<FuzzyNumber> target[3];  // half-extents of A, B, C (A and B widened by the taper)
  const auto halfOf = [s](const FuzzyNumber& e) { return scale(e, 0.5 / s); };
  const char* sorted[3] = {"thickness", "width", "length"};
  std::vector<int> said;  // the roles measured, shortest first
  for (int k = 0; k < 3; ++k)
    if (extents.count(sorted[k])) said.push_back(k);
  for (size_t i = 0; i < said.size(); ++i) {
    int at = said[i];
    // Beside a height, two axes for up to three roles: the shortest role said takes the shorter,
    // the longest the longer (a thickness alone the shorter, a width or length alone the longer).
    if (heightNamed) {
      if (said.size() > 2 && i == 1) continue;
      at = said.size() == 1 ? (said[0] == 0 ? 0 : 1) : (i == 0 ? 0 : 1);
    }
    target[order[at]] = halfOf(extents.at(sorted[said[i]]));
  }
  // An unmeasured axis as long as measured ones follows the nearest in the sorted order, so the
  // roles stay in order: a ball "1 across and 0.2 thick" is a disc, its third axis the width's,
  // not the thickness's (which made the width the longest extent, and the words missed the part).
  int tieOf[3] = {-1, -1, -1};
  int position[3];
  for (int k = 0; k < 3; ++k) position[order[k]] = k;
  for (int k = 0; k < 3; ++k) {
    if (target[k]) continue;
    int nearest = -1;
    for (int j = 0; j < 3; ++j)
      if (j != k && target[j] && tieOf[j] < 0 && std::fabs(half[k] - half[j]) <= 1e-9 * std::max(half[k], half[j]) &&
          (nearest < 0 || std::abs(position[j] - position[k]) < std::abs(position[nearest] - position[k])))
        nearest = j;
    if (nearest >= 0) {
      target[k] = target[nearest];
      tieOf[k] = nearest;
    }
  }
  if (extents.count("height")) {
    target[2] = halfOf(extents.at("height"));
    tieOf[2] = -1;
  }
  // One measure for all three axes (a ball's radius, a cube's side): the noun's proportions
  // stay, and the transform's scale carries the extent's spread, which moves the three together.
  const auto group = [&](int k) { return tieOf[k] < 0 ? k : tieOf[k]; };
  const auto same = [&](int j, int k) {
    return group(j) == group(k) ||
           (target[j] && target[k] && *target[j] == *target[k] && std::fabs(half[j] - half[k]) <= 1e-9 * half[j]);
  };
  // The whole part scaled so that the axes of group g take their target; the proportions stay.
  const auto scaleWhole = [&](int g) {
    const FuzzyNumber& t = *target[g];
    const double mid = (t.core().lo + t.core().hi) / 2.0;
    const double factor = mid / half[g];
    part->a1 = FuzzyNumber::crisp(core.params.a1 * factor);
    part->scale = scale(scale(t, 1.0 / mid), s);
  };
  if (target[0] && target[1] && target[2] && same(0, 1) && same(1, 2)) return scaleWhole(group(0));
  if (keepProportions) {
    int first = -1;
    bool single = true;  // every axis asked for is in one group
    for (int k = 0; k < 3; ++k)
      if (target[k]) {
        if (first >= 0 && !same(k, first)) single = false;
        if (first < 0) first = k;
      }
    if (first >= 0 && single) return scaleWhole(group(first));
  }
  // One group measured whose target would pass an axis it is not measured with ("an extremely
  // thick disc": a thickness of 19 units or more, beside a diameter of 2): the axes would change
  // their sorted roles, and the extent read back (descriptors.h: the shortest, middle and longest)
  // would be another axis's, so the words would not find the part. The whole part is scaled
  // instead, its proportions kept: a disc that thick is a large disc. Height names the z axis, not
  // a role, and is never passed.
  int measured = -1;
  bool one = !extents.count("height");
  for (int k = 0; k < 3; ++k)
    if (target[k]) {
      if (measured >= 0 && !same(k, measured)) one = false;
      if (measured < 0) measured = k;
    }
  if (one && measured >= 0) {
    const Interval support = target[measured]->support();
    bool passes = false;
    for (int j = 0; j < 3; ++j)
      if (!target[j])
        passes = passes || (half[j] >= half[measured] ? support.hi > half[j] : support.lo < half[j]);
    if (passes) return scaleWhole(measured);
  }
  // An unmeasured axis keeps its length, within its role: no longer than any value of a measured
  // axis of a later role, no shorter than any of an earlier one (a box "1 wide and 2 long" keeps
  // its thickness 1.4 no longer, which would make it the width; a bar "4 across" has its length
  // past the width's whole spread, which the sorted extents would clip otherwise).
  for (int k = 0; k < 3; ++k) {
    if (target[k]) continue;
    double lo = 0, hi = std::numeric_limits<double>::infinity();
    for (int j = 0; j < 3; ++j) {
      if (!target[j]) continue;
      if (position[j] < position[k]) lo = std::max(lo, target[j]->support().hi);
      if (position[j] > position[k]) hi = std::min(hi, target[j]->support().lo);
    }
    if (lo <= hi && (half[k] < lo || half[k] > hi)) target[k] = FuzzyNumber::crisp(std::clamp(half[k], lo, hi));
  }
  // B and C scale with a1, and the part's values are independent fuzzy numbers: a fuzzy a1 would
  // spread every other axis by its cut. So A keeps a spread only when its group (A and the axes
  // as long as it) is all that is measured; beside another group's measure, A's group takes its
  // core's midpoint (a round section stays round, and crisp).
  bool othersMeasured = false;
  for (int k = 1; k < 3; ++k) othersMeasured = othersMeasured || (target[k] && group(k) != group(0));
  if (target[0] && !target[0]->isCrisp() && othersMeasured) {
    const FuzzyNumber mid = FuzzyNumber::crisp((target[0]->core().lo + target[0]->core().hi) / 2.0);
    for (int k = 0; k < 3; ++k)
      if (group(k) == group(0)) target[k] = mid;
  }
  const FuzzyNumber a1 = target[0] ? scale(*target[0], 1.0 / fx) : part->a1;
  const double a1Core = (a1.core().lo + a1.core().hi) / 2.0;
  const double was = core.params.a1;
  // An axis of A's group while A keeps a spread is as long as A: its ratio is 1, crisp. Its target
  // over a1's core (as for the others) would be a second spread on top of a1's: B = a1·a2 of two
  // independent numbers, twice as wide as the words ("a moderately narrow puck" read 0.71).
  const auto ratio = [&](int k, const FuzzyNumber& was_k) {
    if (!target[k]) return scale(was_k, was / a1Core);
    if (!a1.isCrisp() && group(k) == group(0)) return FuzzyNumber::crisp(1.0);
    return scale(*target[k], 1.0 / (a1Core * (k == 1 ? fy : 1.0)));
  };
  part->a2 = ratio(1, part->a2);
  part->a3 = ratio(2, part->a3);
  part->a1 = a1;
}

// The description of `text`; a word the grammar lacks is routed onto the vocabulary first
// (word_routes.h: "a skinny pole" is "a thin pole"), and when the text does not read even so, the
// error is the one for the words as written.
PartDescription describedPart(const std::string& text, const Vocabulary& vocabulary) {
  try {
    return parsePartDescription(text, vocabulary);
  } catch (const Error& asWritten) {
    if (asWritten.code() != errc::kInvalidParameter) throw;
    const auto known = [&](const std::string& w) { return knowsLinguisticWord(w, vocabulary); };
    const std::optional<RoutedText> routed = routeUnknownWords(text, vocabulary, systemWordNet(), known);
    if (!routed) throw;
    try {
      return parsePartDescription(routed->text, vocabulary);
    } catch (const Error&) {
      throw asWritten;
    }
  }
}

// A plain adjective beside a noun condition on its descriptor that the words keep: the query asks
// for both (min), so the part takes one degree, the middle of where both are highest. That is 1
// where their cores meet ("a flat board"); "a tapered cylinder" asks for more taper than the
// cylinder's "hardly tapered" holds, and its part is as tapered as the two allow together.
FuzzyNumber degreeForNoun(const Adjective& adjective, const FuzzyNumber& nounSet, const Vocabulary& vocabulary) {
  const std::vector<Breakpoint> both =
      pointwiseMin(nounSet.breakpoints(), vocabulary.plainSet(adjective).breakpoints());
  const double top = height(both);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Breakpoint& b : both)
    if (b.mu == top) {
      lo = std::min(lo, b.x);
      hi = std::max(hi, b.x);
    }
  return FuzzyNumber::crisp(0.5 * (lo + hi));
}

// An exponent word beside a noun whose own exponent shape the words keep ("a round box", the
// paper's rounded box; "a boxy ball", the boxiest ball): the query asks for both, and the shape
// the word alone makes ("round": an ellipsoid) can score 0 for the noun, so the part's words did
// not find it at all. The part's exponents then move along the path the word sets (eps1 = eps2 =
// e for a whole-shape word; for a section word eps2, then eps1, then eps2 again) to where the
// words themselves, read as a query, score it highest: what the words find is what they make.
// Coarse to fine over e in [kMinExponent, 4]; kept only where it scores higher than the word's
// own shape.
void meetTheNounsShape(const std::string& text, bool section, const Vocabulary& vocabulary, FuzzyPart* part) {
  LinguisticQuery query;
  try {
    query = parseLinguisticQuery(text, vocabulary);
  } catch (const Error&) {
    return;  // words the search reads around (routed, or left out): the part stays as made
  }
  // Only where the words keep a noun's exponent shape that the part as made misses: elsewhere the
  // word's own set stands (a crisp compromise would lose its vagueness, and with it the ties
  // that coverage breaks).
  std::vector<const QueryCondition*> kept;
  const std::function<void(const QueryCondition&, bool)> collect = [&](const QueryCondition& c, bool noun) {
    noun = noun || !c.noun.empty();
    if (noun && c.kind == QueryCondition::Kind::kDescriptor) {
      const std::string* whole = vocabulary.wholeShapeDescriptor(c.descriptor);
      if (exponentRule(whole ? *whole : c.descriptor)) kept.push_back(&c);
    }
    for (const QueryCondition& child : c.children) collect(child, noun);
  };
  collect(query.root, false);
  const std::vector<DescriptorValue> made = describePart(*part);
  const bool misses = std::any_of(kept.begin(), kept.end(), [&](const QueryCondition* c) {
    for (const DescriptorValue& v : made)
      if (v.descriptor == c->descriptor) return expectedMembership(v.value, c->set) < 1.0;
    return false;
  });
  if (!misses) return;
  double best = scoreDescriptors(query, made).score;
  // The best e along one path (set(e, candidate) puts e in), coarse to fine; false when no e beats
  // `best` (the part stays).
  const auto along = [&](const std::function<void(double, FuzzyPart*)>& set) {
    const auto scoreAt = [&](double e) {
      FuzzyPart candidate = *part;
      set(e, &candidate);
      return scoreDescriptors(query, describePart(candidate)).score;
    };
    double bestE = -1, step = 0.05;
    for (double e = kMinExponent; e <= 4.0; e += step) {
      const double s = scoreAt(e);
      if (s > best) best = s, bestE = e;
    }
    if (bestE < 0) return false;
    for (int round = 0; round < 2; ++round) {  // around the best, a tenth of the step each time
      const double centre = bestE;
      step /= 10;
      for (int k = -10; k <= 10; ++k) {
        const double e = centre + k * step;
        if (e < kMinExponent || e > 4.0) continue;
        const double s = scoreAt(e);
        if (s > best) best = s, bestE = e;
      }
    }
    set(bestE, part);
    return true;
  };
  const auto setBoth = [](double e, FuzzyPart* p) { p->eps1 = p->eps2 = FuzzyNumber::crisp(e); };
  const auto setEps1 = [](double e, FuzzyPart* p) { p->eps1 = FuzzyNumber::crisp(e); };
  const auto setEps2 = [](double e, FuzzyPart* p) { p->eps2 = FuzzyNumber::crisp(e); };
  if (!section) {
    along(setBoth);
    return;
  }
  // A section word: eps2 first, then the ends' eps1 that the noun's shape also reads (a box's
  // squareness is the mean over both), then eps2 again.
  if (along(setEps2) && along(setEps1)) along(setEps2);
}

}  // namespace

FuzzyPart partFromWords(const std::string& text, const Vocabulary& vocabulary) {
  const PartDescription words = describedPart(text, vocabulary);
  if (words.noun->params.is_null())
    throw Error(errc::kInvalidParameter,
                "'" + words.noun->word + "' names no shape; say which primitive (" +
                    "sphere, ellipsoid, cube, box, cylinder, cone, pyramid, double pyramid, rod, plate, disc, ...)",
                "text");
  FuzzyPart part = parsePart({{"params", words.noun->params}}, "");
  std::vector<AdjectiveUse> uses = words.adjectives;
  // An outline adjective on a flat noun sets its section ("a round plate": eps2).
  const auto descriptorOf = [&](const AdjectiveUse& use) -> const std::string& {
    return vocabulary.descriptorOn(*use.adjective, words.noun);
  };
  std::stable_sort(uses.begin(), uses.end(), [&](const AdjectiveUse& a, const AdjectiveUse& b) {
    return std::find(kOrder.begin(), kOrder.end(), descriptorOf(a)) <
           std::find(kOrder.begin(), kOrder.end(), descriptorOf(b));
  });
  // Extents from adjectives ("a thin rod": a degree, read back through e = d / (1 − d)) and
  // measures ("about 10 long", which win over an adjective of the same extent), set together
  // after the shape and size and before the deformations.
  std::map<std::string, FuzzyNumber> extents;
  bool extentsSet = false;
  const auto setExtents = [&] {
    if (extentsSet) return;
    extentsSet = true;
    for (const MeasureUse& m : words.measures) extents[m.descriptor] = m.extent;
    realizeExtents(extents, words.keepsProportions, &part);
  };
  std::optional<bool> exponentWord;  // an exponent-shape word: whether a section word
  for (const AdjectiveUse& use : uses) {
    const Adjective& a = *use.adjective;
    const std::string& descriptor = descriptorOf(use);
    if (const std::string* whole = vocabulary.wholeShapeDescriptor(descriptor); exponentRule(whole ? *whole : descriptor))
      exponentWord = whole != nullptr;
    const FuzzyNumber d = use.nounSet ? degreeForNoun(a, *use.nounSet, vocabulary) : vocabulary.createdSet(a, use.intensity);
    const bool deformation = std::find(kOrder.begin(), kOrder.end(), descriptor) >=
                             std::find(kOrder.begin(), kOrder.end(), "bendness");
    if (deformation) setExtents();
    if (isExtent(descriptor)) {
      extents[descriptor] = mapIncreasing(realizableDegrees(descriptor, d), [](double x) { return x / (1.0 - x); });
      continue;
    }
    realize(descriptor, d, vocabulary, &part);
  }
  // The edges, after the shape the adjectives gave ("a round box with sharp edges" is a box):
  // the noun's edge exponents at the degree the words say (query/linguistic/edges.h).
  if (words.edges) realizeEdges(words.edges->degree, *words.noun, vocabulary, &part);
  setExtents();
  if (exponentWord && !words.edges) meetTheNounsShape(text, *exponentWord, vocabulary, &part);
  try {
    part.validate();
  } catch (const Error& e) {
    throw Error(errc::kInvalidParameter, "'" + text + "' gives parameters outside their ranges: " + e.what(), "text");
  }
  return part;
}

}  // namespace fsdb
