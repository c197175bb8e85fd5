#pragma once
// AffineForm: affine arithmetic (J. Stolfi and L. H. de Figueiredo, "Self-validated numerical
// methods and applications", 1997, §3) over a fixed set of noise symbols (fsdb issue 3).
//
// A form x̂ = x0 + Σ_i x_i·ε_i + e·ε_* stands for every value it can take with each noise symbol ε_i
// in [−1, 1] and the accumulated error ε_* in [−1, 1]. Inputs that depend on the same ε_i (the
// fuzzy values of a part and the point coordinates) keep that correlation through the operations,
// so x − x is 0 and the range of an affine function of the inputs is exact; interval arithmetic
// (interval.h) would treat each occurrence as independent. This is what makes enclosures of a
// long chain of maps (the inverse deformations) over a box of 14 parameters tight where a first
// order interval or mean-value enclosure is several times too wide.
//
// Contract:
//  * Soundness: if every input's true value lies in its form, so does the result's, for every
//    assignment of the ε_i (the same ε_i for every form). The accumulated error e is treated as a
//    fresh independent symbol every time (the "AF1" variant of Messine): it never cancels, which
//    keeps soundness without allocating symbols. Each operation also adds a rounding slack of a few
//    ulps of the magnitudes involved to e, so results are sound under double rounding as well.
//  * Nonlinear functions use a second-order remainder about the centre x0:
//    f(x) = f(x0) + f'(x0)·(x − x0) + f''(ξ)/2·(x − x0)², with f'' enclosed over the form's range
//    (so the error shrinks quadratically with the box); atan uses the same rule.
//  * A form is `valid` unless an operation left its domain (log or sqrt of a range that reaches
//    0, a reciprocal of a range that holds 0, a non-finite value); invalid propagates, and callers
//    fall back to their interval enclosure. Invalid forms have no meaningful range.
#include "geometry/interval.h"

namespace fsdb {

// Noise symbols: the fourteen part values (slot order, superquadric_slopes.h) and the three
// coordinates of a point box.
inline constexpr int kAffineSymbols = 17;

struct AffineForm {
  double centre = 0.0;
  double dev[kAffineSymbols] = {};  // partial deviations x_i
  double err = 0.0;                 // radius of the accumulated error, >= 0
  bool valid = true;
};

AffineForm affineConstant(double c);
// The form of a value ranging over [range.lo, range.hi] with noise symbol `symbol` (0 <= symbol <
// kAffineSymbols): centre mid, deviation the half width.
AffineForm affineVariable(const Interval& range, int symbol);

double radius(const AffineForm& x);  // Σ|x_i| + e: the largest distance from the centre
Interval range(const AffineForm& x);  // [x0 − radius, x0 + radius]; meaningful only when valid

AffineForm add(const AffineForm& x, const AffineForm& y);
AffineForm sub(const AffineForm& x, const AffineForm& y);
AffineForm add(double c, const AffineForm& x);
AffineForm mul(double c, const AffineForm& x);
AffineForm mul(const AffineForm& x, const AffineForm& y);  // bilinear term bounded by rx·ry
AffineForm sqr(const AffineForm& x);                       // x², (x − x0)² in [0, r²]

AffineForm recip(const AffineForm& x);  // 1/x; invalid if the range holds 0
AffineForm sqrt(const AffineForm& x);   // invalid unless the range is > 0
AffineForm exp(const AffineForm& x);    // invalid if the range exceeds 700 (overflow)
AffineForm log(const AffineForm& x);    // invalid unless the range is > 0
AffineForm sin(const AffineForm& x);
AffineForm cos(const AffineForm& x);
AffineForm atan(const AffineForm& x);

// A form with no correlation: the interval as centre and accumulated error (for quantities only
// an interval enclosure can bound; invalid for non-finite ends).
AffineForm affineFromInterval(const Interval& a);

}  // namespace fsdb
