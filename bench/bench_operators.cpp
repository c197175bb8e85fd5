// Nanoseconds per evaluation of every operator and step function: through the catalogue's
// virtual interface ("catalog/...") and by the direct function or class ("direct/..."), at
// the catalogue defaults plus a few degrees. One iteration = one evaluation; inputs cycle
// through 1024 precomputed random points so nothing folds to a constant.
#include <benchmark/benchmark.h>

#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "geometry/operators/bezier_operator.h"
#include "geometry/operators/blending.h"
#include "geometry/operators/operator_catalog.h"
#include "geometry/operators/smooth_absolute.h"
#include "geometry/operators/step_functions.h"
#include "geometry/operators/tnorms.h"

namespace fsdb {
namespace {

constexpr size_t kPoints = 1024;

std::vector<double> randomValues(double lo, double hi, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<double> v(kPoints);
  for (double& x : v) x = u(rng);
  return v;
}

// Memberships for fuzzy operators, fields for blends, arguments for steps.
const std::vector<double> kA = randomValues(0, 1, 1), kB = randomValues(0, 1, 2);
const std::vector<double> kFieldA = randomValues(-2, 2, 3), kFieldB = randomValues(-2, 2, 4);
const std::vector<double> kT = randomValues(-1.5, 1.5, 5);

template <class F>
void benchBinary(benchmark::State& state, const F& f, bool fields) {
  const std::vector<double>& a = fields ? kFieldA : kA;
  const std::vector<double>& b = fields ? kFieldB : kB;
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(f(a[i], b[i]));
    i = (i + 1) & (kPoints - 1);
  }
}

template <class F>
void benchUnary(benchmark::State& state, const F& f) {
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(f(kT[i]));
    i = (i + 1) & (kPoints - 1);
  }
}

std::string label(const OperatorConfig& c) {
  std::string s = c.name;
  for (const auto& [k, v] : c.params) s += "/" + k + "=" + std::to_string(v).substr(0, 4);
  for (const OperatorConfig& step : c.step) s += "/step=" + step.name;
  return s;
}

template <class Direct>
void registerBinary(const OperatorConfig& config, Direct direct) {
  bool fields = findOperator(config.name)->kind == "blend";
  std::shared_ptr<BinaryOperator> op = makeBinaryOperator(config);
  std::string name = label(config);
  benchmark::RegisterBenchmark(("catalog/" + name).c_str(), [op, fields](benchmark::State& s) {
    if (fields)
      benchBinary(
          s, [&](double a, double b) { return op->unionOf(a, b); }, true);
    else
      benchBinary(
          s, [&](double a, double b) { return op->intersection(a, b); }, false);
  });
  benchmark::RegisterBenchmark(("direct/" + name).c_str(), [direct, fields](benchmark::State& s) {
    benchBinary(s, direct, fields);
  });
}

template <class Direct>
void registerUnary(const OperatorConfig& config, Direct direct) {
  std::shared_ptr<UnaryFunction> f = makeUnaryFunction(config);
  std::string name = label(config);
  benchmark::RegisterBenchmark(("catalog/" + name).c_str(), [f](benchmark::State& s) {
    benchUnary(s, [&](double t) { return (*f)(t); });
  });
  benchmark::RegisterBenchmark(("direct/" + name).c_str(),
                               [direct](benchmark::State& s) { benchUnary(s, direct); });
}

int registerAll() {
  registerBinary(OperatorConfig{"zadeh", {}, {}}, zadehTNorm);
  registerBinary(OperatorConfig{"algebraic", {}, {}}, algebraicTNorm);
  registerBinary(OperatorConfig{"lukasiewicz", {}, {}}, lukasiewiczTNorm);
  registerBinary(OperatorConfig{"dubois_prade", {}, {}},
                 [](double x, double y) { return duboisPradeTNorm(x, y, 0.5); });
  registerBinary(OperatorConfig{"einstein", {}, {}}, einsteinTNorm);
  registerBinary(OperatorConfig{"dombi", {}, {}},
                 [](double x, double y) { return dombiTNorm(x, y, 2.0); });
  registerBinary(OperatorConfig{"hamacher", {}, {}},
                 [](double x, double y) { return hamacherTNorm(x, y, 0.5); });
  registerBinary(OperatorConfig{"weber", {}, {}},
                 [](double x, double y) { return weberTNorm(x, y, 1.0); });
  registerBinary(OperatorConfig{"yager", {}, {}},
                 [](double x, double y) { return yagerTNorm(x, y, 2.0); });
  for (int n : {3, 16, 64})
    registerBinary(OperatorConfig{"bezier", {{"n", n}}, {}},
                   [n](double x, double y) { return bezierOperator(n, x, y); });
  for (int n : {2, 8, 32}) {
    SmoothAnd op(n, 0.5);
    registerBinary(OperatorConfig{"smooth_and", {{"n", n}}, {}}, op);
  }
  for (int n : {3, 8, 32}) {
    SmoothAndHat op(n, 0.5);
    registerBinary(OperatorConfig{"smooth_and_hat", {{"n", n}}, {}}, op);
  }
  // one-shot form: builds the operator (two corner values) at every call
  benchmark::RegisterBenchmark("direct/smooth_and_oneshot/n=2", [](benchmark::State& s) {
    benchBinary(
        s, [](double x, double y) { return smoothAnd(2, 0.5, x, y); }, false);
  });
  {
    ExteriorBlend ext(0.5, 0.25);
    registerBinary(OperatorConfig{"ext_max", {}, {}},
                   [ext](double a, double b) { return ext.unionOf(a, b); });
    InteriorBlend in(0.25);
    registerBinary(OperatorConfig{"int_max", {}, {}},
                   [in](double a, double b) { return in.unionOf(a, b); });
    ExteriorBlend extSigmoid(0.5, 0.25, SmoothUnitStep::sigmoid(7.0));
    registerBinary(OperatorConfig{"ext_max", {}, {{"sigmoid", {}, {}}}},
                   [extSigmoid](double a, double b) { return extSigmoid.unionOf(a, b); });
  }
  for (int n : {3, 8, 32})
    registerUnary(OperatorConfig{"polynomial", {{"n", n}}, {}},
                  [n](double t) { return polynomialStep(n, t); });
  for (int n : {3, 8, 32})
    registerUnary(OperatorConfig{"polynomial_range", {{"n", n}}, {}},
                  [n](double t) { return liTianStepRange(n, 1.0, t); });
  for (int m : {3, 8, 32})
    registerUnary(OperatorConfig{"bspline", {{"m", m}}, {}},
                  [m](double t) { return bsplineStep(m, t); });
  for (int n : {3, 8, 16})
    registerUnary(OperatorConfig{"rising_cutoff", {{"n", n}}, {}},
                  [n](double t) { return risingCutoff(n, t); });
  registerUnary(OperatorConfig{"rising_cutoff_squared", {}, {}},
                [](double t) { return risingCutoffSquared(3, t); });
  registerUnary(OperatorConfig{"sigmoid", {}, {}}, [](double t) { return sigmoidStep(7.0, t); });
  for (int n : {2, 8, 32}) {
    registerUnary(OperatorConfig{"upper_abs", {{"n", n}}, {}},
                  [n](double t) { return upperAbsoluteSpan(n, 1.0, t); });
    registerUnary(OperatorConfig{"lower_abs", {{"n", n}}, {}},
                  [n](double t) { return lowerAbsoluteSpan(n, 1.0, t); });
  }
  return 0;
}

const int kRegistered = registerAll();

}  // namespace
}  // namespace fsdb
