#pragma once
// The fuzzy intersection operators (t-norms) of Li & Tian, Table 1, with the union
// (t-conorm), complement and difference that every t-norm induces.
//
// Contract: arguments are memberships in [0, 1]; each t-norm returns a membership in [0, 1],
// is commutative, T(x, 1) = x and T(x, 0) = 0. Outside [0, 1] the printed formula is evaluated
// as is (no clamping), so callers that need a membership must pass one. A parameter outside the
// range printed in Table 1 throws fsdb::Error(errc::kInvalidParameter) whose path names it.
//
// The union, complement and difference are not in Table 1; they are the standard De Morgan
// duals the paper relies on (Li & Tian, §3.2: "union by duality F = 1 - ∧(1 - S1, 1 - S2)").
namespace fsdb {

double algebraicTNorm(double x, double y);              // xy
double zadehTNorm(double x, double y);                  // min(x, y)
double lukasiewiczTNorm(double x, double y);            // max(0, x + y - 1)
double duboisPradeTNorm(double x, double y, double k);  // xy / max(x, y, k), k in (0, 1]
double einsteinTNorm(double x, double y);               // xy / (2 - (x + y - xy))
double dombiTNorm(double x, double y, double n);        // n > 0; 0 when x or y is 0
double hamacherTNorm(double x, double y, double a);     // a in [0, 1); 0 at x = y = 0
double weberTNorm(double x, double y, double k);        // k in (-1, inf)
double yagerTNorm(double x, double y, double k);        // k in (1, inf), as printed

// The fuzzy complement 1 - x.
inline double fuzzyComplement(double x) { return 1.0 - x; }

// The t-conorm dual to the t-norm `t`: S(x, y) = 1 - T(1 - x, 1 - y) (fuzzy union).
template <class TNorm>
double dualTConorm(const TNorm& t, double x, double y) {
  return 1.0 - t(1.0 - x, 1.0 - y);
}

// The fuzzy difference x minus y: T(x, 1 - y), i.e. x AND NOT y.
template <class TNorm>
double fuzzyDifference(const TNorm& t, double x, double y) {
  return t(x, 1.0 - y);
}

}  // namespace fsdb
