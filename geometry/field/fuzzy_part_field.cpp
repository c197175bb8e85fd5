#include "geometry/field/fuzzy_part_field.h"

#include <algorithm>
#include <limits>
#include <cmath>
#include <vector>

#include "geometry/core/error.h"
#include "geometry/numeric/interval_functions.h"
#include "geometry/core/number_format.h"
#include "geometry/superquadric/deformation.h"
#include "geometry/superquadric/superquadric.h"
#include "geometry/superquadric/superquadric_affine.h"
#include "geometry/superquadric/superquadric_slopes.h"
#include "geometry/superquadric/transform.h"

namespace fsdb {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSlots = kPartSlots;  // superquadric_slopes.h's slot order
// The enclosure is not rounded outwards (superquadric_bounds.h: a few ulps); block decisions that
// levelsAt must reproduce keep this relative distance from the threshold 1.
constexpr double kMargin = 1e-12;
// A box narrower than this, relative to the support, in every value is treated as one θ.
constexpr double kDegenerate = 1e-12;

// Whether an enclosure f of F over a box shows that no θ of the box serves the search: inside
// looks for F <= 1 (excluded when f.lo > 1), outside for F > 1 (excluded when f.hi <= 1).
bool excludes(const Interval& f, bool inside) { return inside ? f.lo > 1.0 : f.hi <= 1.0; }

// The fourteen fuzzy values of a part box, addressed by index for splitting.
Interval& slot(PartBox& b, int i) { return partSlot(b, i); }
const Interval& slot(const PartBox& b, int i) { return partSlot(b, i); }

// F at the centre of the box: a crisp witness (every θ of a validated part's box is valid).
double centreValue(const PartBox& b, const Vec3& p) { return midpointPart(b).insideOutside(p); }

// The enclosure of F over the box at p that the point searches use: the interval enclosure
// (superquadric_bounds.h) and, unless it already excludes the box for the search it serves
// (inside: lo > 1, no θ with F <= 1; else hi <= 1, none with F > 1), intersected with the affine
// one (superquadric_affine.h). Both are sound; the affine one keeps the correlations between the
// fourteen values along the inverse deformations, so over the small boxes of a search it is
// usually the tighter (its remainder is second order), at about the cost of the interval one.
Interval pointEnclosure(const PartBox& b, const Vec3& p, bool inside) {
  const Interval px{p.x, p.x}, py{p.y, p.y}, pz{p.z, p.z};
  const Interval f = insideOutsideBounds(b, px, py, pz);
  if (excludes(f, inside)) return f;
  return intersect(f, insideOutsideAffineBounds(b, px, py, pz));
}

// The search's enclosure step (maxMin): the enclosure of pointEnclosure over the box at p, and the
// box narrowed by affine contraction (contractToQualifying, superquadric_affine.h) to the θ that
// can still qualify (inside: F <= 1, else F > 1): every such θ stays in it, so the search loses
// nothing it looks for. False when no θ of the box qualifies. *f encloses F over the box before
// the narrowing (so over the narrowed box too); *narrowed tells whether the box changed; on true, *form is
// the affine form of F over the box before the narrowing (form->valid false where there is none).
// (Taking the enclosure of the narrowed box again changed no answer and no exhaustion count of the
// bench part at N = 32, so one round.)
bool narrowToQualifying(PartBox* box, const Vec3& p, bool inside, Interval* f, bool* narrowed,
                        AffineForm* form) {
  const Interval px{p.x, p.x}, py{p.y, p.y}, pz{p.z, p.z};
  *narrowed = false;
  *f = insideOutsideBounds(*box, px, py, pz);
  if (excludes(*f, inside)) return false;
  if (!insideOutsideAffineForm(*box, px, py, pz, form)) {
    form->valid = false;
    return true;
  }
  const Interval a = range(*form);
  *f = intersect(*f, {std::max(a.lo, 0.0), std::max(a.hi, 0.0)});
  if (excludes(*f, inside)) return false;
  const PartBox before = *box;
  if (!contractToQualifying(*form, inside, box)) return false;
  for (int i = 0; i < kSlots && !*narrowed; ++i) {
    const Interval& w = partSlot(before, i);
    const Interval& n = partSlot(*box, i);
    *narrowed = w.lo != n.lo || w.hi != n.hi;
  }
  return true;
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

namespace {

// Quasi-concave envelope of a membership (the membership whose cuts are the hulls boxAt uses):
// μ̂(x) = min(max_{y <= x} μ(y), max_{y >= x} μ(y)), so θ_i ∈ cut_i(α) ⇔ μ̂_i(θ_i) >= α (α > 0).
double hullMembership(const FuzzyNumber& v, double x) {
  const double mu = v.membership(x);
  double left = mu, right = mu;
  for (const Breakpoint& b : v.breakpoints()) {
    if (b.x <= x) left = std::max(left, b.mu);
    if (b.x >= x) right = std::max(right, b.mu);
  }
  return std::min(left, right);
}

// sup of μ̂ over [a, b]: 1 where the interval meets the core, else the end nearer to the core
// (μ̂ rises up to the core and falls after it).
double supHullMembership(const FuzzyNumber& v, const Interval& core, const Interval& x) {
  if (x.hi >= core.lo && x.lo <= core.hi) return 1.0;
  return hullMembership(v, x.hi < core.lo ? x.hi : x.lo);
}

// Slack added to membership bounds: the interpolation in membership() rounds (a few ulps).
constexpr double kMembershipSlack = 1e-12;

PlacedSuperquadric thetaAt(const PartBox& b, const double (&v)[kSlots]) {
  return partFromSlots(b.placement.axis, v);
}

}  // namespace

// Monotone collapse as an exclusion test: where F is nondecreasing in a value over the box, some θ
// of the box has F <= 1 only if one with that value at its low end has (moving it down never
// raises F), and some θ has F > 1 only if one with it at its high end has. So if the box with
// every signed value collapsed to that end (slopes: superquadric_slopes.h) is excluded by its
// enclosure, which is tighter than the whole box's, no θ of the whole box qualifies. Before each
// collapse the box itself is tried with the mean value form about Baumann's centre (which already
// holds the collapse: a signed value's centre is its F-lowering or F-raising end). (Only
// exclusion rests on it: a witness in the collapsed box says nothing about the best m(θ) of the
// rest.) The collapsed box is also bounded by the mean value form with those slopes. Each
// slope enclosure and each enclosure counts as an evaluation.
bool FuzzyPartField::collapsedExcludes(const PartBox& box, const Vec3& p, bool inside,
                                       int* evaluations, const int* given, int givenCount,
                                       const Interval* givenSlopes) const {
  const Interval px{p.x, p.x}, py{p.y, p.y}, pz{p.z, p.z};
  PartBox c = box;
  for (int round = 0; round < 3 && *evaluations < options_.evaluationBudget; ++round) {
    int open[kSlots], n = 0;
    Interval d[kSlots];
    if (round == 0) {
      // Slopes over a box that holds this one hold over it (listed values may be single values).
      n = givenCount;
      std::copy(given, given + n, open);
      std::copy(givenSlopes, givenSlopes + n, d);
    } else {
      for (int j = 0; j < fuzzyCount_; ++j)
        if (width(slot(c, fuzzySlots_[j])) > 0.0) open[n++] = fuzzySlots_[j];
      if (n == 0) return false;
      ++*evaluations;
      if (!insideOutsideSlopes(c, px, py, pz, open, n, d)) return false;
    }
    // The mean value form about Baumann's centre (superquadric_slopes.h), one crisp evaluation:
    // where it excludes the box no θ of it qualifies. (No outward rounding: boundsOver's margin.)
    const double end = meanValueEnd(c, p, inside, open, n, d);
    if (inside ? end > 1.0 + kMargin : end <= 1.0 - kMargin) return true;
    bool collapsed = false;
    for (int j = 0; j < n; ++j) {
      const int sign = d[j].lo >= 0.0 ? 1 : d[j].hi <= 0.0 ? -1 : 0;
      if (sign == 0) continue;
      Interval& v = slot(c, open[j]);
      const double end = (sign > 0) == inside ? v.lo : v.hi;
      v = {end, end};
      collapsed = true;
    }
    if (!collapsed) return false;
    ++*evaluations;
    // The enclosure, and the mean value form F(θ) ∈ F(m) + Σ D_j·(θ_j − m_j) about the centre m
    // (the slopes D over the larger box hold those over the collapsed one).
    Interval f = pointEnclosure(c, p, inside);
    const double fm = centreValue(c, p);
    Interval mv{fm, fm};
    for (int j = 0; j < n; ++j) {
      const Interval& v = slot(c, open[j]);
      if (v.lo == v.hi) continue;
      const double m = mid(v);
      mv = add(mv, mul(d[j], Interval{v.lo - m, v.hi - m}));
    }
    if (std::isfinite(mv.lo) && std::isfinite(mv.hi)) f = intersect(f, mv);
    if (excludes(f, inside)) return true;
  }
  return false;
}

// Dominance narrowing, exact for the max-min objective. Where ∂F/∂θ_i keeps one sign over the box
// and moving θ_i towards its core moves F the way the search wants (down for u, up for l), every θ
// of the box is beaten or matched by the θ with that value moved towards the core, as far as the
// box allows: F moves the right way (the slope holds all along, the box is convex) and μ̂_i rises
// or stays (μ̂ rises up to the core and falls after it), so m(θ) does not fall. Hence the θ with
// θ_i beyond the core's near end cannot hold the best m: for u with F nondecreasing in θ_i the box
// keeps [lo, min(hi, max(lo, core.lo))] (a box wholly above the core keeps its lower face), and
// the mirror images for the other three cases. Nothing qualifying with the best m is lost, so the
// searches' guarantees stand; the box loses the half of each signed value that lies on the wrong
// side of the core.
bool FuzzyPartField::narrowByDominance(PartBox* box, const int* open, int count, const Interval* d,
                                       bool inside) const {
  bool changed = false;
  for (int j = 0; j < count; ++j) {
    const int sign = d[j].lo >= 0.0 ? 1 : d[j].hi <= 0.0 ? -1 : 0;
    if (sign == 0) continue;
    Interval& v = slot(*box, open[j]);
    const Interval& core = slot(core_, open[j]);
    if ((sign > 0) == inside) {  // F falls (u) or rises (l) downwards: keep the lower part
      const double top = std::min(v.hi, std::max(v.lo, core.lo));
      changed = changed || top < v.hi;
      v.hi = top;
    } else {
      const double bottom = std::max(v.lo, std::min(v.hi, core.hi));
      changed = changed || bottom > v.lo;
      v.lo = bottom;
    }
  }
  return changed;
}

// The linearised bound of a box (maxMin): every θ of the box that qualifies (F <= 1 for u, F > 1
// for l) satisfies the affine form's linear condition, σ·Σ f_i·ε_i <= σ·(1 − F0) + e (σ = +1 for
// u, −1 for l; ε_i the noise symbols of formBox, the box the form was computed over), and has
// m(θ) >= t only if it lies in P(t). So no qualifying θ of the box has m above the least t at which
// P(t) ∩ box holds no point of that half-space: the least over P(t) ∩ box of σ·Σ f_i·ε_i (each
// term at an end) exceeds the right-hand side. That sum rises with t (the cuts nest), so bisection
// on [0, ub] finds the bound; the box bound ub ignores F, this one trades the values against each
// other. Returns a bound <= ub (rounded up), or −1 when even t = 0 admits no such point.
double FuzzyPartField::linearizedBound(const PartBox& box, const PartBox& formBox,
                                       const AffineForm& form, bool inside, double ub) const {
  const double sigma = inside ? 1.0 : -1.0;
  const double rhs = sigma * (1.0 - form.centre) + form.err;
  double scale = std::fabs(rhs);
  for (int j = 0; j < fuzzyCount_; ++j) scale += std::fabs(form.dev[fuzzySlots_[j]]);
  const double slack = 1e-12 * scale;
  // The least of σ·Σ f_i·ε_i over P(t) ∩ box; +∞ when that set is empty.
  const auto least = [&](double t) {
    double sum = 0.0;
    for (int j = 0; j < fuzzyCount_; ++j) {
      const int i = fuzzySlots_[j];
      const Interval& b = slot(box, i);
      Interval c = b;
      if (t > 0.0) {
        const Interval cut = t >= 1.0 ? slot(core_, i) : values_[i]->alphaCut(t);
        c = {std::max(b.lo, cut.lo), std::min(b.hi, cut.hi)};
        if (c.lo > c.hi) return std::numeric_limits<double>::infinity();
      }
      const Interval& w = slot(formBox, i);
      const double half = 0.5 * w.hi - 0.5 * w.lo;
      const double coefficient = sigma * form.dev[i];
      if (!(half > 0.0) || coefficient == 0.0) continue;
      const double end = coefficient > 0.0 ? c.lo : c.hi;
      sum += coefficient * ((end - mid(w)) / half);
    }
    return sum;
  };
  const auto admits = [&](double t) { return least(t) <= rhs + slack; };
  if (!admits(0.0)) return -1.0;
  if (admits(ub)) return ub;
  double lo = 0.0, hi = ub;  // admits(lo), !admits(hi)
  while (hi - lo > 0.125 * options_.tolerance) {
    const double m = 0.5 * (lo + hi);
    (admits(m) ? lo : hi) = m;
  }
  return std::min(ub, hi + kMembershipSlack);
}

// Max-min branch and bound (see the header): maximise m(θ) = min_i μ̂_i(θ_i) over the θ of P(0)
// with F(p; θ) <= 1 (inside) or F(p; θ) > 1 (!inside).
FuzzyPartField::Search FuzzyPartField::maxMin(const Vec3& p, bool inside) const {
  const double tau = options_.tolerance;
  const Interval px{p.x, p.x}, py{p.y, p.y}, pz{p.z, p.z};
  const auto witness = [&](double f) { return inside ? f <= 1.0 : f > 1.0; };
  // m(θ) of a crisp parameter vector (the fuzzy values only).
  const auto membershipAt = [&](const double (&v)[kSlots]) {
    double m = 1.0;
    for (int i = 0; i < kSlots; ++i)
      if (supportWidth_[i] > 0.0) m = std::min(m, hullMembership(*values_[i], v[i]));
    return m;
  };
  const auto upperBound = [&](const PartBox& b) {
    double ub = 1.0;
    for (int i = 0; i < kSlots; ++i)
      if (supportWidth_[i] > 0.0)
        ub = std::min(ub, supHullMembership(*values_[i], slot(core_, i), slot(b, i)));
    return std::min(1.0, ub + kMembershipSlack);
  };
  struct Node {
    PartBox box;
    double ub;
    double promise;  // −F (inside) or F (outside) at the box centre: larger is nearer a witness
    int depth = 0;   // splits from P(0)
  };
  // Until a witness is known, dive towards one (the box whose centre comes closest, as the
  // depth-first decide does); then best first by the bound.
  bool diving = true;
  const auto lessPromising = [&diving](const Node& a, const Node& b) {
    return diving ? a.promise < b.promise : a.ub < b.ub;
  };
  std::vector<Node> heap;
  heap.reserve(16);
  Search s;
  // The level that only a gain of more than τ beats: the incumbent, and for u at least 0 (u = 0 is
  // a correct answer for every u_true <= τ, witness or not; l = 0 instead claims p ∈ lower(0) and
  // needs the proof over all of P(0)). -1: none yet.
  double base = inside ? 0.0 : -1.0;
  PartBox cut;  // P(base + τ) once there is a base
  // A box whose bound cannot beat the incumbent by more than τ is done with: its bound joins
  // what was pruned.
  const auto prunes = [&](double ub) {
    if (!(base >= 0.0 && ub <= base + tau)) return false;
    s.pruned = std::max(s.pruned, ub);
    return true;
  };
  if (base >= 0.0) cut = cutAt(tau);
  double weight[kSlots], slope[kSlots];
  bool haveWeights = false, haveSlopes = false;
  // Where the guessing slopes are taken: the core midpoint, then the latest incumbent's witness
  // (F's slopes near the best θ so far point to better corners of the cut boxes than those at the
  // core). Only the guesses depend on it: every witness is checked by a crisp evaluation.
  double slopeAt[kSlots];
  for (int i = 0; i < kSlots; ++i) slopeAt[i] = mid(slot(core_, i));
  const auto improve = [&](double m, const PlacedSuperquadric& theta) {
    if (m <= s.incumbent) return;
    if (diving) {
      diving = false;
      std::make_heap(heap.begin(), heap.end(), lessPromising);
    }
    s.incumbent = m;
    s.witness = theta;
    const PartBox at = crispPartBox(theta);  // single values, addressed by slot
    for (int i = 0; i < kSlots; ++i) slopeAt[i] = slot(at, i).lo;
    haveSlopes = false;
    if (m <= base) return;
    base = m;
    if (m + tau <= 1.0) cut = cutAt(m + tau);
  };
  // Guessing slopes: central differences of F at slopeAt (recomputed when a guess needs them
  // after the incumbent moved); their signs pick the corner of a box tried as a witness.
  int evaluations = 0;
  const auto computeSlopes = [&] {
    haveSlopes = true;
    double theta[kSlots];
    for (int i = 0; i < kSlots; ++i) theta[i] = slopeAt[i];
    for (int i = 0; i < kSlots; ++i) {
      slope[i] = 0.0;
      if (supportWidth_[i] <= 0.0) continue;
      const Interval& sup = slot(support_, i);
      const double h = 1e-3 * supportWidth_[i], t0 = theta[i];
      const double a = std::max(sup.lo, t0 - h), b = std::min(sup.hi, t0 + h);
      theta[i] = a;
      const double fa = valueAt(thetaAt(support_, theta), p);
      theta[i] = b;
      const double fb = valueAt(thetaAt(support_, theta), p);
      theta[i] = t0;
      const double g = b > a ? (fb - fa) / (b - a) : 0.0;
      slope[i] = std::isfinite(g) ? g : 0.0;
    }
  };
  // Split weights, from the first box that needs splitting (and deeper ones, below): how far the enclosure's deciding end
  // (lo for a witness inside, hi outside) moves when one value is fixed at its midpoint, per unit
  // of relative width. The value whose width costs the enclosure most is split first; a floor
  // keeps every value in turn.
  const auto computeWeights = [&](const PartBox& box, const Interval& f) {
    haveWeights = true;
    constexpr double kCap = 1e300;  // the enclosure saturates at the largest double
    const auto end = [&](const Interval& g) { return inside ? g.lo : std::min(g.hi, kCap); };
    double largest = 0.0;
    for (int i = 0; i < kSlots; ++i) {
      weight[i] = 0.0;
      const Interval v = slot(box, i);
      if (supportWidth_[i] <= 0.0 || !(width(v) > 0.0)) continue;
      PartBox c = box;
      slot(c, i) = {mid(v), mid(v)};
      ++evaluations;
      const Interval g = pointEnclosure(c, p, inside);
      const double gain = inside ? end(g) - end(f) : end(f) - end(g);
      weight[i] = std::max(gain, 0.0) / (width(v) / supportWidth_[i]);
      largest = std::max(largest, weight[i]);
    }
    for (int i = 0; i < kSlots; ++i)
      weight[i] = largest > 0.0 && std::isfinite(largest) ? std::max(weight[i], 0.02 * largest)
                                                          : 1.0;
  };

  heap.push_back({support_, 1.0, 0.0});
  // A dive that finds no witness in a quarter of the budget may find none at all (u_true <= τ, or
  // no θ of P(0) puts p outside): from then on best first, so that the proof lowers the largest
  // open bound steadily and an exhausted search answers that bound rather than 1.
  const int diveLimit = options_.evaluationBudget / 4;
  while (!heap.empty()) {
    if (diving && evaluations >= diveLimit) {
      diving = false;
      std::make_heap(heap.begin(), heap.end(), lessPromising);
    }
    std::pop_heap(heap.begin(), heap.end(), lessPromising);
    Node node = std::move(heap.back());
    heap.pop_back();
    // Best first: nothing left can beat the incumbent by more than τ (while diving, the heap is
    // ordered by promise: drop just this box).
    if (prunes(node.ub)) {
      if (diving) continue;
      break;
    }
    if (evaluations >= options_.evaluationBudget) {
      s.exhausted = true;
      s.pruned = std::max(s.pruned, node.ub);  // the largest bound still open
      for (const Node& open : heap) s.pruned = std::max(s.pruned, open.ub);
      ++exhaustions_;
      return s;
    }
    if (base >= 0.0) {
      // Only θ with m(θ) > incumbent + τ can still matter, and they lie in P(incumbent + τ).
      const double target = base + tau;
      if (target > 1.0) {
        s.pruned = std::max(s.pruned, node.ub);
        break;
      }
      bool empty = false, shrunk = false;
      for (int i = 0; i < kSlots && !empty; ++i) {
        Interval& v = slot(node.box, i);
        const Interval& c = slot(cut, i);
        const Interval w{std::max(v.lo, c.lo), std::min(v.hi, c.hi)};
        shrunk = shrunk || w.lo != v.lo || w.hi != v.hi;
        v = w;
        empty = v.lo > v.hi;
      }
      // The θ cut away have m(θ) < target: they bound what was dropped.
      if (shrunk) s.pruned = std::max(s.pruned, std::min(node.ub, target));
      if (empty) continue;
      node.ub = std::min(node.ub, upperBound(node.box));
      if (prunes(node.ub)) continue;
    }
    ++evaluations;
    if (inside && missesDeformedHull(node.box, px, py, pz)) continue;  // F > 1 on the whole box
    Interval f;
    bool narrowed = false;
    const PartBox formBox = node.box;  // the box the affine form's noise symbols refer to
    AffineForm form;
    if (!narrowToQualifying(&node.box, p, inside, &f, &narrowed, &form))
      continue;  // no θ of the box qualifies
    if (form.valid) {
      const double lp = linearizedBound(node.box, formBox, form, inside, node.ub);
      if (lp < 0.0) continue;  // no θ of the box satisfies the linear condition
      if (lp < node.ub) {
        node.ub = lp;
        if (prunes(node.ub)) continue;
      }
    }
    if (narrowed) {
      node.ub = std::min(node.ub, upperBound(node.box));
      if (prunes(node.ub)) continue;
    }
    // The slopes over the box: dominance first (it keeps the best m), then the collapse tests.
    int open[kSlots], openCount = 0;
    for (int j = 0; j < fuzzyCount_; ++j)
      if (width(slot(node.box, fuzzySlots_[j])) > 0.0) open[openCount++] = fuzzySlots_[j];
    // (Where they cannot be bounded, the collapse tests cannot run either: they start from them.)
    Interval boxSlopes[kSlots];
    if (openCount > 0) ++evaluations;
    if (openCount > 0 && insideOutsideSlopes(node.box, px, py, pz, open, openCount, boxSlopes)) {
      if (narrowByDominance(&node.box, open, openCount, boxSlopes, inside)) {
        node.ub = std::min(node.ub, upperBound(node.box));
        if (prunes(node.ub)) continue;
      }
      if (collapsedExcludes(node.box, p, inside, &evaluations, open, openCount, boxSlopes))
        continue;
    }
    // The peak of the box: each value clamped towards its core maximises μ̂_i over the box, so a
    // witness there settles the box (m = its bound).
    double peak[kSlots], centre[kSlots];
    for (int i = 0; i < kSlots; ++i) {
      const Interval& v = slot(node.box, i);
      const double c = mid(slot(core_, i));
      peak[i] = std::min(std::max(c, v.lo), v.hi);
      centre[i] = mid(v);
    }
    const PlacedSuperquadric peakTheta = thetaAt(node.box, peak);
    const double fPeak = valueAt(peakTheta, p);
    if (witness(fPeak)) {
      improve(membershipAt(peak), peakTheta);
      if (s.incumbent >= 1.0) break;
      continue;
    }
    // A second guess: the corner that F's guessing slopes say is most favourable (least F for
    // a witness inside, largest outside). From a witness, walk towards the peak (m grows along
    // the segment, each value nearing its core) and keep the last witness: bisection on the
    // segment until m is resolved well below τ.
    if (!haveSlopes) computeSlopes();
    double guess[kSlots];
    for (int i = 0; i < kSlots; ++i) {
      const Interval& v = slot(node.box, i);
      const bool low = (slope[i] > 0.0) == inside;
      guess[i] = slope[i] == 0.0 ? centre[i] : low ? v.lo : v.hi;
    }
    PlacedSuperquadric guessTheta = thetaAt(node.box, guess);
    double fGuess = valueAt(guessTheta, p);
    if (!witness(fGuess)) {
      std::copy(centre, centre + kSlots, guess);
      guessTheta = thetaAt(node.box, guess);
      fGuess = valueAt(guessTheta, p);
    }
    if (witness(fGuess)) {
      // Regula falsi (Illinois) on g(t) = F(θ(t)) − 1, kept inside the shrinking bracket.
      double lo = 0.0, hi = 1.0, at[kSlots];
      double gLo = fGuess - 1.0, gHi = fPeak - 1.0, gHiTrue = gHi;
      double mLo = membershipAt(guess), mHi = membershipAt(peak);
      int side = 0;
      for (int k = 0; k < 40 && mHi - mLo > 0.125 * tau; ++k) {
        const double span = hi - lo;
        double t = std::isfinite(gLo) && std::isfinite(gHi) && gLo != gHi
                       ? lo - gLo * span / (gHi - gLo)
                       : lo + 0.5 * span;
        if (!(t >= lo + 0.02 * span && t <= hi - 0.02 * span)) t = lo + 0.5 * span;
        for (int i = 0; i < kSlots; ++i) at[i] = guess[i] + t * (peak[i] - guess[i]);
        const PlacedSuperquadric theta = thetaAt(node.box, at);
        const double f = valueAt(theta, p);
        if (witness(f)) {
          lo = t;
          gLo = f - 1.0;
          mLo = membershipAt(at);
          guessTheta = theta;
          if (side == -1) gHi *= 0.5;
          side = -1;
        } else {
          hi = t;
          gHi = gHiTrue = f - 1.0;
          mHi = membershipAt(at);
          if (side == 1) gLo *= 0.5;
          side = 1;
        }
        // Close enough: the secant's crossing is within τ/4 of the witness in m. (Only speed
        // rests on this: the next pop cuts the box to P(incumbent + τ) and searches on.)
        if (side == -1 && std::isfinite(gHiTrue) && gHiTrue != gLo) {
          const double tEst = std::min(hi, lo - gLo * (hi - lo) / (gHiTrue - gLo));
          for (int i = 0; i < kSlots; ++i) at[i] = guess[i] + tEst * (peak[i] - guess[i]);
          if (membershipAt(at) - mLo <= 0.25 * tau) break;
        }
      }
      improve(mLo, guessTheta);
      if (s.incumbent >= 1.0) break;
      // Requeue the box: its next pop cuts it to P(incumbent + τ), which drops the part just
      // searched (every later witness in it gains at least τ).
      if (node.ub <= base + tau) {
        s.pruned = std::max(s.pruned, node.ub);
      } else {
        heap.push_back(std::move(node));
        std::push_heap(heap.begin(), heap.end(), lessPromising);
      }
      continue;
    }
    // Weights from the first box that needs splitting, taken again from every box a multiple of
    // fuzzyCount_ splits deep (each value split about once since): the values that cost the
    // enclosure most change as boxes shrink (at N = 64 this ran 118 searches out of budget, 156
    // with the first box's weights kept).
    if (!haveWeights || (node.depth > 0 && node.depth % fuzzyCount_ == 0))
      computeWeights(node.box, f);
    int widest = -1;
    double widestScore = 0.0;
    for (int i = 0; i < kSlots; ++i) {
      if (supportWidth_[i] <= 0.0) continue;
      const double r = width(slot(node.box, i)) / supportWidth_[i];
      if (r <= kDegenerate) continue;
      if (r * weight[i] > widestScore) {
        widest = i;
        widestScore = r * weight[i];
      }
    }
    if (widest < 0) continue;  // one θ: its crisp values did not qualify
    const Interval v = slot(node.box, widest);
    const double m = mid(v);
    ++node.depth;
    Node a = node, b = std::move(node);
    slot(a.box, widest) = {v.lo, m};
    slot(b.box, widest) = {m, v.hi};
    for (Node* child : {&a, &b}) {
      child->ub = std::min(child->ub, upperBound(child->box));
      if (diving) {
        double c[kSlots];
        for (int i = 0; i < kSlots; ++i) c[i] = mid(slot(child->box, i));
        const PlacedSuperquadric theta = thetaAt(child->box, c);
        const double fc = valueAt(theta, p);
        child->promise = inside ? -fc : fc;
        if (witness(fc)) improve(membershipAt(c), theta);
      }
      if (prunes(child->ub)) continue;
      heap.push_back(std::move(*child));
      std::push_heap(heap.begin(), heap.end(), lessPromising);
    }
    if (s.incumbent >= 1.0) break;
  }
  return s;
}

namespace {

// Narrows [lo, hi] around the level where F at a corner moving with α crosses 1: on entry
// qualifies(value(lo)) and !qualifies(value(hi)), with qualifies(f) = f <= 1 (inside) or f > 1
// (!inside), value(α) monotone; on return the same holds and hi − lo <= tau. Secant steps through
// the two latest points (the corners move linearly in α between breakpoints, so they converge
// fast), kept τ/4 inside the bracket, halving after eight; when the next estimate lies within
// 0.45·τ of the last point, a probe τ/2 beyond it on that side usually closes the bracket.
template <typename Value>
void narrowBracket(const Value& value, bool inside, double tau, double* lo, double* hi, double fLo,
                   double fHi) {
  const auto qualifies = [inside](double f) { return inside ? f <= 1.0 : f > 1.0; };
  double a = *lo, fa = fLo, b = *hi, fb = fHi;  // the two latest points
  const auto secant = [&](double* r) {
    if (!(std::isfinite(fa) && std::isfinite(fb) && fa != fb)) return false;
    *r = b - (fb - 1.0) * (b - a) / (fb - fa);
    return std::isfinite(*r);
  };
  const auto take = [&](double t) {
    const double f = value(t);
    if (qualifies(f))
      *lo = t;
    else
      *hi = t;
    a = b;
    fa = fb;
    b = t;
    fb = f;
  };
  for (int k = 0; *hi - *lo > tau; ++k) {
    double t = 0.5 * (*lo + *hi), r;
    if (k < 8 && secant(&r) && r > *lo && r < *hi)
      t = std::min(std::max(r, *lo + 0.25 * tau), *hi - 0.25 * tau);
    if (!(t > *lo && t < *hi)) break;  // τ below the spacing of doubles near the bracket
    take(t);
    if (*hi - *lo > tau && secant(&r) && std::fabs(r - t) < 0.45 * tau) {
      const double q = r > t ? t + 0.5 * tau : t - 0.5 * tau;
      if (q > *lo && q < *hi) take(q);
    }
  }
}

}  // namespace

bool FuzzyPartField::monotoneSigns(const Vec3& lo, const Vec3& hi, signed char* sign) const {
  Interval d[kSlots];
  if (fuzzyCount_ == 0 ||
      !insideOutsideSlopes(support_, {lo.x, hi.x}, {lo.y, hi.y}, {lo.z, hi.z}, fuzzySlots_,
                           fuzzyCount_, d))
    return false;
  for (int i = 0; i < kSlots; ++i) sign[i] = 0;
  for (int j = 0; j < fuzzyCount_; ++j) {
    if (d[j].lo >= 0.0)
      sign[fuzzySlots_[j]] = 1;
    else if (d[j].hi <= 0.0)
      sign[fuzzySlots_[j]] = -1;
    else
      return false;
  }
  return true;
}

PlacedSuperquadric FuzzyPartField::cornerAt(double alpha, const signed char* sign,
                                            bool least) const {
  double v[kSlots];
  for (int i = 0; i < kSlots; ++i) v[i] = slot(support_, i).lo;  // crisp values: lo == hi
  for (int j = 0; j < fuzzyCount_; ++j) {
    const int i = fuzzySlots_[j];
    const Interval c = alpha == 0.0   ? slot(support_, i)
                       : alpha == 1.0 ? slot(core_, i)
                                      : values_[i]->alphaCut(alpha);
    v[i] = (sign[i] > 0) == least ? c.lo : c.hi;
  }
  return thetaAt(support_, v);
}

float FuzzyPartField::roundedUpper(double level, const PlacedSuperquadric& witness) const {
  float u = floatDown(level);
  while (u > 0.0f && !contains(u == 1.0f ? core_ : cutAt(u), witness))
    u = std::nextafter(u, -1.0f);
  return u;
}

// The monotone shortcut. Where F is monotone in every fuzzy value over P(0) at p (signs certified
// by insideOutsideSlopes), moving one value at a time to the end that lowers F never raises it, so
//   g(α) = min{F(p; θ) : θ ∈ P(α)} = F(p; least corner of P(α)),
//   h(α) = max{F(p; θ) : θ ∈ P(α)} = F(p; largest corner of P(α)),
// exactly (P(α) ⊆ P(0) is a box). With θ ∈ P(α) ⇔ m(θ) >= α (α > 0), u_true = sup{α : g(α) <= 1}
// and l_true = inf{α : h(α) <= 1}; g rises and h falls with α (P(α) shrinks). So brackets
// [lo, hi] with g(lo) <= 1 < g(hi) hold u_true (u = lo, witness the least corner of P(lo)), and
// ones with h(lo) > 1 >= h(hi) hold l_true (l = hi, proven: the largest F over P(hi) is <= 1),
// each to τ: the guarantees of the search, with no budget to run out. g(0) > 1: no θ puts p
// inside (u = 0, never); h(0) <= 1: p ∈ lower(0) (l = 0); h(1) > 1: a θ of P(1) puts p outside.
AlphaLevels FuzzyPartField::cornerLevels(const Vec3& p, const signed char* sign,
                                         bool inCore) const {
  const double tau = options_.tolerance;
  AlphaLevels out;
  const auto least = [&](double a) { return valueAt(cornerAt(a, sign, true), p); };
  const double g0 = inCore ? 0.0 : least(0.0);
  if (g0 > 1.0) return {0.0f, kNeverInside};
  const double g1 = inCore ? 0.0 : least(1.0);
  if (g1 > 1.0) {
    double lo = 0.0, hi = 1.0;
    narrowBracket(least, true, tau, &lo, &hi, g0, g1);
    out.upper = roundedUpper(lo, cornerAt(lo, sign, true));
    return out;  // l <= 1 needs p ∈ lower(1) ⊆ upper(1)
  }
  out.upper = 1.0f;
  const auto largest = [&](double a) { return valueAt(cornerAt(a, sign, false), p); };
  const double h0 = largest(0.0);
  if (h0 <= 1.0) {
    out.lower = 0.0f;
    return out;
  }
  const double h1 = largest(1.0);
  if (h1 > 1.0) return out;  // never in lower(1)
  double lo = 0.0, hi = 1.0;
  narrowBracket(largest, false, tau, &lo, &hi, h0, h1);
  out.lower = floatUp(hi);
  return out;
}

// One fuzzy size v (a1, which scales A, B and C together, or the placement scale) and no
// taper, twist or bend: F(p; v) = (ρ/v)^(2/ε1) with ρ = v_ref·G(p; v_ref), G = F^(ε1/2) (docs/api.md §2:
// the canonical ratios scale with 1/v), so S(v) holds p exactly when v >= ρ. Then, with μ̂ the hull
// membership of v (rising up to the core, falling after it), exactly:
//   u = 1 for ρ <= core.hi, μ̂(ρ) on the falling side, 0 (and l = never) beyond the support;
//   l = 0 for ρ <= support.lo, μ̂(ρ) on the rising side, never for ρ > core.lo.
// One evaluation of G gives ρ. Each answer rests on the corner that the monotone shortcut would
// have evaluated (the F-lowering end of P(u) for u, the F-raising end of P(l) for l): F there is
// (ρ/v)^(2/ε1), decided by the identity where v is clear of ρ by a relative 1e-9 (far above the
// rounding of ρ), else by a crisp evaluation of F at that corner. So the answers carry the witnesses
// and proofs of cornerLevels, rounded the same way (u down, l up), and are exact rather than
// τ-brackets. False where a check disagrees (rounding at the boundary, overflow): the caller
// falls back to the general path.
bool FuzzyPartField::sizeLevels(const Vec3& p, AlphaLevels* out) const {
  // G = F^(ε1/2) (superquadric.h) is homogeneous of degree −1 in v: G(p; v) = G(p; v_ref)·v_ref/v,
  // so S(v) holds p exactly when v >= ρ = v_ref·G(p; v_ref). (sizeSlot_ is set only when every
  // value but v is crisp, so the angle is crisp and rotation_ is built.)
  const PlacedSuperquadric& reference = sizeReferencePart_;
  const Placement& pl = reference.placement;
  const Vec3 local = rotation_.applyInverse(p - pl.translate) / pl.scale;
  const double rho =
      sizeReference_ * homogeneousInsideOutside(reference.params, undeformPoint(reference.params, local));
  if (!std::isfinite(rho)) return false;
  const FuzzyNumber& v = *values_[sizeSlot_];
  const Interval support = slot(support_, sizeSlot_), core = slot(core_, sizeSlot_);
  // Does S(value) hold p? By the identity (value >= ρ) where value is clear of ρ by far more than
  // rounding, else by a crisp evaluation of F at that value.
  constexpr double kClear = 1e-9;
  const auto inside = [&](double value) {
    if (value >= rho * (1.0 + kClear)) return true;
    if (value <= rho * (1.0 - kClear)) return false;
    double theta[kSlots];
    for (int i = 0; i < kSlots; ++i) theta[i] = slot(support_, i).lo;
    theta[sizeSlot_] = value;
    return valueAt(thetaAt(support_, theta), p) <= 1.0;
  };
  const auto cut = [&](float alpha) { return alpha >= 1.0f ? core : v.alphaCut(alpha); };
  if (!inside(support.hi)) {  // outside S(θ) for every θ of P(0)
    *out = {0.0f, kNeverInside};
    return true;
  }
  if (!inside(core.hi)) {
    // u = μ̂(ρ) on the falling side, rounded down to a float whose cut still reaches ρ; the
    // witness is that cut's upper end.
    float u = floatDown(hullMembership(v, rho));
    Interval c = cut(u);
    for (int k = 0; k < 8 && u > 0.0f && c.hi < rho; ++k) c = cut(u = std::nextafter(u, -1.0f));
    if (!(u > 0.0f) || c.hi < rho || !inside(c.hi)) return false;
    *out = {u, kNeverInside};
    return true;
  }
  // u = 1 (the witness: the core's upper end).
  if (inside(support.lo)) {  // inside S(θ) for every θ of P(0)
    *out = {1.0f, 0.0f};
    return true;
  }
  if (!inside(core.lo)) {  // a θ of P(1) puts p outside
    *out = {1.0f, kNeverInside};
    return true;
  }
  // l = μ̂(ρ) on the rising side, rounded up to a float whose cut starts at or above ρ: every θ
  // of P(l) puts p inside (its lower end, the F-raising corner, does).
  float l = floatUp(hullMembership(v, rho));
  Interval c = cut(l);
  for (int k = 0; k < 8 && l < 1.0f && c.lo < rho; ++k) c = cut(l = std::nextafter(l, 2.0f));
  if (c.lo < rho || !inside(c.lo)) return false;
  *out = {1.0f, l};
  return true;
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
  const Search up = maxMin(p, true);
  AlphaLevels out;
  if (up.exhausted) {
    // Conservative: an upper bound of u (upper grows); l is not sought below u = 1.
    out.upper = floatUp(std::min(1.0, std::max(up.incumbent, up.pruned)));
    if (out.upper < 1.0f) return out;
  } else {
    if (up.incumbent < 0.0) return out;  // no θ of P(0) puts p inside: u = 0, l = never
    // Round down, keeping the witness: p ∈ upper(u) is shown by θ ∈ P(u).
    const float u = roundedUpper(up.incumbent, up.witness);
    out.upper = u;
    if (u < 1.0f) return out;  // l <= 1 needs p ∈ lower(1) ⊆ upper(1)
  }
  // l(p) = sup{m(θ) : F(p; θ) > 1} (0 when no θ of P(0) puts p outside, proven).
  const Search down = maxMin(p, false);
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

void FuzzyPartField::sampleSubBlock(const BlockLattice& b, int i, int j, int k, int size,
                                    BlockSigns* signs, AlphaLevels* out) const {
  constexpr int d = BlockLattice::kDim;
  const AlphaLevelBounds bounds =
      boundsOver(b.at(i, j, k), b.at(i + size - 1, j + size - 1, k + size - 1));
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
                                         : FuzzyPartField::levelsAt(b.at(x, y, z));
    return;
  }
  if (!uniform && size <= 2 && !crisp_) {
    // Signs that hold over the whole block serve every voxel of it (one slope enclosure per block
    // instead of one per voxel); otherwise levelsAt tries the voxel's own.
    if (signs->state == 0)
      signs->state = monotoneSigns(b.lo(), b.hi(), signs->sign) ? 1 : 2;
    // Inside S(θ) for every θ of P(1) (boundsOver): g(1) <= 1, so u = 1 with no evaluation.
    const bool inCore = bounds.upperMin == 1.0f;
    for (int x = i; x < i + size; ++x)
      for (int y = j; y < j + size; ++y)
        for (int z = k; z < k + size; ++z)
          out[(x * d + y) * d + z] =
              signs->state == 1 ? cornerLevels(b.at(x, y, z), signs->sign, inCore)
                                : FuzzyPartField::levelsAt(b.at(x, y, z));
    return;
  }
  if (uniform || size <= 2) {
    // Qualified: no virtual call (levelsAt's first test is the crisp shortcut).
    for (int x = i; x < i + size; ++x)
      for (int y = j; y < j + size; ++y)
        for (int z = k; z < k + size; ++z)
          out[(x * d + y) * d + z] = uniform ? AlphaLevels{bounds.upperMin, bounds.lowerMin}
                                             : FuzzyPartField::levelsAt(b.at(x, y, z));
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

}  // namespace fsdb
