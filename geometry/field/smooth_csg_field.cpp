#include "geometry/field/smooth_csg_field.h"

#include <map>

#include "geometry/core/error.h"
#include "geometry/field/fuzzy_part_field.h"
#include "geometry/field/shared_field.h"

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

namespace {

// smoothCrispParts with what it made for each node of the DAG so far: a node shared by several
// parents (a SharedField) is smoothed once and stays shared, so the walk and the copies it makes
// are linear in the DAG, not in its expansion.
using SmoothedNodes = std::map<const AlphaFieldSource*, std::shared_ptr<const AlphaFieldSource>>;

std::shared_ptr<const AlphaFieldSource> smoothCrispPartsOnce(const std::shared_ptr<const AlphaFieldSource>& field,
                                                             const LeafSmoothing& smoothing, SmoothedNodes* made) {
  if (const auto* part = dynamic_cast<const FuzzyPartField*>(field.get()))
    return part->isCrisp()
               ? std::make_shared<SmoothedPartField>(std::shared_ptr<const FuzzyPartField>(field, part), smoothing)
               : field;
  if (const auto* shared = dynamic_cast<const SharedField*>(field.get())) {
    auto it = made->find(shared);
    if (it != made->end()) return it->second;
    // The source is held by `field` for the whole call: its address is not reused meanwhile.
    const std::shared_ptr<const AlphaFieldSource> source(field, &shared->source());
    auto smoothed = smoothCrispPartsOnce(source, smoothing, made);
    // Still a plain alpha source: keep it shared. A membership (all parts smoothed) is what
    // the smooth nodes above combine; it stays unwrapped, as before.
    if (smoothed.get() == &shared->source()) smoothed = field;
    else if (!std::dynamic_pointer_cast<const MembershipField>(smoothed)) smoothed = std::make_shared<SharedField>(smoothed);
    (*made)[shared] = smoothed;
    return smoothed;
  }
  if (const auto* csg = dynamic_cast<const CsgField*>(field.get())) {
    std::vector<std::shared_ptr<const AlphaFieldSource>> children;
    for (const auto& c : csg->children()) children.push_back(smoothCrispPartsOnce(c, smoothing, made));
    std::vector<std::shared_ptr<const MembershipField>> memberships = asMemberships(children);
    if (!memberships.empty())
      return std::make_shared<MembershipCsgField>(csg->op(), NodeOperator({"zadeh", {}, {}}), std::move(memberships));
    return std::make_shared<CsgField>(csg->op(), std::move(children));
  }
  return field;
}

}  // namespace

std::shared_ptr<const AlphaFieldSource> smoothCrispParts(const std::shared_ptr<const AlphaFieldSource>& field,
                                                         const LeafSmoothing& smoothing) {
  SmoothedNodes made;
  return smoothCrispPartsOnce(field, smoothing, &made);
}

std::shared_ptr<const AlphaFieldSource> makeSmoothCsgNode(CsgOp op, const OperatorConfig& config,
                                                          const LeafSmoothing& smoothing,
                                                          std::vector<std::shared_ptr<const AlphaFieldSource>> children) {
  NodeOperator node = checkedOperator(config);
  validateLeafSmoothing(smoothing);
  checkChildren(children);
  SmoothedNodes made;  // one walk for all children: siblings that share a node share its copy
  for (auto& c : children) c = smoothCrispPartsOnce(c, smoothing, &made);
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
}

double MembershipCsgField::membership(const Vec3& p) const {
  return foldChildren(children_, [&](const MembershipField& c) { return c.membership(p); }, op_, operator_);
}

MembershipRange MembershipCsgField::membershipOver(const Vec3& lo, const Vec3& hi) const {
  return foldChildren(children_, [&](const MembershipField& c) { return c.membershipOver(lo, hi); }, op_, operator_);
}

void MembershipCsgField::boundingBox(Vec3* lo, Vec3* hi) const {
  std::call_once(boxOnce_, [this] { csgBoundingBox(op_, {children_.begin(), children_.end()}, &lo_, &hi_); });
  *lo = lo_;
  *hi = hi_;
}

}  // namespace fsdb
