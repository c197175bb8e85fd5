#pragma once
// Random fuzzy numbers for property tests. Always seeded by the caller (std::mt19937 with a
// fixed seed), so failures reproduce.
#include <algorithm>
#include <ostream>
#include <random>
#include <vector>

#include "geometry/fuzzy/fuzzy_number.h"

namespace fsdb::testing {

inline double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// A triangular number inside [-10, 10], sides at least 0.2 wide unless `allowVertical`.
inline FuzzyNumber randomTriangular(std::mt19937& rng, bool allowVertical = false) {
  const double m = uniform(rng, -8, 8);
  double left = uniform(rng, 0.2, 2.0), right = uniform(rng, 0.2, 2.0);
  if (allowVertical && uniform(rng, 0, 1) < 0.2) left = 0;
  if (allowVertical && uniform(rng, 0, 1) < 0.2) right = 0;
  return FuzzyNumber::triangular(m - left, m, m + right);
}

inline FuzzyNumber randomTrapezoidal(std::mt19937& rng) {
  const double b = uniform(rng, -8, 8);
  const double c = b + uniform(rng, 0.0, 2.0);
  return FuzzyNumber::trapezoidal(b - uniform(rng, 0.2, 2.0), b, c, c + uniform(rng, 0.2, 2.0));
}

inline FuzzyNumber randomTriOrTrap(std::mt19937& rng) {
  return uniform(rng, 0, 1) < 0.5 ? randomTriangular(rng) : randomTrapezoidal(rng);
}

// A convex piecewise-linear number with up to 4 breakpoints on each side, including
// horizontal pieces and vertical jumps now and then.
inline FuzzyNumber randomConvexPoints(std::mt19937& rng) {
  auto side = [&rng](int n) {
    std::vector<double> mus;
    for (int i = 0; i < n; ++i) {
      const double u = uniform(rng, 0, 1);
      mus.push_back(u < 0.15 ? 0.5 : u);  // repeated levels make horizontal pieces
    }
    std::sort(mus.begin(), mus.end());
    return mus;
  };
  std::vector<Breakpoint> points;
  double x = uniform(rng, -8, 6);
  points.push_back({x, 0});
  for (double mu : side(std::uniform_int_distribution<int>(0, 4)(rng))) {
    x += uniform(rng, 0, 1) < 0.1 ? 0.0 : uniform(rng, 0.05, 1.0);
    points.push_back({x, mu});
  }
  x += uniform(rng, 0.05, 1.0);
  points.push_back({x, 1});
  if (uniform(rng, 0, 1) < 0.5) {
    x += uniform(rng, 0.05, 1.0);
    points.push_back({x, 1});
  }
  std::vector<double> down = side(std::uniform_int_distribution<int>(0, 4)(rng));
  std::reverse(down.begin(), down.end());
  for (double mu : down) {
    x += uniform(rng, 0, 1) < 0.1 ? 0.0 : uniform(rng, 0.05, 1.0);
    points.push_back({x, mu});
  }
  x += uniform(rng, 0.05, 1.0);
  points.push_back({x, 0});
  return FuzzyNumber::fromPoints(points);
}

// Any normal piecewise-linear number: random mu at random increasing x, one of them 1.
inline FuzzyNumber randomPoints(std::mt19937& rng) {
  const int n = std::uniform_int_distribution<int>(2, 9)(rng);
  const int top = std::uniform_int_distribution<int>(0, n - 1)(rng);
  std::vector<Breakpoint> points;
  double x = uniform(rng, -8, 6);
  for (int i = 0; i < n; ++i) {
    x += uniform(rng, 0, 1) < 0.1 ? 0.0 : uniform(rng, 0.05, 1.0);
    points.push_back({x, i == top ? 1.0 : uniform(rng, 0, 1)});
  }
  return FuzzyNumber::fromPoints(points);
}

}  // namespace fsdb::testing

namespace fsdb {

// gtest prints failing FuzzyNumbers as their breakpoints.
inline void PrintTo(const FuzzyNumber& a, std::ostream* os) {
  *os << "[";
  for (const Breakpoint& p : a.breakpoints()) *os << "(" << p.x << ", " << p.mu << ")";
  *os << "]";
}

}  // namespace fsdb
