#include "geometry/fuzzy_part_field.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/error.h"
#include "geometry/interval_functions.h"
#include "geometry/number_format.h"
#include "geometry/transform.h"

namespace fsdb {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSlots = 14;
// The enclosure is not rounded outwards (superquadric_bounds.h: a few ulps); block decisions that
// levelsAt must reproduce keep this relative distance from the threshold 1.
constexpr double kMargin = 1e-12;
// A box narrower than this, relative to the support, in every value is treated as one θ.
constexpr double kDegenerate = 1e-12;

// The fourteen fuzzy values of a part box, addressed by index for splitting.
Interval& slot(PartBox& b, int i) {
  SuperquadricBox& q = b.params;
  PlacementBox& p = b.placement;
  Interval* const slots[kSlots] = {&q.eps1, &q.eps2, &q.a1, &q.a2, &q.a3, &q.kx,  &q.ky,
                                   &q.kv,   &q.t,    &p.tx, &p.ty, &p.tz, &p.deg, &p.scale};
  return *slots[i];
}
const Interval& slot(const PartBox& b, int i) { return slot(const_cast<PartBox&>(b), i); }

// F at the centre of the box: a crisp witness (every θ of a validated part's box is valid).
double centreValue(const PartBox& b, const Vec3& p) {
  PlacedSuperquadric part;
  const SuperquadricBox& q = b.params;
  part.params = {mid(q.eps1), mid(q.eps2), mid(q.a1), mid(q.a2), mid(q.a3),
                 mid(q.kx),   mid(q.ky),   mid(q.kv), mid(q.t)};
  const PlacementBox& pl = b.placement;
  part.placement.translate = {mid(pl.tx), mid(pl.ty), mid(pl.tz)};
  part.placement.axis = pl.axis;
  part.placement.deg = mid(pl.deg);
  part.placement.scale = mid(pl.scale);
  return part.insideOutside(p);
}

// Directed conversions, so that float storage keeps the rounding directions of levelsAt.
float floatDown(double v) {
  float f = static_cast<float>(v);
  return static_cast<double>(f) > v ? std::nextafter(f, -1.0f) : f;
}
float floatUp(double v) {
  float f = static_cast<float>(v);
  return static_cast<double>(f) < v ? std::nextafter(f, 2.0f) : f;
}

}  // namespace

FuzzyPartField::FuzzyPartField(const FuzzyPart& part, FuzzyPartFieldOptions options)
    : part_(part), options_(options) {
  part_.validate();
  if (!(options_.tolerance > 0.0 && options_.tolerance <= 0.5))
    throw Error(errc::kInvalidParameter,
                "tolerance must be in (0, 0.5]; got " + formatNumber(options_.tolerance),
                "tolerance");
  if (options_.evaluationBudget < 1)
    throw Error(errc::kInvalidParameter, "evaluationBudget must be >= 1", "evaluationBudget");
  support_ = part_.boxAt(0.0);
  core_ = part_.boxAt(1.0);
  for (int i = 0; i < kSlots; ++i) supportWidth_[i] = width(slot(support_, i));
}

bool FuzzyPartField::decide(const Vec3& p, const PartBox& box, Question q) const {
  const bool possibly = q == Question::kPossibly;
  const Interval px{p.x, p.x}, py{p.y, p.y}, pz{p.z, p.z};
  struct Item {
    PartBox box;
    double centre;  // F at the box centre
  };
  // Is the crisp value a witness that settles the question?
  const auto settles = [&](double f) { return possibly ? f <= 1.0 : f > 1.0; };
  const double first = centreValue(box, p);
  std::vector<Item> stack{{box, first}};
  int evaluations = 0;
  while (!stack.empty()) {
    if (evaluations >= options_.evaluationBudget) {
      ++exhaustions_;
      return possibly;  // conservative: upper grows, lower shrinks
    }
    const Item item = std::move(stack.back());
    stack.pop_back();
    ++evaluations;
    const Interval f = insideOutsideBounds(item.box, px, py, pz);
    // The enclosure excludes the box from the question (no witness can lie in it).
    if (possibly ? f.lo > 1.0 : f.hi <= 1.0) continue;
    // A crisp witness: inside (possibly) or outside (not necessarily).
    if (settles(item.centre)) return possibly;
    // Split the value that is widest relative to its support: a common yardstick for sizes, angles
    // and exponents.
    int widest = -1;
    double widestRelative = kDegenerate;
    for (int i = 0; i < kSlots; ++i) {
      if (supportWidth_[i] <= 0.0) continue;
      const double r = width(slot(item.box, i)) / supportWidth_[i];
      if (r > widestRelative) {
        widest = i;
        widestRelative = r;
      }
    }
    // One θ (up to kDegenerate): its crisp value, which did not settle, is the answer for it.
    if (widest < 0) continue;
    Item a = item, b = item;
    const Interval v = slot(item.box, widest);
    const double m = mid(v);
    slot(a.box, widest) = {v.lo, m};
    slot(b.box, widest) = {m, v.hi};
    a.centre = centreValue(a.box, p);
    b.centre = centreValue(b.box, p);
    if (settles(a.centre) || settles(b.centre)) return possibly;
    // Depth first, most promising half on top: the smaller F for a witness inside, the larger for a
    // witness outside.
    const bool aFirst = possibly ? a.centre <= b.centre : a.centre >= b.centre;
    stack.push_back(aFirst ? std::move(b) : std::move(a));
    stack.push_back(aFirst ? std::move(a) : std::move(b));
  }
  return !possibly;  // every sub-box excluded: no θ inside (possibly), none
                     // outside (necessarily)
}

bool FuzzyPartField::possiblyInside(const Vec3& p, double alpha) const {
  return decide(p,
                alpha == 0.0   ? support_
                : alpha == 1.0 ? core_
                               : part_.boxAt(alpha),
                Question::kPossibly);
}

bool FuzzyPartField::necessarilyInside(const Vec3& p, double alpha) const {
  return decide(p,
                alpha == 0.0   ? support_
                : alpha == 1.0 ? core_
                               : part_.boxAt(alpha),
                Question::kNecessarily);
}

AlphaLevels FuzzyPartField::levelsAt(const Vec3& p) const {
  const double tau = options_.tolerance;
  // Fast exits (SPEC §3: P(α) shrinks as α grows, so both predicates are monotone in α).
  if (necessarilyInside(p, 0.0)) return {1.0f, 0.0f};  // in lower(0) ⊆ lower(α) ⊆ upper(α)
  if (!possiblyInside(p, 0.0)) return {0.0f, kNeverInside};
  AlphaLevels out;
  double u = 1.0;
  if (!possiblyInside(p, 1.0)) {
    // Invariant: possibly at lo, not at hi. Report lo: every reported membership has a witness.
    double lo = 0.0, hi = 1.0;
    while (hi - lo > tau) {
      const double m = 0.5 * (lo + hi);
      (possiblyInside(p, m) ? lo : hi) = m;
    }
    u = lo;
  }
  out.upper = floatDown(u);
  // l <= 1 needs p ∈ lower(1) ⊆ upper(1), so it is only sought where u = 1: this keeps lower ⊆
  // upper in the output even where rounding could make the predicates disagree.
  if (u == 1.0 && necessarilyInside(p, 1.0)) {
    // Invariant: not necessarily at lo (lo = 0 was the fast exit), necessarily at hi. Report hi.
    double lo = 0.0, hi = 1.0;
    while (hi - lo > tau) {
      const double m = 0.5 * (lo + hi);
      (necessarilyInside(p, m) ? hi : lo) = m;
    }
    out.lower = floatUp(hi);
  }
  return out;
}

AlphaLevelBounds FuzzyPartField::boundsOver(const Vec3& lo, const Vec3& hi) const {
  const Interval x{lo.x, hi.x}, y{lo.y, hi.y}, z{lo.z, hi.z};
  AlphaLevelBounds b;  // the non-uniform default: u in [0, 1], l in [0, never]
  const Interval f0 = insideOutsideBounds(support_, x, y, z);
  if (f0.lo > 1.0 + kMargin) return {0.0f, 0.0f, kNeverInside, kNeverInside};
  if (f0.hi <= 1.0 - kMargin) return {1.0f, 1.0f, 0.0f, 0.0f};
  const Interval f1 = insideOutsideBounds(core_, x, y, z);
  if (f1.lo > 1.0 + kMargin) {
    // Outside S(θ) for every θ in P(1): never in lower(1), and u < 1.
    b.lowerMin = b.lowerMax = kNeverInside;
  } else if (f1.hi <= 1.0 - kMargin) {
    // Inside S(θ) for every θ in P(1): in lower(1) (l <= 1) and in upper(1) (u = 1).
    b.upperMin = 1.0f;
    b.lowerMax = 1.0f;
  }
  return b;
}

void FuzzyPartField::boundingBox(Vec3* lo, Vec3* hi) const {
  const SuperquadricBox& q = support_.params;
  const PlacementBox& pl = support_.placement;
  // Canonical half-lengths, widened by the taper factor (SPEC §2: X = x(kx·z/C + 1), |z| <= C).
  double X = q.a1.hi * (1.0 + magnitude(q.kx));
  double Y = q.a1.hi * q.a2.hi * (1.0 + magnitude(q.ky));
  double Z = q.a1.hi * q.a3.hi;
  // Twist turns the cross-section about z: it stays within the circle of the corner radius.
  if (magnitude(q.t) > 0.0) X = Y = std::hypot(X, Y);
  // Bend with curvature k, γ = k·z: X' − x = (1/k − x)(1 − cos γ) and Z' = sin γ·(1/k − x).
  // With 1 − cos γ <= min(2, γ²/2) and |sin γ| <= min(1, |γ|):
  //   |X' − x| <= (1 + K·X)·min(2/|k|, |k|·Z²/2) <= (1 + K·X)·min(Z, K·Z²/2),
  //   |Z'| <= min(1/|k|, Z) + X·min(1, |k|·Z) <= Z + X·min(1, K·Z),   K = max |kv|.
  const double K = magnitude(q.kv);
  if (K > 0.0) {
    const double bentX = X + (1.0 + K * X) * std::min(Z, 0.5 * K * Z * Z);
    const double bentZ = Z + X * std::min(1.0, K * Z);
    X = bentX;
    Z = bentZ;
  }
  // Placement: scale, rotate, translate. The local box is symmetric, so every scale up to the
  // largest maps it into the largest scaled box.
  const double s = pl.scale.hi;
  const Vec3 half{s * X, s * Y, s * Z};
  const Rotation r = Rotation::fromAxisAngle(pl.axis, mid(pl.deg));
  Vec3 extent{0.0, 0.0, 0.0};
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner{(c & 1) ? half.x : -half.x, (c & 2) ? half.y : -half.y,
                      (c & 4) ? half.z : -half.z};
    const Vec3 w = r.apply(corner);
    extent = {std::max(extent.x, std::fabs(w.x)), std::max(extent.y, std::fabs(w.y)),
              std::max(extent.z, std::fabs(w.z))};
  }
  // Angles within δ of the mid angle move a point v by at most the chord 2·sin(δ/2)·|v|.
  const double delta = std::min(0.5 * width(pl.deg) * kPi / 180.0, kPi);
  const double pad = 2.0 * std::sin(0.5 * delta) * norm(half);
  *lo = {pl.tx.lo - extent.x - pad, pl.ty.lo - extent.y - pad, pl.tz.lo - extent.z - pad};
  *hi = {pl.tx.hi + extent.x + pad, pl.ty.hi + extent.y + pad, pl.tz.hi + extent.z + pad};
}

}  // namespace fsdb
