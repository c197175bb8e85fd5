#pragma once
// The operator catalogue: every fuzzy set operator, blend, smooth unit step and smooth absolute
// function fsdb offers, with its parameters, ranges, defaults and paper reference. It is the
// registry behind GET /operators and POST /operators/evaluate and the `operator` of CSG nodes
// (docs/api.md §2).
//
// Contract: validateOperator checks a configuration against the catalogue and fills defaults;
// makeBinaryOperator / makeUnaryFunction validate and build an evaluator that never throws.
// Every failure is an fsdb::Error: an unknown name is errc::kUnknownName with path "name" and a
// message naming the closest known names; an unknown parameter, a value out of range or a
// non-integer where an integer is required is errc::kInvalidParameter with the parameter as
// path ("delta", or "step.n" inside the nested step of a blend) and a message giving the
// allowed range and the value received. Unbounded ranges use max = +infinity (exclusive).
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace fsdb {

struct ParamSpec {
  std::string name;
  double min, max;
  bool minInclusive, maxInclusive;
  double defaultValue;
  bool integer;
  std::string description;
};

struct OperatorSpec {
  std::string name;  // "zadeh", "yager", "bezier", "smooth_and", "ext_max", "polynomial", ...
  // "fuzzy_operator": binary on memberships in [0,1]; intersection = the t-norm, union = the
  //                   dual t-conorm, difference = T(a, 1 - b).
  // "blend":          binary on real implicit fields (inside where F >= 0), Li, eq. 21-27.
  // "step":           unary smooth unit step functions.
  // "absolute":       unary upper / lower smooth absolute functions (Li & Tian, eq. 9, 11).
  std::string kind;
  int arity;  // 2 or 1
  std::vector<ParamSpec> params;
  bool takesStep;         // ext_max, int_max: "step" is a nested step-function configuration
  std::string reference;  // "seed 000 Table 1" (Li & Tian), "seed 001 eq. 20-23" (Li), ...
  std::string formula;    // one line of plain text
  std::string description;
};

const std::vector<OperatorSpec>& operatorCatalog();
const OperatorSpec* findOperator(const std::string& name);  // nullptr if unknown

struct OperatorConfig {
  std::string name;
  std::map<std::string, double> params;
  std::vector<OperatorConfig> step;  // 0 or 1 element
};

// Validates against the catalogue and fills defaults (for a blend without a step, the default
// step polynomial{n = 3, epsilon = 1}). The nested step of a blend must be of kind "step" and
// keep its own range parameter (epsilon, or R) at 1: the blend's epsilon is the rising range.
OperatorConfig validateOperator(const OperatorConfig& config);

// The validated step of `owner` (owner.step: 0 or 1 element; none gives polynomial{n = 3}): a
// known step of kind "step" whose range parameter (epsilon, or R) stays 1, because the owner sets
// the rising range (a blend's epsilon; a CSG node's "range", geometry/field/smoothed_part_field.h).
// Paths "step", "step.name", "step.<parameter>".
OperatorConfig validateNestedStep(const OperatorConfig& owner);

enum class Combine { Intersection, Union, Difference };

class BinaryOperator {
 public:
  virtual ~BinaryOperator() = default;
  virtual double intersection(double a, double b) const = 0;
  virtual double unionOf(double a, double b) const = 0;
  virtual double difference(double a, double b) const = 0;  // a minus b
  double apply(Combine c, double a, double b) const;
  virtual bool actsOnMemberships() const = 0;  // true for fuzzy_operator, false for blend
};

class UnaryFunction {
 public:
  virtual ~UnaryFunction() = default;
  virtual double operator()(double t) const = 0;
};

// Validates; the kind must be fuzzy_operator or blend, else errc::kInvalidParameter, path "name".
std::unique_ptr<BinaryOperator> makeBinaryOperator(const OperatorConfig& config);

// Validates; the kind must be step or absolute, else errc::kInvalidParameter, path "name".
std::unique_ptr<UnaryFunction> makeUnaryFunction(const OperatorConfig& config);

}  // namespace fsdb
