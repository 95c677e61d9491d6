// Every kind of bad input gives one LoadError naming the file and the problem, never a crash.
// The files are generated here, in a temporary folder, from a valid one-triangle glTF.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "expect_load_error.h"
#include "gltf_fixture.h"
#include "scene/load.h"

namespace bounce {
namespace {

using test::expectLoadError;
using test::GltfFixture;
using test::TempDir;

TEST(MalformedInput, ValidFixtureLoads) {  // the baseline every other case corrupts
  TempDir dir;
  GltfFixture f = GltfFixture::triangle();
  f.writeGltf(dir / "ok.gltf");
  f.writeGlb(dir / "ok.glb");
  for (const char* name : {"ok.gltf", "ok.glb"}) {
    const Scene scene = loadScene(dir / name);
    ASSERT_EQ(scene.triangleCount(), 1u);
    // No NORMAL given: flat normal of the counter-clockwise triangle, +z.
    EXPECT_EQ(scene.meshes[0].normals[0], glm::vec3(0, 0, 1));
  }
}

TEST(MalformedInput, MissingFile) {
  TempDir dir;
  expectLoadError(dir / "absent.gltf", "not found");
  expectLoadError(dir / "absent.obj", "not found");
}

TEST(MalformedInput, UnsupportedExtension) {
  TempDir dir;
  test::writeText(dir / "scene.fbx", "x");
  expectLoadError(dir / "scene.fbx", "unsupported file extension");
}

TEST(MalformedInput, TruncatedGlb) {
  TempDir dir;
  GltfFixture::triangle().writeGlb(dir / "cut.glb");
  const std::vector<unsigned char> whole = test::readAll(dir / "cut.glb");
  // Cut inside the header, inside the JSON chunk and inside the BIN chunk.
  for (const std::size_t keep : {std::size_t{10}, whole.size() / 2, whole.size() - 4}) {
    test::writeBytes(dir / "cut.glb", {whole.begin(), whole.begin() + static_cast<long>(keep)});
    expectLoadError(dir / "cut.glb", "truncated");
  }
}

TEST(MalformedInput, TruncatedGltfJson) {
  TempDir dir;
  GltfFixture::triangle().writeGltf(dir / "cut.gltf");
  const std::vector<unsigned char> whole = test::readAll(dir / "cut.gltf");
  test::writeBytes(dir / "cut.gltf",
                   {whole.begin(), whole.begin() + static_cast<long>(whole.size() / 2)});
  expectLoadError(dir / "cut.gltf", "invalid glTF");
}

TEST(MalformedInput, TruncatedBin) {
  TempDir dir;
  GltfFixture f = GltfFixture::triangle();
  f.writeGltf(dir / "cut.gltf");
  test::writeBytes(dir / "cut.bin", std::vector<unsigned char>(f.bin.begin(), f.bin.begin() + 20));
  try {
    loadScene(dir / "cut.gltf");
    ADD_FAILURE() << "a truncated .bin loaded";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("cut.gltf"), std::string::npos) << e.what();
    EXPECT_FALSE(e.reason().empty());
  }
}

TEST(MalformedInput, AccessorIndexOutOfRange) {
  TempDir dir;
  GltfFixture f = GltfFixture::triangle();
  f.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 7;
  f.writeGltf(dir / "accessor.gltf");
  expectLoadError(dir / "accessor.gltf", "out of range");
}

TEST(MalformedInput, BufferViewAndBufferIndexOutOfRange) {
  TempDir dir;
  GltfFixture f = GltfFixture::triangle();
  f.doc["accessors"][0]["bufferView"] = 9;
  f.writeGltf(dir / "view.gltf");
  expectLoadError(dir / "view.gltf", "out of range");
  GltfFixture g = GltfFixture::triangle();
  g.doc["bufferViews"][0]["buffer"] = 3;
  g.writeGltf(dir / "buffer.gltf");
  expectLoadError(dir / "buffer.gltf", "out of range");
}

TEST(MalformedInput, AccessorBeyondItsBufferView) {
  TempDir dir;
  GltfFixture f = GltfFixture::triangle();
  f.doc["accessors"][0]["count"] = 1000;
  f.writeGltf(dir / "count.gltf");
  expectLoadError(dir / "count.gltf", "exceeds");
  GltfFixture g = GltfFixture::triangle();
  g.doc["bufferViews"][0]["byteLength"] = 4000;  // the view runs past the buffer's end
  g.writeGltf(dir / "length.gltf");
  try {
    loadScene(dir / "length.gltf");
    ADD_FAILURE() << "a bufferView past its buffer loaded";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("length.gltf"), std::string::npos) << e.what();
  }
}

TEST(MalformedInput, VertexIndexOutOfRange) {
  TempDir dir;
  GltfFixture f = GltfFixture::triangle();
  const uint16_t bad = 9;  // 3 vertices only
  std::memcpy(f.bin.data() + 36 + 2, &bad, sizeof bad);
  f.writeGlb(dir / "index.glb");
  expectLoadError(dir / "index.glb", "index 9");
}

TEST(MalformedInput, NonFinitePositions) {
  TempDir dir;
  for (const float bad :
       {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    GltfFixture f = GltfFixture::triangle();
    f.setFloat(4 * 4, bad);  // vertex 1, y
    f.writeGltf(dir / "nan.gltf");
    expectLoadError(dir / "nan.gltf", "not finite");
  }
}

TEST(MalformedInput, UnknownRequiredExtension) {
  TempDir dir;
  GltfFixture f = GltfFixture::triangle();
  f.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  f.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  f.writeGltf(dir / "required.gltf");
  expectLoadError(dir / "required.gltf", "KHR_draco_mesh_compression");
}

// An unknown extension that is only *used* is optional by the glTF spec: the file loads and
// the extension is ignored (documented in docs/units.md's loader notes).
TEST(MalformedInput, UnknownOptionalExtensionIsIgnored) {
  TempDir dir;
  GltfFixture f = GltfFixture::triangle();
  f.doc["extensionsUsed"] = {"EXT_made_up"};
  f.doc["nodes"][0]["extensions"] = {{"EXT_made_up", {{"x", 1}}}};
  f.writeGltf(dir / "optional.gltf");
  EXPECT_EQ(loadScene(dir / "optional.gltf").triangleCount(), 1u);
}

TEST(MalformedInput, NonTrianglePrimitives) {
  TempDir dir;
  for (const int mode : {0, 1, 5, 6}) {  // points, lines, triangle strip, triangle fan
    GltfFixture f = GltfFixture::triangle();
    f.doc["meshes"][0]["primitives"][0]["mode"] = mode;
    f.writeGltf(dir / "mode.gltf");
    expectLoadError(dir / "mode.gltf", "triangles");
  }
}

TEST(MalformedInput, ObjProblems) {
  TempDir dir;
  test::writeText(dir / "index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  expectLoadError(dir / "index.obj", "vertex 9");
  test::writeText(dir / "nomtl.obj",
                  "mtllib absent.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
  expectLoadError(dir / "nomtl.obj", "absent.mtl");
  test::writeText(dir / "undefined.mtl", "newmtl a\nKd 0.5 0.5 0.5\n");
  test::writeText(dir / "undefined.obj",
                  "mtllib undefined.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl b\nf 1 2 3\n");
  expectLoadError(dir / "undefined.obj", "'b'");
}

// Finite in the file's double but beyond float's ~3.4e38 once converted: not representable in
// the scene model, so an error rather than an infinite emitter, light or camera.
TEST(MalformedInput, ValuesBeyondFloatRange) {
  TempDir dir;
  // 1e42 nits = 1e42/683 ≈ 1.5e39 W/(sr·m²) (1e40 nits would still fit: 1.5e37).
  GltfFixture emissive = GltfFixture::triangle();
  emissive.doc["meshes"][0]["primitives"][0]["material"] = 0;
  emissive.doc["materials"] = {
      {{"name", "sun"},
       {"emissiveFactor", {1.0, 1.0, 1.0}},
       {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 1e42}}}}}}};
  emissive.writeGltf(dir / "strength.gltf");
  expectLoadError(dir / "strength.gltf", "exceeds bounce's limit of 1e12");
  for (const char* type : {"point", "directional"}) {
    GltfFixture light = GltfFixture::triangle();
    light.doc["extensions"] = {
        {"KHR_lights_punctual", {{"lights", {{{"type", type}, {"intensity", 1e300}}}}}}};
    light.doc["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", 0}}}};
    light.writeGltf(dir / "intensity.gltf");
    expectLoadError(dir / "intensity.gltf", "exceeds bounce's limit of 1e12");
  }
  GltfFixture camera = GltfFixture::triangle();
  camera.doc["cameras"] = {
      {{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 1e39}}}}};
  camera.doc["nodes"][0]["camera"] = 0;
  camera.writeGltf(dir / "znear.gltf");
  expectLoadError(dir / "znear.gltf", "not representable");
}

}  // namespace
}  // namespace bounce
