#pragma once
// SmoothUnitStep: one chosen smooth unit step function with its rising range (Li, Def. 3),
// as a small value that the blends (Li, eq. 18-27) and the operator catalogue pass around.
// Evaluation dispatches on a family tag (no virtual call, no allocation).
//
// Contract: the factories validate (fsdb::Error, kInvalidParameter, path = the parameter's
// catalogue name: "n", "m", "alpha", "epsilon", "R") and the object then never throws.
// operator()(t) is mu(t / epsilon) for the family's unit-range step mu; for polynomialRange it
// is Li & Tian's H_{n,R}(t), whose range parameter is R.
namespace fsdb {

enum class StepFamily {
  kPolynomial,           // Li, eq. 5-6 H_n
  kPolynomialRange,      // Li & Tian, eq. 2-3 H_{n,R}
  kBSpline,              // Li, eq. 7 B_m
  kRisingCutoff,         // Li, eq. 16 R_n
  kRisingCutoffSquared,  // Li, §2.1.3 R_n^2
  kSigmoid,              // Li, eq. 17 S_alpha
};

class SmoothUnitStep {
 public:
  static SmoothUnitStep polynomial(int n, double epsilon = 1.0);
  static SmoothUnitStep polynomialRange(int n, double R = 1.0);
  static SmoothUnitStep bspline(int m, double epsilon = 1.0);
  static SmoothUnitStep risingCutoff(int n, double epsilon = 1.0);
  static SmoothUnitStep risingCutoffSquared(int n, double epsilon = 1.0);
  static SmoothUnitStep sigmoid(double alpha, double epsilon = 1.0);

  double operator()(double t) const;

  StepFamily family() const { return family_; }
  int degree() const { return degree_; }           // n or m; 0 for the sigmoid
  double alpha() const { return alpha_; }          // sigmoid only; 0 otherwise
  double risingRange() const { return epsilon_; }  // epsilon, or R for polynomialRange

 private:
  SmoothUnitStep(StepFamily family, int degree, double alpha, double epsilon)
      : family_(family), degree_(degree), alpha_(alpha), epsilon_(epsilon) {}

  StepFamily family_;
  int degree_;
  double alpha_;
  double epsilon_;
};

}  // namespace fsdb
