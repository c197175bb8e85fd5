// server/service/mesh_format: OBJ and binary STL bytes of a small mesh.
#include "server/service/mesh_format.h"

#include <gtest/gtest.h>

#include <cstring>

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
