#include "geometry/field/smoothed_part_field.h"

#include <algorithm>
#include <cmath>

#include "geometry/core/error.h"

namespace fsdb {

double defaultSmoothingRange(const PlacedSuperquadric& part) {
  return 0.1 * part.placement.scale * std::min({part.params.A(), part.params.B(), part.params.C()});
}

namespace {

// Memberships below this are flushed to 0 (smoothed_part_field.h): the node operators' boundary
// values apply where a step's unbounded tail would leave a trace.
constexpr double kSmallestMembership = 0x1p-24;

PlacedSuperquadric crispPart(const FuzzyPartField& leaf) {
  if (!leaf.isCrisp())
    throw Error(errc::kInvalidDocument, "only a crisp part is smoothed into a membership field", "part");
  return leaf.part().coreRepresentative();
}

}  // namespace

std::shared_ptr<const UnaryFunction> validateLeafSmoothing(const LeafSmoothing& smoothing) {
  if (smoothing.range && !(*smoothing.range > 0.0 && std::isfinite(*smoothing.range)))
    throw Error(errc::kInvalidParameter, "range must be a finite number > 0 (world units)", "range");
  const OperatorConfig step = validateNestedStep({"node", {}, {smoothing.step}});
  std::shared_ptr<const UnaryFunction> f = makeUnaryFunction(step);
  if (std::abs((*f)(0.0) - 0.5) > 1e-12)
    throw Error(errc::kInvalidParameter,
                "the step '" + step.name + "' has step(0) != 1/2, so the part's surface would not be its 0.5 level",
                "step.name");
  return f;
}

SmoothedPartField::SmoothedPartField(std::shared_ptr<const FuzzyPartField> leaf, const LeafSmoothing& smoothing)
    : leaf_(std::move(leaf)),
      part_(crispPart(*leaf_)),
      range_(smoothing.range ? *smoothing.range : defaultSmoothingRange(leaf_->part().coreRepresentative())),
      step_(validateLeafSmoothing(smoothing)) {}

// std::call_once alone costs a library call on every membership (measured +2.5 % of CPU on a
// smooth difference of three parts at 192); the flag keeps the common path to one load.
void SmoothedPartField::growBox() const {
  if (boxReady_.load(std::memory_order_acquire)) return;
  std::call_once(boxOnce_, [this] {
    leaf_->boundingBox(&lo_, &hi_);
    lo_ = lo_ - Vec3{range_, range_, range_};
    hi_ = hi_ + Vec3{range_, range_, range_};
    boxReady_.store(true, std::memory_order_release);
  });
}

double SmoothedPartField::membership(const Vec3& p) const {
  growBox();
  if (p.x < lo_.x || p.y < lo_.y || p.z < lo_.z || p.x > hi_.x || p.y > hi_.y || p.z > hi_.z) return 0.0;
  const double mu = (*step_)(-part_.pseudoDistance(p) / range_);  // Li & Tian, §2.1: μ(F(P))
  return mu < kSmallestMembership ? 0.0 : mu;
}

MembershipRange SmoothedPartField::membershipOver(const Vec3& lo, const Vec3& hi) const {
  growBox();
  if (!boxesMeet(lo, hi, lo_, hi_)) return {0.0, 0.0};
  return {0.0, 1.0};
}

void SmoothedPartField::boundingBox(Vec3* lo, Vec3* hi) const {
  growBox();
  *lo = lo_;
  *hi = hi_;
}

}  // namespace fsdb
