#pragma once
// FuzzyBall: an analytic AlphaFieldSource for tests: a ball centred at c whose radius is the
// triangular fuzzy number tri(r1, r2, r3). Its upper(α) is the ball of radius
// r3 − α(r3 − r2) and its lower(α) the ball of radius r1 + α(r2 − r1), so
//   u(p) = 1 for d <= r2, (r3 − d)/(r3 − r2) for r2 < d < r3, else 0
//   l(p) = 0 for d <= r1, (d − r1)/(r2 − r1) for r1 < d <= r2, else never   (d = |p − c|)
#include <algorithm>
#include <cmath>

#include "geometry/alpha_field.h"

namespace fsdb::testing {

class FuzzyBall : public AlphaFieldSource {
 public:
  FuzzyBall(Vec3 c, double r1, double r2, double r3) : c_(c), r1_(r1), r2_(r2), r3_(r3) {}

  AlphaLevels levelsAt(const Vec3& p) const override { return levelsAtDistance(norm(p - c_)); }

  AlphaLevelBounds boundsOver(const Vec3& lo, const Vec3& hi) const override {
    // Exact nearest and farthest distances from c to the box; the levels are monotone in d.
    auto nearest = [](double c, double a, double b) { return c < a ? a - c : (c > b ? c - b : 0.0); };
    auto farthest = [](double c, double a, double b) { return std::max(std::fabs(c - a), std::fabs(c - b)); };
    const double dMin = std::hypot(nearest(c_.x, lo.x, hi.x), nearest(c_.y, lo.y, hi.y), nearest(c_.z, lo.z, hi.z));
    const double dMax =
        std::hypot(farthest(c_.x, lo.x, hi.x), farthest(c_.y, lo.y, hi.y), farthest(c_.z, lo.z, hi.z));
    const AlphaLevels near = levelsAtDistance(dMin), far = levelsAtDistance(dMax);
    return {far.upper, near.upper, near.lower, far.lower};
  }

  void boundingBox(Vec3* lo, Vec3* hi) const override {
    *lo = {c_.x - r3_, c_.y - r3_, c_.z - r3_};
    *hi = {c_.x + r3_, c_.y + r3_, c_.z + r3_};
  }

  double upperRadius(double alpha) const { return r3_ - alpha * (r3_ - r2_); }
  double lowerRadius(double alpha) const { return r1_ + alpha * (r2_ - r1_); }

 private:
  AlphaLevels levelsAtDistance(double d) const {
    AlphaLevels v;
    v.upper = d <= r2_ ? 1.0f : (d < r3_ ? static_cast<float>((r3_ - d) / (r3_ - r2_)) : 0.0f);
    v.lower = d <= r1_ ? 0.0f : (d <= r2_ ? static_cast<float>((d - r1_) / (r2_ - r1_)) : kNeverInside);
    return v;
  }

  Vec3 c_;
  double r1_, r2_, r3_;
};

}  // namespace fsdb::testing
