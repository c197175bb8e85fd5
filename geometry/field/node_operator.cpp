#include "geometry/field/node_operator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/core/error.h"

namespace fsdb {
namespace {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();
// Widening of a monotone operator's corner bounds: above the measured rounding dips (2e-16).
constexpr double kBoundMargin = 1e-9;

Combine toCombine(CsgOp op) {
  switch (op) {
    case CsgOp::kUnion: return Combine::Union;
    case CsgOp::kIntersection: return Combine::Intersection;
    case CsgOp::kDifference: return Combine::Difference;
  }
  return Combine::Union;  // unreachable: every CsgOp is handled above
}

// The t-norm's boundary values (T(0, x) = 0, T(1, 1) = 1, S(1, x) = 1, S(0, 0) = 0; difference
// T(a, 1 − b)), or kNoValue where they do not fix the result.
double boundaryValue(CsgOp op, double a, double b) {
  switch (op) {
    case CsgOp::kUnion:
      if (a >= 1.0 || b >= 1.0) return 1.0;
      if (a <= 0.0 && b <= 0.0) return 0.0;
      break;
    case CsgOp::kIntersection:
      if (a <= 0.0 || b <= 0.0) return 0.0;
      if (a >= 1.0 && b >= 1.0) return 1.0;
      break;
    case CsgOp::kDifference:
      if (a <= 0.0 || b >= 1.0) return 0.0;
      if (a >= 1.0 && b <= 0.0) return 1.0;
      break;
  }
  return kNoValue;
}

bool provenMonotone(const OperatorSpec& spec) {
  // tests/geometry/field/node_operator_test measures the dips of the three others.
  return spec.kind == "fuzzy_operator" && spec.name != "smooth_and_hat";
}

}  // namespace

double possibilityOf(AlphaLevels v) { return v.upper; }

double necessityOf(AlphaLevels v) { return v.lower <= 1.0f ? 1.0 - double(v.lower) : 0.0; }

AlphaLevels levelsFromPossibility(double possibility, double necessity) {
  // Floats round u down and l up (upper(α) and lower(α) only shrink; as fuzzy_part_field.h), so
  // u = 1 only where Π = 1 and l = 0 only where N = 1.
  const float u = floatDown(std::clamp(possibility, 0.0, 1.0));
  // N > 0 ⇒ Π = 1 (lower(α) ⊆ upper(α)): where Π < 1 the point is in no lower(α).
  if (!(necessity > 0.0) || u < 1.0f) return {u, kNeverInside};
  return {u, floatUp(1.0 - std::min(necessity, 1.0))};
}

NodeOperator::NodeOperator(const OperatorConfig& config)
    : config_(validateOperator(config)), op_(makeBinaryOperator(config_)),
      monotone_(provenMonotone(*findOperator(config_.name))) {}

double NodeOperator::combine(CsgOp op, double a, double b) const {
  const double fixed = boundaryValue(op, a, b);
  if (!std::isnan(fixed)) return fixed;
  if (op_->actsOnMemberships()) return op_->apply(toCombine(op), a, b);
  // Blends act on f = μ − 1/2, inside where f >= 0 (Li & Tian, §2.1; Li, eq. 21-27).
  return std::clamp(op_->apply(toCombine(op), a - 0.5, b - 0.5) + 0.5, 0.0, 1.0);
}

AlphaLevels NodeOperator::combine(CsgOp op, AlphaLevels a, AlphaLevels b) const {
  const bool difference = op == CsgOp::kDifference;
  // difference: Π' = T(ΠA, 1 − NB), N' = T(NA, 1 − ΠB); otherwise the same operator on both.
  const double p = combine(op, possibilityOf(a), difference ? necessityOf(b) : possibilityOf(b));
  const double n = combine(op, necessityOf(a), difference ? possibilityOf(b) : necessityOf(b));
  return levelsFromPossibility(p, n);
}

MembershipRange NodeOperator::combine(CsgOp op, MembershipRange a, MembershipRange b) const {
  // The boundary values fix the result over the box when they fix it at its four corners (the
  // regions where they apply are monotone).
  const double corner = boundaryValue(op, a.lo, b.lo);
  if (!std::isnan(corner) && corner == boundaryValue(op, a.lo, b.hi) && corner == boundaryValue(op, a.hi, b.lo) &&
      corner == boundaryValue(op, a.hi, b.hi))
    return {corner, corner};
  if (!monotone_) return {0.0, 1.0};
  const bool difference = op == CsgOp::kDifference;  // non-increasing in b
  double lo = combine(op, a.lo, difference ? b.hi : b.lo);
  double hi = combine(op, a.hi, difference ? b.lo : b.hi);
  if (lo > 0.0 && lo < 1.0) lo = std::max(0.0, lo - kBoundMargin);
  if (hi > 0.0 && hi < 1.0) hi = std::min(1.0, hi + kBoundMargin);
  return {lo, hi};
}

AlphaLevelBounds NodeOperator::combine(CsgOp op, const AlphaLevelBounds& a, const AlphaLevelBounds& b) const {
  auto possibility = [](const AlphaLevelBounds& x) { return MembershipRange{x.upperMin, x.upperMax}; };
  auto necessity = [](const AlphaLevelBounds& x) {
    return MembershipRange{necessityOf({0.0f, x.lowerMax}), necessityOf({0.0f, x.lowerMin})};
  };
  const bool difference = op == CsgOp::kDifference;
  const MembershipRange p = combine(op, possibility(a), difference ? necessity(b) : possibility(b));
  const MembershipRange n = combine(op, necessity(a), difference ? possibility(b) : necessity(b));
  // levelsFromPossibility's l falls as N' rises and as Π' rises (the axiom's enforcement: never
  // below Π' = 1, finite at 1), and its u rises with Π'.
  return {levelsFromPossibility(p.lo, 0.0).upper, levelsFromPossibility(p.hi, 0.0).upper,
          levelsFromPossibility(p.hi, n.hi).lower, levelsFromPossibility(p.lo, n.lo).lower};
}

}  // namespace fsdb
