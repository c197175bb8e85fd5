#pragma once
// What the voxel-layer mesh tests check of a TriangleMesh (geometry/voxel/envelope_mesh.h): its
// signed volume and whether it is closed and consistently oriented.
#include <cstdint>
#include <map>
#include <utility>

#include "geometry/voxel/envelope_mesh.h"

namespace fsdb::testing {

// Signed volume by the divergence theorem: positive when the triangles face outwards.
inline double signedVolume(const TriangleMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles) v += dot(m.vertices[t[0]], cross(m.vertices[t[1]], m.vertices[t[2]])) / 6.0;
  return v;
}

// Closed and consistently oriented: every directed edge appears once and its reverse once.
inline bool closedAndOriented(const TriangleMesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  for (const auto& [e, n] : directed) {
    if (n != 1) return false;
    auto rev = directed.find({e.second, e.first});
    if (rev == directed.end() || rev->second != 1) return false;
  }
  return !m.triangles.empty();
}

}  // namespace fsdb::testing
