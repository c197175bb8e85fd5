// See query/linguistic/edges.h.
#include "query/linguistic/edges.h"

#include "geometry/fuzzy/fuzzy_arithmetic.h"
#include "query/linguistic/degree_sets.h"
#include "query/linguistic/descriptors.h"

namespace fsdb {
namespace {

// A noun's exponent as its params give it: 1 when they leave it out (a superquadric's default)
// or when the noun has no shape.
double nounExponent(const Noun* noun, const char* name) {
  if (!noun || !noun->params.is_object()) return 1.0;
  const auto it = noun->params.find(name);
  return it != noun->params.end() && it->is_number() ? it->get<double>() : 1.0;
}

}  // namespace

EdgeExponents edgeExponentsOf(const Noun* noun) {
  EdgeExponents e{nounExponent(noun, "eps1") < 1.0, nounExponent(noun, "eps2") < 1.0};
  if (!e.eps1 && !e.eps2) e = EdgeExponents{};
  return e;
}

FuzzyNumber edgeDescriptorSet(const FuzzyNumber& d, const Noun* noun, const Vocabulary& vocabulary) {
  const int index = descriptorIndex(vocabulary.edgeDescriptor());
  const EdgeExponents edges = edgeExponentsOf(noun);
  const int k = int(edges.eps1) + int(edges.eps2);
  double others = 0.0;  // Σ_other f(ε_o)
  if (!edges.eps1) others += exponentDegree(index, nounExponent(noun, "eps1"));
  if (!edges.eps2) others += exponentDegree(index, nounExponent(noun, "eps2"));
  if (k == 2) return d;  // exactly the words' set (no rounding through the arithmetic)
  // One edge exponent: its degree is read over the descriptor's domain (descriptors.h:
  // degreeDomain; a part made from the words has ε >= 0.01 there) before the mean moves it off
  // the domain's end, as the search reads a whole set over it (withinDegreeDomains). Without it
  // "a slightly smooth cylinder" found its own part at 0.998, below every crisp cylinder.
  const Interval domain = degreeDomain(index);
  return add(scale(withinDegrees(d, domain.lo, domain.hi), k / 2.0), FuzzyNumber::crisp(others / 2.0));
}

}  // namespace fsdb
