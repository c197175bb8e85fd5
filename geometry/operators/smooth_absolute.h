#pragma once
// Smooth absolute functions, smooth minima and the smooth fuzzy intersections built on them
// (Li & Tian, §3.2): the upper absolute |x|_n (eq. 8-9), the lower absolute (eq. 10-11),
// min_{n,delta} and its hatted form (eq. 12-13), and the fuzzy operators AND_{n,delta}
// (eq. 14-20) and hatted AND_{n,delta} (eq. 21-24).
//
// Contract: |x|_n >= |x| with equality for |x| >= n, C^n; the lower absolute is <= |x|, equal
// for |x| >= n, C^(n-1); the span-delta forms differ from |x| only on (-delta, delta). The two
// AND operators take memberships in [0, 1], satisfy Identity (AND(x,1) = AND(1,x) = x) and
// Dominance (AND(x,0) = AND(0,x) = 0), are symmetric, Boolean on {0,1}, and approach min as
// delta shrinks; AND is C^n, hatted AND is C^(n-1) and equals min exactly where
// delta <= x, y <= 1 - delta and |x - y| >= delta. Degrees outside [1, 32] (or [0, 32] for the
// unscaled absolutes) and delta <= 0 throw fsdb::Error(kInvalidParameter, path "n" / "delta").
//
// The Coons correction of eq. 16-19 is implemented with the general bilinear corner term; see
// SmoothAnd below for why the printed alpha = -|0|_{n,delta} is not used.
namespace fsdb {

// Degrees: the absolutes evaluate by an O(n^2) dynamic programme (like the polynomial steps,
// whose cap they share); C^32 is far beyond what sampling can show.
inline constexpr int kMaxSmoothAbsoluteDegree = 32;

// Li & Tian, eq. 8: the degree-n upper absolute |x|_n, n in [0, 32].
double upperAbsolute(int n, double x);

// Li & Tian, eq. 9: |x|_{n,delta} = (delta/n) |n x / delta|_n, n in [1, 32], delta > 0.
double upperAbsoluteSpan(int n, double delta, double x);

// Li & Tian, eq. 10: the degree-n lower absolute 2 x H_n(x) - x (Li & Tian's H_n), n in [0, 32].
double lowerAbsolute(int n, double x);

// Li & Tian, eq. 11: (delta/n) lowerAbsolute(n, n x / delta), n in [1, 32], delta > 0.
double lowerAbsoluteSpan(int n, double delta, double x);

// Li & Tian, eq. 12: min_{n,delta}(x, y) = (x + y - |x - y|_{n,delta}) / 2.
double smoothMin(int n, double delta, double x, double y);

// Li & Tian, eq. 13: the same with the lower absolute.
double smoothMinHat(int n, double delta, double x, double y);

// Li & Tian, eq. 14-20: AND_{n,delta}(x, y) = min_{n,delta}(x, y) - S(x, y), S the Coons patch of
// the four boundary curves of min_{n,delta} (C0 on y = 0 and x = 0, C1 on y = 1 and x = 1).
//
// The paper prints S3 = alpha (1 - x - y + 2xy) with alpha = -|0|_{n,delta} (eq. 19). A Coons
// patch must subtract the bilinear interpolant of its four corners, and here the corners are
// C0(0) = C1(1) = -|0|_{n,delta}/2 and C0(1) = C1(0) = (1 - |1|_{n,delta})/2. With the printed
// alpha the laws stated right after eq. 20 fail: AND(x, 1) = x (1 - |0|_{n,delta}/2) and
// AND(x, 0) = -(1 - x) |0|_{n,delta}/2. The laws win: S3 is the general bilinear corner term,
// which for delta <= 1 (where |1|_{n,delta} = 1) is the printed form with
// alpha = -|0|_{n,delta}/2.
//
// The constant -|0|_{n,delta}/2 appears in min_{n,delta}, in C0, C1 and so in each of S1, S2 and
// S3 (whose weights sum to 1): it cancels exactly in eq. 20, so the curves are evaluated without
// it, from |t|_{n,delta} - |0|_{n,delta}. That matters for a large span: |0|_{n,delta} grows like
// delta while AND stays in [0, 1], and subtracting it let rounding grow with delta. As delta
// grows, AND tends to the product x y: a quadratic |t|_{n,delta} - |0|_{n,delta} = c t^2 cancels
// in eq. 20, so for n = 1 AND is x y for every delta >= 1, and for n > 1 the distance to x y
// falls like 1/delta^2.
class SmoothAnd {
 public:
  SmoothAnd(int n, double delta);  // validates n in [1, 32], delta > 0
  double operator()(double x, double y) const;
  int n() const { return n_; }
  double delta() const { return delta_; }

 private:
  double spanIncrement(double t) const;  // |t|_{n,delta} - |0|_{n,delta}
  double c0(double x) const;  // eq. 14 less its constant, so C0(0) = C1(1) = 0
  double c1(double x) const;  // eq. 15 less its constant
  int n_;
  double delta_;
  double absZero_;            // |0|_{n,delta}
  double cornerOffDiagonal_;  // C0(1) = C1(0), less the constant
};

// Li & Tian, eq. 21-24: hatted AND_{n,delta}(x, y) = hatted min_{n,delta}(x, y) - (S1 + S2 - S3)
// with the boundary curves xH_n(-nx/delta) and (1-x)H_n(-n(1-x)/delta). The paper omits S3;
// its corners are 0, 0 and H_n(-n/delta) twice, which vanish for delta <= 1, so this equals the
// printed formula there and keeps Identity and Dominance for delta > 1 too (same treatment as
// SmoothAnd).
class SmoothAndHat {
 public:
  SmoothAndHat(int n, double delta);  // validates n in [1, 32], delta > 0
  double operator()(double x, double y) const;
  int n() const { return n_; }
  double delta() const { return delta_; }

 private:
  double c0(double x) const;  // eq. 21
  double c1(double x) const;  // eq. 22
  int n_;
  double delta_;
  double cornerOffDiagonal_;  // C0(1) = C1(0) = H_n(-n/delta)
};

// One-shot forms of the two operators (construct and evaluate).
double smoothAnd(int n, double delta, double x, double y);
double smoothAndHat(int n, double delta, double x, double y);

namespace reference {

// Li & Tian, eq. 8 by its literal recursion (2^n calls), n in [0, 32].
double upperAbsolute(int n, double x);

}  // namespace reference

}  // namespace fsdb
