// The baked frame in a closed furnace (the edges of surfaces as right as their middle): a room
// whose every surface (walls, a block resting on the floor, a box against a wall) has albedo ρ and
// emits Le. Light in a closed furnace is the same at every point, L = Le/(1 − ρ); of the
// irradiance E = π·L, π·Le comes straight from emitters, so the indirect irradiance is
// E_ind = π·Le·ρ/(1 − ρ) and `--mode indirect` must draw ρ/π·E_ind = Le·ρ²/(1 − ρ) at every
// pixel: along edges, in corners and where the block stands on the floor as in the middle of a
// wall.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "indirect_accuracy.h"
#include "shadow_scenes.h"
#include "test_scenes.h"

namespace bounce::test {
namespace {

// Turns the last mesh added inside out (its faces point into the box).
void turnInside(Scene& scene) {
  Mesh& mesh = scene.meshes.back();
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
  for (glm::vec3& n : mesh.normals) n = -n;
}

TEST(FurnaceFrame, IndirectLightIsUniformAtEdgesAndCorners) {
  constexpr float kRho = 0.5f, kLe = 1.0f;
  Material m;
  m.name = "furnace";
  m.albedo = glm::vec3(kRho);
  m.emission = glm::vec3(kLe);
  Scene scene;
  addBox(scene, {-1.0f, 0.0f, -1.0f}, {1.0f, 1.5f, 1.0f}, m);
  turnInside(scene);
  addBox(scene, {-0.5f, 0.0f, -0.3f}, {0.0f, 0.45f, 0.2f}, m);  // resting on the floor
  addBox(scene, {0.3f, 0.0f, -1.0f}, {0.8f, 0.9f, -0.6f}, m);   // against the back wall
  Camera camera;
  camera.name = "corner";
  camera.yfov = 1.3f;
  camera.cameraToWorld = glm::inverse(
      glm::lookAt(glm::vec3(0.85f, 1.35f, 0.85f), glm::vec3(-0.3f, 0.1f, -0.5f), {0, 1, 0}));

  // bounce-bake's defaults but a 2.5% target error per texel (at the default 10% the noise alone
  // reaches 12% at some pixels after denoising) and 4096 texels (7.6 cm) to keep it CI-sized.
  SceneBakeSettings settings = lightmapOnlySettings();
  settings.targetError = 0.025f;
  settings.spp = 16384;
  settings.texelBudget = 4096;
  const Bake baked = bakeScene(scene, settings).folder;
  testContext();
  constexpr int kSize = 64;
  const Image frame = renderIndirect(scene, baked, camera, kSize, kSize);
  const double exact = kLe * kRho * kRho / (1.0 - kRho);
  int over3 = 0, over1 = 0;
  double worst = 0.0, sum = 0.0, bias = 0.0;
  int wx = 0, wy = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double l = frame.pixels[static_cast<std::size_t>(y) * kSize + x].g;
      const double e = std::abs(l - exact) / exact;
      sum += e;
      bias += (l - exact) / exact;
      over3 += e > 0.03 ? 1 : 0;
      over1 += e > 0.01 ? 1 : 0;
      if (e > worst) worst = e, wx = x, wy = y;
    }
  std::printf(
      "furnace %dx%d atlas, texel %.4f m: bias %+.4f, mean |rel| %.4f, worst %.4f at (%d, %d) "
      "(L = %.4f, exact %.4f), pixels over 1%%: %d, over 3%%: %d of %d; texel error mean %.4f\n",
      baked.layout.width, baked.layout.height, baked.layout.texelSize, bias / (kSize * kSize),
      sum / (kSize * kSize), worst, wx, wy,
      frame.pixels[static_cast<std::size_t>(wy) * kSize + wx].g, exact, over1, over3, kSize * kSize,
      baked.manifest.estimatedError.mean);
  // What is left is the bake's noise, the same everywhere: mean |rel| 0.5% and 13 of 65,536
  // pixels over 3% (worst 3.8%) at 256². A texel whose sample points lie in or behind the
  // neighbouring surface is off by far more (−17% at corners was reported against the bake
  // before this test existed).
  EXPECT_LE(worst, 0.05) << "at (" << wx << ", " << wy << ")";
  EXPECT_LE(std::abs(bias) / (kSize * kSize), 0.01);
}

}  // namespace
}  // namespace bounce::test
