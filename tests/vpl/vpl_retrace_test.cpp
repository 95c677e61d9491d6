// VPLs traced again with the dynamic instances where they are (vpl/vpl_retrace.h).
//  - Nothing dynamic moved: the re-trace with the bake's count rule (read from its bake.json) is
//    the bake's own VPL set, bit for bit (the corpus bake: a floor, a wall, an emissive panel,
//    a point light).
//  - A dynamic square placed under a point light: the bounce-1 VPLs on it carry ρ·I·Ω (W per
//    channel), Ω the solid angle it subtends from the light, a closed form, at each of two
//    placements; and no bounce-1 VPL lies on the floor inside its shadow. Tolerance: 4 standard
//    errors of a binomial count (a path's first hit is the square with probability p = Ω/4π;
//    the stratified sampler only lowers the variance).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "bake_folder/bake_folder.h"
#include "scene/load.h"
#include "trace/sampling.h"
#include "trace/test_scenes.h"
#include "vpl/vpl_retrace.h"

namespace bounce {
namespace {

TEST(VplRetrace, WithNothingMovedItIsTheBakesVplSetBitForBit) {
  const std::filesystem::path dir = std::filesystem::path(BOUNCE_SOURCE_DIR) / "tests/corpus/bake";
  const Scene scene = loadScene(dir / "scene.gltf");
  const Bake bake = readBake(dir / "valid.bake", scene);
  ASSERT_TRUE(bake.vpls.has_value());
  ASSERT_FALSE(bake.vpls->empty());
  std::vector<glm::mat4> transforms;
  for (const Instance& instance : scene.instances) transforms.push_back(instance.transform);
  PlacedVplTracer tracer(scene, vplSettingsOfBake(bake.manifest, bake.vpls->size()));
  const std::vector<Vpl> again = tracer.trace(transforms);
  ASSERT_EQ(again.size(), bake.vpls->size());
  for (std::size_t i = 0; i < again.size(); ++i) {
    const Vpl &a = again[i], &b = (*bake.vpls)[i];
    EXPECT_EQ(a.position, b.position) << i;
    EXPECT_EQ(a.normal, b.normal) << i;
    EXPECT_EQ(a.flux, b.flux) << i;
    EXPECT_EQ(a.from, b.from) << i;
    EXPECT_EQ(a.path, b.path) << i;
  }
}

TEST(VplRetrace, ReadsTheCountRuleFromTheManifest) {
  BakeManifest manifest;
  manifest.settings.seed = 7;
  manifest.vpls = BakeManifest::Vpls{.errorTarget = 0.05, .cap = 123};
  const VplSettings s = vplSettingsOfBake(manifest, 100);
  EXPECT_EQ(s.maxVpls, 123);
  EXPECT_FLOAT_EQ(s.relativeError, 0.05f);
  EXPECT_EQ(s.seed, 7u);
  const VplSettings none = vplSettingsOfBake(BakeManifest{}, 100000);
  EXPECT_EQ(none.maxVpls, VplSettings{}.maxVpls);
  EXPECT_EQ(none.seed, VplSettings{}.seed);
  // A tampered cap: held to about the bake's count.
  manifest.vpls = BakeManifest::Vpls{.errorTarget = 1e-30, .cap = 4000000000};
  const VplSettings huge = vplSettingsOfBake(manifest, 16);
  EXPECT_EQ(huge.maxVpls, 2 * 16 + kVplBatch);
}

// Solid angle of an a × a square seen from a point on its axis at distance d.
double squareSolidAngle(double a, double d) {
  return 4.0 * std::asin(a * a / (a * a + 4.0 * d * d));
}

TEST(VplRetrace, APlacedSquareHoldsTheLightItInterceptsAndShadowsTheFloor) {
  constexpr double kSide = 0.4;                    // m
  const glm::vec3 lightAt(0.0f, 1.0f, 0.0f);       // m
  const glm::vec3 intensity(3.0f, 2.0f, 1.0f);     // W/sr, unequal channels
  const glm::vec3 squareAlbedo(0.8f, 0.5f, 0.3f);  // unequal channels
  Scene scene;
  const uint32_t floor = test::addMaterial(scene, glm::vec3(0.5f));
  const uint32_t square = test::addMaterial(scene, squareAlbedo);
  constexpr float kFloor = 20.0f;
  test::addQuad(scene, {-kFloor, 0, -kFloor}, {-kFloor, 0, kFloor}, {kFloor, 0, kFloor},
                {kFloor, 0, -kFloor}, floor);
  const float h = static_cast<float>(kSide / 2);
  test::addQuad(scene, {-h, 0, -h}, {-h, 0, h}, {h, 0, h}, {h, 0, -h}, square);  // faces +y
  scene.instances.back().mobility = Mobility::Dynamic;
  scene.instances.back().transform = glm::translate(glm::mat4(1.0f), {5.0f, 0.5f, 0.0f});
  Light light;
  light.type = LightType::Point;
  light.position = lightAt;
  light.intensity = intensity;
  scene.lights.push_back(light);

  constexpr int kPaths = 16384;
  VplSettings settings;
  settings.maxVpls = 1 << 22;
  settings.minPaths = kPaths;
  settings.relativeError = 1.0f;  // stop at minPaths
  settings.seed = 3;
  PlacedVplTracer tracer(scene, settings);
  for (const double below : {0.3, 0.6}) {  // m under the light
    std::vector<glm::mat4> transforms;
    for (const Instance& instance : scene.instances) transforms.push_back(instance.transform);
    transforms.back() =
        glm::translate(glm::mat4(1.0f), lightAt - glm::vec3(0.0f, static_cast<float>(below), 0));
    const std::vector<Vpl> vpls = tracer.trace(transforms);

    glm::dvec3 onSquare(0.0);
    std::size_t inShadow = 0, onFloor = 0;
    const double shadowHalf = 0.5 * kSide / below;  // on the floor, 1 m under the light
    for (const Vpl& vpl : vpls) {
      if (vpl.from != lightAt) continue;  // bounce 1: the segment starts at the light
      if (std::abs(vpl.position.y - (lightAt.y - below)) < 1e-4)
        onSquare += glm::dvec3(vpl.flux);
      else if (std::abs(vpl.position.y) < 1e-4) {
        ++onFloor;
        if (std::abs(vpl.position.x) < 0.98 * shadowHalf &&
            std::abs(vpl.position.z) < 0.98 * shadowHalf)
          ++inShadow;
      }
    }
    const double omega = squareSolidAngle(kSide, below);
    const double p = omega / (4.0 * kPi);
    const double relativeSigma = std::sqrt(p * (1.0 - p) / kPaths) / p;
    for (int c = 0; c < 3; ++c) {
      const double expected = static_cast<double>(squareAlbedo[c] * intensity[c]) * omega;
      EXPECT_NEAR(onSquare[c], expected, 4.0 * relativeSigma * expected)
          << "square " << below << " m under the light, channel " << c;
    }
    EXPECT_GT(onFloor, static_cast<std::size_t>(kPaths / 4));
    EXPECT_EQ(inShadow, 0u) << "bounce-1 VPLs in the square's shadow, " << below << " m";
    std::printf(
        "square %.1f m under the light: Omega %.4f sr, bounce-1 flux on it %.4f W "
        "(green; closed form %.4f, 4 sigma %.1f%%), %zu floor VPLs, %zu in its shadow\n",
        below, omega, onSquare.g, squareAlbedo.g * intensity.g * omega, 400.0 * relativeSigma,
        onFloor, inShadow);
  }
}

}  // namespace
}  // namespace bounce
