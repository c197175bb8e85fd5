// FuzzyPartField's block proof (provenOverBlock): a branch and bound over P(0) that settles a
// whole block of voxels outside upper(0) or inside lower(0) where the enclosure over the block
// and all of P(0) (boundsOver) is too loose to. The argument: docs/design/fuzzy-part-field.md,
// "Bounds over a block".
#include <vector>

#include "geometry/field/fuzzy_part_field.h"
#include "geometry/field/fuzzy_part_field_detail.h"
#include "geometry/superquadric/superquadric_slopes.h"

namespace fsdb {

using namespace part_field_detail;

bool FuzzyPartField::provenOverBlock(const Interval& x, const Interval& y, const Interval& z,
                                     bool outside, int budget) const {
  // outside: every (p, θ) of the block × P(0) has F > 1 (no point of it is in upper(0));
  // otherwise every one has F <= 1 (every point is in lower(0)). Decisions keep boundsOver's
  // margin of 1e-12 from 1 (the enclosures are not rounded outwards).
  const auto decided = [&](const Interval& f) {
    return outside ? f.lo > 1.0 + kMargin : f.hi <= 1.0 - kMargin;
  };
  // A crisp θ that puts the block's centre on the other side refutes the claim: stop there
  // rather than spend the budget splitting around it.
  const Vec3 centre{mid(x), mid(y), mid(z)};
  const auto refutes = [&](double f) { return outside ? f <= 1.0 : f > 1.0; };
  std::vector<PartBox> stack{support_};
  int evaluations = 0;
  while (!stack.empty()) {
    PartBox box = std::move(stack.back());
    stack.pop_back();
    if (refutes(centreValue(box, centre))) return false;
    if (evaluations >= budget) return false;
    // Outside every S(θ)'s local hull: F > 1 on the box, however loose the enclosure.
    if (outside && missesDeformedHull(box, x, y, z)) continue;
    if (decided(boxEnclosure(box, x, y, z, outside, &evaluations))) continue;
    // Monotone collapse (as collapsedExcludes does for one point): where ∂F/∂θ_i keeps one sign
    // over the block and the box, F's least (outside) or largest value over the box is taken
    // with θ_i at one end, for every point of the block; so the claim holds on the box if it
    // holds on the box with those values collapsed to that end, whose enclosure is tighter.
    int open[kSlots], n = 0;
    for (int j = 0; j < fuzzyCount_; ++j)
      if (width(slot(box, fuzzySlots_[j])) > 0.0) open[n++] = fuzzySlots_[j];
    Interval d[kSlots];
    ++evaluations;
    if (n > 0 && insideOutsideSlopes(box, x, y, z, open, n, d)) {
      PartBox collapsed = box;
      if (collapseMonotone(&collapsed, open, n, d, outside) &&
          decided(boxEnclosure(collapsed, x, y, z, outside, &evaluations)))
        continue;
    }
    // Split across the value widest relative to its support.
    int widest = -1;
    double widestRelative = kDegenerate;
    for (int j = 0; j < fuzzyCount_; ++j) {
      const int i = fuzzySlots_[j];
      const double r = width(slot(box, i)) / supportWidth_[i];
      if (r > widestRelative) {
        widest = i;
        widestRelative = r;
      }
    }
    if (widest < 0) return false;  // one θ, and its enclosure over the block did not decide
    const Interval v = slot(box, widest);
    PartBox upperHalf = box;
    slot(box, widest).hi = mid(v);
    slot(upperHalf, widest).lo = mid(v);
    stack.push_back(std::move(upperHalf));
    stack.push_back(std::move(box));
  }
  return true;
}

}  // namespace fsdb
