// Features the scene model cannot hold load without them, and Scene::warnings says so, naming
// the material, so the tools can tell the user what they are not seeing.
#include <gtest/gtest.h>

#include <stb/stb_image_write.h>

#include <algorithm>

#include "gltf_fixture.h"
#include "scene/load.h"

namespace bounce {
namespace {

bool anyWarningHas(const Scene& scene, const std::string& a, const std::string& b) {
  return std::any_of(scene.warnings.begin(), scene.warnings.end(), [&](const std::string& w) {
    return w.find(a) != std::string::npos && w.find(b) != std::string::npos;
  });
}

// The fixture's triangle with material 0 `material` and one 1×1 PNG as texture 0.
test::GltfFixture texturedTriangle(const test::TempDir& dir, const nlohmann::json& material) {
  const unsigned char rgb[3] = {255, 128, 0};
  EXPECT_NE(stbi_write_png((dir / "glow.png").string().c_str(), 1, 1, 3, rgb, 3), 0);
  test::GltfFixture f = test::GltfFixture::triangle();
  f.doc["images"] = {{{"uri", "glow.png"}}};
  f.doc["textures"] = {{{"source", 0}}};
  f.doc["materials"] = {material};
  f.doc["meshes"][0]["primitives"][0]["material"] = 0;
  return f;
}

TEST(GltfWarnings, EmissiveTextureIsNamedWithItsMaterial) {
  test::TempDir dir;
  texturedTriangle(dir, {{"name", "neon sign"},
                         {"emissiveFactor", {1.0, 1.0, 1.0}},
                         {"emissiveTexture", {{"index", 0}}}})
      .writeGltf(dir / "emissive.gltf");
  const Scene scene = loadScene(dir / "emissive.gltf");
  EXPECT_TRUE(anyWarningHas(scene, "neon sign", "emissiveTexture")) << scene.warnings.size();
  // The emission itself still loads, uniform: emissiveFactor 1 nit = 1/683 W/(sr·m²).
  EXPECT_NEAR(scene.materials.at(0).emission.r, 1.0f / 683.0f, 1e-9f);
}

TEST(GltfWarnings, TextureTransformIsNamedWithItsMaterial) {
  test::TempDir dir;
  texturedTriangle(
      dir,
      {{"name", "tiles"},
       {"pbrMetallicRoughness",
        {{"baseColorTexture",
          {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {4.0, 4.0}}}}}}}}}}})
      .writeGltf(dir / "transform.gltf");
  const Scene scene = loadScene(dir / "transform.gltf");
  EXPECT_TRUE(anyWarningHas(scene, "tiles", "KHR_texture_transform")) << scene.warnings.size();
}

TEST(GltfWarnings, PlainFileHasNone) {
  test::TempDir dir;
  texturedTriangle(
      dir, {{"name", "plain"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}})
      .writeGltf(dir / "plain.gltf");
  EXPECT_TRUE(loadScene(dir / "plain.gltf").warnings.empty());
}

}  // namespace
}  // namespace bounce
