#pragma once
// Surfaces of an EnvelopeGrid: the boundary of lower(α) or upper(α) as a closed triangle mesh
// (OpenVDB's volumeToMesh, marching cubes on the cell-centred lattice), and the grids as .vdb
// bytes. Pure computation: writing files is the caller's business (server/service/mesh_format.h).
//
// Contract:
// - bound kUpper meshes {u ≥ α} (for α = 0: {u > 0}, the support of upper(0)); kLower meshes
//   {l ≤ α}, as EnvelopeGrid::volumes counts them: the surface runs half-way between inside and
//   outside voxel centres, so it encloses the voxel-count volume (envelope_mesh.cpp says why). The mesh is closed and consistently oriented (outward normals) because the
//   iso-field handed to volumeToMesh is negative inside, positive outside and never changes sign
//   across the grid's background. An empty set gives an empty mesh.
// - Vertices are in world coordinates. Quads are split into two triangles.
// - vdbBytes writes both grids ("upper", "lower") in OpenVDB's stream format, readable by
//   io::Stream / vdb_print after saving.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/voxel/envelope_grid.h"
#include "geometry/core/vec3.h"

namespace fsdb {

enum class EnvelopeBound { kLower, kUpper };

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

// Unit normals per vertex: the area-weighted mean of the normals of its triangles (their winding
// gives the side); (0, 0, 0) for a vertex of no triangle or of degenerate ones only.
std::vector<Vec3> vertexNormals(const TriangleMesh& mesh);

// Throws fsdb::Error(invalid_parameter, "alpha") unless 0 <= alpha <= 1.
TriangleMesh extractMesh(const EnvelopeGrid& grid, double alpha, EnvelopeBound bound);

std::string vdbBytes(const EnvelopeGrid& grid);

}  // namespace fsdb
