// Base-colour textures multiply the albedo, and are oriented as the scene model says: uv (0,0)
// is the top-left texel, row 0 the top row.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "test_scenes.h"

namespace bounce::test {
namespace {

constexpr int kSize = 64;
constexpr float kPi = std::numbers::pi_v<float>;

Scene texturedFloor(Texture texture, glm::vec3 albedo) {
  Scene scene;
  scene.textures.push_back(std::move(texture));
  Material m;
  m.name = "textured";
  m.albedo = albedo;
  m.albedoTexture = 0;
  // 2 m × 1 m, uv (0,0) at z = +0.5, v = 1 at z = −0.5.
  addQuad(scene, {-1, 0, 0.5f}, {2, 0, 0}, {0, 0, -1}, m);
  scene.materials.back() = m;
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = {0, -1, 0};
  sun.irradiance = glm::vec3(kPi);  // ρ/π · E = ρ
  scene.lights.push_back(sun);
  return scene;
}

TEST(AlbedoTexture, TexelMultipliesAlbedo) {
  Texture texture;
  texture.width = texture.height = 1;
  texture.texels = {{0.5f, 0.25f, 1.0f}};
  const Image image =
      render(texturedFloor(texture, {0.8f, 0.8f, 0.4f}), downCamera(2.0f), kSize, kSize);
  const glm::vec3 expected(0.4f, 0.2f, 0.4f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.at(32, 32)[c], expected[c], 1e-3f * expected[c]);
}

TEST(AlbedoTexture, RowZeroIsAtVZero) {
  Texture texture;
  texture.width = 1;
  texture.height = 2;
  texture.texels = {{1, 0, 0}, {0, 1, 0}};  // top row red, bottom row green
  const Camera camera = downCamera(2.0f);
  const Image image = render(texturedFloor(texture, glm::vec3(1.0f)), camera, kSize, kSize);
  // Find the pixels of the column x = 32 that see z = +0.25 (v = 0.25, row 0's centre) and
  // z = −0.25 (v = 0.75, row 1's centre); bilinear filtering blends < 10% there.
  int redRow = -1, greenRow = -1;
  for (int y = 0; y < kSize; ++y) {
    const float z = floorPoint(camera, kSize, kSize, 32, y).z;
    if (redRow < 0 ||
        std::abs(z - 0.25f) < std::abs(floorPoint(camera, kSize, kSize, 32, redRow).z - 0.25f))
      redRow = y;
    if (greenRow < 0 ||
        std::abs(z + 0.25f) < std::abs(floorPoint(camera, kSize, kSize, 32, greenRow).z + 0.25f))
      greenRow = y;
  }
  EXPECT_GT(image.at(32, redRow).r, 0.9f);
  EXPECT_LT(image.at(32, redRow).g, 0.1f);
  EXPECT_GT(image.at(32, greenRow).g, 0.9f);
  EXPECT_LT(image.at(32, greenRow).r, 0.1f);
}

}  // namespace
}  // namespace bounce::test
