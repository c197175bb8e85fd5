#pragma once
// File formats of exported meshes: Wavefront OBJ (text, 1-based indices) and binary STL
// (80-byte header, little-endian float32 facets with computed normals, as admesh and slicers
// read them).
#include <string>

#include "geometry/voxel/envelope_mesh.h"

namespace fsdb {

std::string toObj(const TriangleMesh& mesh);
std::string toBinaryStl(const TriangleMesh& mesh);

}  // namespace fsdb
