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

constexpr float kRho = 0.5f, kLe = 1.0f;

// The furnace room seen from a high corner: every surface ρ = 0.5, Le = 1 W/(sr·m²).
struct Furnace {
  Scene scene;
  Camera camera;
};
Furnace furnace() {
  Furnace f;
  Scene& scene = f.scene;
  Camera& camera = f.camera;
  Material m;
  m.name = "furnace";
  m.albedo = glm::vec3(kRho);
  m.emission = glm::vec3(kLe);
  addBox(scene, {-1.0f, 0.0f, -1.0f}, {1.0f, 1.5f, 1.0f}, m);
  turnInside(scene);
  addBox(scene, {-0.5f, 0.0f, -0.3f}, {0.0f, 0.45f, 0.2f}, m);  // resting on the floor
  addBox(scene, {0.3f, 0.0f, -1.0f}, {0.8f, 0.9f, -0.6f}, m);   // against the back wall
  camera.name = "corner";
  camera.yfov = 1.3f;
  camera.cameraToWorld = glm::inverse(
      glm::lookAt(glm::vec3(0.85f, 1.35f, 0.85f), glm::vec3(-0.3f, 0.1f, -0.5f), {0, 1, 0}));

  return f;
}

// The rendered indirect frame's relative error against Le·ρ²/(1 − ρ), W/(sr·m²).
struct FrameError {
  double worst = 0.0, mean = 0.0, bias = 0.0;
  int worstX = 0, worstY = 0, over3 = 0, over1 = 0;
};
FrameError frameError(const Image& frame) {
  const double exact = kLe * kRho * kRho / (1.0 - kRho);
  FrameError f;
  const std::size_t n = frame.pixels.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double e = (frame.pixels[i].g - exact) / exact;
    f.mean += std::abs(e) / static_cast<double>(n);
    f.bias += e / static_cast<double>(n);
    f.over3 += std::abs(e) > 0.03 ? 1 : 0;
    f.over1 += std::abs(e) > 0.01 ? 1 : 0;
    if (std::abs(e) > f.worst) {
      f.worst = std::abs(e);
      f.worstX = static_cast<int>(i % static_cast<std::size_t>(frame.width));
      f.worstY = static_cast<int>(i / static_cast<std::size_t>(frame.width));
    }
  }
  return f;
}

TEST(FurnaceFrame, IndirectLightIsUniformAtEdgesAndCorners) {
#ifdef __SANITIZE_ADDRESS__
  // About 27 s under AddressSanitizer, most of it the path tracer's reference or the bake's
  // samples; the same code runs under ASan in the smaller tests. CI's sanitizer stage keeps to
  // its 30 minutes.
  GTEST_SKIP() << "an accuracy measurement: run in the release build";
#endif
  const auto [scene, camera] = furnace();
  // bounce-bake's defaults but a 2.5% target error per texel (at the default 10% the noise alone
  // reached 12% at some pixels after denoising before issue 15) and 4096 texels (7.6 cm) to keep it
  // CI-sized.
  SceneBakeSettings settings = lightmapOnlySettings();
  settings.targetError = 0.025f;
  settings.maxSpp = 16384;
  settings.texelBudget = 4096;
  const Bake baked = bakeScene(scene, settings).folder;
  testContext();
  constexpr int kSize = 64;
  const Image frame = renderIndirect(scene, baked, camera, kSize, kSize);
  const FrameError e = frameError(frame);
  std::printf(
      "furnace %dx%d atlas, texel %.4f m: bias %+.4f, mean |rel| %.4f, worst %.4f at (%d, %d), "
      "pixels over 1%%: %d, over 3%%: %d of %d; texel error mean %.4f\n",
      baked.layout.width, baked.layout.height, baked.layout.texelSize, e.bias, e.mean, e.worst,
      e.worstX, e.worstY, e.over1, e.over3, kSize * kSize, baked.manifest.estimatedError.mean);
  // What is left is the bake's noise, the same everywhere: mean |rel| 0.5% and 13 of 65,536
  // pixels over 3% (worst 3.8%) at 256². A texel whose sample points lie in or behind the
  // neighbouring surface is off by far more (−17% at corners was reported against the bake
  // before this test existed).
  EXPECT_LE(e.worst, 0.05) << "at (" << e.worstX << ", " << e.worstY << ")";
  EXPECT_LE(std::abs(e.bias), 0.01);
}

// Issue 15: the default bake (10% target error per texel) must put every pixel of the furnace
// within 3% of the exact value, at CI size (4096 texels, 7.6 cm). 3% is the bound. The
// noise at this size: texels carry 6.7% estimated relative error before the denoiser (≈ 300 spp);
// after it the pixels' mean |rel| is 0.3% and the worst of 4096 2.5% (this seed; others not
// measured), and the test fails with the old filter (worst 6.0%) or the old stop from 32
// samples (bias −1.7%, worst 5.0%).
TEST(FurnaceFrame, DefaultBakeIsWithinThreePercentEverywhere) {
#ifdef __SANITIZE_ADDRESS__
  // About 7.0 s under AddressSanitizer, most of it the bake's samples; the same code runs under
  // ASan in the smaller tests. CI's whole run keeps to its 25 minutes.
  GTEST_SKIP() << "an accuracy measurement: run in the release build";
#endif
  const auto [scene, camera] = furnace();
  SceneBakeSettings settings = lightmapOnlySettings();
  settings.texelBudget = 4096;
  const Bake baked = bakeScene(scene, settings).folder;
  testContext();
  constexpr int kSize = 64;
  const Image frame = renderIndirect(scene, baked, camera, kSize, kSize);
  const FrameError e = frameError(frame);
  std::printf(
      "default furnace %dx%d atlas, texel %.4f m: bias %+.4f, mean |rel| %.4f, worst %.4f at "
      "(%d, %d), pixels over 1%%: %d, over 3%%: %d of %d; texel error mean %.4f; %.1f spp, "
      "irradiance %.2f s\n",
      baked.layout.width, baked.layout.height, baked.layout.texelSize, e.bias, e.mean, e.worst,
      e.worstX, e.worstY, e.over1, e.over3, kSize * kSize, baked.manifest.estimatedError.mean,
      baked.manifest.samples.perTexelMean, baked.manifest.measured.seconds.irradiance);
  EXPECT_LE(e.worst, 0.03) << "at (" << e.worstX << ", " << e.worstY << ")";
  EXPECT_LE(std::abs(e.bias), 0.01);
}

}  // namespace
}  // namespace bounce::test
