#include "geometry/smooth_csg_field.h"

#include "geometry/error.h"
#include "geometry/fuzzy_part_field.h"

namespace fsdb {

std::shared_ptr<const AlphaFieldSource> smoothCrispParts(const std::shared_ptr<const AlphaFieldSource>& field,
                                                         const LeafSmoothing& smoothing) {
  if (const auto* part = dynamic_cast<const FuzzyPartField*>(field.get()))
    return part->isCrisp() ? std::make_shared<SmoothedPartField>(*part, smoothing) : field;
  if (const auto* csg = dynamic_cast<const CsgField*>(field.get())) {
    std::vector<std::shared_ptr<const AlphaFieldSource>> children;
    for (const auto& c : csg->children()) children.push_back(smoothCrispParts(c, smoothing));
    return std::make_shared<CsgField>(csg->op(), std::move(children));
  }
  return field;
}

namespace {

NodeOperator checkedOperator(const OperatorConfig& config) {
  try {
    return NodeOperator(config);
  } catch (const Error& e) {
    throw e.withPathPrefix("operator");
  }
}

}  // namespace

SmoothCsgField::SmoothCsgField(CsgOp op, const OperatorConfig& config, const LeafSmoothing& smoothing,
                               std::vector<std::shared_ptr<const AlphaFieldSource>> children)
    : op_(op), operator_(checkedOperator(config)) {
  validateLeafSmoothing(smoothing);
  if (children.size() < 2)
    throw Error(errc::kInvalidDocument, "a Boolean node needs at least two children", "children");
  for (const auto& c : children) {
    if (!c) throw Error(errc::kInvalidDocument, "a Boolean node has an empty child", "children");
    children_.push_back(smoothCrispParts(c, smoothing));
  }
}

AlphaLevels SmoothCsgField::levelsAt(const Vec3& p) const {
  AlphaLevels acc = children_[0]->levelsAt(p);
  for (size_t i = 1; i < children_.size(); ++i) acc = operator_.combine(op_, acc, children_[i]->levelsAt(p));
  return acc;
}

AlphaLevelBounds SmoothCsgField::boundsOver(const Vec3& lo, const Vec3& hi) const {
  AlphaLevelBounds acc = children_[0]->boundsOver(lo, hi);
  for (size_t i = 1; i < children_.size(); ++i) acc = operator_.combine(op_, acc, children_[i]->boundsOver(lo, hi));
  return acc;
}

void SmoothCsgField::boundingBox(Vec3* lo, Vec3* hi) const { csgBoundingBox(op_, children_, lo, hi); }

}  // namespace fsdb
