#pragma once
// FuzzyBall: an analytic AlphaFieldSource (geometry/field/alpha_field.h) for the voxel tests and
// benches: a ball of centre c and triangular fuzzy radius tri(r1, r2, r3), r1 ≤ r2 ≤ r3.
// At level α its radius interval is [r1 + α(r2 − r1), r3 − α(r3 − r2)], so (docs/api.md §3)
//   upper(α) = ball of radius r3 − α(r3 − r2),  lower(α) = ball of radius r1 + α(r2 − r1),
// and with d = |p − c|:
//   u = 1 (d ≤ r2), (r3 − d)/(r3 − r2) (r2 < d < r3), 0 (d ≥ r3);
//   l = 0 (d ≤ r1), (d − r1)/(r2 − r1) (r1 < d ≤ r2), kNeverInside (d > r2).
// Both are monotone in d, so exact bounds over a box come from the exact nearest and farthest
// distances from c to the box. r1 = r2 = r3 gives a crisp ball.
#include <algorithm>
#include <cmath>

#include "geometry/field/alpha_field.h"

namespace fsdb {

class FuzzyBall : public AlphaFieldSource {
 public:
  FuzzyBall(Vec3 centre, double r1, double r2, double r3)
      : c_(centre), r1_(r1), r2_(r2), r3_(r3) {}

  double upperRadius(double alpha) const { return r3_ - alpha * (r3_ - r2_); }
  double lowerRadius(double alpha) const { return r1_ + alpha * (r2_ - r1_); }

  AlphaLevels levelsAt(const Vec3& p) const override {
    const double d = norm(p - c_);
    return {upperOf(d), lowerOf(d)};
  }

  AlphaLevelBounds boundsOver(const Vec3& lo, const Vec3& hi) const override {
    const double dMin = nearest(lo, hi), dMax = farthest(lo, hi);
    AlphaLevelBounds b;
    b.upperMin = upperOf(dMax);
    b.upperMax = upperOf(dMin);
    b.lowerMin = lowerOf(dMin);
    b.lowerMax = lowerOf(dMax);
    return b;
  }

  void boundingBox(Vec3* lo, Vec3* hi) const override {
    *lo = c_ - Vec3{r3_, r3_, r3_};
    *hi = c_ + Vec3{r3_, r3_, r3_};
  }

 private:
  float upperOf(double d) const {
    if (d <= r2_) return 1.0f;
    if (d >= r3_) return 0.0f;
    return static_cast<float>((r3_ - d) / (r3_ - r2_));
  }
  float lowerOf(double d) const {
    if (d <= r1_) return 0.0f;
    if (d > r2_) return kNeverInside;
    return static_cast<float>((d - r1_) / (r2_ - r1_));
  }
  double nearest(const Vec3& lo, const Vec3& hi) const {
    const Vec3 q{std::clamp(c_.x, lo.x, hi.x), std::clamp(c_.y, lo.y, hi.y),
                 std::clamp(c_.z, lo.z, hi.z)};
    return norm(q - c_);
  }
  double farthest(const Vec3& lo, const Vec3& hi) const {
    const Vec3 q{std::max(c_.x - lo.x, hi.x - c_.x), std::max(c_.y - lo.y, hi.y - c_.y),
                 std::max(c_.z - lo.z, hi.z - c_.z)};
    return norm(q);
  }

  Vec3 c_;
  double r1_, r2_, r3_;
};

}  // namespace fsdb
