#pragma once
// The degree-n Bézier (generalised algebraic) fuzzy intersection operator B_n of Li & Tian, eq. 4:
// the tensor-product Bézier surface over [0,1]^2 whose control value at (i, j) is min(i, j)/n.
//
// Contract: x, y are memberships in [0, 1]; the result is in [0, 1], symmetric, with
// B_n(x, 0) = 0, B_n(x, 1) = x, B_n <= min and B_1 <= B_2 <= ... -> min (Li & Tian, after eq. 7).
// n outside [1, kMaxBezierDegree] throws fsdb::Error(kInvalidParameter, path "n").
namespace fsdb {

// Degrees above 64 are refused: the paper itself advises against high degrees (cost grows
// with n while the gap to min shrinks only like 1/sqrt(n); 64 is already within ~0.035 of min
// on the diagonal), and 2^-64 bounds the smallest Bernstein value the evaluation starts from,
// so no intermediate underflows.
inline constexpr int kMaxBezierDegree = 64;

// The degree-n Bernstein basis at t: out[k] = C(n,k) (1-t)^(n-k) t^k, k = 0..n (Li & Tian, after
// eq. 4). `out` must hold n + 1 values.
void bernsteinBasis(int n, double t, double* out);

// Li & Tian, eq. 4, evaluated in O(n) (see the .cpp for the rearrangement).
double bezierOperator(int n, double x, double y);

// Li & Tian, eq. 4 summed literally, term by term, in O(n^2): the reference the tests hold the
// fast form to.
double bezierOperatorLiteral(int n, double x, double y);

}  // namespace fsdb
