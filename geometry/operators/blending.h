#pragma once
// Exterior and interior blending of implicit shapes with smooth unit step functions (Li, §3):
// S_abs (eq. 18-19), Ext_max (eq. 20) with its union, intersection and difference (eq. 21-23),
// and Int_max (eq. 24) with eq. 25-27.
//
// Contract: arguments are values of real implicit functions, a point being inside where F >= 0.
// Every blend is parameterised by a unit step mu (rising range [-1, 1]; default: Li's
// piecewise polynomial H_3, C^2, as in the paper's §4 examples) and uses mu_epsilon(t) =
// mu(t / epsilon) (Def. 3); pass a step with unit range to get exactly the paper's mu_epsilon.
// With a compactly supported step:
//  - S_abs(t) = |t| exactly for |t| >= delta + epsilon and = t^2/(2 delta) + delta/2 exactly
//    for |t| <= delta - epsilon; for epsilon <= delta it never falls below |t|, so the
//    Ext_max union contains both operands (Ext_max >= max);
//  - min(x, y) <= Int_max(x, y) <= max(x, y) for any step with values in [0, 1].
// delta <= 0 or epsilon <= 0 throws fsdb::Error(kInvalidParameter, path "delta" / "epsilon").
#include "geometry/operators/smooth_unit_step.h"

namespace fsdb {

// The step of the paper's examples (Li, §4): piecewise cubic H_3 with rising range 1.
SmoothUnitStep defaultBlendStep();

class ExteriorBlend {
 public:
  ExteriorBlend(double delta, double epsilon, SmoothUnitStep mu = defaultBlendStep());

  double sAbs(double t) const;                    // eq. 18-19
  double extMax(double x, double y) const;        // eq. 20
  double unionOf(double a, double b) const;       // eq. 21
  double intersection(double a, double b) const;  // eq. 22
  double difference(double a, double b) const;    // eq. 23, a minus b

  double delta() const { return delta_; }
  double epsilon() const { return epsilon_; }

 private:
  double muEpsilon(double t) const { return mu_(t / epsilon_); }  // Def. 3
  double delta_;
  double epsilon_;
  SmoothUnitStep mu_;
};

class InteriorBlend {
 public:
  explicit InteriorBlend(double epsilon, SmoothUnitStep mu = defaultBlendStep());

  double intMax(double x, double y) const;        // eq. 24
  double unionOf(double a, double b) const;       // eq. 25
  double intersection(double a, double b) const;  // eq. 26
  double difference(double a, double b) const;    // eq. 27, a minus b

  double epsilon() const { return epsilon_; }

 private:
  double muEpsilon(double t) const { return mu_(t / epsilon_); }  // Def. 3
  double epsilon_;
  SmoothUnitStep mu_;
};

// One-shot forms: S_abs(t, delta, epsilon), Ext_max(x, y, delta, epsilon), Int_max(x, y, epsilon).
double sAbs(double t, double delta, double epsilon, const SmoothUnitStep& mu = defaultBlendStep());
double extMax(double x, double y, double delta, double epsilon,
              const SmoothUnitStep& mu = defaultBlendStep());
double intMax(double x, double y, double epsilon, const SmoothUnitStep& mu = defaultBlendStep());

}  // namespace fsdb
