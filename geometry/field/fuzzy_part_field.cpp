#include "geometry/field/fuzzy_part_field.h"

#include <algorithm>
#include <mutex>
#include <limits>
#include <cmath>
#include <vector>

#include "geometry/core/error.h"
#include "geometry/core/number_format.h"
#include "geometry/field/fuzzy_part_field_detail.h"
#include "geometry/superquadric/deformation.h"
#include "geometry/superquadric/superquadric_extent.h"
#include "geometry/superquadric/superquadric.h"
#include "geometry/superquadric/transform.h"

namespace fsdb {

using namespace part_field_detail;

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
  coreMidpoint_ = crispPartBox(midpointPart(core_));
  for (int i = 0; i < kSlots; ++i) supportWidth_[i] = width(slot(support_, i));
  const FuzzyNumber* const values[kSlots] = {
      &part_.eps1, &part_.eps2, &part_.a1, &part_.a2, &part_.a3, &part_.kx,  &part_.ky,
      &part_.kv,   &part_.t,    &part_.tx, &part_.ty, &part_.tz, &part_.deg, &part_.scale};
  for (int i = 0; i < kSlots; ++i) values_[i] = values[i];
  for (int i = 0; i < kSlots; ++i)
    if (supportWidth_[i] > 0.0) fuzzySlots_[fuzzyCount_++] = i;
  crispAngle_ = supportWidth_[12] <= 0.0;
  if (crispAngle_) rotation_ = Rotation::fromAxisAngle(part_.axis, support_.placement.deg.lo);
  bool allCrisp = true;
  for (int i = 0; i < kSlots; ++i) allCrisp = allCrisp && supportWidth_[i] <= 0.0;
  if (allCrisp) crisp_.emplace(part_.coreRepresentative());
  // One fuzzy size (a1 or the placement scale) of an undeformed part: F is homogeneous in it.
  if (fuzzyCount_ == 1 && (fuzzySlots_[0] == 2 || fuzzySlots_[0] == 13)) {
    bool undeformed = true;
    for (int i : {5, 6, 7, 8}) undeformed = undeformed && isPoint(slot(support_, i), 0.0);
    if (undeformed) {
      sizeSlot_ = fuzzySlots_[0];
      double v[kSlots];
      for (int i = 0; i < kSlots; ++i) v[i] = slot(support_, i).lo;
      sizeReference_ = mid(slot(core_, sizeSlot_));
      v[sizeSlot_] = sizeReference_;
      sizeReferencePart_ = partFromSlots(support_.placement.axis, v);
    }
  }
}

PartBox FuzzyPartField::cutAt(double alpha) const {
  PartBox box = support_;  // crisp values as they are
  for (int i = 0; i < kSlots; ++i)
    if (supportWidth_[i] > 0.0) slot(box, i) = values_[i]->alphaCut(alpha);
  return box;
}

double FuzzyPartField::valueAt(const PlacedSuperquadric& theta, const Vec3& p) const {
  if (!crispAngle_) return theta.insideOutside(p);
  // PlacementFrame::toLocal with the rotation built once.
  const Placement& pl = theta.placement;
  const Vec3 local = rotation_.applyInverse(p - pl.translate) / pl.scale;
  return insideOutside(theta.params, undeformPoint(theta.params, local));
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
    if (possibly && missesDeformedHull(item.box, px, py, pz)) continue;  // F > 1 on the box
    const Interval f = pointEnclosure(item.box, p, possibly);
    // The enclosure excludes the box from the question (no witness can lie in it).
    if (excludes(f, possibly)) continue;
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

PartBox FuzzyPartField::levelBox(double alpha) const {
  return alpha == 0.0 ? support_ : alpha == 1.0 ? core_ : part_.boxAt(alpha);
}

bool FuzzyPartField::possiblyInside(const Vec3& p, double alpha) const {
  return decide(p, levelBox(alpha), Question::kPossibly);
}

bool FuzzyPartField::necessarilyInside(const Vec3& p, double alpha) const {
  return decide(p, levelBox(alpha), Question::kNecessarily);
}

AlphaLevels FuzzyPartField::levelsAt(const Vec3& p) const {
  if (crisp_) {
    if (crisp_->insideOutside(p) <= 1.0) return {1.0f, 0.0f};
    return {0.0f, kNeverInside};
  }
  // Outside the local box that holds every S(θ): u = 0, l = never (the enclosure of the
  // deformations alone is loose far from the part).
  if (missesDeformedHull(support_, {p.x, p.x}, {p.y, p.y}, {p.z, p.z})) return {0.0f, kNeverInside};
  AlphaLevels sized;
  if (sizeSlot_ >= 0 && sizeLevels(p, &sized)) return sized;
  signed char sign[kSlots];
  if (monotoneSigns(p, p, sign)) return cornerLevels(p, sign);
  const double tau = options_.tolerance;
  // u(p) = sup{m(θ) : F(p; θ) <= 1}: the incumbent, whose witness is in P(incumbent).
  {
    // Fast exits: the enclosure over all of P(0) decides most points away from the band.
    const Interval f = pointEnclosure(support_, p, false);
    if (f.hi <= 1.0) return {1.0f, 0.0f};  // in lower(0) ⊆ lower(α) ⊆ upper(α)
    if (f.lo > 1.0) return {0.0f, kNeverInside};
  }
  AlphaLevels out;
  // F monotone over the cut near the answer (levelsAboveCut): u, and often l, with no search.
  Seed upSeed, downSeed;
  const int above = levelsAboveCut(p, &out, &upSeed, &downSeed);
  if (above == 2) return out;
  if (above == 0) {
    const Search up = maxMin(p, true, upSeed);
    if (up.exhausted) {
      // Conservative: an upper bound of u (upper grows); l is not sought below u = 1.
      out.upper = floatUp(std::min(1.0, std::max(up.incumbent, up.pruned)));
      // u = 1 says p ∈ upper(1). The open bound reaches 1 wherever a box around the core stayed
      // open, so ask P(1) itself (one θ for triangular numbers): where no θ of it puts p inside
      // (proven: decide answers true when its own budget runs out), u_true < 1 and the largest
      // float below 1 is still an upper bound of it.
      if (out.upper == 1.0f && !decide(p, core_, Question::kPossibly))
        out.upper = std::nextafter(1.0f, 0.0f);
      if (out.upper < 1.0f) return out;
    } else {
      if (up.incumbent < 0.0) return out;  // no θ of P(0) puts p inside: u = 0, l = never
      // Round down, keeping the witness: p ∈ upper(u) is shown by θ ∈ P(u).
      float u = roundedUpper(up.incumbent, up.witness);
      // Within τ of 1 the search may stop at a witness below the core although one in P(1) exists
      // (its bound, 1, did not beat the incumbent by τ). upper(1) must hold every point of the
      // true upper(1), so ask P(1) itself, as the l search below does for lower(1): a witness
      // there, or a decision that ran out of budget (conservative), makes u = 1.
      if (u < 1.0f && u + tau >= 1.0 - kMargin && decide(p, core_, Question::kPossibly)) u = 1.0f;
      out.upper = u;
      if (u < 1.0f) return out;  // l <= 1 needs p ∈ lower(1) ⊆ upper(1)
    }
  }
  // l(p) = sup{m(θ) : F(p; θ) > 1} (0 when no θ of P(0) puts p outside, proven).
  const Search down = maxMin(p, false, downSeed);
  if (!down.exhausted && down.incumbent < 0.0 && down.pruned < 0.0) {
    out.lower = 0.0f;  // every box excluded: p ∈ lower(0)
    return out;
  }
  if (down.incumbent >= 1.0) return out;  // a θ of P(1) puts p outside: never in lower(1)
  const double l = std::max(down.incumbent, down.pruned);
  if (l >= 1.0) {
    // Within τ of 1: p ∈ lower(1) only if every θ of the core puts it inside.
    if (decide(p, core_, Question::kNecessarily)) out.lower = 1.0f;
    return out;
  }
  // Not proven in lower(0): l > 0 (τ is within the tolerance of any l_true in [0, τ]).
  out.lower = floatUp(std::max(l, tau));
  return out;
}

void FuzzyPartField::sampleBlock(const BlockLattice& b, AlphaLevels* out) const {
  constexpr int d = BlockLattice::kDim;
  const int half = d / 2;
  BlockSigns signs;
  for (int i = 0; i < d; i += half)
    for (int j = 0; j < d; j += half)
      for (int k = 0; k < d; k += half) sampleSubBlock(b, i, j, k, half, &signs, out);
}

// Enclosure evaluations a block proof may spend on a 4³ and a 2³ sub-block. (At N = 128 the
// slightly bent cylinder took 0.85 s with 24 and 12, 0.82 s with 48 and 16, 0.99 s with 16 and 8.)
constexpr int kBlockProofBudget4 = 24;
constexpr int kBlockProofBudget2 = 12;

void FuzzyPartField::sampleSubBlock(const BlockLattice& b, int i, int j, int k, int size,
                                    BlockSigns* signs, AlphaLevels* out) const {
  constexpr int d = BlockLattice::kDim;
  const Vec3 lo = b.at(i, j, k), hi = b.at(i + size - 1, j + size - 1, k + size - 1);
  AlphaLevelBounds bounds = boundsOver(lo, hi);
  if (!bounds.uniform() && !crisp_ && sizeSlot_ < 0) {
    // Where F is monotone in every value over the whole block, its voxels take the corner levels
    // (a few crisp evaluations each) and a block proof would cost more than it spares (the very
    // sharp pyramid at N = 128: 0.19 s without, 0.43 s with).
    if (signs->state == 0) signs->state = monotoneSigns(b.lo(), b.hi(), signs->sign) ? 1 : 2;
    // Otherwise the enclosure over all of P(0) may be loose (wide or many fuzzy values): split
    // P(0) for the whole sub-block before each voxel searches it alone. The core's midpoint at the
    // centre says which claim can hold (outside there refutes "in lower(0)", inside "outside
    // upper(0)").
    if (signs->state == 2) {
      const bool outside = centreValue(core_, 0.5 * (lo + hi)) > 1.0;
      if (provenOverBlock({lo.x, hi.x}, {lo.y, hi.y}, {lo.z, hi.z}, outside,
                          size >= 4 ? kBlockProofBudget4 : kBlockProofBudget2))
        bounds = outside ? AlphaLevelBounds{0.0f, 0.0f, kNeverInside, kNeverInside}
                         : AlphaLevelBounds{1.0f, 1.0f, 0.0f, 0.0f};
    }
  }
  const bool uniform = bounds.uniform();
  if (!uniform && sizeSlot_ >= 0) {
    // One fuzzy size of an undeformed part: each voxel in closed form (sizeLevels), already at 4³:
    // the 2³ bounds cost more than the voxels they would spare (the 10-part assembly at 256 took
    // 90 ms this way, 100-106 ms with them).
    AlphaLevels sized;
    for (int x = i; x < i + size; ++x)
      for (int y = j; y < j + size; ++y)
        for (int z = k; z < k + size; ++z)
          out[(x * d + y) * d + z] = sizeLevels(b.at(x, y, z), &sized)
                                         ? sized
                                         : (b.check(), FuzzyPartField::levelsAt(b.at(x, y, z)));
    return;
  }
  if (!uniform && size <= 2 && !crisp_) {
    // Signs that hold over the whole block serve every voxel of it (one slope enclosure per block
    // instead of one per voxel); otherwise levelsAt tries the voxel's own.
    if (signs->state == 0)
      signs->state = monotoneSigns(b.lo(), b.hi(), signs->sign) ? 1 : 2;
    // Inside S(θ) for every θ of P(1) (boundsOver): g(1) <= 1, so u = 1 with no evaluation.
    const bool inCore = bounds.upperMin == 1.0f;
    // The build's deadline is checked before each voxel's search (BlockLattice::checkpoint): one
    // search is bounded by its budget, a block of them is not (seconds for the all-fuzzy part).
    for (int x = i; x < i + size; ++x)
      for (int y = j; y < j + size; ++y)
        for (int z = k; z < k + size; ++z)
          out[(x * d + y) * d + z] =
              signs->state == 1 ? cornerLevels(b.at(x, y, z), signs->sign, inCore)
                                : (b.check(), FuzzyPartField::levelsAt(b.at(x, y, z)));
    return;
  }
  if (uniform || size <= 2) {
    // Qualified: no virtual call (levelsAt's first test is the crisp shortcut).
    for (int x = i; x < i + size; ++x)
      for (int y = j; y < j + size; ++y)
        for (int z = k; z < k + size; ++z)
          out[(x * d + y) * d + z] = uniform ? AlphaLevels{bounds.upperMin, bounds.lowerMin}
                                             : (b.check(), FuzzyPartField::levelsAt(b.at(x, y, z)));
    return;
  }
  const int half = size / 2;
  for (int x = i; x < i + size; x += half)
    for (int y = j; y < j + size; y += half)
      for (int z = k; z < k + size; z += half) sampleSubBlock(b, x, y, z, half, signs, out);
}

namespace reference {

// The previous levelsAt: bisection in α with one branch-and-bound decision per bracket.
AlphaLevels bisectionLevelsAt(const FuzzyPartField& field, const Vec3& p) {
  const double tau = field.tolerance();
  const auto possiblyInside = [&](const Vec3& q, double a) { return field.possiblyInside(q, a); };
  const auto necessarilyInside = [&](const Vec3& q, double a) {
    return field.necessarilyInside(q, a);
  };
  // Fast exits (docs/api.md §3: P(α) shrinks as α grows, so both predicates are monotone in α).
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

}  // namespace reference

AlphaLevelBounds FuzzyPartField::boundsOver(const Vec3& lo, const Vec3& hi) const {
  const Interval x{lo.x, hi.x}, y{lo.y, hi.y}, z{lo.z, hi.z};
  AlphaLevelBounds b;  // the non-uniform default: u in [0, 1], l in [0, never]
  // (Crisp parts skip it: their enclosure is the crisp value up to rounding.)
  if (!crisp_ && missesDeformedHull(support_, x, y, z))
    return {0.0f, 0.0f, kNeverInside, kNeverInside};
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
  // Computed on first use: parsing a part (imports, searches) never pays for it.
  std::call_once(boxOnce_, [this] { tightenBoundingBox(); });
  *lo = boxLo_;
  *hi = boxHi_;
}

void FuzzyPartField::looseBoundingBox(Vec3* lo, Vec3* hi) const {
  const PlacementBox& pl = support_.placement;
  double X, Y, Z;
  deformedHalfExtents(support_.params, &X, &Y, &Z);
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

// The loose box (deformation and placement bounds over the support box) can be much larger than
// upper(0): a bend's bound takes the largest deflection at every height, and the rotation pad the
// box's whole diagonal. The forward maps' box is tight to about a canonical cell's image. Then
// cells of the box that boundsOver proves outside upper(0) are cut away, down to cells of
// 1/kTightCells of its sides: the result is the hull of the cells that could not be excluded (so
// it holds upper(0) whenever the box before does). Cells already inside the hull found so far
// are skipped, and children nearer the box's centre go first, so the hull grows from the inside
// and most cells are never tested. (docs/design/fuzzy-part-field.md, "The bounding box".)
void FuzzyPartField::tightenBoundingBox() const {
  looseBoundingBox(&boxLo_, &boxHi_);
  {
    // The forward maps' box (superquadric_extent.h) is tight where the loose one is not; both
    // hold upper(0), so their intersection does.
    Vec3 lo, hi;
    partExtent(support_, &lo, &hi);
    const Vec3 a = componentMax(boxLo_, lo), b = componentMin(boxHi_, hi);
    if (a.x <= b.x && a.y <= b.y && a.z <= b.z) boxLo_ = a, boxHi_ = b;
  }
  constexpr int kTightCells = 96;  // finest cell: 1/96 of the loose box's side per axis
  const Vec3 lo = boxLo_, hi = boxHi_;
  const Vec3 centre = (lo + hi) * 0.5;
  const Vec3 finest = (hi - lo) / double(kTightCells);
  Vec3 hullLo{INFINITY, INFINITY, INFINITY}, hullHi{-INFINITY, -INFINITY, -INFINITY};
  const auto within = [&](const Vec3& a, const Vec3& b) {
    return a.x >= hullLo.x && a.y >= hullLo.y && a.z >= hullLo.z && b.x <= hullHi.x &&
           b.y <= hullHi.y && b.z <= hullHi.z;
  };
  const auto cells = [](double w, double f) { return f > 0.0 ? w / f : 0.0; };  // finest cells across
  const auto distance = [&](const std::pair<Vec3, Vec3>& c) {
    return norm((c.first + c.second) * 0.5 - centre);
  };
  // Depth first with an explicit stack; a cell is split across its widest side (relative to the
  // finest cell) until every side is at most the finest cell.
  std::vector<std::pair<Vec3, Vec3>> stack{{lo, hi}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    if (within(a, b)) continue;
    if (boundsOver(a, b).upperMax == 0.0f) continue;  // outside upper(0): nothing to hold
    const double rx = cells(b.x - a.x, finest.x), ry = cells(b.y - a.y, finest.y),
                 rz = cells(b.z - a.z, finest.z);
    const double widest = std::max({rx, ry, rz});
    // The side's midpoint, or NaN where the side has no double strictly inside it: far from the
    // origin (a part placed at 1e16, where doubles are 2 apart) a side can be wider than the
    // finest cell and still not split, and halving it would give the same cell back for ever.
    const auto midpoint = [](double l, double h) {
      const double m = 0.5 * l + 0.5 * h;
      return (m > l && m < h) ? m : NAN;
    };
    const double m = widest == rx ? midpoint(a.x, b.x) : widest == ry ? midpoint(a.y, b.y) : midpoint(a.z, b.z);
    if (!(widest > 1.0 + 1e-9) || std::isnan(m)) {
      hullLo = componentMin(hullLo, a);
      hullHi = componentMax(hullHi, b);
      continue;
    }
    Vec3 midLo = b, midHi = a;  // the two halves: [a, midLo] and [midHi, b]
    if (widest == rx) midLo.x = midHi.x = m;
    else if (widest == ry) midLo.y = midHi.y = m;
    else midLo.z = midHi.z = m;
    std::pair<Vec3, Vec3> first{a, midLo}, second{midHi, b};
    if (distance(first) > distance(second)) std::swap(first, second);
    stack.push_back(second);  // popped after the nearer half
    stack.push_back(first);
  }
  // Every cell excluded would mean an empty upper(0), which a valid part never has (S(core) has
  // volume): keep the loose box rather than trust that.
  if (hullLo.x > hullHi.x) return;
  boxLo_ = hullLo;  // cells of the loose box: the hull lies in it
  boxHi_ = hullHi;
}

}  // namespace fsdb
