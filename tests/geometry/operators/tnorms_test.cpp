// Li & Tian, Table 1: the t-norm laws (boundary, commutativity, monotonicity, associativity,
// bounded by min), the printed formulas at sample points, the induced union, complement and
// difference, and the parameter ranges.
#include "geometry/operators/tnorms.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "geometry/core/error.h"

namespace fsdb {
namespace {

struct NamedTNorm {
  std::string name;
  std::function<double(double, double)> t;
};

std::vector<NamedTNorm> allTNorms() {
  return {
      {"algebraic", algebraicTNorm},
      {"zadeh", zadehTNorm},
      {"lukasiewicz", lukasiewiczTNorm},
      {"dubois_prade k=0.3", [](double x, double y) { return duboisPradeTNorm(x, y, 0.3); }},
      {"dubois_prade k=1", [](double x, double y) { return duboisPradeTNorm(x, y, 1.0); }},
      {"einstein", einsteinTNorm},
      {"dombi n=0.5", [](double x, double y) { return dombiTNorm(x, y, 0.5); }},
      {"dombi n=3", [](double x, double y) { return dombiTNorm(x, y, 3.0); }},
      {"dombi n=500", [](double x, double y) { return dombiTNorm(x, y, 500.0); }},
      {"hamacher a=0", [](double x, double y) { return hamacherTNorm(x, y, 0.0); }},
      {"hamacher a=0.7", [](double x, double y) { return hamacherTNorm(x, y, 0.7); }},
      {"weber k=-0.9", [](double x, double y) { return weberTNorm(x, y, -0.9); }},
      {"weber k=5", [](double x, double y) { return weberTNorm(x, y, 5.0); }},
      {"yager k=1.5", [](double x, double y) { return yagerTNorm(x, y, 1.5); }},
      {"yager k=1000", [](double x, double y) { return yagerTNorm(x, y, 1000.0); }},
  };
}

std::vector<double> grid(int steps) {
  std::vector<double> g;
  for (int i = 0; i <= steps; ++i) g.push_back(double(i) / steps);
  return g;
}

TEST(TNorms, BoundaryLawsCommutativityAndRange) {
  for (const auto& [name, t] : allTNorms()) {
    for (double x : grid(40)) {
      EXPECT_NEAR(t(x, 1.0), x, 1e-12) << name << " identity at " << x;
      EXPECT_NEAR(t(1.0, x), x, 1e-12) << name << " identity at " << x;
      EXPECT_NEAR(t(x, 0.0), 0.0, 1e-12) << name << " dominance at " << x;
      EXPECT_NEAR(t(0.0, x), 0.0, 1e-12) << name << " dominance at " << x;
      for (double y : grid(40)) {
        double v = t(x, y);
        EXPECT_NEAR(v, t(y, x), 1e-12) << name;
        EXPECT_GE(v, -1e-12) << name;
        EXPECT_LE(v, std::min(x, y) + 1e-12) << name << " above min at " << x << "," << y;
      }
    }
  }
}

TEST(TNorms, MonotoneAndAssociative) {
  for (const auto& [name, t] : allTNorms()) {
    for (double x : grid(20)) {
      for (double y : grid(20)) {
        if (y < 1.0) {
          EXPECT_LE(t(x, y), t(x, y + 0.05) + 1e-12) << name << " at " << x << "," << y;
        }
        for (double z : grid(10)) EXPECT_NEAR(t(t(x, y), z), t(x, t(y, z)), 1e-9) << name;
      }
    }
  }
}

TEST(TNorms, PrintedFormulasAtSamplePoints) {
  double x = 0.6, y = 0.3;
  EXPECT_DOUBLE_EQ(algebraicTNorm(x, y), 0.18);
  EXPECT_DOUBLE_EQ(zadehTNorm(x, y), 0.3);
  EXPECT_NEAR(lukasiewiczTNorm(x, y), 0.0, 0.0);
  EXPECT_NEAR(lukasiewiczTNorm(0.8, 0.7), 0.5, 1e-15);
  EXPECT_DOUBLE_EQ(duboisPradeTNorm(x, y, 0.5), 0.18 / 0.6);  // max(x,y) >= k: min
  EXPECT_DOUBLE_EQ(duboisPradeTNorm(0.2, 0.1, 0.5), 0.02 / 0.5);
  EXPECT_DOUBLE_EQ(einsteinTNorm(x, y), 0.18 / (2.0 - (0.9 - 0.18)));
  EXPECT_NEAR(dombiTNorm(x, y, 2.0),
              1.0 / (1.0 + std::sqrt(std::pow(1 / x - 1, 2) + std::pow(1 / y - 1, 2))), 1e-15);
  EXPECT_DOUBLE_EQ(hamacherTNorm(x, y, 0.25), 0.18 / (0.25 + 0.75 * (0.9 - 0.18)));
  EXPECT_NEAR(weberTNorm(x, y, 2.0), (0.9 + 2 * 0.18 - 1) / 3.0, 1e-15);
  EXPECT_NEAR(yagerTNorm(x, y, 2.0), 1.0 - std::sqrt(0.16 + 0.49), 1e-15);
  EXPECT_EQ(yagerTNorm(0.1, 0.2, 2.0), 0.0);  // min(1, ...) clips
}

TEST(TNorms, SpecialPointsAndLimits) {
  EXPECT_EQ(dombiTNorm(0.0, 0.0, 2.0), 0.0);
  EXPECT_EQ(dombiTNorm(0.0, 0.7, 2.0), 0.0);
  EXPECT_EQ(dombiTNorm(1.0, 1.0, 2.0), 1.0);
  EXPECT_EQ(hamacherTNorm(0.0, 0.0, 0.0), 0.0);  // defined 0 where the formula is 0/0
  EXPECT_NEAR(hamacherTNorm(0.5, 0.5, 0.0), 0.25 / 0.75, 1e-15);
  // Large exponents approach min without overflow (the scaled p-norm).
  EXPECT_NEAR(yagerTNorm(0.7, 0.8, 1e6), 0.7, 1e-5);
  EXPECT_NEAR(dombiTNorm(0.3, 0.4, 1e6), 0.3, 1e-5);
  EXPECT_NEAR(dombiTNorm(1e-300, 0.5, 2.0), 1e-300, 1e-310);
  // Weber k -> inf approaches the algebraic product; k = 0 is Lukasiewicz.
  EXPECT_NEAR(weberTNorm(0.6, 0.7, 1e9), 0.42, 1e-8);
  EXPECT_DOUBLE_EQ(weberTNorm(0.6, 0.7, 0.0), lukasiewiczTNorm(0.6, 0.7));
  // Dubois-Prade k = 1 is the algebraic product.
  EXPECT_DOUBLE_EQ(duboisPradeTNorm(0.6, 0.7, 1.0), 0.6 * 0.7);
}

TEST(TNorms, UnionComplementDifferenceByDuality) {
  for (const auto& [name, t] : allTNorms()) {
    for (double x : grid(10)) {
      EXPECT_DOUBLE_EQ(fuzzyComplement(x), 1.0 - x);
      EXPECT_NEAR(dualTConorm(t, x, 0.0), x, 1e-12) << name;  // union identity
      EXPECT_NEAR(dualTConorm(t, x, 1.0), 1.0, 1e-12) << name;
      EXPECT_NEAR(fuzzyDifference(t, x, 0.0), x, 1e-12) << name;  // x minus nothing
      EXPECT_NEAR(fuzzyDifference(t, x, 1.0), 0.0, 1e-12) << name;
      for (double y : grid(10)) {
        EXPECT_GE(dualTConorm(t, x, y), std::max(x, y) - 1e-12) << name;
        EXPECT_DOUBLE_EQ(dualTConorm(t, x, y), 1.0 - t(1.0 - x, 1.0 - y));
        EXPECT_DOUBLE_EQ(fuzzyDifference(t, x, y), t(x, 1.0 - y));
      }
    }
  }
  EXPECT_DOUBLE_EQ(dualTConorm(zadehTNorm, 0.2, 0.7), 0.7);                     // max
  EXPECT_NEAR(dualTConorm(algebraicTNorm, 0.2, 0.7), 0.2 + 0.7 - 0.14, 1e-15);  // probabilistic sum
}

void expectInvalid(const std::function<void()>& f, const std::string& path) {
  try {
    f();
    ADD_FAILURE() << "no error for " << path;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter);
    EXPECT_EQ(e.path(), path);
    EXPECT_NE(std::string(e.what()).find("got"), std::string::npos) << e.what();
  }
}

TEST(TNorms, ParametersOutsideTable1RangesThrow) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expectInvalid([] { duboisPradeTNorm(0.5, 0.5, 0.0); }, "k");
  expectInvalid([] { duboisPradeTNorm(0.5, 0.5, 1.01); }, "k");
  expectInvalid([] { dombiTNorm(0.5, 0.5, 0.0); }, "n");
  expectInvalid([=] { dombiTNorm(0.5, 0.5, nan); }, "n");
  expectInvalid([] { hamacherTNorm(0.5, 0.5, 1.0); }, "a");
  expectInvalid([] { hamacherTNorm(0.5, 0.5, -0.1); }, "a");
  expectInvalid([] { weberTNorm(0.5, 0.5, -1.0); }, "k");
  expectInvalid([] { yagerTNorm(0.5, 0.5, 1.0); }, "k");
  EXPECT_NO_THROW(duboisPradeTNorm(0.5, 0.5, 1.0));
  EXPECT_NO_THROW(hamacherTNorm(0.5, 0.5, 0.0));
}

}  // namespace
}  // namespace fsdb
