#pragma once
// Fuzzy arithmetic by Zadeh's extension principle, computed per alpha-cut with interval
// arithmetic (Zhang, Pham & Chen, §3.2, eq. 3-4): for convex operands,
// cut_alpha(A op B) = cut_alpha(A) op cut_alpha(B).
//
// Levels: the result is built from its cuts at a set of alpha levels and is linear in alpha
// between them (FuzzyNumber::fromAlphaCuts). Every level in the union of both operands'
// breakpoint levels is used, with the strong cut as well as the closed one, so horizontal
// pieces of the operands carry over.
//  - add, subtract: the cut ends are sums of functions linear between those levels, so the
//    result is exact.
//  - min, max: the cut ends are the min / max of such functions; adding the levels where they
//    cross (lo_A = lo_B, hi_A = hi_B) makes the result exact too.
//  - multiply, divide: the cut ends are products (quadratic) or quotients (rational) in alpha.
//    The result is exact at every sampled level: the union of breakpoint levels, the
//    kArithmeticRefinementLevels uniform levels k/64, and the levels where a cut end of an
//    operand crosses 0 (where the product switches corners); linear in between.
//  - scale, negate: exact, by mapping the breakpoints (non-convex shapes are kept).
// Non-convex operands: alpha-cuts are taken as hulls (FuzzyNumber::alphaCut), so the binary
// operations act on the operands' convex hulls (quasi-concave envelopes) and return convex
// numbers.
// Errors: divide() by a number whose support holds 0 throws fsdb::Error with code
// errc::kDomainError, path "divisor"; scale() by a non-finite k throws errc::kInvalidParameter,
// path "k".
#include "geometry/fuzzy/fuzzy_number.h"

namespace fsdb {

// Uniform alpha levels (k / 64) added for multiply and divide.
inline constexpr int kArithmeticRefinementLevels = 64;

FuzzyNumber add(const FuzzyNumber& a, const FuzzyNumber& b);
FuzzyNumber subtract(const FuzzyNumber& a, const FuzzyNumber& b);
FuzzyNumber multiply(const FuzzyNumber& a, const FuzzyNumber& b);
FuzzyNumber divide(const FuzzyNumber& a, const FuzzyNumber& b);
FuzzyNumber min(const FuzzyNumber& a, const FuzzyNumber& b);
FuzzyNumber max(const FuzzyNumber& a, const FuzzyNumber& b);
FuzzyNumber scale(const FuzzyNumber& a, double k);
FuzzyNumber negate(const FuzzyNumber& a);

FuzzyNumber operator+(const FuzzyNumber& a, const FuzzyNumber& b);
FuzzyNumber operator-(const FuzzyNumber& a, const FuzzyNumber& b);
FuzzyNumber operator*(const FuzzyNumber& a, const FuzzyNumber& b);
FuzzyNumber operator/(const FuzzyNumber& a, const FuzzyNumber& b);
FuzzyNumber operator-(const FuzzyNumber& a);

}  // namespace fsdb
