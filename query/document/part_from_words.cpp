#include "query/document/part_from_words.h"

#include <algorithm>
#include <cmath>

#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_arithmetic.h"
#include "query/linguistic/degree_sets.h"
#include "query/linguistic/descriptors.h"
#include "query/linguistic/linguistic_query.h"
#include "query/document/part_json.h"
#include "query/linguistic/vocabulary.h"

namespace fsdb {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The order in which adjectives act (see the header).
const std::vector<std::string> kOrder = {"squariness", "roundness", "bevelness", "pinchness", "elongation",
                                         "bendness",   "taperness", "twistness", "size"};

FuzzyNumber affine(const FuzzyNumber& d, double slope, double offset) {
  return add(scale(d, slope), FuzzyNumber::crisp(offset));
}

// f increasing: the set's breakpoints mapped through f.
template <typename F>
FuzzyNumber mapIncreasing(const FuzzyNumber& d, F f) {
  std::vector<Breakpoint> points = d.breakpoints();
  for (Breakpoint& p : points) p.x = f(p.x);
  return FuzzyNumber::fromPoints(points);
}

void realize(const std::string& descriptor, const FuzzyNumber& d, FuzzyPart* part) {
  if (descriptor == "squariness") part->eps1 = part->eps2 = affine(d, -0.95, 1.0);
  if (descriptor == "roundness") part->eps1 = part->eps2 = affine(d, 0.95, 0.05);
  if (descriptor == "bevelness") part->eps1 = part->eps2 = affine(d, 1.0, 1.0);
  if (descriptor == "pinchness") part->eps1 = part->eps2 = affine(d, 2.0, 2.0);
  if (descriptor == "elongation") {
    part->a2 = FuzzyNumber::crisp(1.0);
    part->a3 = mapIncreasing(d, [](double x) {
      x = std::min(0.98, std::max(0.02, x));
      return x < 0.5 ? 2.0 * x : 1.0 / (2.0 - 2.0 * x);
    });
  }
  const SuperquadricParams core = part->coreRepresentative().params;  // the size so far
  if (descriptor == "bendness") part->kv = scale(d, kPi / (2.0 * core.a1 * core.a3));
  if (descriptor == "taperness") part->kx = part->ky = negate(d);
  if (descriptor == "twistness") part->t = scale(d, kPi);
  if (descriptor == "size") {
    const double l = core.a1 * std::cbrt(core.a2 * core.a3);
    part->scale = mapIncreasing(d, [l](double x) {
      x = std::min(0.95, std::max(0.05, x));
      return x / (1.0 - x) / l;
    });
  }
}

}  // namespace

FuzzyPart partFromWords(const std::string& text, const Vocabulary& vocabulary) {
  const PartDescription words = parsePartDescription(text, vocabulary);
  if (words.noun->params.is_null())
    throw Error(errc::kInvalidParameter,
                "'" + words.noun->word + "' names no shape; say which primitive (" +
                    "sphere, ellipsoid, cube, box, cylinder, cone, pyramid, double pyramid, rod, plate, disc, ...)",
                "text");
  FuzzyPart part = parsePart({{"params", words.noun->params}}, "");
  std::vector<AdjectiveUse> uses = words.adjectives;
  std::stable_sort(uses.begin(), uses.end(), [](const AdjectiveUse& a, const AdjectiveUse& b) {
    return std::find(kOrder.begin(), kOrder.end(), a.adjective->descriptor) <
           std::find(kOrder.begin(), kOrder.end(), b.adjective->descriptor);
  });
  for (const AdjectiveUse& use : uses) {
    const Adjective& a = *use.adjective;
    FuzzyNumber d = use.intensity ? *use.intensity : a.create ? *a.create : vocabulary.plainCreate();
    if (a.lowPole && !(a.create && !use.intensity)) d = mirroredDegrees(d);
    realize(a.descriptor, d, &part);
  }
  try {
    part.validate();
  } catch (const Error& e) {
    throw Error(errc::kInvalidParameter, "'" + text + "' gives parameters outside their ranges: " + e.what(), "text");
  }
  return part;
}

}  // namespace fsdb
