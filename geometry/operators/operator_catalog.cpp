#include "geometry/operators/operator_catalog.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "geometry/core/closest_names.h"
#include "geometry/core/error.h"
#include "geometry/core/parameter_check.h"
#include "geometry/operators/bezier_operator.h"
#include "geometry/operators/blending.h"
#include "geometry/operators/smooth_absolute.h"
#include "geometry/operators/smooth_unit_step.h"
#include "geometry/operators/step_functions.h"
#include "geometry/operators/tnorms.h"

namespace fsdb {

double BinaryOperator::apply(Combine c, double a, double b) const {
  switch (c) {
    case Combine::Intersection: return intersection(a, b);
    case Combine::Union: return unionOf(a, b);
    case Combine::Difference: return difference(a, b);
  }
  return intersection(a, b);  // unreachable: every Combine is handled above
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// --- evaluators -------------------------------------------------------------------------------

// A t-norm with the union and difference it induces (tnorms.h).
template <class TNorm>
class FuzzyOperator final : public BinaryOperator {
 public:
  explicit FuzzyOperator(TNorm t) : t_(std::move(t)) {}
  double intersection(double a, double b) const override { return t_(a, b); }
  double unionOf(double a, double b) const override { return dualTConorm(t_, a, b); }
  double difference(double a, double b) const override { return fuzzyDifference(t_, a, b); }
  bool actsOnMemberships() const override { return true; }

 private:
  TNorm t_;
};

template <class TNorm>
std::unique_ptr<BinaryOperator> fuzzy(TNorm t) {
  return std::make_unique<FuzzyOperator<TNorm>>(std::move(t));
}

// ExteriorBlend or InteriorBlend (blending.h), which carry all three set operations.
template <class Blend>
class BlendOperator final : public BinaryOperator {
 public:
  explicit BlendOperator(Blend blend) : blend_(std::move(blend)) {}
  double intersection(double a, double b) const override { return blend_.intersection(a, b); }
  double unionOf(double a, double b) const override { return blend_.unionOf(a, b); }
  double difference(double a, double b) const override { return blend_.difference(a, b); }
  bool actsOnMemberships() const override { return false; }

 private:
  Blend blend_;
};

template <class Blend>
std::unique_ptr<BinaryOperator> blend(Blend b) {
  return std::make_unique<BlendOperator<Blend>>(std::move(b));
}

template <class F>
class Unary final : public UnaryFunction {
 public:
  explicit Unary(F f) : f_(std::move(f)) {}
  double operator()(double t) const override { return f_(t); }

 private:
  F f_;
};

template <class F>
std::unique_ptr<UnaryFunction> unary(F f) {
  return std::make_unique<Unary<F>>(std::move(f));
}

// --- the table --------------------------------------------------------------------------------

using BinaryFactory = std::unique_ptr<BinaryOperator> (*)(const OperatorConfig&);
using UnaryFactory = std::unique_ptr<UnaryFunction> (*)(const OperatorConfig&);
using StepFactory = SmoothUnitStep (*)(const OperatorConfig&);

struct Entry {
  OperatorSpec spec;
  BinaryFactory binary = nullptr;  // fuzzy_operator, blend
  UnaryFactory unary = nullptr;    // step, absolute
  StepFactory step = nullptr;      // step: the SmoothUnitStep it stands for (blends nest it)
};

// After validation every parameter is present.
double real(const OperatorConfig& c, const char* name) { return c.params.at(name); }
int integer(const OperatorConfig& c, const char* name) {
  return static_cast<int>(c.params.at(name));
}

ParamSpec realParam(std::string name, double min, bool minInclusive, double max, bool maxInclusive,
                    double defaultValue, std::string description) {
  return {std::move(name), min,          max,   minInclusive,
          maxInclusive,    defaultValue, false, std::move(description)};
}

ParamSpec degreeParam(std::string name, int max, int defaultValue, std::string description) {
  return {std::move(name),      1.0,  double(max),           true, true,
          double(defaultValue), true, std::move(description)};
}

ParamSpec positiveParam(std::string name, double defaultValue, std::string description) {
  return realParam(std::move(name), 0.0, false, kInf, false, defaultValue, std::move(description));
}

ParamSpec risingRangeParam() {
  return positiveParam("epsilon", 1.0,
                       "rising range (Li, Def. 3): the step rises over [-epsilon, epsilon]");
}

const char* const kPolynomialCap =
    " n is capped at 32: evaluation is an O(n^2) recursion (about 500 multiply-adds at 32), "
    "and smoothness beyond C^31 is invisible at any sampling.";

Entry fuzzyEntry(std::string name, std::vector<ParamSpec> params, std::string reference,
                 std::string formula, std::string description, BinaryFactory make) {
  Entry e;
  e.spec = {
      std::move(name),    "fuzzy_operator",      2, std::move(params), false, std::move(reference),
      std::move(formula), std::move(description)};
  e.binary = make;
  return e;
}

Entry blendEntry(std::string name, std::vector<ParamSpec> params, std::string reference,
                 std::string formula, std::string description, BinaryFactory make) {
  Entry e;
  e.spec = {std::move(name),
            "blend",
            2,
            std::move(params),
            true,
            std::move(reference),
            std::move(formula),
            std::move(description)};
  e.binary = make;
  return e;
}

SmoothUnitStep stepFromConfig(const OperatorConfig& c);

Entry stepEntry(std::string name, std::vector<ParamSpec> params, std::string reference,
                std::string formula, std::string description, StepFactory step) {
  Entry e;
  e.spec = {std::move(name),
            "step",
            1,
            std::move(params),
            false,
            std::move(reference),
            std::move(formula),
            std::move(description)};
  e.step = step;
  e.unary = [](const OperatorConfig& c) { return unary(stepFromConfig(c)); };
  return e;
}

Entry absoluteEntry(std::string name, std::string reference, std::string formula,
                    std::string description, UnaryFactory make) {
  Entry e;
  e.spec = {std::move(name),
            "absolute",
            1,
            {degreeParam("n", kMaxSmoothAbsoluteDegree, 2,
                         std::string("degree; the function is C^n (upper) or C^(n-1) (lower).") +
                             kPolynomialCap),
             positiveParam("delta", 1.0, "span: equals |t| for |t| >= delta")},
            false,
            std::move(reference),
            std::move(formula),
            std::move(description)};
  e.unary = make;
  return e;
}

std::vector<Entry> buildTable() {
  std::vector<Entry> t;
  const std::string table1 = "seed 000 Table 1";

  // --- fuzzy operators: Li & Tian, Table 1 ---
  t.push_back(fuzzyEntry("zadeh", {}, table1, "T(x,y) = min(x,y)",
                         "Zadeh's minimum (the default): exact alpha-cut semantics; not smooth "
                         "along x = y.",
                         [](const OperatorConfig&) { return fuzzy(zadehTNorm); }));
  t.push_back(fuzzyEntry("algebraic", {}, table1, "T(x,y) = x*y",
                         "Algebraic product: smooth everywhere but far from min (it is B_1 of "
                         "Li & Tian, eq. 4).",
                         [](const OperatorConfig&) { return fuzzy(algebraicTNorm); }));
  t.push_back(fuzzyEntry("lukasiewicz", {}, table1, "T(x,y) = max(0, x + y - 1)",
                         "Lukasiewicz bounded difference.",
                         [](const OperatorConfig&) { return fuzzy(lukasiewiczTNorm); }));
  t.push_back(fuzzyEntry(
      "dubois_prade", {realParam("k", 0.0, false, 1.0, true, 0.5, "threshold k in (0, 1]")}, table1,
      "T(x,y) = x*y / max(x, y, k)",
      "Dubois-Prade: min(x,y) wherever max(x,y) >= k, x*y/k below; k = 1 is the algebraic "
      "product, k -> 0 approaches min.",
      [](const OperatorConfig& c) {
        return fuzzy([k = real(c, "k")](double x, double y) { return duboisPradeTNorm(x, y, k); });
      }));
  t.push_back(fuzzyEntry("einstein", {}, table1, "T(x,y) = x*y / (2 - (x + y - x*y))",
                         "Einstein product.",
                         [](const OperatorConfig&) { return fuzzy(einsteinTNorm); }));
  t.push_back(fuzzyEntry(
      "dombi", {positiveParam("n", 2.0, "exponent n > 0 (real); larger n is closer to min")},
      table1, "T(x,y) = 1 / (1 + ((1/x - 1)^n + (1/y - 1)^n)^(1/n)), 0 when x or y is 0",
      "Dombi family.", [](const OperatorConfig& c) {
        return fuzzy([n = real(c, "n")](double x, double y) { return dombiTNorm(x, y, n); });
      }));
  t.push_back(fuzzyEntry(
      "hamacher", {realParam("a", 0.0, true, 1.0, false, 0.5, "a in [0, 1)")}, table1,
      "T(x,y) = x*y / (a + (1 - a)(x + y - x*y)), 0 at x = y = 0",
      "Hamacher family; a = 0 is the Hamacher product.", [](const OperatorConfig& c) {
        return fuzzy([a = real(c, "a")](double x, double y) { return hamacherTNorm(x, y, a); });
      }));
  t.push_back(fuzzyEntry(
      "weber", {realParam("k", -1.0, false, kInf, false, 1.0, "k in (-1, inf)")}, table1,
      "T(x,y) = max(0, (x + y + k*x*y - 1) / (1 + k))",
      "Weber family; k = 0 is Lukasiewicz, k -> inf approaches the algebraic product.",
      [](const OperatorConfig& c) {
        return fuzzy([k = real(c, "k")](double x, double y) { return weberTNorm(x, y, k); });
      }));
  t.push_back(fuzzyEntry(
      "yager", {realParam("k", 1.0, false, kInf, false, 2.0, "k in (1, inf) as printed")}, table1,
      "T(x,y) = 1 - min(1, ((1 - x)^k + (1 - y)^k)^(1/k))",
      "Yager family; larger k is closer to min.", [](const OperatorConfig& c) {
        return fuzzy([k = real(c, "k")](double x, double y) { return yagerTNorm(x, y, k); });
      }));

  // --- fuzzy operators: Li & Tian, §3 ---
  t.push_back(fuzzyEntry(
      "bezier",
      {degreeParam("n", kMaxBezierDegree, 3,
                   "degree n >= 1. Capped at 64: B_n approaches min only like 1/sqrt(n) (max gap "
                   "0.25 at n = 1, 0.16 at 3, 0.035 at 64) while the cost grows with n, and the "
                   "paper advises against high degrees; use smooth_and to get close to min.")},
      "seed 000 eq. 4-7", "B_n(x,y) = sum_{i,j=0..n} min(i,j)/n * B_i^n(x) * B_j^n(y)",
      "Bezier (generalised algebraic) operator: B_1 = x*y <= B_2 <= ... <= min; smooth, "
      "polynomial.",
      [](const OperatorConfig& c) {
        return fuzzy([n = integer(c, "n")](double x, double y) { return bezierOperator(n, x, y); });
      }));
  t.push_back(fuzzyEntry(
      "smooth_and",
      {degreeParam("n", kMaxSmoothAbsoluteDegree, 2,
                   std::string("degree: the operator is C^n.") + kPolynomialCap),
       positiveParam("delta", 0.5,
                     "blending range along x = y; smaller is closer to min (the paper's figures "
                     "use 1.5, 1.0, 0.5). With the general Coons corner term Identity and "
                     "Dominance hold for every delta, and values stay in [0, 1] (checked for "
                     "delta from 0.01 to 1e300); as delta grows AND tends to the product x y.")},
      "seed 000 eq. 8-9, 12, 14-20",
      "AND(x,y) = min_{n,delta}(x,y) - Coons patch of the boundary curves of min_{n,delta}",
      "Smooth piecewise polynomial intersection AND_{n,delta}; union by duality 1 - AND(1-x, "
      "1-y). The Coons corner term interpolates all four corners (the printed alpha = "
      "-|0|_{n,delta} breaks Identity; alpha = -|0|_{n,delta}/2 for delta <= 1).",
      [](const OperatorConfig& c) { return fuzzy(SmoothAnd(integer(c, "n"), real(c, "delta"))); }));
  t.push_back(fuzzyEntry(
      "smooth_and_hat",
      {degreeParam("n", kMaxSmoothAbsoluteDegree, 3,
                   std::string("degree: the operator is C^(n-1).") + kPolynomialCap),
       positiveParam("delta", 0.5,
                     "blending range; equals min exactly where delta <= x, y <= 1 - delta and "
                     "|x - y| >= delta. Identity and Dominance hold for every delta; values "
                     "stay in [0, 1] (checked for delta from 0.01 to 1e300).")},
      "seed 000 eq. 10-11, 13, 21-24",
      "AND^(x,y) = min^_{n,delta}(x,y) - (S1^ + S2^ - S3^), boundary curves x*H_n(-n*x/delta)",
      "Shape-preserving smooth intersection: identical to min away from the blend region. "
      "S3^ (absent in print) is the corner term H_n(-n/delta)(x + y - 2xy), zero for "
      "delta <= 1.",
      [](const OperatorConfig& c) {
        return fuzzy(SmoothAndHat(integer(c, "n"), real(c, "delta")));
      }));

  // --- blends: Li, §3 ---
  t.push_back(blendEntry(
      "ext_max",
      {positiveParam("delta", 0.5,
                     "blending range: S_abs is the parabola t^2/(2 delta) + delta/2 on |t| < "
                     "delta (Li's Fig. 4 uses 0.5, 1, 5)"),
       positiveParam("epsilon", 0.25,
                     "rising range of the step (Li's Fig. 4 uses 0.25); the union contains "
                     "both operands while epsilon <= delta")},
      "seed 001 eq. 18-23",
      "union (a + b + S_abs(a - b, delta, epsilon))/2; intersection -Ext_max(-a,-b); "
      "difference -Ext_max(-a,b)",
      "Exterior blending of implicit fields (inside where F >= 0): can bridge separate shapes.",
      [](const OperatorConfig& c) {
        return blend(
            ExteriorBlend(real(c, "delta"), real(c, "epsilon"), stepFromConfig(c.step.front())));
      }));
  t.push_back(blendEntry(
      "int_max",
      {positiveParam("epsilon", 0.25,
                     "rising range of the step: the transition width (Li's Fig. 9 uses "
                     "1/4, 5, 10)")},
      "seed 001 eq. 24-27",
      "union (1 - mu_eps(b - a)) a + mu_eps(b - a) b; intersection -Int_max(-a,-b); difference "
      "-Int_max(-a,b)",
      "Interior blending of implicit fields: the union lies between min and max of the fields, "
      "so it never grows beyond the operands.",
      [](const OperatorConfig& c) {
        return blend(InteriorBlend(real(c, "epsilon"), stepFromConfig(c.step.front())));
      }));

  // --- steps: Li & Tian, §2.1; Li, §2 ---
  t.push_back(stepEntry(
      "polynomial",
      {degreeParam(
           "n", kMaxPolynomialStepDegree, 3,
           std::string("degree: C^(n-1); n = 3 (C^2) is the paper's choice.") + kPolynomialCap),
       risingRangeParam()},
      "seed 001 eq. 5-6, Def. 3",
      "H_n(t/epsilon), H_n(t) = f_n(n(t+1)/2), f_n(t) = t/n f_{n-1}(t) + (1 - t/n) f_{n-1}(t-1)",
      "Piecewise polynomial smooth unit step; the default step of the blends.",
      [](const OperatorConfig& c) {
        return SmoothUnitStep::polynomial(integer(c, "n"), real(c, "epsilon"));
      }));
  t.push_back(stepEntry(
      "polynomial_range",
      {degreeParam("n", kMaxPolynomialStepDegree, 3,
                   std::string("degree: C^(n-1).") + kPolynomialCap),
       positiveParam("R", 1.0, "supporting range: the step rises over [-R, R]")},
      "seed 000 eq. 2-3",
      "H_{n,R}(x) = H_n(n x/R), H_n(x) = ((1 + x/n) H_{n-1}(x+1) + (1 - x/n) H_{n-1}(x-1))/2",
      "Li & Tian's recursion for the same function as polynomial{n, epsilon = R}.",
      [](const OperatorConfig& c) {
        return SmoothUnitStep::polynomialRange(integer(c, "n"), real(c, "R"));
      }));
  t.push_back(stepEntry(
      "bspline",
      {degreeParam("m", kMaxBSplineOrder, 3,
                   "B-spline order: C^(m-1). Capped at 32: the truncated-power closed form "
                   "cancels, with worst errors ~1e-14 at order 20, ~1e-12 at 32, 1e-7 at 64."),
       risingRangeParam()},
      "seed 001 eq. 7-8, Def. 3", "B_m(t/epsilon), B_m(t) = (1/delta) integral_{-1}^{t} N_m(s) ds",
      "Integrated uniform B-spline step; equals polynomial{n = m}.", [](const OperatorConfig& c) {
        return SmoothUnitStep::bspline(integer(c, "m"), real(c, "epsilon"));
      }));
  const std::string cutoffCap =
      " Capped at 16: the slope at 0 grows like (pi/2)^(n-1) (about 480 at 16), beyond which the "
      "step is a jump at any sampling.";
  t.push_back(
      stepEntry("rising_cutoff",
                {degreeParam("n", kMaxRisingCutoffLevel, 3,
                             "recursion level: 2^(n-1) - 1 derivatives vanish at +-1." + cutoffCap),
                 risingRangeParam()},
                "seed 001 eq. 14-16, Def. 3",
                "R_n(t/epsilon), R_1(t) = sin(pi/4 (1 + t)), R_{n+1}(t) = R_n(sin(pi t/2))",
                "Rising cutoff step (Wickerhauser): R_n(t)^2 + R_n(-t)^2 = 1, R_n(0) = sqrt(1/2).",
                [](const OperatorConfig& c) {
                  return SmoothUnitStep::risingCutoff(integer(c, "n"), real(c, "epsilon"));
                }));
  t.push_back(
      stepEntry("rising_cutoff_squared",
                {degreeParam("n", kMaxRisingCutoffLevel, 3, "recursion level of R_n." + cutoffCap),
                 risingRangeParam()},
                "seed 001 §2.1.3, Def. 3", "R_n(t/epsilon)^2",
                "Squared rising cutoff: antisymmetric about (0, 1/2), a balanced blend.",
                [](const OperatorConfig& c) {
                  return SmoothUnitStep::risingCutoffSquared(integer(c, "n"), real(c, "epsilon"));
                }));
  t.push_back(stepEntry(
      "sigmoid",
      {positiveParam("alpha", 7.0,
                     "steepness; alpha > ln((1 - e)/e) keeps the step within e of 0 and 1 "
                     "outside the rising range (default 7 > ln 999: within 1e-3)"),
       risingRangeParam()},
      "seed 001 eq. 17, Def. 3", "S_alpha(t/epsilon) = 1 / (1 + exp(-alpha t/epsilon))",
      "Logistic step: smooth to every order but never exactly 0 or 1.",
      [](const OperatorConfig& c) {
        return SmoothUnitStep::sigmoid(real(c, "alpha"), real(c, "epsilon"));
      }));

  // --- absolutes: Li & Tian, §3.2 ---
  t.push_back(
      absoluteEntry("upper_abs", "seed 000 eq. 8-9", "|t|_{n,delta} = (delta/n) |n t/delta|_n",
                    "Upper smooth absolute: >= |t|, C^n.", [](const OperatorConfig& c) {
                      return unary([n = integer(c, "n"), delta = real(c, "delta")](double x) {
                        return upperAbsoluteSpan(n, delta, x);
                      });
                    }));
  t.push_back(absoluteEntry("lower_abs", "seed 000 eq. 10-11",
                            "|t|^_{n,delta} = (delta/n)(2 u H_n(u) - u), u = n t/delta",
                            "Lower smooth absolute: <= |t|, C^(n-1).", [](const OperatorConfig& c) {
                              return unary(
                                  [n = integer(c, "n"), delta = real(c, "delta")](double x) {
                                    return lowerAbsoluteSpan(n, delta, x);
                                  });
                            }));
  return t;
}

// The specs (what operatorCatalog() hands out) and, at the same index, how to build each.
struct Catalog {
  std::vector<OperatorSpec> specs;
  std::vector<Entry> entries;
};

const Catalog& catalog() {
  static const Catalog c = [] {
    Catalog built;
    built.entries = buildTable();
    for (const Entry& e : built.entries) built.specs.push_back(e.spec);
    return built;
  }();
  return c;
}

// The entry behind a spec of operatorCatalog().
const Entry& entryOf(const OperatorSpec& spec) {
  return catalog().entries[&spec - catalog().specs.data()];
}

SmoothUnitStep stepFromConfig(const OperatorConfig& c) {
  return entryOf(*findOperator(c.name)).step(c);
}

// --- validation -------------------------------------------------------------------------------

// The three known names nearest to `name`, nearest first.
std::string closestOperatorNames(const std::string& name) {
  std::vector<std::string> names;
  for (const OperatorSpec& spec : operatorCatalog()) names.push_back(spec.name);
  return closestNames(name, names);
}

std::string parameterNames(const OperatorSpec& spec) {
  std::string list;
  for (const ParamSpec& p : spec.params) list += (list.empty() ? "" : ", ") + p.name;
  if (spec.takesStep) list += (list.empty() ? "" : ", ") + std::string("step");
  return list.empty() ? "none" : list;
}

void checkParameter(const ParamSpec& p, double v) {
  bool isInteger = std::isfinite(v) && v == std::floor(v);
  if (p.integer && !(isInteger && inRange(v, p.min, p.minInclusive, p.max, p.maxInclusive)))
    throw Error(errc::kInvalidParameter,
                p.name + " must be an integer in " +
                    formatRange(p.min, p.minInclusive, p.max, p.maxInclusive) + "; got " +
                    formatNumber(v),
                p.name);
  requireInRange(p.name, v, p.min, p.minInclusive, p.max, p.maxInclusive);
}

}  // namespace

const std::vector<OperatorSpec>& operatorCatalog() { return catalog().specs; }

OperatorConfig validateNestedStep(const OperatorConfig& owner) {
  if (owner.step.size() > 1)
    throw Error(errc::kInvalidParameter,
                "'" + owner.name + "' takes one step function; got " +
                    std::to_string(owner.step.size()),
                "step");
  OperatorConfig step = owner.step.empty() ? OperatorConfig{"polynomial", {}, {}}
                                                 // Li, §4: H_3, C^2
                                                 : owner.step.front();
  try {
    step = validateOperator(step);
  } catch (const Error& e) {
    throw e.withPathPrefix("step");
  }
  const std::string& kind = findOperator(step.name)->kind;
  if (kind != "step")
    throw Error(errc::kInvalidParameter,
                "the step of '" + owner.name + "' must be a step function; '" + step.name +
                    "' is of kind " + kind,
                "step.name");
  for (const char* range : {"epsilon", "R"}) {
    auto it = step.params.find(range);
    if (it != step.params.end() && it->second != 1.0)
      throw Error(errc::kInvalidParameter,
                  std::string("the rising range is set by '") + owner.name +
                      "' (a blend's epsilon, a CSG node's range), so the step's " + range +
                      " must stay 1; got " + formatNumber(it->second),
                  std::string("step.") + range);
  }
  return step;
}

const OperatorSpec* findOperator(const std::string& name) {
  for (const OperatorSpec& spec : operatorCatalog())
    if (spec.name == name) return &spec;
  return nullptr;
}

OperatorConfig validateOperator(const OperatorConfig& config) {
  const OperatorSpec* found = findOperator(config.name);
  if (!found)
    throw Error(errc::kUnknownName,
                "unknown operator '" + quotedWord(config.name) + "'; closest: " + closestOperatorNames(config.name),
                "name");
  const OperatorSpec& spec = *found;
  for (const auto& given : config.params) {
    bool known = std::any_of(spec.params.begin(), spec.params.end(),
                             [&](const ParamSpec& p) { return p.name == given.first; });
    if (!known)
      throw Error(errc::kInvalidParameter,
                  "'" + spec.name + "' has no parameter '" + given.first +
                      "'; its parameters: " + parameterNames(spec),
                  given.first);
  }
  OperatorConfig out{spec.name, {}, {}};
  for (const ParamSpec& p : spec.params) {
    auto it = config.params.find(p.name);
    double v = it == config.params.end() ? p.defaultValue : it->second;
    checkParameter(p, v);
    out.params[p.name] = v;
  }
  if (spec.takesStep) {
    out.step.push_back(validateNestedStep(config));
  } else if (!config.step.empty()) {
    throw Error(errc::kInvalidParameter, "'" + spec.name + "' takes no step function", "step");
  }
  return out;
}

std::unique_ptr<BinaryOperator> makeBinaryOperator(const OperatorConfig& config) {
  OperatorConfig valid = validateOperator(config);
  const OperatorSpec& spec = *findOperator(valid.name);
  if (!entryOf(spec).binary)
    throw Error(errc::kInvalidParameter,
                "'" + valid.name + "' is a unary function (kind " + spec.kind +
                    "); a fuzzy_operator or blend is needed here",
                "name");
  return entryOf(spec).binary(valid);
}

std::unique_ptr<UnaryFunction> makeUnaryFunction(const OperatorConfig& config) {
  OperatorConfig valid = validateOperator(config);
  const OperatorSpec& spec = *findOperator(valid.name);
  if (!entryOf(spec).unary)
    throw Error(errc::kInvalidParameter,
                "'" + valid.name + "' is a binary operator (kind " + spec.kind +
                    "); a step or absolute function is needed here",
                "name");
  return entryOf(spec).unary(valid);
}

}  // namespace fsdb
