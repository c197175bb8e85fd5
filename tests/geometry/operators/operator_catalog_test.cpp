// The operator catalogue: completeness against docs/api.md §2, defaults, validation errors (code,
// path, message), construction and evaluation of every entry, and agreement with the direct
// functions.
#include "geometry/operators/operator_catalog.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "geometry/operators/bezier_operator.h"
#include "geometry/operators/blending.h"
#include "geometry/core/error.h"
#include "geometry/core/parameter_check.h"
#include "geometry/operators/smooth_absolute.h"
#include "geometry/operators/step_functions.h"
#include "geometry/operators/tnorms.h"

namespace fsdb {
namespace {

Error errorOf(const OperatorConfig& config) {
  try {
    validateOperator(config);
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "no error for " << config.name;
  return Error("", "");
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(OperatorCatalog, ListsEveryOperatorNamedInSpecSection2) {
  for (const char* name :
       {"zadeh", "algebraic", "lukasiewicz", "dubois_prade", "einstein", "dombi", "hamacher",
        "weber", "yager", "bezier", "smooth_and", "smooth_and_hat", "ext_max", "int_max"}) {
    const OperatorSpec* spec = findOperator(name);
    ASSERT_NE(spec, nullptr) << name;
    EXPECT_EQ(spec->arity, 2) << name;
  }
  const char* specParams[][3] = {{"bezier", "n", ""},
                                 {"smooth_and", "n", "delta"},
                                 {"smooth_and_hat", "n", "delta"},
                                 {"ext_max", "delta", "epsilon"},
                                 {"int_max", "epsilon", ""}};
  for (auto& row : specParams) {
    const OperatorSpec* spec = findOperator(row[0]);
    for (int i = 1; i < 3; ++i) {
      if (!*row[i]) continue;
      EXPECT_TRUE(std::any_of(spec->params.begin(), spec->params.end(),
                              [&](const ParamSpec& p) { return p.name == row[i]; }))
          << row[0] << " lacks " << row[i];
    }
  }
  EXPECT_TRUE(findOperator("ext_max")->takesStep);
  EXPECT_TRUE(findOperator("int_max")->takesStep);
  for (const char* name : {"polynomial", "polynomial_range", "bspline", "rising_cutoff",
                           "rising_cutoff_squared", "sigmoid"})
    EXPECT_EQ(findOperator(name)->kind, "step") << name;
  EXPECT_EQ(findOperator("upper_abs")->kind, "absolute");
  EXPECT_EQ(findOperator("lower_abs")->kind, "absolute");
  EXPECT_EQ(findOperator("no_such_operator"), nullptr);
}

TEST(OperatorCatalog, EntriesAreWellFormed) {
  std::set<std::string> names;
  for (const OperatorSpec& spec : operatorCatalog()) {
    EXPECT_TRUE(names.insert(spec.name).second) << "duplicate " << spec.name;
    EXPECT_TRUE(spec.kind == "fuzzy_operator" || spec.kind == "blend" || spec.kind == "step" ||
                spec.kind == "absolute")
        << spec.name;
    EXPECT_EQ(spec.arity, spec.kind == "fuzzy_operator" || spec.kind == "blend" ? 2 : 1);
    EXPECT_EQ(spec.takesStep, spec.kind == "blend") << spec.name;
    EXPECT_TRUE(contains(spec.reference, "seed 00")) << spec.name;
    EXPECT_FALSE(spec.formula.empty()) << spec.name;
    EXPECT_FALSE(spec.description.empty()) << spec.name;
    EXPECT_EQ(findOperator(spec.name), &spec);
    for (const ParamSpec& p : spec.params) {
      EXPECT_TRUE(inRange(p.defaultValue, p.min, p.minInclusive, p.max, p.maxInclusive))
          << spec.name << "." << p.name;
      if (p.integer) {
        EXPECT_EQ(p.defaultValue, std::floor(p.defaultValue));
        EXPECT_TRUE(std::isfinite(p.max)) << spec.name << "." << p.name << " needs a cap";
        // a cap must say why
        EXPECT_TRUE(contains(p.description, "Capped") || contains(p.description, "capped"))
            << spec.name << "." << p.name;
      }
      EXPECT_FALSE(p.description.empty());
    }
  }
  EXPECT_EQ(names.size(), 22u);
}

TEST(OperatorCatalog, ValidationFillsDefaults) {
  OperatorConfig yager = validateOperator({"yager", {}, {}});
  EXPECT_EQ(yager.params.at("k"), 2.0);
  OperatorConfig hat = validateOperator({"smooth_and_hat", {{"delta", 0.2}}, {}});
  EXPECT_EQ(hat.params.at("n"), 3.0);
  EXPECT_EQ(hat.params.at("delta"), 0.2);
  EXPECT_EQ(validateOperator({"smooth_and", {}, {}}).params.at("n"), 2.0);
  OperatorConfig ext = validateOperator({"ext_max", {}, {}});
  ASSERT_EQ(ext.step.size(), 1u);
  EXPECT_EQ(ext.step[0].name, "polynomial");
  EXPECT_EQ(ext.step[0].params.at("n"), 3.0);
  EXPECT_EQ(ext.step[0].params.at("epsilon"), 1.0);
  OperatorConfig intMax = validateOperator({"int_max", {}, {{"sigmoid", {{"alpha", 9}}, {}}}});
  EXPECT_EQ(intMax.step[0].params.at("alpha"), 9.0);
  EXPECT_EQ(intMax.step[0].params.at("epsilon"), 1.0);
  EXPECT_TRUE(validateOperator({"zadeh", {}, {}}).step.empty());
}

TEST(OperatorCatalog, EveryEntryConstructsWithDefaultsAndEvaluatesFinite) {
  for (const OperatorSpec& spec : operatorCatalog()) {
    OperatorConfig config{spec.name, {}, {}};
    if (spec.arity == 2) {
      auto op = makeBinaryOperator(config);
      EXPECT_EQ(op->actsOnMemberships(), spec.kind == "fuzzy_operator");
      double lo = op->actsOnMemberships() ? 0.0 : -3.0, hi = op->actsOnMemberships() ? 1.0 : 3.0;
      for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 20; ++j) {
          double a = lo + (hi - lo) * i / 20, b = lo + (hi - lo) * j / 20;
          for (Combine c : {Combine::Intersection, Combine::Union, Combine::Difference}) {
            double v = op->apply(c, a, b);
            EXPECT_TRUE(std::isfinite(v)) << spec.name;
            if (op->actsOnMemberships()) {
              EXPECT_GE(v, -1e-12) << spec.name;
              EXPECT_LE(v, 1 + 1e-12) << spec.name;
            }
          }
        }
      if (op->actsOnMemberships()) {  // Identity and Dominance of every fuzzy intersection
        for (double x : {0.0, 0.3, 0.8, 1.0}) {
          EXPECT_NEAR(op->intersection(x, 1.0), x, 1e-12) << spec.name;
          EXPECT_NEAR(op->intersection(x, 0.0), 0.0, 1e-12) << spec.name;
          EXPECT_NEAR(op->unionOf(x, 0.0), x, 1e-12) << spec.name;
        }
      }
      EXPECT_THROW(makeUnaryFunction(config), Error) << spec.name;
    } else {
      auto f = makeUnaryFunction(config);
      for (double t = -4.0; t <= 4.0; t += 0.125) EXPECT_TRUE(std::isfinite((*f)(t))) << spec.name;
      EXPECT_THROW(makeBinaryOperator(config), Error) << spec.name;
    }
  }
}

TEST(OperatorCatalog, WrongArityIsAnInvalidNameParameter) {
  try {
    makeBinaryOperator({"polynomial", {}, {}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter);
    EXPECT_EQ(e.path(), "name");
  }
  try {
    makeUnaryFunction({"yager", {}, {}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter);
    EXPECT_EQ(e.path(), "name");
  }
}

// Values outside [min, max] (or on an exclusive end), NaN, and non-integers for integers.
std::vector<double> badValues(const ParamSpec& p) {
  std::vector<double> bad = {std::numeric_limits<double>::quiet_NaN()};
  if (std::isfinite(p.min)) bad.push_back(p.minInclusive ? p.min - 1 : p.min);
  if (std::isfinite(p.max))
    bad.push_back(p.maxInclusive ? p.max + 1 : p.max);
  else
    bad.push_back(std::numeric_limits<double>::infinity());
  if (p.integer) bad.push_back(p.defaultValue + 0.5);
  return bad;
}

TEST(OperatorCatalog, EveryParameterRejectsBadValuesWithItsPath) {
  for (const OperatorSpec& spec : operatorCatalog())
    for (const ParamSpec& p : spec.params)
      for (double v : badValues(p)) {
        Error e = errorOf({spec.name, {{p.name, v}}, {}});
        EXPECT_EQ(e.code(), errc::kInvalidParameter) << spec.name << "." << p.name << "=" << v;
        EXPECT_EQ(e.path(), p.name) << spec.name;
        EXPECT_TRUE(contains(e.what(), formatRange(p.min, p.minInclusive, p.max, p.maxInclusive)))
            << e.what();
        EXPECT_TRUE(contains(e.what(), "got " + formatNumber(v))) << e.what();
        EXPECT_THROW(spec.arity == 2 ? (void)makeBinaryOperator({spec.name, {{p.name, v}}, {}})
                                     : (void)makeUnaryFunction({spec.name, {{p.name, v}}, {}}),
                     Error);
      }
}

TEST(OperatorCatalog, NestedStepParametersRejectBadValuesWithStepPath) {
  for (const char* blend : {"ext_max", "int_max"})
    for (const OperatorSpec& step : operatorCatalog()) {
      if (step.kind != "step") continue;
      for (const ParamSpec& p : step.params)
        for (double v : badValues(p)) {
          Error e = errorOf({blend, {}, {{step.name, {{p.name, v}}, {}}}});
          EXPECT_EQ(e.code(), errc::kInvalidParameter) << blend << " " << step.name;
          EXPECT_EQ(e.path(), "step." + p.name) << blend << " " << step.name << " " << v;
          EXPECT_TRUE(contains(e.what(), "got")) << e.what();
        }
    }
}

TEST(OperatorCatalog, RangeBoundariesThatAreInsideAreAccepted) {
  EXPECT_NO_THROW(validateOperator({"dubois_prade", {{"k", 1.0}}, {}}));
  EXPECT_NO_THROW(validateOperator({"hamacher", {{"a", 0.0}}, {}}));
  EXPECT_NO_THROW(validateOperator({"bezier", {{"n", 64}}, {}}));
  EXPECT_NO_THROW(validateOperator({"bezier", {{"n", 1}}, {}}));
  EXPECT_NO_THROW(validateOperator({"smooth_and", {{"n", 32}, {"delta", 1e-6}}, {}}));
  EXPECT_NO_THROW(validateOperator({"weber", {{"k", -0.999}}, {}}));
  EXPECT_NO_THROW(validateOperator({"yager", {{"k", 1.0001}}, {}}));
}

TEST(OperatorCatalog, UnknownNamesSuggestCloseOnes) {
  struct Case {
    const char* typo;
    const char* expected;
  } cases[] = {{"yagr", "yager"},
               {"smooth-and", "smooth_and"},
               {"zadeh ", "zadeh"},
               {"extmax", "ext_max"},
               {"Hamacher", "hamacher"},
               {"bezeir", "bezier"},
               {"rising_cutof", "rising_cutoff"}};
  for (const Case& c : cases) {
    Error e = errorOf({c.typo, {}, {}});
    EXPECT_EQ(e.code(), errc::kUnknownName);
    EXPECT_EQ(e.path(), "name");
    EXPECT_TRUE(contains(e.what(), c.expected)) << e.what();
    EXPECT_TRUE(contains(e.what(), c.typo)) << e.what();
  }
  Error nested = errorOf({"ext_max", {}, {{"polynomal", {}, {}}}});
  EXPECT_EQ(nested.code(), errc::kUnknownName);
  EXPECT_EQ(nested.path(), "step.name");
  EXPECT_TRUE(contains(nested.what(), "polynomial")) << nested.what();
}

TEST(OperatorCatalog, UnknownParametersAndMisplacedStepsAreRejected) {
  Error unknown = errorOf({"yager", {{"p", 2}}, {}});
  EXPECT_EQ(unknown.code(), errc::kInvalidParameter);
  EXPECT_EQ(unknown.path(), "p");
  EXPECT_TRUE(contains(unknown.what(), "k")) << unknown.what();
  Error zadehStep = errorOf({"zadeh", {}, {{"polynomial", {}, {}}}});
  EXPECT_EQ(zadehStep.path(), "step");
  Error twoSteps = errorOf({"int_max", {}, {{"polynomial", {}, {}}, {"bspline", {}, {}}}});
  EXPECT_EQ(twoSteps.path(), "step");
  Error notAStep = errorOf({"ext_max", {}, {{"upper_abs", {}, {}}}});
  EXPECT_EQ(notAStep.code(), errc::kInvalidParameter);
  EXPECT_EQ(notAStep.path(), "step.name");
  Error nestedUnknown = errorOf({"ext_max", {}, {{"polynomial", {{"delta", 1}}, {}}}});
  EXPECT_EQ(nestedUnknown.path(), "step.delta");
  // The blend's epsilon is the rising range; the nested step keeps its own at 1.
  Error range = errorOf({"ext_max", {}, {{"polynomial", {{"epsilon", 0.5}}, {}}}});
  EXPECT_EQ(range.path(), "step.epsilon");
  Error rangeR = errorOf({"int_max", {}, {{"polynomial_range", {{"R", 2}}, {}}}});
  EXPECT_EQ(rangeR.path(), "step.R");
  Error nestedNested = errorOf({"ext_max", {}, {{"polynomial", {}, {{"polynomial", {}, {}}}}}});
  EXPECT_EQ(nestedNested.path(), "step.step");
}

TEST(OperatorCatalog, EvaluatorsAgreeWithTheDirectFunctions) {
  auto yager = makeBinaryOperator({"yager", {{"k", 3}}, {}});
  auto bezier = makeBinaryOperator({"bezier", {{"n", 5}}, {}});
  auto andOp = makeBinaryOperator({"smooth_and", {{"n", 3}, {"delta", 0.4}}, {}});
  auto hat = makeBinaryOperator({"smooth_and_hat", {}, {}});
  auto ext = makeBinaryOperator({"ext_max", {{"delta", 0.7}}, {{"bspline", {{"m", 4}}, {}}}});
  auto in = makeBinaryOperator({"int_max", {{"epsilon", 0.3}}, {{"rising_cutoff", {}, {}}}});
  ExteriorBlend extDirect(0.7, 0.25, SmoothUnitStep::bspline(4));
  InteriorBlend inDirect(0.3, SmoothUnitStep::risingCutoff(3));
  for (double a = 0.0; a <= 1.0; a += 0.125)
    for (double b = 0.0; b <= 1.0; b += 0.125) {
      EXPECT_EQ(yager->intersection(a, b), yagerTNorm(a, b, 3));
      EXPECT_EQ(yager->unionOf(a, b), 1 - yagerTNorm(1 - a, 1 - b, 3));
      EXPECT_EQ(yager->difference(a, b), yagerTNorm(a, 1 - b, 3));
      EXPECT_EQ(yager->apply(Combine::Union, a, b), yager->unionOf(a, b));
      EXPECT_EQ(yager->apply(Combine::Difference, a, b), yager->difference(a, b));
      EXPECT_EQ(yager->apply(Combine::Intersection, a, b), yager->intersection(a, b));
      EXPECT_EQ(bezier->intersection(a, b), bezierOperator(5, a, b));
      EXPECT_EQ(andOp->intersection(a, b), smoothAnd(3, 0.4, a, b));
      EXPECT_EQ(andOp->unionOf(a, b), 1 - smoothAnd(3, 0.4, 1 - a, 1 - b));
      EXPECT_EQ(hat->intersection(a, b), smoothAndHat(3, 0.5, a, b));
      double x = 4 * a - 2, y = 4 * b - 2;  // fields, not memberships
      EXPECT_EQ(ext->unionOf(x, y), extDirect.unionOf(x, y));
      EXPECT_EQ(ext->intersection(x, y), extDirect.intersection(x, y));
      EXPECT_EQ(ext->difference(x, y), extDirect.difference(x, y));
      EXPECT_EQ(in->unionOf(x, y), inDirect.unionOf(x, y));
      EXPECT_EQ(in->intersection(x, y), inDirect.intersection(x, y));
      EXPECT_EQ(in->difference(x, y), inDirect.difference(x, y));
    }
  auto step = makeUnaryFunction({"sigmoid", {{"alpha", 5}, {"epsilon", 0.5}}, {}});
  auto range = makeUnaryFunction({"polynomial_range", {{"n", 4}, {"R", 2}}, {}});
  auto upper = makeUnaryFunction({"upper_abs", {{"n", 3}, {"delta", 0.5}}, {}});
  auto lower = makeUnaryFunction({"lower_abs", {}, {}});
  auto cutoff2 = makeUnaryFunction({"rising_cutoff_squared", {{"n", 2}}, {}});
  auto spline = makeUnaryFunction({"bspline", {{"m", 5}, {"epsilon", 2}}, {}});
  auto poly = makeUnaryFunction({"polynomial", {}, {}});
  for (double t = -3; t <= 3; t += 0.1) {
    EXPECT_EQ((*step)(t), sigmoidStep(5, t / 0.5));
    EXPECT_EQ((*range)(t), liTianStepRange(4, 2, t));
    EXPECT_EQ((*upper)(t), upperAbsoluteSpan(3, 0.5, t));
    EXPECT_EQ((*lower)(t), lowerAbsoluteSpan(2, 1.0, t));
    EXPECT_EQ((*cutoff2)(t), risingCutoffSquared(2, t));
    EXPECT_EQ((*spline)(t), bsplineStep(5, t / 2));
    EXPECT_EQ((*poly)(t), polynomialStep(3, t));
  }
}

}  // namespace
}  // namespace fsdb
