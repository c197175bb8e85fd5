// server/service/mesh_format: OBJ, binary STL and GLB bytes of a small mesh.
#include "server/service/mesh_format.h"

#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>

namespace fsdb {
namespace {

TriangleMesh tetrahedron() {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

float floatAt(const std::string& s, size_t offset) {
  float v;
  std::memcpy(&v, s.data() + offset, 4);
  return v;
}

TEST(MeshFormat, ObjListsVerticesAndOneBasedFaces) {
  const std::string obj = toObj(tetrahedron());
  EXPECT_EQ(obj.rfind("# fsdb mesh: 4 vertices, 4 triangles\n", 0), 0u);
  EXPECT_NE(obj.find("v 1 0 0\n"), std::string::npos);
  EXPECT_NE(obj.find("f 1 3 2\n"), std::string::npos);
  EXPECT_NE(obj.find("f 2 3 4\n"), std::string::npos);
}

TEST(MeshFormat, BinaryStlHasHeaderCountAndUnitNormals) {
  const std::string stl = toBinaryStl(tetrahedron());
  ASSERT_EQ(stl.size(), 84u + 50u * 4u);
  EXPECT_EQ(stl.substr(0, 15), "fsdb binary STL");
  std::uint32_t count;
  std::memcpy(&count, stl.data() + 80, 4);
  EXPECT_EQ(count, 4u);
  // First facet (0, 2, 1) lies in z = 0 facing −z.
  EXPECT_FLOAT_EQ(floatAt(stl, 84 + 8), -1.0f);
  EXPECT_FLOAT_EQ(floatAt(stl, 84 + 0), 0.0f);
  // Its second vertex is (0, 1, 0).
  EXPECT_FLOAT_EQ(floatAt(stl, 84 + 12 + 12 + 4), 1.0f);
}

}  // namespace
}  // namespace fsdb

namespace fsdb {
namespace {

uint32_t u32At(const std::string& s, size_t offset) {
  uint32_t v;
  std::memcpy(&v, s.data() + offset, 4);
  return v;
}

// The JSON chunk of a GLB, after checking the container: magic, version, total length, chunk
// types and 4-byte alignment.
nlohmann::json glbJson(const std::string& glb, std::string* bin) {
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  EXPECT_EQ(u32At(glb, 4), 2u);
  EXPECT_EQ(u32At(glb, 8), glb.size());
  const uint32_t jsonLength = u32At(glb, 12);
  EXPECT_EQ(u32At(glb, 16), 0x4E4F534Au);
  EXPECT_EQ(jsonLength % 4, 0u);
  const nlohmann::json j = nlohmann::json::parse(glb.substr(20, jsonLength));
  const size_t binAt = 20 + jsonLength;
  if (binAt < glb.size()) {
    const uint32_t binLength = u32At(glb, binAt);
    EXPECT_EQ(u32At(glb, binAt + 4), 0x004E4942u);
    EXPECT_EQ(binLength % 4, 0u);
    *bin = glb.substr(binAt + 8, binLength);
  }
  return j;
}

TEST(MeshFormat, GlbHoldsNamedMeshesWithNormals) {
  TriangleMesh moved = tetrahedron();
  for (Vec3& v : moved.vertices) v = v + Vec3{2, 0, 0};
  std::string bin;
  const nlohmann::json j = glbJson(toGlb({{"lower", tetrahedron()}, {"upper", moved}}), &bin);
  EXPECT_EQ(j["asset"]["version"], "2.0");
  ASSERT_EQ(j["meshes"].size(), 2u);
  EXPECT_EQ(j["meshes"][0]["name"], "lower");
  EXPECT_EQ(j["nodes"][1]["name"], "upper");
  EXPECT_EQ(j["scenes"][0]["nodes"], nlohmann::json({0, 1}));
  EXPECT_EQ(j["buffers"][0]["byteLength"], bin.size());
  const nlohmann::json& primitive = j["meshes"][1]["primitives"][0];
  const nlohmann::json& position = j["accessors"][primitive["attributes"]["POSITION"].get<size_t>()];
  EXPECT_EQ(position["count"], 4);
  EXPECT_EQ(position["min"], nlohmann::json({2.0, 0.0, 0.0}));
  EXPECT_EQ(position["max"], nlohmann::json({3.0, 1.0, 1.0}));
  EXPECT_EQ(j["accessors"][primitive["indices"].get<size_t>()]["count"], 12);
  // Normals: unit length.
  const nlohmann::json& normals = j["accessors"][primitive["attributes"]["NORMAL"].get<size_t>()];
  const nlohmann::json& view = j["bufferViews"][normals["bufferView"].get<size_t>()];
  for (int v = 0; v < 4; ++v) {
    const size_t at = view["byteOffset"].get<size_t>() + size_t(v) * 12;
    const double x = floatAt(bin, at), y = floatAt(bin, at + 4), z = floatAt(bin, at + 8);
    EXPECT_NEAR(x * x + y * y + z * z, 1.0, 1e-6) << v;
  }
  // Vertex 1 is (1,0,0) of the lower one: its faces' normals -z, -y and (1,1,1)/√3 (area √3/2).
  const nlohmann::json& lowerNormals =
      j["accessors"][j["meshes"][0]["primitives"][0]["attributes"]["NORMAL"].get<size_t>()];
  const size_t at = j["bufferViews"][lowerNormals["bufferView"].get<size_t>()]["byteOffset"].get<size_t>() + 12;
  const Vec3 sum = Vec3{0, 0, -0.5} + Vec3{0, -0.5, 0} + Vec3{0.5, 0.5, 0.5};
  const Vec3 unit = sum / norm(sum);
  EXPECT_NEAR(floatAt(bin, at), unit.x, 1e-6);
  EXPECT_NEAR(floatAt(bin, at + 4), unit.y, 1e-6);
  EXPECT_NEAR(floatAt(bin, at + 8), unit.z, 1e-6);
}

TEST(MeshFormat, GlbListsEmptyMeshesInsteadOfEmptyAccessors) {
  std::string bin;
  const nlohmann::json j = glbJson(toGlb({{"lower", TriangleMesh{}}, {"upper", tetrahedron()}}), &bin);
  ASSERT_EQ(j["meshes"].size(), 1u);
  EXPECT_EQ(j["meshes"][0]["name"], "upper");
  EXPECT_EQ(j["scenes"][0]["extras"]["empty"], nlohmann::json({"lower"}));
  std::string none;
  const nlohmann::json nothing = glbJson(toGlb({{"lower", TriangleMesh{}}, {"upper", TriangleMesh{}}}), &none);
  EXPECT_FALSE(nothing.contains("meshes"));
  EXPECT_FALSE(nothing.contains("buffers"));
  EXPECT_FALSE(nothing["scenes"][0].contains("nodes"));
  EXPECT_EQ(nothing["scenes"][0]["extras"]["empty"], nlohmann::json({"lower", "upper"}));
  EXPECT_TRUE(none.empty());
}

}  // namespace
}  // namespace fsdb
