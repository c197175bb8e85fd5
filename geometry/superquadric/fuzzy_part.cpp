#include "geometry/superquadric/fuzzy_part.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "geometry/core/error.h"
#include "geometry/numeric/interval_functions.h"
#include "geometry/core/number_format.h"

namespace fsdb {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string formatSupport(const Interval& s) {
  return "[" + formatNumber(s.lo) + ", " + formatNumber(s.hi) + "]";
}

// The support must lie in the range. Both ends are checked, so NaN and infinities fail too (the
// ranges are intervals, so the ends decide for the whole support).
void requireSupport(const std::string& path, const FuzzyNumber& v, double min, bool minInclusive,
                    double max, bool maxInclusive, const std::string& range) {
  const Interval s = v.support();
  const auto ok = [&](double x) {
    return (minInclusive ? x >= min : x > min) && (maxInclusive ? x <= max : x < max);
  };
  if (!(ok(s.lo) && ok(s.hi)))
    throw Error(errc::kInvalidParameter,
                path + " support must lie in " + range + "; got " + formatSupport(s), path);
}

constexpr double kHuge = 1.7976931348623157e308;

}  // namespace

FuzzyPart FuzzyPart::fromCrisp(const PlacedSuperquadric& part) {
  FuzzyPart f;
  const SuperquadricParams& q = part.params;
  f.eps1 = FuzzyNumber::crisp(q.eps1);
  f.eps2 = FuzzyNumber::crisp(q.eps2);
  f.a1 = FuzzyNumber::crisp(q.a1);
  f.a2 = FuzzyNumber::crisp(q.a2);
  f.a3 = FuzzyNumber::crisp(q.a3);
  f.kx = FuzzyNumber::crisp(q.kx);
  f.ky = FuzzyNumber::crisp(q.ky);
  f.kv = FuzzyNumber::crisp(q.kv);
  f.t = FuzzyNumber::crisp(q.t);
  f.tx = FuzzyNumber::crisp(part.placement.translate.x);
  f.ty = FuzzyNumber::crisp(part.placement.translate.y);
  f.tz = FuzzyNumber::crisp(part.placement.translate.z);
  f.axis = part.placement.axis;
  f.deg = FuzzyNumber::crisp(part.placement.deg);
  f.scale = FuzzyNumber::crisp(part.placement.scale);
  return f;
}

void FuzzyPart::validate() const {
  // docs/api.md §2 ranges, required of the whole support so that every θ in every P(α) is valid.
  requireSupport("params.eps1", eps1, 0.0, false, 4.0, true, "(0, 4]");
  requireSupport("params.eps2", eps2, 0.0, false, 4.0, true, "(0, 4]");
  requireSupport("params.a1", a1, 0.0, false, kHuge, true, "(0, inf)");
  requireSupport("params.a2", a2, 0.0, false, kHuge, true, "(0, inf)");
  requireSupport("params.a3", a3, 0.0, false, kHuge, true, "(0, inf)");
  const Interval sa1 = a1.support(), sa2 = a2.support(), sa3 = a3.support();
  if (!std::isfinite(sa1.hi * sa2.hi))
    throw Error(errc::kInvalidParameter, "params.a2 support makes B = a1·a2 overflow", "params.a2");
  const double maxC = sa1.hi * sa3.hi;
  if (!std::isfinite(maxC))
    throw Error(errc::kInvalidParameter, "params.a3 support makes C = a1·a3 overflow", "params.a3");
  requireSupport("params.kx", kx, -1.0, true, 1.0, true, "[-1, 1]");
  requireSupport("params.ky", ky, -1.0, true, 1.0, true, "[-1, 1]");
  requireSupport("params.kv", kv, -kHuge, true, kHuge, true, "the finite numbers");
  // |kv|·C < π over the whole box: the worst case is the largest |kv| with the largest C.
  const double maxKv = magnitude(kv.support());
  if (!(maxKv * maxC < kPi))
    throw Error(errc::kInvalidParameter,
                "params.kv support must satisfy |kv|·C < π over the whole "
                "parameter box; got "
                "max |kv| = " +
                    formatNumber(maxKv) + " and max C = a1·a3 = " + formatNumber(maxC),
                "params.kv");
  requireSupport("params.t", t, -kHuge, true, kHuge, true, "the finite numbers");
  requireSupport("transform.translate[0]", tx, -kHuge, true, kHuge, true, "the finite numbers");
  requireSupport("transform.translate[1]", ty, -kHuge, true, kHuge, true, "the finite numbers");
  requireSupport("transform.translate[2]", tz, -kHuge, true, kHuge, true, "the finite numbers");
  if (!isFinite(axis) || !(norm(axis) > 0.0))
    throw Error(errc::kInvalidParameter, "transform.rotate.axis must be a finite, non-zero vector",
                "transform.rotate.axis");
  requireSupport("transform.rotate.deg", deg, -kHuge, true, kHuge, true, "the finite numbers");
  requireSupport("transform.scale", scale, 0.0, false, kHuge, true, "(0, inf)");
}

PartBox FuzzyPart::boxAt(double alpha) const {
  if (!(alpha >= 0.0 && alpha <= 1.0))
    throw Error(errc::kInvalidParameter, "alpha must be in [0, 1]; got " + formatNumber(alpha),
                "alpha");
  PartBox box;
  SuperquadricBox& q = box.params;
  q.eps1 = eps1.alphaCut(alpha);
  q.eps2 = eps2.alphaCut(alpha);
  q.a1 = a1.alphaCut(alpha);
  q.a2 = a2.alphaCut(alpha);
  q.a3 = a3.alphaCut(alpha);
  q.kx = kx.alphaCut(alpha);
  q.ky = ky.alphaCut(alpha);
  q.kv = kv.alphaCut(alpha);
  q.t = t.alphaCut(alpha);
  PlacementBox& p = box.placement;
  p.tx = tx.alphaCut(alpha);
  p.ty = ty.alphaCut(alpha);
  p.tz = tz.alphaCut(alpha);
  p.axis = axis;
  p.deg = deg.alphaCut(alpha);
  p.scale = scale.alphaCut(alpha);
  return box;
}

PlacedSuperquadric FuzzyPart::coreRepresentative() const {
  return midpointPart(boxAt(1.0));  // the 1-cut is the core (hull)
}

std::vector<double> FuzzyPart::breakpointLevels() const {
  std::vector<double> levels{0.0, 1.0};
  for (const FuzzyNumber* v :
       {&eps1, &eps2, &a1, &a2, &a3, &kx, &ky, &kv, &t, &tx, &ty, &tz, &deg, &scale})
    for (const Breakpoint& b : v->breakpoints())
      if (b.mu >= 0.0 && b.mu <= 1.0) levels.push_back(b.mu);
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  return levels;
}

}  // namespace fsdb
