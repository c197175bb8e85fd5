#pragma once
// The fuzzy bent, tapered, twisted, placed part of the alpha-field benchmarks
// (bench/bench_fuzzy_part_field.cpp) and of the tests that hold its grid to the definitions: all
// fourteen values fuzzy, each a symmetric triangle of about ±5 % around its core.
#include "geometry/superquadric/fuzzy_part.h"

namespace fsdb::testing {

inline FuzzyPart allValuesFuzzyPart() {
  const auto spread = [](double m, double s) { return FuzzyNumber::triangular(m - s, m, m + s); };
  FuzzyPart part;
  part.eps1 = spread(0.7, 0.035);
  part.eps2 = spread(1.3, 0.065);
  part.a1 = spread(1.0, 0.05);
  part.a2 = spread(0.8, 0.04);
  part.a3 = spread(2.0, 0.1);
  part.kx = spread(0.4, 0.05);
  part.ky = spread(-0.3, 0.05);
  part.kv = spread(0.3, 0.015);
  part.t = spread(1.2, 0.05);
  part.tx = spread(0.5, 0.025);
  part.ty = spread(-0.25, 0.0125);
  part.tz = spread(0.1, 0.005);
  part.axis = {1, 1, 0};
  part.deg = spread(30, 3);
  part.scale = spread(1.5, 0.075);
  return part;
}

}  // namespace fsdb::testing
