#include "geometry/voxel/envelope_mesh.h"

#include <openvdb/io/Stream.h>
#include <openvdb/tools/ChangeBackground.h>
#include <openvdb/tools/ValueTransformer.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <sstream>

#include "geometry/voxel/envelope_grid_vdb.h"
#include "geometry/core/error.h"

namespace fsdb {
namespace {

// The iso-field is the set's indicator, −½ inside and +½ outside, with the same membership tests
// as EnvelopeGrid::volumes (u ≥ α and u > 0; l ≤ α). Marching cubes then puts every surface
// vertex half-way between an inside and an outside voxel centre, so the mesh encloses what the
// voxel count measures. Feeding the levels themselves would bias the surface: u and l jump
// (1 → 0, 0 → never) at crisp boundaries, and a linear crossing next to a plateau sits on the
// inside voxel's centre, half a voxel too far in (5% of the volume of a 24-voxel-radius ball).
constexpr float kInside = -0.5f, kOutside = 0.5f;

}  // namespace

std::vector<Vec3> vertexNormals(const TriangleMesh& mesh) {
  std::vector<Vec3> normals(mesh.vertices.size(), Vec3{0, 0, 0});
  for (const auto& t : mesh.triangles) {
    // The cross product's length is twice the triangle's area: the weights.
    const Vec3 n = cross(mesh.vertices[t[1]] - mesh.vertices[t[0]], mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    for (std::uint32_t i : t) normals[i] = normals[i] + n;
  }
  for (Vec3& n : normals) {
    const double len = norm(n);
    n = len > 0 ? n / len : Vec3{0, 0, 0};
  }
  return normals;
}

TriangleMesh extractMesh(const EnvelopeGrid& grid, double alpha, EnvelopeBound bound) {
  if (!(alpha >= 0.0 && alpha <= 1.0)) throw Error(errc::kInvalidParameter, "alpha must lie in [0, 1]", "alpha");
  initializeOpenVdb();
  const float a = static_cast<float>(alpha);
  openvdb::FloatGrid::Ptr field;
  if (bound == EnvelopeBound::kUpper) {
    field = upperGrid(grid)->deepCopy();
    openvdb::tools::foreach(field->beginValueAll(), [a](const openvdb::FloatGrid::ValueAllIter& it) {
      it.setValue(*it > 0.0f && *it >= a ? kInside : kOutside);
    });
  } else {
    field = lowerGrid(grid)->deepCopy();
    openvdb::tools::foreach(field->beginValueAll(), [a](const openvdb::FloatGrid::ValueAllIter& it) {
      it.setValue(*it <= a ? kInside : kOutside);
    });
  }
  const float background = kOutside;
  openvdb::tools::changeBackground(field->tree(), background);
  // Marching cubes needs voxels: interior tiles become leaves (their values are uniform, so
  // only tiles on the boundary of the set contribute faces).
  field->tree().voxelizeActiveTiles();

  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*field, points, quads, 0.0);

  TriangleMesh mesh;
  mesh.vertices.reserve(points.size());
  for (const auto& p : points) mesh.vertices.push_back({p.x(), p.y(), p.z()});
  mesh.triangles.reserve(2 * quads.size());
  for (const auto& q : quads) {
    // volumeToMesh orients quads for fields that are negative inside; keep its winding.
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  return mesh;
}

std::string vdbBytes(const EnvelopeGrid& grid) {
  initializeOpenVdb();
  openvdb::GridPtrVec grids;
  grids.push_back(upperGrid(grid)->deepCopy());
  grids.push_back(lowerGrid(grid)->deepCopy());
  std::ostringstream out(std::ios_base::binary);
  openvdb::io::Stream(out).write(grids);
  return out.str();
}

}  // namespace fsdb
