#pragma once
// File formats of exported meshes: Wavefront OBJ (text, 1-based indices), binary STL
// (80-byte header, little-endian float32 facets with computed normals, as admesh and slicers
// read them), and binary glTF 2.0 (GLB: several named meshes in one file, for browsers and
// three.js).
#include <string>
#include <utility>
#include <vector>

#include "geometry/voxel/envelope_mesh.h"

namespace fsdb {

std::string toObj(const TriangleMesh& mesh);
std::string toBinaryStl(const TriangleMesh& mesh);

// A GLB file (glTF 2.0 binary container: a JSON chunk and a BIN chunk) with one node and one
// mesh per named input, in order: float32 POSITION (with the min/max glTF requires), float32
// NORMAL (per vertex, the area-weighted mean of its triangles' normals, unit length), uint32
// indices, one triangle primitive each. An input without triangles (lower(α) empty at high α)
// has no mesh, since glTF forbids empty accessors; its name is listed in the scene's
// extras.empty instead. Little-endian, 4-byte aligned chunks.
using NamedMesh = std::pair<std::string, TriangleMesh>;
std::string toGlb(const std::vector<NamedMesh>& meshes);

}  // namespace fsdb
