#include "server/service/mesh_format.h"

#include <cmath>
#include <cstring>
#include <sstream>

namespace fsdb {
namespace {

void putFloat(std::string& out, float v) {
  // STL is little-endian; so is every machine fsdb builds on (x86-64, arm64).
  char b[4];
  std::memcpy(b, &v, 4);
  out.append(b, 4);
}

}  // namespace

std::string toObj(const TriangleMesh& mesh) {
  std::ostringstream out;
  out.precision(9);
  out << "# fsdb mesh: " << mesh.vertices.size() << " vertices, " << mesh.triangles.size() << " triangles\n";
  for (const Vec3& v : mesh.vertices) out << "v " << v.x << ' ' << v.y << ' ' << v.z << '\n';
  for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  return out.str();
}

std::string toBinaryStl(const TriangleMesh& mesh) {
  std::string out(80, '\0');
  const std::string header = "fsdb binary STL";
  out.replace(0, header.size(), header);
  const auto count = static_cast<std::uint32_t>(mesh.triangles.size());
  char c[4];
  std::memcpy(c, &count, 4);
  out.append(c, 4);
  out.reserve(out.size() + 50 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &d = mesh.vertices[t[2]];
    Vec3 n = cross(b - a, d - a);
    const double len = norm(n);
    if (len > 0) n = n / len;
    for (double v : {n.x, n.y, n.z}) putFloat(out, static_cast<float>(v));
    for (const Vec3* p : {&a, &b, &d})
      for (double v : {p->x, p->y, p->z}) putFloat(out, static_cast<float>(v));
    out.append(2, '\0');  // attribute byte count
  }
  return out;
}

}  // namespace fsdb
