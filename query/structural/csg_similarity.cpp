#include "query/structural/csg_similarity.h"

#include <algorithm>
#include <cmath>

#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_arithmetic.h"
#include "geometry/fuzzy/fuzzy_similarity.h"
#include "query/structural/csg_graph.h"

namespace fsdb {

CsgScore scoreCommonSubgraph(const CsgGraph& query, const CsgGraph& stored, const CommonSubgraph& match,
                             const LeafSimilarityMatrix& transformSimilarity, const CsgWeights& weights) {
  for (double w : {weights.components, weights.transforms, weights.structure})
    if (!std::isfinite(w) || w < 0)
      throw Error(errc::kInvalidParameter, "CSG weights must be finite and >= 0", "weights");
  const double total = weights.components + weights.transforms + weights.structure;
  if (!(total > 0)) throw Error(errc::kInvalidParameter, "CSG weights must not all be 0", "weights");
  if (transformSimilarity.rows != query.leafCount || transformSimilarity.cols != stored.leafCount ||
      transformSimilarity.values.size() != size_t(query.leafCount) * size_t(stored.leafCount))
    throw Error(errc::kInvalidParameter, "the transform similarity matrix must be query leaves x stored leaves",
                "transformSimilarity");
  CsgScore out;
  double components = 0, transforms = 0;
  for (const NodeMatch& m : match.matches) {
    const CsgGraphNode& q = query.nodes[size_t(m.queryNode)];
    if (q.op != CsgGraphOp::Leaf) continue;
    components += m.similarity;
    transforms += transformSimilarity.at(q.leaf, stored.nodes[size_t(m.storedNode)].leaf);
  }
  // Shearer, Bunke, Venkatesh 2001: |mcs| / max(|G1|, |G2|); the same denominator for the leaves.
  const double nodes = double(std::max(query.size(), stored.size()));
  const double leaves = double(std::max(query.leafCount, stored.leafCount));
  out.structure = nodes > 0 ? double(match.matchedNodes) / nodes : 0;
  out.components = leaves > 0 ? components / leaves : 0;
  out.transforms = leaves > 0 ? transforms / leaves : 0;
  // Zhang, Pham & Chen, §5: w1·components + w2·transforms + w3·structure, normalised to [0,1].
  out.score = (weights.components * out.components + weights.transforms * out.transforms +
               weights.structure * out.structure) /
              total;
  // 1 exactly when every weighted term is 1, whatever the rounding of the weighted sum.
  const bool exact = (weights.components == 0 || out.components == 1) && (weights.transforms == 0 || out.transforms == 1) &&
                     (weights.structure == 0 || out.structure == 1);
  out.score = exact ? 1.0 : std::min(std::nextafter(1.0, 0.0), std::max(0.0, out.score));
  return out;
}

double partSimilarity(const FuzzyPart& a, const FuzzyPart& b) {
  double s = 1;
  for (auto member : {&FuzzyPart::eps1, &FuzzyPart::eps2, &FuzzyPart::a1, &FuzzyPart::a2, &FuzzyPart::a3,
                      &FuzzyPart::kx, &FuzzyPart::ky, &FuzzyPart::kv, &FuzzyPart::t})
    s = std::min(s, similarity(a.*member, b.*member));
  return s;
}

namespace {

bool isCrispZero(const FuzzyNumber& x) {
  return x.isCrisp() && x.support().lo == 0;
}

// The rotation term of transformSimilarity (query/structural/csg_similarity.h).
double rotationSimilarity(const FuzzyPart& a, const FuzzyPart& b) {
  const FuzzyNumber zero = FuzzyNumber::crisp(0.0);
  if (isCrispZero(a.deg)) return similarity(zero, b.deg);  // a is the identity: its axis says nothing
  if (isCrispZero(b.deg)) return similarity(a.deg, zero);
  const double na = norm(a.axis), nb = norm(b.axis);
  if (!(na > 0) || !(nb > 0)) return 0;
  const double cosine = dot(a.axis, b.axis) / (na * nb);
  // A rotation by θ about -axis is the rotation by -θ about axis.
  const FuzzyNumber degB = cosine >= 0 ? b.deg : negate(b.deg);
  return similarity(a.deg, degB) * std::min(1.0, std::fabs(cosine));
}

}  // namespace

double transformSimilarity(const FuzzyPart& a, const FuzzyPart& b) {
  double s = rotationSimilarity(a, b);
  for (auto member : {&FuzzyPart::tx, &FuzzyPart::ty, &FuzzyPart::tz, &FuzzyPart::scale})
    s = std::min(s, similarity(a.*member, b.*member));
  return s;
}

}  // namespace fsdb
