#include "geometry/csg_field.h"

#include <algorithm>

#include "geometry/error.h"

namespace fsdb {

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

AlphaLevels CsgField::levelsAt(const Vec3& p) const {
  AlphaLevels acc = children_[0]->levelsAt(p);
  for (size_t i = 1; i < children_.size(); ++i) {
    // Short cuts that cannot change the result: an intersection or difference whose left side
    // is already empty at every level stays empty.
    if (op_ != CsgOp::kUnion && acc.upper == 0.0f && acc.lower == kNeverInside) return acc;
    const AlphaLevels next = children_[i]->levelsAt(p);
    switch (op_) {
      case CsgOp::kUnion: acc = alphaUnion(acc, next); break;
      case CsgOp::kIntersection: acc = alphaIntersection(acc, next); break;
      case CsgOp::kDifference: acc = alphaDifference(acc, next); break;
    }
  }
  return acc;
}

AlphaLevelBounds CsgField::boundsOver(const Vec3& lo, const Vec3& hi) const {
  AlphaLevelBounds acc = children_[0]->boundsOver(lo, hi);
  for (size_t i = 1; i < children_.size(); ++i) {
    const AlphaLevelBounds next = children_[i]->boundsOver(lo, hi);
    switch (op_) {
      case CsgOp::kUnion: acc = boundsUnion(acc, next); break;
      case CsgOp::kIntersection: acc = boundsIntersection(acc, next); break;
      case CsgOp::kDifference: acc = boundsDifference(acc, next); break;
    }
  }
  return acc;
}

void CsgField::boundingBox(Vec3* lo, Vec3* hi) const { csgBoundingBox(op_, children_, lo, hi); }

void csgBoundingBox(CsgOp op, const std::vector<std::shared_ptr<const AlphaFieldSource>>& children, Vec3* lo,
                    Vec3* hi) {
  children[0]->boundingBox(lo, hi);
  if (op == CsgOp::kDifference) return;
  for (size_t i = 1; i < children.size(); ++i) {
    Vec3 clo, chi;
    children[i]->boundingBox(&clo, &chi);
    if (op == CsgOp::kUnion) {
      *lo = {std::min(lo->x, clo.x), std::min(lo->y, clo.y), std::min(lo->z, clo.z)};
      *hi = {std::max(hi->x, chi.x), std::max(hi->y, chi.y), std::max(hi->z, chi.z)};
    } else {
      *lo = {std::max(lo->x, clo.x), std::max(lo->y, clo.y), std::max(lo->z, clo.z)};
      *hi = {std::min(hi->x, chi.x), std::min(hi->y, chi.y), std::min(hi->z, chi.z)};
    }
  }
  if (op == CsgOp::kIntersection) {  // an empty overlap collapses to a point
    hi->x = std::max(hi->x, lo->x);
    hi->y = std::max(hi->y, lo->y);
    hi->z = std::max(hi->z, lo->z);
  }
}

}  // namespace fsdb
