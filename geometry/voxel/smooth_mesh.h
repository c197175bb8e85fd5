#pragma once
// Smooth surfaces of lower(α) and upper(α) (docs/api.md §3): extractMesh's closed, outward mesh
// (volumeToMesh on the set's voxel indicator, geometry/voxel/envelope_mesh.h) gives the
// topology; each vertex is then moved onto the set's true boundary by root-finding on the exact
// point evaluation of the source the grid was built from (AlphaFieldSource::levelsAt), along its
// normal. The voxel mesh is terraced (every vertex half-way between voxel centres, so a crisp
// sphere comes out faceted in voxel steps); the moved one lies on the surface wherever the
// boundary is within reach, for crisp parts (where the stored levels jump) and fuzzy regions
// (where they vary) alike.
//
// Contract:
//  * The triangles are extractMesh's, unchanged: closed, consistently oriented, and outward as
//    long as no vertex crosses another sheet of the surface (sheets closer than the search
//    reach, 1.5 voxels, are the exception).
//  * A vertex v with unit normal n (the area-weighted mean of its triangles') moves to the
//    sign change of membership(v + t·n) nearest t = 0 among t = ±h/4, ±h/2, …, ±3h/2 (h the
//    voxel size), refined by 8 bisections (to h·2^-10); with no sign change in reach it stays.
//    Membership is the exact one: u(p) ≥ α and u(p) > 0 for upper(α), l(p) ≤ α for lower(α).
//  * Vertices are moved in parallel (TBB); the result does not depend on the thread count.
//  * `deadline` is checked before each run of 256 vertices (every TBB task checks it), so a
//    mesh stops within the time of one run past it: Error(limit_exceeded, ..., kDeadlinePath of
//    envelope_grid.h), and nothing is returned.
// Throws fsdb::Error(invalid_parameter, "alpha") unless 0 <= alpha <= 1.
#include <chrono>
#include <cstdint>

#include "geometry/field/alpha_field.h"
#include "geometry/voxel/envelope_mesh.h"

namespace fsdb {

struct SmoothMeshStats {
  std::uint64_t vertices = 0;     // vertices of the mesh
  std::uint64_t moved = 0;        // vertices placed on a sign change
  std::uint64_t unmoved = 0;      // vertices with no sign change in reach (left where they were)
  std::uint64_t evaluations = 0;  // levelsAt calls
};

TriangleMesh extractSmoothMesh(
    const EnvelopeGrid& grid, const AlphaFieldSource& source, double alpha, EnvelopeBound bound,
    SmoothMeshStats* stats = nullptr,
    std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max());

}  // namespace fsdb
