#include "geometry/field/csg_field.h"

#include <algorithm>
#include <mutex>

#include "geometry/core/error.h"

namespace fsdb {

const char* csgOpName(CsgOp op) {
  switch (op) {
    case CsgOp::kUnion: return "union";
    case CsgOp::kIntersection: return "intersection";
    case CsgOp::kDifference: return "difference";
  }
  return "union";
}

bool csgOpFromName(const std::string& name, CsgOp* op) {
  for (const CsgOp o : {CsgOp::kUnion, CsgOp::kIntersection, CsgOp::kDifference})
    if (name == csgOpName(o)) {
      *op = o;
      return true;
    }
  return false;
}

AlphaLevelBounds boundsUnion(const AlphaLevelBounds& a, const AlphaLevelBounds& b) {
  return {std::max(a.upperMin, b.upperMin), std::max(a.upperMax, b.upperMax), std::min(a.lowerMin, b.lowerMin),
          std::min(a.lowerMax, b.lowerMax)};
}

AlphaLevelBounds boundsIntersection(const AlphaLevelBounds& a, const AlphaLevelBounds& b) {
  return {std::min(a.upperMin, b.upperMin), std::min(a.upperMax, b.upperMax), std::max(a.lowerMin, b.lowerMin),
          std::max(a.lowerMax, b.lowerMax)};
}

// difference: u = min(uA, lB) (increasing in uA and in lB), l = max(lA, uB) (increasing in both).
AlphaLevelBounds boundsDifference(const AlphaLevelBounds& a, const AlphaLevelBounds& b) {
  auto clampUnit = [](float v) { return std::clamp(v, 0.0f, 1.0f); };
  // l jumps to kNeverInside where uB reaches 1 (alphaDifference), so the bounds follow it.
  const float lowerMin = b.upperMin >= 1.0f ? kNeverInside : std::max(a.lowerMin, b.upperMin);
  const float lowerMax = b.upperMax >= 1.0f ? kNeverInside : std::max(a.lowerMax, b.upperMax);
  return {clampUnit(std::min(a.upperMin, b.lowerMin)), clampUnit(std::min(a.upperMax, b.lowerMax)), lowerMin,
          lowerMax};
}

CsgField::CsgField(CsgOp op, std::vector<std::shared_ptr<const AlphaFieldSource>> children)
    : op_(op), children_(std::move(children)) {
  if (children_.size() < 2)
    throw Error(errc::kInvalidDocument, "a Boolean node needs at least two children", "children");
  for (const auto& c : children_)
    if (!c) throw Error(errc::kInvalidDocument, "a Boolean node has an empty child", "children");
}

// On first use, not in the constructor: a fuzzy part's box is a subdivision (fuzzy_part_field.h),
// and parsing a shape to store it or search it never needs the boxes.
void CsgField::ensureChildBoxes() const {
  std::call_once(boxesOnce_, [this] {
    childLo_.resize(children_.size());
    childHi_.resize(children_.size());
    for (size_t i = 0; i < children_.size(); ++i) children_[i]->boundingBox(&childLo_[i], &childHi_[i]);
  });
}

namespace {

bool isBackground(AlphaLevels v) { return v.upper == 0.0f && v.lower == kNeverInside; }

}  // namespace

AlphaLevels alphaCombine(CsgOp op, AlphaLevels a, AlphaLevels b) {
  switch (op) {
    case CsgOp::kUnion: return alphaUnion(a, b);
    case CsgOp::kIntersection: return alphaIntersection(a, b);
    case CsgOp::kDifference: return alphaDifference(a, b);
  }
  return a;
}

AlphaLevelBounds boundsCombine(CsgOp op, const AlphaLevelBounds& a, const AlphaLevelBounds& b) {
  switch (op) {
    case CsgOp::kUnion: return boundsUnion(a, b);
    case CsgOp::kIntersection: return boundsIntersection(a, b);
    case CsgOp::kDifference: return boundsDifference(a, b);
  }
  return a;
}

void CsgField::sampleBlock(const BlockLattice& b, AlphaLevels* out) const {
  constexpr int n = BlockLattice::kSize;
  const Vec3 lo = b.lo(), hi = b.hi();
  ensureChildBoxes();
  // A child's value over the block when it is one value there (`*uniform` set), else false.
  const auto constantOver = [&](size_t i, AlphaLevels* value) {
    if (!boxesMeet(lo, hi, childLo_[i], childHi_[i])) {
      *value = AlphaLevels{};
      return true;
    }
    const AlphaLevelBounds cb = children_[i]->boundsOver(lo, hi);
    if (!cb.uniform()) return false;
    *value = {cb.upperMin, cb.lowerMin};
    return true;
  };
  AlphaLevels c;
  if (constantOver(0, &c))
    std::fill(out, out + n, c);
  else
    children_[0]->sampleBlock(b, out);
  std::vector<AlphaLevels> next;
  for (size_t i = 1; i < children_.size(); ++i) {
    // Nothing left to change: an empty intersection or difference, a union inside everywhere.
    bool settled = true;
    for (int v = 0; v < n && settled; ++v)
      settled = op_ == CsgOp::kUnion ? (out[v].upper == 1.0f && out[v].lower == 0.0f)
                                     : isBackground(out[v]);
    if (settled) return;
    if (constantOver(i, &c)) {
      // The background is the identity of the union and of a subtrahend.
      if (op_ != CsgOp::kIntersection && isBackground(c)) continue;
      for (int v = 0; v < n; ++v) out[v] = alphaCombine(op_, out[v], c);
      continue;
    }
    next.resize(n);
    children_[i]->sampleBlock(b, next.data());
    for (int v = 0; v < n; ++v) out[v] = alphaCombine(op_, out[v], next[v]);
  }
}

AlphaLevels CsgField::levelsAt(const Vec3& p) const {
  // A child whose bounding box misses p is background there (boundingBox holds upper(0)).
  ensureChildBoxes();
  const auto childAt = [&](size_t i) {
    return boxesMeet(p, p, childLo_[i], childHi_[i]) ? children_[i]->levelsAt(p) : AlphaLevels{};
  };
  AlphaLevels acc = childAt(0);
  for (size_t i = 1; i < children_.size(); ++i) {
    // Short cuts that cannot change the result: an intersection or difference whose left side
    // is already empty at every level stays empty.
    if (op_ != CsgOp::kUnion && isBackground(acc)) return acc;
    acc = alphaCombine(op_, acc, childAt(i));
  }
  return acc;
}

AlphaLevelBounds CsgField::boundsOver(const Vec3& lo, const Vec3& hi) const {
  AlphaLevelBounds acc = children_[0]->boundsOver(lo, hi);
  for (size_t i = 1; i < children_.size(); ++i) acc = boundsCombine(op_, acc, children_[i]->boundsOver(lo, hi));
  return acc;
}

namespace {

// The contract's box rule over the children's boxes.
void combineBoxes(CsgOp op, const std::vector<Vec3>& los, const std::vector<Vec3>& his, Vec3* lo, Vec3* hi) {
  *lo = los[0];
  *hi = his[0];
  if (op == CsgOp::kDifference) return;
  for (size_t i = 1; i < los.size(); ++i) {
    if (op == CsgOp::kUnion) {
      *lo = componentMin(*lo, los[i]);
      *hi = componentMax(*hi, his[i]);
    } else {
      *lo = componentMax(*lo, los[i]);
      *hi = componentMin(*hi, his[i]);
    }
  }
  if (op == CsgOp::kIntersection) *hi = componentMax(*hi, *lo);  // an empty overlap: a point
}

}  // namespace

// From the children's boxes found once (ensureChildBoxes): asking the children again each time
// made the box of a DAG cost its expansion (a shape naming the previous one twice, 30 deep:
// 2^30 calls).
void CsgField::boundingBox(Vec3* lo, Vec3* hi) const {
  ensureChildBoxes();
  combineBoxes(op_, childLo_, childHi_, lo, hi);
}

void csgBoundingBox(CsgOp op, const std::vector<std::shared_ptr<const AlphaFieldSource>>& children, Vec3* lo,
                    Vec3* hi) {
  std::vector<Vec3> los(children.size()), his(children.size());
  for (size_t i = 0; i < children.size(); ++i) children[i]->boundingBox(&los[i], &his[i]);
  combineBoxes(op, los, his, lo, hi);
}

}  // namespace fsdb
