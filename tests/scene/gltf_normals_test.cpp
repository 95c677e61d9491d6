// Shading normals from glTF NORMAL data that is zero or not finite: they come from the
// geometry (area-weighted geometric normals, else flat per triangle), never an arbitrary axis.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "gltf_fixture.h"
#include "scene/load.h"

namespace bounce {
namespace {

// The fixture's triangle lies in z = 0, counter-clockwise seen from +z: a wall facing +z.
TEST(GltfNormals, ZeroNormalsTakeTheTrianglesNormal) {
  test::TempDir dir;
  test::GltfFixture f = test::GltfFixture::triangle();
  f.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] =
      f.addFloats({0, 0, 0, 0, 0, 0, 0, 0, 0}, "VEC3");
  f.writeGltf(dir / "zero.gltf");
  const Mesh mesh = loadScene(dir / "zero.gltf").meshes.at(0);
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  for (const glm::vec3& n : mesh.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

// An indexed primitive over `positions` with the given NORMAL data and uint16 indices.
void setIndexedMesh(test::GltfFixture& f, const std::vector<float>& positions,
                    const std::vector<float>& normals, const std::vector<uint16_t>& indices) {
  const int pos = f.addFloats(positions, "VEC3");
  const int nrm = f.addFloats(normals, "VEC3");
  const std::size_t offset = f.bin.size();
  f.bin.resize(offset + (indices.size() * 2 + 3) / 4 * 4);
  std::memcpy(f.bin.data() + offset, indices.data(), indices.size() * 2);
  f.doc["bufferViews"].push_back(
      {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", indices.size() * 2}});
  f.doc["accessors"].push_back({{"bufferView", f.doc["bufferViews"].size() - 1},
                                {"componentType", 5123},
                                {"count", indices.size()},
                                {"type", "SCALAR"}});
  f.doc["meshes"][0]["primitives"][0] = {{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}}},
                                         {"indices", f.doc["accessors"].size() - 1},
                                         {"mode", 4}};
}

void expectNear(glm::vec3 a, glm::vec3 b) {
  EXPECT_LT(glm::distance(a, b), 1e-6f) << a.x << " " << a.y << " " << a.z;
}

// Triangles A = (0,1,2) in z = 0, cross (0,0,1), and B = (1,3,2) with v3 = (1,1,1), cross
// (v3−v1)×(v2−v1) = (0,1,1)×(−1,1,0) = (−1,−1,1). Zero normals at v1, v2 (shared) become
// (0,0,1)+(−1,−1,1) = (−1,−1,2)/√6, at v3 (B only) (−1,−1,1)/√3; v0's valid (0,0,2) is only
// normalized.
TEST(GltfNormals, SharedVerticesSumTheirTrianglesAreaWeighted) {
  test::TempDir dir;
  test::GltfFixture f = test::GltfFixture::triangle();
  setIndexedMesh(f, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 1}, {0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0},
                 {0, 1, 2, 1, 3, 2});
  f.writeGltf(dir / "fold.gltf");
  const Mesh mesh = loadScene(dir / "fold.gltf").meshes.at(0);
  ASSERT_EQ(mesh.normals.size(), 4u);
  expectNear(mesh.normals[0], glm::vec3(0, 0, 1));
  expectNear(mesh.normals[1], glm::vec3(-1, -1, 2) / std::sqrt(6.0f));
  expectNear(mesh.normals[2], glm::vec3(-1, -1, 2) / std::sqrt(6.0f));
  expectNear(mesh.normals[3], glm::vec3(-1, -1, 1) / std::sqrt(3.0f));
}

// Back-to-back triangles (0,1,2) and (0,2,1) cancel: each triangle gets its own copies of the
// corners carrying its flat normal, +z for the first and −z for the second.
TEST(GltfNormals, CancellingFacesGetFlatNormals) {
  test::TempDir dir;
  test::GltfFixture f = test::GltfFixture::triangle();
  setIndexedMesh(f, {0, 0, 0, 1, 0, 0, 0, 1, 0}, std::vector<float>(9, 0.0f), {0, 1, 2, 0, 2, 1});
  f.writeGltf(dir / "sheet.gltf");
  const Mesh mesh = loadScene(dir / "sheet.gltf").meshes.at(0);
  ASSERT_EQ(mesh.indices.size(), 6u);
  for (std::size_t c = 0; c < 6; ++c) {
    const uint32_t i = mesh.indices[c];
    ASSERT_LT(i, mesh.normals.size());
    expectNear(mesh.normals[i], glm::vec3(0, 0, c < 3 ? 1.0f : -1.0f));
  }
  // The corners keep their positions: the second triangle is still (0,0,0), (0,1,0), (1,0,0).
  expectNear(mesh.positions[mesh.indices[4]], glm::vec3(0, 1, 0));
  expectNear(mesh.positions[mesh.indices[5]], glm::vec3(1, 0, 0));
}

}  // namespace
}  // namespace bounce
