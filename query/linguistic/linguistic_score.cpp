// Scoring of linguistic queries (query/linguistic/linguistic_query.h; docs/api.md §5;
// Zhang, Pham & Chen, §2.2 and §5).
#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "geometry/core/closest_names.h"
#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_similarity.h"
#include "query/linguistic/linguistic_query.h"
#include "query/linguistic/vocabulary.h"

namespace fsdb {
namespace {

using Kind = QueryCondition::Kind;

struct Context {
  const LinguisticQuery* query;
  const std::vector<ShapeComponent>* components;  // null: a lone part (relations score 0)
  const std::vector<DescriptorValue>* values;     // the component the descriptor conditions read
  std::string component;                          // its path, for explain
  std::vector<ConditionScore>* explain;
  // Scoring a noun's defaults ("a knob" is small): a value scores its expected membership in the
  // set, not S (geometry/fuzzy/fuzzy_similarity.h, expectedMembership).
  bool nounDefaults = false;
};

double aggregate(const std::string& how, const std::vector<double>& scores) {
  if (scores.empty()) return 1.0;  // "anything"
  if (how == "min") return *std::min_element(scores.begin(), scores.end());
  if (how == "product") {
    double p = 1.0;
    for (double s : scores) p *= s;
    return p;
  }
  if (how == "mean") {
    double sum = 0.0;
    for (double s : scores) sum += s;
    return sum / static_cast<double>(scores.size());
  }
  throw Error(errc::kInvalidParameter, "unknown aggregation '" + quotedWord(how) + "'; expected min, product or mean",
              "aggregation");
}

const Direction* directionOf(const QueryCondition& c) {
  if (c.directionSets) return &*c.directionSets;
  const Direction* d = activeVocabulary().direction(c.direction);
  if (!d) throw Error(errc::kInvalidParameter, "unknown direction '" + quotedWord(c.direction) + "'", "direction");
  return d;
}

Vec3 coreCentre(const FuzzyPart& p) { return p.coreRepresentative().placement.translate; }

// A condition's score, and its score as the words asked (they differ only in a closest-match
// query, query/linguistic/closest_match.h: `score` ranks, `asked` is explained); `coverage` breaks
// ties of score (QueryScore::coverage): 1 where the condition says nothing of vagueness.
struct Scores {
  double score = 0.0;
  double asked = 0.0;
  double coverage = 1.0;
};

Scores score(const QueryCondition& c, Context& ctx);

// Writes a condition's scores into its explain entry.
void explainAt(size_t slot, const Scores& s, const Context& ctx) {
  ConditionScore& e = (*ctx.explain)[slot];
  e.score = s.asked;
  if (ctx.query->closestMatch) e.closeness = s.score;
}

// The best ordered pair of distinct components for a relation. Each noun phrase is scored once
// per component; a pair's direction and distance are computed only when its two scores could
// still beat the best pair so far.
Scores relationScore(const QueryCondition& c, Context& ctx) {
  const size_t slot = ctx.explain->size();
  ctx.explain->push_back({c.text, 0.0, ""});
  if (ctx.query->closestMatch) (*ctx.explain)[slot].closeness = 0.0;
  if (!ctx.components || c.children.size() != 2) return {0.0, 0.0, 0.0};  // scores 0: covers nothing
  const Direction* direction = directionOf(c);
  const auto& comps = *ctx.components;
  struct Scored {
    Scores scores;
    std::vector<ConditionScore> explain;
  };
  std::vector<Scored> subject, other;
  for (const ShapeComponent& comp : comps) {
    for (size_t side = 0; side < 2; ++side) {
      Scored s;
      Context one{ctx.query, ctx.components, &comp.descriptors, comp.path, &s.explain};
      s.scores = score(c.children[side], one);
      (side == 0 ? subject : other).push_back(std::move(s));
    }
  }
  double best = 0.0;
  size_t bestI = 0, bestJ = 0;
  bool found = false;
  for (size_t i = 0; i < comps.size(); ++i) {
    for (size_t j = 0; j < comps.size(); ++j) {
      if (i == j) continue;
      double s = std::min(subject[i].scores.score, other[j].scores.score);
      if (found && s <= best) continue;  // cannot win: the first best pair stays (stable ties)
      if (!ctx.query->closestMatch)
        s = std::min(s, relationMembership(*direction, c.distance, comps[i].part, comps[j].part));
      if (!found || s > best) {
        best = s;
        bestI = i;
        bestJ = j;
        found = true;
      }
    }
  }
  if (!found) return {0.0, 0.0, 0.0};  // fewer than two components
  Scores total{best, best, 1.0};
  if (ctx.query->closestMatch) {
    // Ranked by the noun phrases (and their relaxed conditions); the words as asked, placement
    // included, are explained for the pair that gave the total.
    total.asked = std::min({subject[bestI].scores.asked, other[bestJ].scores.asked,
                            relationMembership(*direction, c.distance, comps[bestI].part, comps[bestJ].part)});
  }
  (*ctx.explain)[slot].component = comps[bestI].path + ", " + comps[bestJ].path;
  explainAt(slot, total, ctx);
  for (const auto* e : {&subject[bestI].explain, &other[bestJ].explain})
    ctx.explain->insert(ctx.explain->end(), e->begin(), e->end());
  return total;
}

// Two descriptor conditions that score alike on any part: same descriptor, set and words.
bool sameDescriptorCondition(const QueryCondition& a, const QueryCondition& b) {
  return a.kind == Kind::kDescriptor && b.kind == Kind::kDescriptor && a.descriptor == b.descriptor &&
         a.text == b.text && a.set == b.set;
}

Scores score(const QueryCondition& c, Context& ctx) {
  if (c.kind == Kind::kRelation) return relationScore(c, ctx);
  const size_t slot = ctx.explain->size();
  if (!c.text.empty()) ctx.explain->push_back({c.text, 0.0, ctx.component});
  Scores s;
  switch (c.kind) {
    case Kind::kDescriptor:
      s.coverage = 0.0;  // no value of the descriptor covers nothing
      if (ctx.values)
        for (const DescriptorValue& v : *ctx.values)
          if (v.descriptor == c.descriptor) {
            s.score = ctx.nounDefaults ? expectedMembership(v.value, c.set) : similarity(v.value, c.set);
            if (c.asked) s.asked = ctx.nounDefaults ? expectedMembership(v.value, *c.asked) : similarity(v.value, *c.asked);
            else s.asked = s.score;
            if (c.relativeTo < 1.0) {  // QueryCondition::relativeTo
              s.score = std::min(1.0, s.score / c.relativeTo);
              s.asked = std::min(1.0, s.asked / c.relativeTo);
            }
            s.coverage = coverage(v.value, c.set);
          }
      break;
    case Kind::kAnd: {
      std::vector<double> scores, asked;
      scores.reserve(c.children.size());
      asked.reserve(c.children.size());
      s.coverage = 1.0;  // the least of the children's
      const QueryCondition* previous = nullptr;  // the last descriptor child scored
      const bool outer = ctx.nounDefaults;
      ctx.nounDefaults = outer || !c.noun.empty();
      for (const QueryCondition& child : c.children) {
        // A descriptor condition said again right after itself ("a large large ... ball") scores
        // what it scored: the same set against the same value. Its explain entry is repeated, so
        // the answer is the same under every aggregation; only the similarity is not recomputed
        // (a 10,000-word text of one repeated word computed it 10,000 times per candidate).
        if (previous && sameDescriptorCondition(*previous, child)) {
          if (!child.text.empty()) {
            ctx.explain->push_back({child.text, 0.0, ctx.component});
            explainAt(ctx.explain->size() - 1, {scores.back(), asked.back()}, ctx);
          }
          scores.push_back(scores.back());
          asked.push_back(asked.back());
          continue;  // its coverage is in s.coverage already
        }
        const Scores one = score(child, ctx);
        scores.push_back(one.score);
        asked.push_back(one.asked);
        s.coverage = std::min(s.coverage, one.coverage);
        previous = child.kind == Kind::kDescriptor ? &child : nullptr;
      }
      ctx.nounDefaults = outer;
      s.score = aggregate(ctx.query->aggregation, scores);
      s.asked = aggregate(ctx.query->aggregation, asked);
      break;
    }
    case Kind::kOr:
      s.coverage = 0.0;  // the largest of the children's
      for (const QueryCondition& child : c.children) {
        const Scores one = score(child, ctx);
        s = {std::max(s.score, one.score), std::max(s.asked, one.asked), std::max(s.coverage, one.coverage)};
      }
      break;
    case Kind::kNot:
      // "not bent" asks for no degree that a value could span: no tie-break (coverage 1).
      if (!c.children.empty()) {
        const Scores one = score(c.children[0], ctx);
        s = {1.0 - one.score, 1.0 - one.asked, 1.0};
      } else {
        s = {0.0, 0.0, 1.0};
      }
      break;
    case Kind::kRelation:
      break;
  }
  // A noun's conditions are its defaults, not what the user said of the part ("a slightly bent
  // cylinder" says its bend, not its roundness): they break no ties.
  if (!c.noun.empty()) s.coverage = 1.0;
  if (!c.text.empty()) explainAt(slot, s, ctx);
  return s;
}

// Does the condition read a component's descriptors outside any relation?
bool readsComponent(const QueryCondition& c) {
  if (c.kind == Kind::kDescriptor) return true;
  if (c.kind == Kind::kRelation) return false;
  for (const QueryCondition& child : c.children)
    if (readsComponent(child)) return true;
  return false;
}

// Pre-order over the DAG: a subtree shared by several parents (a stored shape named more than
// once) is listed at its first occurrence only. Its later occurrences are the same leaves at the
// same placements, which change no score: a descriptor condition takes the best component, and
// a relation between a leaf and its own copy has a zero offset, which no direction admits
// (directionMembership is 0). Listing them cost 2^depth components (a shape naming the previous
// one twice, 16 deep: 131,072) and scoring relations the square of that.
void collectComponents(const CsgTree& node, const std::string& path, std::vector<ShapeComponent>* out,
                       std::unordered_set<const CsgTree*>* seen) {
  if (!seen->insert(&node).second) return;
  if (node.leaf) {
    out->push_back({path, node.part, describePart(node.part)});
    return;
  }
  for (size_t i = 0; i < node.children.size(); ++i)
    collectComponents(*node.children[i], path + ".children[" + std::to_string(i) + "]", out, seen);
}

}  // namespace

bool saysVagueness(const QueryCondition& c) {
  if (!c.noun.empty() || c.kind == Kind::kNot || c.kind == Kind::kRelation) return false;
  if (c.kind == Kind::kDescriptor) return true;
  for (const QueryCondition& child : c.children)
    if (saysVagueness(child)) return true;
  return false;
}

QueryScore scoreDescriptors(const LinguisticQuery& query, const std::vector<DescriptorValue>& values) {
  QueryScore result;
  Context ctx{&query, nullptr, &values, "", &result.explain};
  const Scores s = score(query.root, ctx);
  result.score = s.score;
  result.coverage = saysVagueness(query.root) ? s.coverage : 0.0;
  return result;
}

QueryScore scoreShape(const LinguisticQuery& query, const std::vector<ShapeComponent>& components) {
  QueryScore best;
  if (!readsComponent(query.root) || components.empty()) {
    Context ctx{&query, &components, nullptr, "", &best.explain};
    const Scores s = score(query.root, ctx);
    best.score = s.score;
    best.coverage = saysVagueness(query.root) ? s.coverage : 0.0;
    return best;
  }
  bool first = true;
  const bool vague = saysVagueness(query.root);
  for (const ShapeComponent& component : components) {
    QueryScore candidate;
    Context ctx{&query, &components, &component.descriptors, component.path, &candidate.explain};
    const Scores s = score(query.root, ctx);
    candidate.score = s.score;
    candidate.coverage = vague ? s.coverage : 0.0;
    // The best component, and of equal ones the one that covers most (as objects rank); the first
    // of those.
    if (first || candidate.score > best.score || (candidate.score == best.score && candidate.coverage > best.coverage))
      best = std::move(candidate);
    first = false;
  }
  return best;
}

nlohmann::json explainJson(const QueryScore& score) {
  nlohmann::json out = nlohmann::json::array();
  for (const ConditionScore& c : score.explain) {
    nlohmann::json e = {{"text", c.text}, {"score", c.score}};
    if (!c.component.empty()) e["component"] = c.component;
    if (c.closeness) e["closeness"] = *c.closeness;
    out.push_back(std::move(e));
  }
  return out;
}

std::vector<ShapeComponent> shapeComponents(const CsgTree& tree) {
  std::vector<ShapeComponent> out;
  std::unordered_set<const CsgTree*> seen;
  collectComponents(tree, "tree", &out, &seen);
  return out;
}

FuzzyNumber centreDistance(const FuzzyPart& a, const FuzzyPart& b) {
  if (a.tx.isCrisp() && a.ty.isCrisp() && a.tz.isCrisp() && b.tx.isCrisp() && b.ty.isCrisp() && b.tz.isCrisp()) {
    const Vec3 d = coreCentre(a) - coreCentre(b);
    return FuzzyNumber::crisp(std::sqrt(dot(d, d)));
  }
  std::vector<double> levels = a.breakpointLevels();
  const std::vector<double> more = b.breakpointLevels();
  levels.insert(levels.end(), more.begin(), more.end());
  for (int k = 0; k <= kDescriptorLevels; ++k) levels.push_back(static_cast<double>(k) / kDescriptorLevels);
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  std::vector<Interval> cuts;
  for (double alpha : levels) {
    const PlacementBox pa = a.boxAt(alpha).placement, pb = b.boxAt(alpha).placement;
    double nearest = 0.0, farthest = 0.0;
    for (const auto& [x, y] : {std::pair{pa.tx, pb.tx}, std::pair{pa.ty, pb.ty}, std::pair{pa.tz, pb.tz}}) {
      const Interval d = sub(x, y);
      const double lo = (d.lo <= 0.0 && d.hi >= 0.0) ? 0.0 : std::min(std::fabs(d.lo), std::fabs(d.hi));
      const double hi = std::max(std::fabs(d.lo), std::fabs(d.hi));
      nearest += lo * lo;
      farthest += hi * hi;
    }
    cuts.push_back({std::sqrt(nearest), std::sqrt(farthest)});
  }
  return FuzzyNumber::fromAlphaCuts(levels, cuts);
}

double relationMembership(const Direction& direction, const std::optional<FuzzyNumber>& distance,
                          const FuzzyPart& subject, const FuzzyPart& other) {
  double s = directionMembership(direction, coreCentre(subject) - coreCentre(other));
  // The distance's alpha-cuts cost more than the direction: skip them when the pair already fails.
  if (distance && s > 0.0) s = std::min(s, similarity(centreDistance(subject, other), *distance));
  return s;
}

}  // namespace fsdb
