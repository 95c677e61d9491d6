// Albedo textures: sRGB-encoded files decode to linear (IEC 61966-2-1), through glTF's
// baseColorTexture and OBJ's map_Kd, with rows top first and OBJ's v flipped.
#include <gtest/gtest.h>

#include <stb/stb_image_write.h>

#include <cmath>

#include "expect_load_error.h"
#include "gltf_fixture.h"
#include "scene/load.h"
#include "scene/texture_decode.h"

namespace bounce {
namespace {

// sRGB decode, written out independently: c ≤ 0.04045 → c/12.92, else ((c+0.055)/1.055)^2.4.
double expectedLinear(int byte) {
  const double c = byte / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// A 2×2 PNG: top row (0, 128, 255) and (10, 10, 10); bottom row (255, 255, 255) and (64, 0, 0).
void writeTestPng(const std::filesystem::path& path) {
  const unsigned char rgb[12] = {0, 128, 255, 10, 10, 10, 255, 255, 255, 64, 0, 0};
  ASSERT_NE(stbi_write_png(path.string().c_str(), 2, 2, 3, rgb, 6), 0);
}

void expectTestTexels(const Texture& t) {
  ASSERT_EQ(t.width, 2);
  ASSERT_EQ(t.height, 2);
  EXPECT_NEAR(t.texels[0].r, 0.0, 1e-6);
  EXPECT_NEAR(t.texels[0].g, expectedLinear(128), 1e-6);  // ≈ 0.2158
  EXPECT_NEAR(t.texels[0].b, 1.0, 1e-6);
  EXPECT_NEAR(t.texels[1].r, expectedLinear(10), 1e-7);  // linear segment: 10/255/12.92
  EXPECT_NEAR(t.texels[3].r, expectedLinear(64), 1e-6);
  EXPECT_EQ(t.texels[2], glm::vec3(1.0f));
}

TEST(Texture, SrgbTransferFunction) {
  EXPECT_NEAR(srgbToLinear(0.5f), 0.2140411, 1e-6);
  EXPECT_NEAR(srgbToLinear(0.04045f), 0.04045 / 12.92, 1e-7);
  EXPECT_FLOAT_EQ(srgbToLinear(1.0f), 1.0f);
}

TEST(Texture, GltfBaseColorTextureIsDecodedToLinear) {
  test::TempDir dir;
  writeTestPng(dir / "albedo.png");
  test::GltfFixture f = test::GltfFixture::triangle();
  const int uv = f.addFloats({0, 0, 1, 0, 0, 1}, "VEC2");
  f.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = uv;
  f.doc["meshes"][0]["primitives"][0]["material"] = 0;
  f.doc["images"] = {{{"uri", "albedo.png"}}};
  f.doc["textures"] = {{{"source", 0}}};
  f.doc["materials"] = {
      {{"pbrMetallicRoughness",
        {{"baseColorTexture", {{"index", 0}}}, {"baseColorFactor", {0.5, 1, 1, 1}}}}}};
  f.writeGltf(dir / "textured.gltf");
  const Scene scene = loadScene(dir / "textured.gltf");
  ASSERT_EQ(scene.textures.size(), 1u);
  expectTestTexels(scene.textures[0]);
  EXPECT_EQ(scene.materials[0].albedoTexture, 0u);
  EXPECT_EQ(scene.materials[0].albedo, glm::vec3(0.5f, 1.0f, 1.0f));
  EXPECT_EQ(scene.meshes[0].uv0[1], glm::vec2(1, 0));
}

TEST(Texture, ObjMapKdIsDecodedAndVIsFlipped) {
  test::TempDir dir;
  writeTestPng(dir / "albedo.png");
  test::writeText(dir / "t.mtl", "newmtl m\nKd 1 1 1\nmap_Kd albedo.png\n");
  test::writeText(dir / "t.obj",
                  "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 0.25\n"
                  "usemtl m\nf 1/1 2/2 3/3\n");
  const Scene scene = loadScene(dir / "t.obj");
  ASSERT_EQ(scene.textures.size(), 1u);
  expectTestTexels(scene.textures[0]);
  // OBJ's v runs up from the bottom row; bounce's from the top row: v' = 1 − v.
  EXPECT_EQ(scene.meshes.at(0).uv0.at(2), glm::vec2(0.0f, 0.75f));
  EXPECT_EQ(scene.meshes.at(0).normals.at(0), glm::vec3(0, 0, 1));
}

TEST(Texture, GltfMissingImageIsALoadError) {
  test::TempDir dir;
  test::GltfFixture f = test::GltfFixture::triangle();
  f.doc["meshes"][0]["primitives"][0]["material"] = 0;
  f.doc["images"] = {{{"uri", "absent.png"}}};
  f.doc["textures"] = {{{"source", 0}}};
  f.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  f.writeGltf(dir / "noimage.gltf");
  test::expectLoadError(dir / "noimage.gltf", "absent.png");
}

// Issue 15: OBJ/MTL files written where file names ignore letter case name their textures in
// another case than the disk has them, and with backslashes (`map_Kd SP_LUK.JPG` for
// `sp_luk.JPG`): the texture is read and a warning names both spellings. Two files matching alike
// are not guessed between: the scene is refused as for a missing texture.
TEST(Texture, ObjMapKdInAnotherLetterCaseIsFoundWithAWarning) {
  test::TempDir dir;
  std::filesystem::create_directory(dir / "Maps");
  writeTestPng(dir / "Maps" / "sp_luk.JPG");  // a PNG by its content, whatever the extension says
  test::writeText(dir / "t.mtl", "newmtl m\nKd 1 1 1\nmap_Kd maps\\SP_LUK.JPG\n");
  test::writeText(dir / "t.obj", "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n");
  const Scene scene = loadScene(dir / "t.obj");
  ASSERT_EQ(scene.textures.size(), 1u);
  expectTestTexels(scene.textures[0]);
  bool warned = false;
  for (const std::string& w : scene.warnings)
    warned |= w.find("'maps\\SP_LUK.JPG'") != std::string::npos &&
              w.find("'Maps/sp_luk.JPG'") != std::string::npos;
  EXPECT_TRUE(warned) << (scene.warnings.empty() ? "no warning" : scene.warnings.front());

  writeTestPng(dir / "Maps" / "SP_luk.jpg");  // now two files answer to the name
  test::expectLoadError(dir / "t.obj", "SP_LUK.JPG");
}

TEST(Texture, MissingTextureFileIsALoadError) {
  test::TempDir dir;
  test::writeText(dir / "t.mtl", "newmtl m\nmap_Kd absent.png\n");
  test::writeText(dir / "t.obj", "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n");
  try {
    loadScene(dir / "t.obj");
    ADD_FAILURE() << "loaded with a missing texture";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("absent.png"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace bounce
