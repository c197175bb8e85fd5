#pragma once
// Smooth unit step functions: the Heaviside step, the piecewise polynomial steps of Li & Tian,
// eq. 2-3 and Li, eq. 5-6, the integrated B-spline step (Li, eq. 7-8), the rising
// cutoff steps (Li, eq. 14-16), the sigmoid (Li, eq. 17; Li & Tian, eq. 1) and the
// rising range of Li, Def. 3.
//
// Contract: each step is nondecreasing, 0 far left, 1 far right. The piecewise polynomial,
// B-spline and rising cutoff steps are exactly 0 / 1 outside their support ([-n, n] for
// liTianStep, [0, n] for cardinalStep, [-1, 1] for the others); the sigmoid never is. Degrees
// outside the documented range throw fsdb::Error(kInvalidParameter) with path "n" or "m"; a
// non-positive alpha, R or epsilon throws with path "alpha", "R" or "epsilon".
//
// The main functions evaluate fast (dynamic programming over the shifted arguments in O(n^2),
// a closed form, or an O(n) iteration); namespace `reference` holds the literal recursive
// definitions (exponential cost for eq. 2 and eq. 5) that the tests hold the fast forms to.
namespace fsdb {

// Piecewise polynomial steps (Li & Tian's H_n, Li's f_n and H_n): the dynamic programme costs
// O(n^2) multiply-adds (n = 32: ~500), and C^31 is already far beyond what a voxel grid or a
// mesh can show; larger degrees only cost time.
inline constexpr int kMaxPolynomialStepDegree = 32;
// Integrated B-spline step by truncated powers: the alternating sum cancels, and the measured
// worst absolute error (against exact rational arithmetic) grows from 1e-14 at order 20 to
// ~1e-12 at 32, 2e-11 at 40 and 1e-7 at 64. 32 keeps it below 1e-11; polynomialStep equals B_m
// and is stable, so nothing is lost by the cap.
inline constexpr int kMaxBSplineOrder = 32;
// Rising cutoff R_n: its slope at 0 grows like (pi/2)^(n-1) (about 480 at n = 16): beyond that
// the "smooth" step is a jump at any practical sampling.
inline constexpr int kMaxRisingCutoffLevel = 16;

// The Heaviside unit step H_0: 0 for t < 0, 1/2 at 0, 1 for t > 0 (Li & Tian, eq. 2; Li,
// eq. 4).
double heaviside(double t);

// Li & Tian, eq. 2: H_n(x), support [-n, n], C^(n-1), H_n(x) + H_n(-x) = 1. n in [0, 32].
double liTianStep(int n, double x);

// Li & Tian, eq. 3: H_{n,R}(x) = H_n(n x / R), support [-R, R]. n in [1, 32], R > 0.
double liTianStepRange(int n, double R, double x);

// Li, eq. 5: f_n(t), rising over [0, n] (the integral of the order-n cardinal B-spline).
// n in [0, 32].
double cardinalStep(int n, double t);

// Li, eq. 6: H_n(t) = f_n(n (t + 1) / 2), support [-1, 1], C^(n-1). n in [1, 32].
// Equals liTianStep(n, n t) (Li & Tian's H_n with its support scaled to [-1, 1]).
double polynomialStep(int n, double t);

// Li, eq. 7: B_m(t), the normalised integral of the order-m uniform B-spline on [-1, 1],
// C^(m-1), by the closed form in truncated powers. m in [1, 32].
double bsplineStep(int m, double t);

// Li, eq. 16: the rising cutoff R_n(t) (R_1(t) = sin(pi/4 (1 + t))), with
// R_n(t)^2 + R_n(-t)^2 = 1 and 2^(n-1) - 1 vanishing derivatives at +-1. n in [1, 16].
double risingCutoff(int n, double t);

// R_n(t)^2: a step antisymmetric about (0, 1/2), R_n^2(t) + R_n^2(-t) = 1 (Li, §2.1.3).
double risingCutoffSquared(int n, double t);

// Li, eq. 17: S_alpha(t) = 1 / (1 + e^(-alpha t)), alpha > 0.
double sigmoidStep(double alpha, double t);

// Li, after eq. 17: for 0 < epsilon < 1, any alpha greater than ln((1 - epsilon) /
// epsilon) gives S_alpha(t) < epsilon for t < -1 and S_alpha(t) > 1 - epsilon for t > 1.
// Returns that bound (<= 0, i.e. any alpha, when epsilon >= 1/2).
double sigmoidAlphaBound(double epsilon);

// Li, Def. 3: mu_epsilon(t) = mu(t / epsilon), the step `mu` with rising range
// [-epsilon, epsilon]. epsilon > 0.
template <class Step>
double withRisingRange(const Step& mu, double epsilon, double t) {
  return mu(t / epsilon);
}

namespace reference {

// Li & Tian, eq. 2 by its literal recursion: 2^n calls. n in [0, 32].
double liTianStep(int n, double x);

// Li, eq. 5 by its literal recursion: 2^n calls. n in [0, 32].
double cardinalStep(int n, double t);

// Li, eq. 6 on top of the literal eq. 5.
double polynomialStep(int n, double t);

// The order-m cardinal B-spline M_m(u) on [0, m] by the Cox-de Boor recursion (2^m calls):
// M_1 = 1 on [0, 1), M_k(u) = (u M_{k-1}(u) + (k - u) M_{k-1}(u - 1)) / (k - 1).
double cardinalBSpline(int m, double u);

// Li, eq. 7 literally: (1/delta) * integral_{-1}^{t} N_m(s) ds with N_m(s) = M_m(m(s+1)/2)
// and delta = integral_{-1}^{1} N_m, both by Gauss-Legendre quadrature on each knot interval
// (exact for the polynomial pieces). m in [1, 32].
double bsplineStep(int m, double t);

// Li, eq. 14-15: mu_k = sin(theta_{k-1}), theta_k = (pi/2) mu_k^2, theta_0 of eq. 15;
// R_n = mu_n. n in [1, 16].
double risingCutoff(int n, double t);

}  // namespace reference

}  // namespace fsdb
