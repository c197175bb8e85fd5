// FuzzyPartField's max-min search (maxMin) and the exclusion and narrowing tests it runs on each
// box. The algorithm and its guarantees: docs/design/fuzzy-part-field.md.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "geometry/field/fuzzy_part_field.h"
#include "geometry/field/fuzzy_part_field_detail.h"
#include "geometry/superquadric/superquadric_slopes.h"

namespace fsdb {

using namespace part_field_detail;

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
    if (!collapseMonotone(&c, open, n, d, inside)) return false;
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

// Max-min branch and bound (docs/design/fuzzy-part-field.md): maximise m(θ) = min_i μ̂_i(θ_i) over
// the θ of P(0) with F(p; θ) <= 1 (inside) or F(p; θ) > 1 (!inside). One object per search: the
// state its steps share (the heap of open boxes, the incumbent, the cut, the guessing slopes and
// the split weights); run() pops boxes and hands each to the steps in order.
class FuzzyPartField::MaxMinSearch {
 public:
  MaxMinSearch(const FuzzyPartField& field, const Vec3& p, bool inside)
      : field_(field), p_(p), px_{p.x, p.x}, py_{p.y, p.y}, pz_{p.z, p.z}, inside_(inside),
        tau_(field.options_.tolerance), budget_(field.options_.evaluationBudget),
        // The level that only a gain of more than τ beats: the incumbent, and for u at least 0
        // (u = 0 is a correct answer for every u_true <= τ, witness or not; l = 0 instead claims
        // p ∈ lower(0) and needs the proof over all of P(0)). -1: none yet.
        base_(inside ? 0.0 : -1.0) {
    heap_.reserve(16);
    if (base_ >= 0.0) cut_ = field_.cutAt(tau_);
    for (int i = 0; i < kSlots; ++i) slopeAt_[i] = mid(slot(field_.core_, i));
  }

  Search run(const Seed& seed);

 private:
  struct Node {
    PartBox box;
    double ub;
    double promise;  // −F (inside) or F (outside) at the box centre: larger is nearer a witness
    int depth = 0;   // splits from P(0)
  };
  // What a step decided about the box it was given.
  enum class Outcome { kContinue, kNextBox, kStop };

  bool witness(double f) const { return inside_ ? f <= 1.0 : f > 1.0; }
  double membershipAt(const double (&v)[kSlots]) const;
  double upperBound(const PartBox& b) const;
  bool prunes(double ub);
  void improve(double m, const PlacedSuperquadric& theta);
  void computeSlopes();
  void computeWeights(const PartBox& box, const Interval& f);
  // The heap of open boxes. Until a witness is known, dive towards one (the box whose centre comes
  // closest, as the depth-first decide does); then best first by the bound.
  bool lessPromising(const Node& a, const Node& b) const {
    return diving_ ? a.promise < b.promise : a.ub < b.ub;
  }
  void push(Node node);
  Node pop();
  void stopDiving();
  // The steps of one box, in the order run() takes them.
  Outcome cutToTarget(Node* node);
  bool excluded(Node* node, Interval* f);
  Outcome tryWitnesses(Node* node);
  double walkTowardsPeak(const Node& node, const double (&guess)[kSlots], const double (&peak)[kSlots],
                         double fGuess, double fPeak, PlacedSuperquadric* guessTheta) const;
  Outcome split(Node node, const Interval& f);

  const FuzzyPartField& field_;
  const Vec3 p_;
  const Interval px_, py_, pz_;
  const bool inside_;
  const double tau_;
  const int budget_;
  bool diving_ = true;
  std::vector<Node> heap_;
  Search s_;
  double base_;
  PartBox cut_;  // P(base + τ) once there is a base
  double weight_[kSlots], slope_[kSlots];
  bool haveWeights_ = false, haveSlopes_ = false;
  // Where the guessing slopes are taken: the core midpoint, then the latest incumbent's witness
  // (F's slopes near the best θ so far point to better corners of the cut boxes than those at the
  // core). Only the guesses depend on it: every witness is checked by a crisp evaluation.
  double slopeAt_[kSlots];
  int evaluations_ = 0;
  double corePeakValue_ = 0.0;  // F at the core's midpoint, taken first by run()
};

FuzzyPartField::Search FuzzyPartField::maxMin(const Vec3& p, bool inside, const Seed& seed) const {
  return MaxMinSearch(*this, p, inside).run(seed);
}

FuzzyPartField::Search FuzzyPartField::MaxMinSearch::run(const Seed& seed) {
  // The peak of P(0), every value at its core's midpoint, first: where it is a witness, m = 1 is
  // the answer with one crisp evaluation and no enclosure (tryWitnesses would find it too, but
  // only after the first box's exclusion tests, which cannot succeed there).
  {
    double peak[kSlots];
    for (int i = 0; i < kSlots; ++i) peak[i] = mid(slot(field_.core_, i));
    const PlacedSuperquadric theta = thetaAt(field_.support_, peak);
    corePeakValue_ = field_.valueAt(theta, p_);
    if (witness(corePeakValue_)) {
      improve(membershipAt(peak), theta);
      if (s_.incumbent >= 1.0) return s_;
    }
  }
  // A caller's witness (the monotone shortcut's bracket end): every box is cut to the level it
  // must beat from the first one on.
  if (seed.level >= 0.0) improve(seed.level, seed.witness);
  heap_.push_back({field_.support_, 1.0, 0.0});
  // A dive that finds no witness in a quarter of the budget may find none at all (u_true <= τ, or
  // no θ of P(0) puts p outside): from then on best first, so that the proof lowers the largest
  // open bound steadily and an exhausted search answers that bound rather than 1.
  const int diveLimit = budget_ / 4;
  while (!heap_.empty()) {
    if (diving_ && evaluations_ >= diveLimit) stopDiving();
    Node node = pop();
    // Best first: nothing left can beat the incumbent by more than τ (while diving, the heap is
    // ordered by promise: drop just this box).
    if (prunes(node.ub)) {
      if (diving_) continue;
      break;
    }
    if (evaluations_ >= budget_) {
      s_.exhausted = true;
      s_.pruned = std::max(s_.pruned, node.ub);  // the largest bound still open
      for (const Node& open : heap_) s_.pruned = std::max(s_.pruned, open.ub);
      ++field_.exhaustions_;
      return s_;
    }
    Outcome outcome = cutToTarget(&node);
    if (outcome == Outcome::kStop) break;
    if (outcome == Outcome::kNextBox) continue;
    Interval f;
    if (excluded(&node, &f)) continue;
    outcome = tryWitnesses(&node);
    if (outcome == Outcome::kStop) break;
    if (outcome == Outcome::kNextBox) continue;
    if (split(std::move(node), f) == Outcome::kStop) break;
  }
  return s_;
}

// m(θ) of a crisp parameter vector (the fuzzy values only).
double FuzzyPartField::MaxMinSearch::membershipAt(const double (&v)[kSlots]) const {
  double m = 1.0;
  for (int i = 0; i < kSlots; ++i)
    if (field_.supportWidth_[i] > 0.0) m = std::min(m, hullMembership(*field_.values_[i], v[i]));
  return m;
}

// The box bound: min_i of the largest μ̂_i over the box's interval.
double FuzzyPartField::MaxMinSearch::upperBound(const PartBox& b) const {
  double ub = 1.0;
  for (int i = 0; i < kSlots; ++i)
    if (field_.supportWidth_[i] > 0.0)
      ub = std::min(ub, supHullMembership(*field_.values_[i], slot(field_.core_, i), slot(b, i)));
  return std::min(1.0, ub + kMembershipSlack);
}

// A box whose bound cannot beat the incumbent by more than τ is done with: its bound joins what
// was pruned.
bool FuzzyPartField::MaxMinSearch::prunes(double ub) {
  if (!(base_ >= 0.0 && ub <= base_ + tau_)) return false;
  s_.pruned = std::max(s_.pruned, ub);
  return true;
}

void FuzzyPartField::MaxMinSearch::improve(double m, const PlacedSuperquadric& theta) {
  if (m <= s_.incumbent) return;
  if (diving_) stopDiving();
  s_.incumbent = m;
  s_.witness = theta;
  const PartBox at = crispPartBox(theta);  // single values, addressed by slot
  for (int i = 0; i < kSlots; ++i) slopeAt_[i] = slot(at, i).lo;
  haveSlopes_ = false;
  if (m <= base_) return;
  base_ = m;
  if (m + tau_ <= 1.0) cut_ = field_.cutAt(m + tau_);
}

// Guessing slopes: central differences of F at slopeAt (recomputed when a guess needs them after
// the incumbent moved); their signs pick the corner of a box tried as a witness.
void FuzzyPartField::MaxMinSearch::computeSlopes() {
  haveSlopes_ = true;
  double theta[kSlots];
  for (int i = 0; i < kSlots; ++i) theta[i] = slopeAt_[i];
  for (int i = 0; i < kSlots; ++i) {
    slope_[i] = 0.0;
    if (field_.supportWidth_[i] <= 0.0) continue;
    const Interval& sup = slot(field_.support_, i);
    const double h = 1e-3 * field_.supportWidth_[i], t0 = theta[i];
    const double a = std::max(sup.lo, t0 - h), b = std::min(sup.hi, t0 + h);
    theta[i] = a;
    const double fa = field_.valueAt(thetaAt(field_.support_, theta), p_);
    theta[i] = b;
    const double fb = field_.valueAt(thetaAt(field_.support_, theta), p_);
    theta[i] = t0;
    const double g = b > a ? (fb - fa) / (b - a) : 0.0;
    slope_[i] = std::isfinite(g) ? g : 0.0;
  }
}

// Split weights, from the first box that needs splitting (and deeper ones, see split): how far
// the enclosure's deciding end (lo for a witness inside, hi outside) moves when one value is fixed
// at its midpoint, per unit of relative width. The value whose width costs the enclosure most is
// split first; a floor keeps every value in turn.
void FuzzyPartField::MaxMinSearch::computeWeights(const PartBox& box, const Interval& f) {
  haveWeights_ = true;
  constexpr double kCap = 1e300;  // the enclosure saturates at the largest double
  const auto end = [&](const Interval& g) { return inside_ ? g.lo : std::min(g.hi, kCap); };
  double largest = 0.0;
  for (int i = 0; i < kSlots; ++i) {
    weight_[i] = 0.0;
    const Interval v = slot(box, i);
    if (field_.supportWidth_[i] <= 0.0 || !(width(v) > 0.0)) continue;
    PartBox c = box;
    slot(c, i) = {mid(v), mid(v)};
    ++evaluations_;
    const Interval g = pointEnclosure(c, p_, inside_);
    const double gain = inside_ ? end(g) - end(f) : end(f) - end(g);
    weight_[i] = std::max(gain, 0.0) / (width(v) / field_.supportWidth_[i]);
    largest = std::max(largest, weight_[i]);
  }
  for (int i = 0; i < kSlots; ++i)
    weight_[i] = largest > 0.0 && std::isfinite(largest) ? std::max(weight_[i], 0.02 * largest)
                                                         : 1.0;
}

void FuzzyPartField::MaxMinSearch::push(Node node) {
  heap_.push_back(std::move(node));
  std::push_heap(heap_.begin(), heap_.end(),
                 [this](const Node& a, const Node& b) { return lessPromising(a, b); });
}

FuzzyPartField::MaxMinSearch::Node FuzzyPartField::MaxMinSearch::pop() {
  std::pop_heap(heap_.begin(), heap_.end(),
                [this](const Node& a, const Node& b) { return lessPromising(a, b); });
  Node node = std::move(heap_.back());
  heap_.pop_back();
  return node;
}

void FuzzyPartField::MaxMinSearch::stopDiving() {
  diving_ = false;
  std::make_heap(heap_.begin(), heap_.end(),
                 [this](const Node& a, const Node& b) { return lessPromising(a, b); });
}

// Once there is a base, only θ with m(θ) > incumbent + τ can still matter, and they lie in
// P(incumbent + τ): the box is cut to it. kStop when that level is above 1, kNextBox when the cut
// leaves nothing or a bound that cannot win.
FuzzyPartField::MaxMinSearch::Outcome FuzzyPartField::MaxMinSearch::cutToTarget(Node* node) {
  if (base_ < 0.0) return Outcome::kContinue;
  const double target = base_ + tau_;
  if (target > 1.0) {
    s_.pruned = std::max(s_.pruned, node->ub);
    return Outcome::kStop;
  }
  bool empty = false, shrunk = false;
  for (int i = 0; i < kSlots && !empty; ++i) {
    Interval& v = slot(node->box, i);
    const Interval& c = slot(cut_, i);
    const Interval w{std::max(v.lo, c.lo), std::min(v.hi, c.hi)};
    shrunk = shrunk || w.lo != v.lo || w.hi != v.hi;
    v = w;
    empty = v.lo > v.hi;
  }
  // The θ cut away have m(θ) < target: they bound what was dropped.
  if (shrunk) s_.pruned = std::max(s_.pruned, std::min(node->ub, target));
  if (empty) return Outcome::kNextBox;
  node->ub = std::min(node->ub, upperBound(node->box));
  return prunes(node->ub) ? Outcome::kNextBox : Outcome::kContinue;
}

// The sound exclusions of one box, each of which may also narrow it or lower its bound: the
// deformed hull, the enclosure with affine contraction, the linearised bound, dominance and the
// monotone collapse. True when no θ of the box can improve on the incumbent; *f is the
// enclosure over the box (before narrowing), for the split weights.
bool FuzzyPartField::MaxMinSearch::excluded(Node* node, Interval* f) {
  ++evaluations_;
  if (inside_ && missesDeformedHull(node->box, px_, py_, pz_)) return true;  // F > 1 on the box
  bool narrowed = false;
  const PartBox formBox = node->box;  // the box the affine form's noise symbols refer to
  AffineForm form;
  if (!narrowToQualifying(&node->box, p_, inside_, f, &narrowed, &form))
    return true;  // no θ of the box qualifies
  if (form.valid) {
    const double lp = field_.linearizedBound(node->box, formBox, form, inside_, node->ub);
    if (lp < 0.0) return true;  // no θ of the box satisfies the linear condition
    if (lp < node->ub) {
      node->ub = lp;
      if (prunes(node->ub)) return true;
    }
  }
  if (narrowed) {
    node->ub = std::min(node->ub, upperBound(node->box));
    if (prunes(node->ub)) return true;
  }
  // The slopes over the box: dominance first (it keeps the best m), then the collapse tests.
  int open[kSlots], openCount = 0;
  for (int j = 0; j < field_.fuzzyCount_; ++j)
    if (width(slot(node->box, field_.fuzzySlots_[j])) > 0.0) open[openCount++] = field_.fuzzySlots_[j];
  // (Where they cannot be bounded, the collapse tests cannot run either: they start from them.)
  Interval boxSlopes[kSlots];
  if (openCount > 0) ++evaluations_;
  if (openCount > 0 && insideOutsideSlopes(node->box, px_, py_, pz_, open, openCount, boxSlopes)) {
    if (field_.narrowByDominance(&node->box, open, openCount, boxSlopes, inside_)) {
      node->ub = std::min(node->ub, upperBound(node->box));
      if (prunes(node->ub)) return true;
    }
    if (field_.collapsedExcludes(node->box, p_, inside_, &evaluations_, open, openCount, boxSlopes))
      return true;
  }
  return false;
}

// Crisp witnesses in the box: its peak (each value clamped towards its core maximises μ̂_i over
// the box, so a witness there settles the box: m = its bound), else the corner that the guessing
// slopes favour (least F for a witness inside, largest outside) or the centre, walked towards the
// peak. kContinue when neither is a witness (the box is split).
FuzzyPartField::MaxMinSearch::Outcome FuzzyPartField::MaxMinSearch::tryWitnesses(Node* node) {
  double peak[kSlots], centre[kSlots];
  bool corePeak = true;  // the box holds the core's midpoint: its peak is P(0)'s, F known (run)
  for (int i = 0; i < kSlots; ++i) {
    const Interval& v = slot(node->box, i);
    const double c = mid(slot(field_.core_, i));
    peak[i] = std::min(std::max(c, v.lo), v.hi);
    corePeak = corePeak && peak[i] == c;
    centre[i] = mid(v);
  }
  const PlacedSuperquadric peakTheta = thetaAt(node->box, peak);
  const double fPeak = corePeak ? corePeakValue_ : field_.valueAt(peakTheta, p_);
  if (witness(fPeak)) {
    improve(membershipAt(peak), peakTheta);
    return s_.incumbent >= 1.0 ? Outcome::kStop : Outcome::kNextBox;
  }
  if (!haveSlopes_) computeSlopes();
  double guess[kSlots];
  for (int i = 0; i < kSlots; ++i) {
    const Interval& v = slot(node->box, i);
    const bool low = (slope_[i] > 0.0) == inside_;
    guess[i] = slope_[i] == 0.0 ? centre[i] : low ? v.lo : v.hi;
  }
  PlacedSuperquadric guessTheta = thetaAt(node->box, guess);
  double fGuess = field_.valueAt(guessTheta, p_);
  if (!witness(fGuess)) {
    std::copy(centre, centre + kSlots, guess);
    guessTheta = thetaAt(node->box, guess);
    fGuess = field_.valueAt(guessTheta, p_);
  }
  if (!witness(fGuess)) return Outcome::kContinue;
  const double m = walkTowardsPeak(*node, guess, peak, fGuess, fPeak, &guessTheta);
  improve(m, guessTheta);
  if (s_.incumbent >= 1.0) return Outcome::kStop;
  // Requeue the box: its next pop cuts it to P(incumbent + τ), which drops the part just searched
  // (every later witness in it gains at least τ).
  if (node->ub <= base_ + tau_) {
    s_.pruned = std::max(s_.pruned, node->ub);
  } else {
    push(std::move(*node));
  }
  return Outcome::kNextBox;
}

// From a witness at guess, walk towards the peak (m grows along the segment, each value nearing
// its core) and keep the last witness (*guessTheta; returns its m): regula falsi (Illinois) on
// g(t) = F(θ(t)) − 1, kept inside the shrinking bracket, until m is resolved well below τ.
double FuzzyPartField::MaxMinSearch::walkTowardsPeak(const Node& node,
                                                     const double (&guess)[kSlots],
                                                     const double (&peak)[kSlots], double fGuess,
                                                     double fPeak,
                                                     PlacedSuperquadric* guessTheta) const {
  double lo = 0.0, hi = 1.0, at[kSlots];
  double gLo = fGuess - 1.0, gHi = fPeak - 1.0, gHiTrue = gHi;
  double mLo = membershipAt(guess), mHi = membershipAt(peak);
  int side = 0;
  for (int k = 0; k < 40 && mHi - mLo > 0.125 * tau_; ++k) {
    const double span = hi - lo;
    double t = std::isfinite(gLo) && std::isfinite(gHi) && gLo != gHi
                   ? lo - gLo * span / (gHi - gLo)
                   : lo + 0.5 * span;
    if (!(t >= lo + 0.02 * span && t <= hi - 0.02 * span)) t = lo + 0.5 * span;
    for (int i = 0; i < kSlots; ++i) at[i] = guess[i] + t * (peak[i] - guess[i]);
    const PlacedSuperquadric theta = thetaAt(node.box, at);
    const double f = field_.valueAt(theta, p_);
    if (witness(f)) {
      lo = t;
      gLo = f - 1.0;
      mLo = membershipAt(at);
      *guessTheta = theta;
      if (side == -1) gHi *= 0.5;
      side = -1;
    } else {
      hi = t;
      gHi = gHiTrue = f - 1.0;
      mHi = membershipAt(at);
      if (side == 1) gLo *= 0.5;
      side = 1;
    }
    // Close enough: the secant's crossing is within τ/4 of the witness in m. (Only speed rests
    // on this: the next pop cuts the box to P(incumbent + τ) and searches on.)
    if (side == -1 && std::isfinite(gHiTrue) && gHiTrue != gLo) {
      const double tEst = std::min(hi, lo - gLo * (hi - lo) / (gHiTrue - gLo));
      for (int i = 0; i < kSlots; ++i) at[i] = guess[i] + tEst * (peak[i] - guess[i]);
      if (membershipAt(at) - mLo <= 0.25 * tau_) break;
    }
  }
  return mLo;
}

// Splits the box across the value whose relative width costs the enclosure most, and queues the
// halves that can still win (while diving, each half's centre is tried as a witness first).
FuzzyPartField::MaxMinSearch::Outcome FuzzyPartField::MaxMinSearch::split(Node node,
                                                                          const Interval& f) {
  // Weights from the first box that needs splitting, taken again from every box a multiple of
  // fuzzyCount_ splits deep (each value split about once since): the values that cost the
  // enclosure most change as boxes shrink (at N = 64 this ran 118 searches out of budget, 156
  // with the first box's weights kept).
  if (!haveWeights_ || (node.depth > 0 && node.depth % field_.fuzzyCount_ == 0))
    computeWeights(node.box, f);
  int widest = -1;
  double widestScore = 0.0;
  for (int i = 0; i < kSlots; ++i) {
    if (field_.supportWidth_[i] <= 0.0) continue;
    const double r = width(slot(node.box, i)) / field_.supportWidth_[i];
    if (r <= kDegenerate) continue;
    if (r * weight_[i] > widestScore) {
      widest = i;
      widestScore = r * weight_[i];
    }
  }
  if (widest < 0) return Outcome::kNextBox;  // one θ: its crisp values did not qualify
  const Interval v = slot(node.box, widest);
  const double m = mid(v);
  ++node.depth;
  Node a = node, b = std::move(node);
  slot(a.box, widest) = {v.lo, m};
  slot(b.box, widest) = {m, v.hi};
  for (Node* child : {&a, &b}) {
    child->ub = std::min(child->ub, upperBound(child->box));
    if (diving_) {
      double c[kSlots];
      for (int i = 0; i < kSlots; ++i) c[i] = mid(slot(child->box, i));
      const PlacedSuperquadric theta = thetaAt(child->box, c);
      const double fc = field_.valueAt(theta, p_);
      child->promise = inside_ ? -fc : fc;
      if (witness(fc)) improve(membershipAt(c), theta);
    }
    if (prunes(child->ub)) continue;
    push(std::move(*child));
  }
  return s_.incumbent >= 1.0 ? Outcome::kStop : Outcome::kNextBox;
}

}  // namespace fsdb
