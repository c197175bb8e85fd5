#include "server/service/mesh_format.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>

namespace fsdb {
namespace {

void putFloat(std::string& out, float v) {
  // STL is little-endian; so is every machine fsdb builds on (x86-64, arm64).
  char b[4];
  std::memcpy(b, &v, 4);
  out.append(b, 4);
}

template <typename T>
void put(std::string& out, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  out.append(b, sizeof(T));
}

}  // namespace

std::string toGlb(const std::vector<NamedMesh>& meshes) {
  nlohmann::json gltf = {{"asset", {{"version", "2.0"}, {"generator", "fsdb"}}},
                         {"scene", 0},
                         {"buffers", nlohmann::json::array()},
                         {"bufferViews", nlohmann::json::array()},
                         {"accessors", nlohmann::json::array()},
                         {"meshes", nlohmann::json::array()},
                         {"nodes", nlohmann::json::array()}};
  nlohmann::json scene = nlohmann::json::object();
  nlohmann::json sceneNodes = nlohmann::json::array(), empty = nlohmann::json::array();
  std::string bin;
  // A buffer view of `bytes` (appended 4-byte aligned) and an accessor over it.
  const auto addAccessor = [&](const std::string& bytes, int componentType, const char* type, size_t count,
                               int target, nlohmann::json extra) {
    while (bin.size() % 4) bin.push_back('\0');
    const size_t view = gltf["bufferViews"].size();
    gltf["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes.size()},
                                   {"target", target}});
    bin += bytes;
    nlohmann::json accessor = {{"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}};
    accessor.update(extra);
    gltf["accessors"].push_back(accessor);
    return gltf["accessors"].size() - 1;
  };
  for (const auto& [name, mesh] : meshes) {
    if (mesh.triangles.empty()) {
      empty.push_back(name);
      continue;
    }
    std::string positions, normals, indices;
    std::array<float, 3> lo{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                            std::numeric_limits<float>::max()};
    std::array<float, 3> hi{-lo[0], -lo[1], -lo[2]};
    for (const Vec3& v : mesh.vertices) {
      const std::array<float, 3> f{static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
      for (int k = 0; k < 3; ++k) {
        put(positions, f[k]);
        lo[k] = std::min(lo[k], f[k]);
        hi[k] = std::max(hi[k], f[k]);
      }
    }
    // glTF wants unit normals: a vertex of degenerate triangles only gets +z.
    for (const Vec3& n : vertexNormals(mesh)) {
      const Vec3 unit = norm(n) > 0 ? n : Vec3{0, 0, 1};
      for (double c : {unit.x, unit.y, unit.z}) put(normals, static_cast<float>(c));
    }
    for (const auto& t : mesh.triangles)
      for (std::uint32_t i : t) put(indices, i);
    constexpr int kFloat = 5126, kUnsignedInt = 5125, kArrayBuffer = 34962, kElementArrayBuffer = 34963;
    const size_t p = addAccessor(positions, kFloat, "VEC3", mesh.vertices.size(), kArrayBuffer,
                                 {{"min", {lo[0], lo[1], lo[2]}}, {"max", {hi[0], hi[1], hi[2]}}});
    const size_t n = addAccessor(normals, kFloat, "VEC3", mesh.vertices.size(), kArrayBuffer, nlohmann::json::object());
    const size_t i = addAccessor(indices, kUnsignedInt, "SCALAR", mesh.triangles.size() * 3, kElementArrayBuffer,
                                 nlohmann::json::object());
    gltf["meshes"].push_back(
        {{"name", name},
         {"primitives", {{{"attributes", {{"POSITION", p}, {"NORMAL", n}}}, {"indices", i}, {"mode", 4}}}}});
    sceneNodes.push_back(gltf["nodes"].size());
    gltf["nodes"].push_back({{"name", name}, {"mesh", gltf["meshes"].size() - 1}});
  }
  while (bin.size() % 4) bin.push_back('\0');
  if (!sceneNodes.empty()) scene["nodes"] = sceneNodes;
  if (!empty.empty()) scene["extras"] = {{"empty", empty}};
  gltf["scenes"] = nlohmann::json::array({scene});
  // glTF forbids empty arrays: drop the ones nothing went into (and the buffer with no bytes).
  for (const char* key : {"bufferViews", "accessors", "meshes", "nodes"})
    if (gltf[key].empty()) gltf.erase(key);
  if (bin.empty()) {
    gltf.erase("buffers");
  } else {
    gltf["buffers"].push_back({{"byteLength", bin.size()}});
  }
  std::string json = gltf.dump();
  while (json.size() % 4) json.push_back(' ');  // the JSON chunk is padded with spaces
  std::string out;
  put(out, std::uint32_t{0x46546C67});  // "glTF"
  put(out, std::uint32_t{2});
  put(out, static_cast<std::uint32_t>(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
  put(out, static_cast<std::uint32_t>(json.size()));
  put(out, std::uint32_t{0x4E4F534A});  // "JSON"
  out += json;
  if (!bin.empty()) {
    put(out, static_cast<std::uint32_t>(bin.size()));
    put(out, std::uint32_t{0x004E4942});  // "BIN\0"
    out += bin;
  }
  return out;
}

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
