#pragma once
// Piecewise-linear functions given by breakpoints: the one representation behind fuzzy numbers,
// sampled fuzzy sets (Bernardes, Wu & D'Ottaviano: memberships over radius-vector angles) and their
// AND/OR.
//
// Contract for a breakpoint list f = [(x0, mu0), ..., (xn, mun)]:
//  - x is finite and non-decreasing, mu is finite; between consecutive breakpoints with
//    x_i < x_{i+1} the function is the straight line joining them;
//  - several breakpoints may share one x (a vertical jump); the value *at* such an x is the
//    largest of their mu (the upper semicontinuous reading, so alpha-cuts are closed), the limit
//    from the left is the first one's mu and the limit from the right the last one's mu;
//  - the function is 0 outside [x0, xn] (a fuzzy set is 0 off its support).
// Functions that take a list check it (checkPiecewiseLinear) and throw fsdb::Error with code
// errc::kInvalidParameter and path "[i]" (the bad breakpoint) when it is malformed.
#include <vector>

namespace fsdb {

struct Breakpoint {
  double x;
  double mu;
};

bool operator==(const Breakpoint& a, const Breakpoint& b);
bool operator!=(const Breakpoint& a, const Breakpoint& b);

// Throws unless every x and mu is finite and x is non-decreasing.
void checkPiecewiseLinear(const std::vector<Breakpoint>& f);

double valueAt(const std::vector<Breakpoint>& f, double x);     // 0 outside [x0, xn]
double leftLimit(const std::vector<Breakpoint>& f, double x);   // lim f(t), t -> x from below
double rightLimit(const std::vector<Breakpoint>& f, double x);  // lim f(t), t -> x from above

// Exact integral of f (trapezoids; vertical jumps add nothing).
double area(const std::vector<Breakpoint>& f);
// The largest mu (0 for an empty list, as f is 0 everywhere then).
double height(const std::vector<Breakpoint>& f);

// The exact pointwise min / max of f and g (Bernardes, Wu & D'Ottaviano, §3: AND / OR of fuzzy
// sets), with a breakpoint added wherever the two lines cross between breakpoints.
std::vector<Breakpoint> pointwiseMin(const std::vector<Breakpoint>& f,
                                     const std::vector<Breakpoint>& g);
std::vector<Breakpoint> pointwiseMax(const std::vector<Breakpoint>& f,
                                     const std::vector<Breakpoint>& g);

}  // namespace fsdb
