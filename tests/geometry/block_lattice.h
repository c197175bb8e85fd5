#pragma once
// Test helpers for AlphaFieldSource (geometry/field/alpha_field.h): sampleBlock lattices, bounds checks.
#include <gtest/gtest.h>

#include "geometry/field/alpha_field.h"

// An 8³ lattice of voxel centres from `first`, spacing h.
inline fsdb::BlockLattice latticeAt(const fsdb::Vec3& first, double h) {
  fsdb::BlockLattice b;
  for (int n = 0; n < fsdb::BlockLattice::kDim; ++n) {
    b.x[n] = first.x + n * h;
    b.y[n] = first.y + n * h;
    b.z[n] = first.z + n * h;
  }
  return b;
}

// sampleBlock must give, voxel by voxel, exactly what levelsAt gives.
inline void expectBlockMatchesPoints(const fsdb::AlphaFieldSource& s, const fsdb::BlockLattice& b) {
  constexpr int d = fsdb::BlockLattice::kDim;
  fsdb::AlphaLevels out[fsdb::BlockLattice::kSize];
  s.sampleBlock(b, out);
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j)
      for (int k = 0; k < d; ++k) {
        const fsdb::AlphaLevels v = s.levelsAt(b.at(i, j, k));
        const fsdb::AlphaLevels w = out[(i * d + j) * d + k];
        ASSERT_EQ(v.upper, w.upper) << i << " " << j << " " << k;
        ASSERT_EQ(v.lower, w.lower) << i << " " << j << " " << k;
      }
}

// Do the levels lie within the bounds (u in [upperMin, upperMax], l in [lowerMin, lowerMax])?
inline ::testing::AssertionResult levelsWithin(const fsdb::AlphaLevels& v, const fsdb::AlphaLevelBounds& b) {
  if (v.upper >= b.upperMin && v.upper <= b.upperMax && v.lower >= b.lowerMin && v.lower <= b.lowerMax)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "levels (u " << v.upper << ", l " << v.lower << ") outside bounds u ["
                                       << b.upperMin << ", " << b.upperMax << "], l [" << b.lowerMin << ", "
                                       << b.lowerMax << "]";
}

// Does a point's pair keep lower(α) ⊆ upper(α) for every α, i.e. l <= 1 ⇒ u = 1 (docs/api.md §3;
// geometry/field/node_operator.h)? Nesting in α holds for any pair (upper(α) = {u >= α} shrinks,
// lower(α) = {l <= α} grows).
inline ::testing::AssertionResult lowerInsideUpper(const fsdb::AlphaLevels& v) {
  if (v.lower > 1.0f || v.upper == 1.0f) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "l = " << v.lower << " <= 1 but u = " << v.upper << " < 1";
}
