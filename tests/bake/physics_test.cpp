// The baked irradiance against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "bake_scenes.h"
#include "trace/sampling.h"

namespace bounce {
namespace {

// The closed furnace (bake_scenes.h): E = π(L − Le) = π·Le·ρ/(1 − ρ) at every point.
TEST(BakePhysics, FurnaceIndirectIrradianceIsExact) {
  const test::ClosedFurnace furnace(0.5f, 1.0f);
  const test::World& world = furnace.world;
  const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.125f, 40);
  const LightmapBake bake = bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout,
                                         test::testBakeSettings(64));
  const double exact = furnace.exactIndirectIrradiance();
  double sum = 0, variance = 0;
  int n = 0, outliers = 0;
  for (std::size_t t = 0; t < bake.covered.size(); ++t) {
    if (!bake.covered[t]) continue;
    ASSERT_FALSE(bake.invalid[t]);
    const double e = luminance(bake.irradiance.pixels[t]);
    const double se = bake.relativeError[t] * e;
    sum += e;
    variance += se * se;
    ++n;
    if (std::abs(e - exact) > 5.0 * se) ++outliers;
  }
  ASSERT_EQ(n, 6 * 64);
  const double mean = sum / n, standardError = std::sqrt(variance) / n;
  EXPECT_NEAR(mean, exact, 5.0 * standardError) << "standard error " << standardError;
  EXPECT_LE(outliers, n / 100);
  EXPECT_EQ(bake.nonFiniteSamples, 0u);
}

// The furnace above with every face's albedo a base-colour texture: 256 × 256 texels in stripes,
// every 4th column colour b and the others a (a factor f multiplies it), sampled bilinearly at
// each path vertex's uv0. Each point sees the other faces' stripes through a kernel that varies
// slowly on their period (1.6 cm against ≥ 12.5 cm from the texel's points to the nearest edge),
// so the light it gets is that of the area mean ρ̄ = f·(3a + b)/4, a filtered colour no texel has:
// E = π·Le·ρ̄/(1 − ρ̄) per channel, as in the untextured furnace. Only texels at least a texel away
// from every edge are compared. The bias of that approximation is second order in cell/distance
// (< 0.1%), far under the statistical tolerance. Ignoring the texture (ρ = f), or reading it at
// each triangle's first corner (uv (0, 0) blends a and b half and half), misses by 10% or more.
TEST(BakePhysics, TexturedFurnaceBouncesTheTexturesMeanColour) {
  const float le = 1.0f;
  const glm::vec3 a(0.9f, 0.1f, 0.6f), b(0.1f, 0.5f, 0.2f), factor(0.9f);
  test::World world;
  test::addInwardTexturedBox(world.scene, glm::vec3(0.0f), glm::vec3(1.0f),
                             test::addMaterial(world.scene, factor, glm::vec3(le)),
                             test::stripedTexture(a, b));
  world.build();
  const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.125f, 40);
  const LightmapBake bake = bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout,
                                         test::testBakeSettings(128));
  const glm::dvec3 rho = glm::dvec3(factor) * glm::dvec3(3.0f * a + b) * 0.25;
  const glm::dvec3 exact = kPi * static_cast<double>(le) * rho / (1.0 - rho);
  glm::dvec3 sum(0.0), sum2(0.0);
  int n = 0;
  for (int y = 0; y < atlas.layout.height; ++y)
    for (int x = 0; x < atlas.layout.width; ++x) {
      glm::vec3 p;
      uint32_t instance;
      const std::size_t t = bake.irradiance.index(x, y);
      if (!bake.covered[t] || !atlas.texelCentre(x, y, p, instance)) continue;
      int inside = 0;  // coordinates at least a texel from the face's edges
      for (int k = 0; k < 3; ++k) inside += p[k] > 0.125f && p[k] < 0.875f ? 1 : 0;
      if (inside < 2) continue;
      const glm::dvec3 e(bake.irradiance.pixels[t]);
      sum += e;
      sum2 += e * e;
      ++n;
    }
  ASSERT_EQ(n, 6 * 36);
  const glm::dvec3 mean = sum / static_cast<double>(n);
  // The texels are independent estimates of one value: their spread gives the mean's error.
  const glm::dvec3 standardError = glm::sqrt(
      glm::max(sum2 / static_cast<double>(n) - mean * mean, 0.0) / static_cast<double>(n - 1));
  std::printf(
      "textured furnace, %d texels: E = (%.4f, %.4f, %.4f), exact (%.4f, %.4f, %.4f), "
      "standard error (%.4f, %.4f, %.4f) W/m²\n",
      n, mean.x, mean.y, mean.z, exact.x, exact.y, exact.z, standardError.x, standardError.y,
      standardError.z);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(mean[c], exact[c], 5.0 * standardError[c] + 1e-3 * exact[c])
        << "channel " << c << ", standard error " << standardError[c];
}

// A point light of intensity I at height h over a black-free plane (nothing else in the
// scene): no light reflects back, so the default (indirect) lightmap is exactly 0; marked
// baked-only (Light::bakeDirect) its direct light E = I·h/(h² + r²)^{3/2} is baked.
TEST(BakePhysics, BakedOnlyLightHasItsDirectLightBaked) {
  for (const bool bakeDirect : {false, true}) {
    test::World world;
    const uint32_t m = test::addMaterial(world.scene, glm::vec3(0.5f));
    test::addQuad(world.scene, {-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, m);
    Light light;
    light.type = LightType::Point;
    light.position = {0, 1, 0};
    light.intensity = glm::vec3(2.0f, 1.0f, 0.5f);
    light.bakeDirect = bakeDirect;
    world.scene.lights.push_back(light);
    world.build();
    const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.05f, 48);
    LightmapBakeSettings settings = test::testBakeSettings(32);
    settings.pointsPerTexel = 32;  // 32 samples: each point exactly once (stratified pick)
    const LightmapBake bake =
        bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, settings);
    int checked = 0;
    for (int y = 0; y < atlas.layout.height; ++y) {
      for (int x = 0; x < atlas.layout.width; ++x) {
        const std::size_t t = bake.irradiance.index(x, y);
        glm::vec3 p;
        uint32_t instance;
        if (!bake.covered[t] || !atlas.texelCentre(x, y, p, instance)) continue;
        const glm::vec3 e = bake.irradiance.pixels[t];
        if (!bakeDirect) {
          EXPECT_EQ(e, glm::vec3(0.0f));
        } else {
          // The texel holds E's mean over its area (32 points): against the closed form's
          // mean over the 5 cm square (64×64 midpoint rule); E varies ≤ 8% across a texel and
          // 32 low-discrepancy points average that to ≲ 0.2%.
          double mean = 0;
          for (int i = 0; i < 64; ++i) {
            for (int j = 0; j < 64; ++j) {
              const double qx = p.x + 0.05 * ((i + 0.5) / 64 - 0.5);
              const double qz = p.z + 0.05 * ((j + 0.5) / 64 - 0.5);
              mean += 1.0 / std::pow(1.0 + qx * qx + qz * qz, 1.5) / (64 * 64);
            }
          }
          const glm::vec3 exact = light.intensity * static_cast<float>(mean);
          EXPECT_NEAR(e.r, exact.r, 2e-3f * exact.r) << p.x << "," << p.z;
          EXPECT_NEAR(e.b, exact.b, 2e-3f * exact.b);
        }
        ++checked;
      }
    }
    EXPECT_EQ(checked, 40 * 40);
  }
}

// An emissive quad whose material is marked bakeDirect (extras.bounce.bake = "all") has its
// direct light in the map: E at a floor texel against the point-to-rectangle integral
// L·∫ cosθ_x cosθ_y / r² dA (midpoint rule); unmarked, the map holds only reflected light, and
// here there is none (the emitter is black, the floor sees nothing else).
TEST(BakePhysics, BakedOnlyEmitterHasItsDirectLightBaked) {
  for (const bool bakeDirect : {false, true}) {
    test::World world;
    const uint32_t floor = test::addMaterial(world.scene, glm::vec3(0.5f));
    test::addQuad(world.scene, {-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, floor);
    const glm::vec3 le(3.0f, 2.0f, 1.0f);
    const uint32_t lamp = test::addMaterial(world.scene, glm::vec3(0.0f), le);
    world.scene.materials[lamp].bakeDirect = bakeDirect;
    // 0.4 m square at y = 0.8 m facing down (its corners clockwise seen from below).
    test::addQuad(world.scene, {-0.2f, 0.8f, -0.2f}, {0.2f, 0.8f, -0.2f}, {0.2f, 0.8f, 0.2f},
                  {-0.2f, 0.8f, 0.2f}, lamp);
    world.build();
    const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.1f, 48);
    LightmapBakeSettings settings = test::testBakeSettings(256);
    const LightmapBake bake =
        bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, settings);
    int checked = 0;
    for (int y = 0; y < atlas.layout.height; ++y)
      for (int x = 0; x < atlas.layout.width; ++x) {
        const std::size_t t = bake.irradiance.index(x, y);
        glm::vec3 p;
        uint32_t instance;
        if (!bake.covered[t] || !atlas.texelCentre(x, y, p, instance) || instance != 0) continue;
        const glm::vec3 e = bake.irradiance.pixels[t];
        if (!bakeDirect) {
          EXPECT_EQ(e, glm::vec3(0.0f));
        } else {
          double exact = 0.0;  // sr: ∫ cosθ_x cosθ_y / r² dA over the light (cos = 0.8 / r)
          const int n = 100;
          for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
              const double qx = -0.2 + 0.4 * (i + 0.5) / n - p.x,
                           qz = -0.2 + 0.4 * (j + 0.5) / n - p.z;
              const double r2 = qx * qx + qz * qz + 0.64;
              exact += 0.64 / (r2 * r2) * (0.16 / (n * n));
            }
          // The texel's mean over its 10 cm square against the value at its centre (E is smooth
          // at 0.8 m: its curvature moves the mean ≲ 1%) and 4 of the texel's standard errors.
          const double tolerance = 0.01 * exact * le.r + 4.0 * bake.relativeError[t] * e.r;
          EXPECT_NEAR(e.r, le.r * exact, tolerance) << p.x << "," << p.z;
          EXPECT_NEAR(e.b / e.r, le.b / le.r, 1e-3);
        }
        ++checked;
      }
    EXPECT_EQ(checked, 20 * 20);
  }
}

}  // namespace
}  // namespace bounce
