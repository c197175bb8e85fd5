#include "geometry/field/smooth_csg_field.h"

#include "geometry/core/error.h"
#include "geometry/field/fuzzy_part_field.h"

namespace fsdb {
namespace {

NodeOperator checkedOperator(const OperatorConfig& config) {
  try {
    return NodeOperator(config);
  } catch (const Error& e) {
    throw e.withPathPrefix("operator");
  }
}

template <typename Field>
void checkChildren(const std::vector<std::shared_ptr<const Field>>& children) {
  if (children.size() < 2)
    throw Error(errc::kInvalidDocument, "a Boolean node needs at least two children", "children");
  for (const auto& c : children)
    if (!c) throw Error(errc::kInvalidDocument, "a Boolean node has an empty child", "children");
}

// The children as memberships, or empty when one of them is not.
std::vector<std::shared_ptr<const MembershipField>> asMemberships(
    const std::vector<std::shared_ptr<const AlphaFieldSource>>& children) {
  std::vector<std::shared_ptr<const MembershipField>> memberships;
  for (const auto& c : children) {
    auto m = std::dynamic_pointer_cast<const MembershipField>(c);
    if (!m) return {};
    memberships.push_back(std::move(m));
  }
  return memberships;
}

// The left fold of the node's operator over the children's values (levels, bounds, memberships).
template <typename Children, typename Value>
auto foldChildren(const Children& children, Value value, CsgOp op, const NodeOperator& node) {
  auto acc = value(*children[0]);
  for (size_t i = 1; i < children.size(); ++i) acc = node.combine(op, acc, value(*children[i]));
  return acc;
}

}  // namespace

std::shared_ptr<const AlphaFieldSource> smoothCrispParts(const std::shared_ptr<const AlphaFieldSource>& field,
                                                         const LeafSmoothing& smoothing) {
  if (const auto* part = dynamic_cast<const FuzzyPartField*>(field.get()))
    return part->isCrisp() ? std::make_shared<SmoothedPartField>(*part, smoothing) : field;
  if (const auto* csg = dynamic_cast<const CsgField*>(field.get())) {
    std::vector<std::shared_ptr<const AlphaFieldSource>> children;
    for (const auto& c : csg->children()) children.push_back(smoothCrispParts(c, smoothing));
    std::vector<std::shared_ptr<const MembershipField>> memberships = asMemberships(children);
    if (!memberships.empty())
      return std::make_shared<MembershipCsgField>(csg->op(), NodeOperator({"zadeh", {}, {}}), std::move(memberships));
    return std::make_shared<CsgField>(csg->op(), std::move(children));
  }
  return field;
}

std::shared_ptr<const AlphaFieldSource> makeSmoothCsgNode(CsgOp op, const OperatorConfig& config,
                                                          const LeafSmoothing& smoothing,
                                                          std::vector<std::shared_ptr<const AlphaFieldSource>> children) {
  NodeOperator node = checkedOperator(config);
  validateLeafSmoothing(smoothing);
  checkChildren(children);
  for (auto& c : children) c = smoothCrispParts(c, smoothing);
  std::vector<std::shared_ptr<const MembershipField>> memberships = asMemberships(children);
  if (!memberships.empty()) return std::make_shared<MembershipCsgField>(op, std::move(node), std::move(memberships));
  return std::make_shared<SmoothCsgField>(op, std::move(node), std::move(children));
}

SmoothCsgField::SmoothCsgField(CsgOp op, NodeOperator nodeOperator,
                               std::vector<std::shared_ptr<const AlphaFieldSource>> children)
    : op_(op), operator_(std::move(nodeOperator)), children_(std::move(children)) {
  checkChildren(children_);
}

AlphaLevels SmoothCsgField::levelsAt(const Vec3& p) const {
  return foldChildren(children_, [&](const AlphaFieldSource& c) { return c.levelsAt(p); }, op_, operator_);
}

AlphaLevelBounds SmoothCsgField::boundsOver(const Vec3& lo, const Vec3& hi) const {
  return foldChildren(children_, [&](const AlphaFieldSource& c) { return c.boundsOver(lo, hi); }, op_, operator_);
}

void SmoothCsgField::boundingBox(Vec3* lo, Vec3* hi) const { csgBoundingBox(op_, children_, lo, hi); }

MembershipCsgField::MembershipCsgField(CsgOp op, NodeOperator nodeOperator,
                                       std::vector<std::shared_ptr<const MembershipField>> children)
    : op_(op), operator_(std::move(nodeOperator)), children_(std::move(children)) {
  checkChildren(children_);
  csgBoundingBox(op_, {children_.begin(), children_.end()}, &lo_, &hi_);
}

double MembershipCsgField::membership(const Vec3& p) const {
  return foldChildren(children_, [&](const MembershipField& c) { return c.membership(p); }, op_, operator_);
}

MembershipRange MembershipCsgField::membershipOver(const Vec3& lo, const Vec3& hi) const {
  return foldChildren(children_, [&](const MembershipField& c) { return c.membershipOver(lo, hi); }, op_, operator_);
}

void MembershipCsgField::boundingBox(Vec3* lo, Vec3* hi) const {
  *lo = lo_;
  *hi = hi_;
}

}  // namespace fsdb
