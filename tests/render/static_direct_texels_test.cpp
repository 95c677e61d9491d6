// GL-free: the static area lights' irradiance vectors per lightmap texel
// (render/static_direct_texels.h) on a floor whose region fills the middle of a 32² atlas, under an
// off-centre panel of unequal RGB radiance, every texel's visibility V = 0.4 for it. A covered
// texel holds V·F_c with n·F_c the exact irradiance (Lambert's formula written apart,
// support/polygon_form_factor.h) at the floor point its centre maps to; a texel within one texel
// of the region holds the same at the region's nearest point (what a bilinear tap reads); one
// further out holds nothing.
#include "render/static_direct_texels.h"

#include <gtest/gtest.h>

#include <numbers>

#include "lightmap_scenes.h"
#include "scene/area_lights.h"
#include "scene/light_falloff.h"
#include "support/polygon_form_factor.h"

namespace bounce::test {
namespace {

constexpr int kSize = 32;
constexpr float kV = 0.4f;

Scene floorUnderOffCentrePanel() {
  return floorUnderPanel({0.1f, 0.5f, -0.4f}, {0.3f, 0, 0}, {0, 0, 0.2f});
}

// The floor's point (x, 0, z) at atlas texel coordinates s (texels): u = ¼ + ½(x + ½), likewise
// v with z, so the floor covers texels [8, 24) both ways.
glm::vec3 floorPoint(glm::vec2 s) {
  const glm::vec2 uv = s / static_cast<float>(kSize);
  return {(uv.x - 0.25f) / 0.5f - 0.5f, 0.0f, (uv.y - 0.25f) / 0.5f - 0.5f};
}

glm::vec3 exactIrradiance(const Scene& scene, glm::vec3 p) {
  const Mesh& panel = scene.meshes[1];
  std::vector<glm::dvec3> polygon;
  for (const glm::vec3& v : panel.positions) polygon.emplace_back(v);
  const double f = std::abs(polygonFormFactor(polygon, glm::dvec3(p), glm::dvec3(0, 1, 0)));
  return scene.materials[1].emission * static_cast<float>(std::numbers::pi * f);
}

TEST(StaticDirectTexels, EachTexelHoldsVTimesTheExactIrradianceVectorOfItsNearestPoint) {
  const Scene scene = floorUnderOffCentrePanel();
  LightmapLayout layout;
  layout.width = layout.height = kSize;
  InstanceLightmapUv region{0, {}};
  const Mesh& floor = scene.meshes[0];
  for (uint32_t index : floor.indices)
    region.cornerUv.push_back(
        0.25f + 0.5f * glm::vec2(floor.positions[index].x + 0.5f, floor.positions[index].z + 0.5f));
  layout.instances = {region};
  BakedVisibility visibility;
  visibility.width = visibility.height = kSize;
  visibility.lightCount = 1;
  TexelVisibility record;
  record.light[0] = 0;
  record.visible[0] = kV;
  visibility.texels.assign(kSize * kSize, record);
  const AreaLightSet lights = sceneAreaLights(scene);
  ASSERT_EQ(lights.lights.size(), 1u);

  const std::vector<glm::vec3> f =
      staticDirectTexels(scene, layout, visibility, PrecomputedLights{&lights, 1, {}, {}});
  ASSERT_EQ(f.size(), 3u * kSize * kSize);
  int covered = 0, ring = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::size_t t = static_cast<std::size_t>(y * kSize + x);
      // n = +y: E_c = F_c.y.
      const glm::vec3 e(f[t].y, f[kSize * kSize + t].y, f[2 * kSize * kSize + t].y);
      const glm::vec2 centre(x + 0.5f, y + 0.5f);
      const glm::vec2 nearest = glm::clamp(centre, glm::vec2(8.0f), glm::vec2(24.0f));
      const glm::vec2 off = glm::abs(centre - nearest);
      if (std::max(off.x, off.y) >= 1.0f) {
        EXPECT_EQ(e, glm::vec3(0.0f)) << "texel " << x << "," << y << " is beyond every tap";
        continue;
      }
      const glm::vec3 expected = kV * exactIrradiance(scene, floorPoint(nearest));
      ASSERT_GT(expected.b, 0.0f);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(e[c], expected[c], 1e-4f * expected[c]) << "texel " << x << "," << y;
      covered += off == glm::vec2(0.0f);
      ring += off != glm::vec2(0.0f);
    }
  EXPECT_EQ(covered, 16 * 16);
  EXPECT_EQ(ring, 18 * 18 - 16 * 16);
}

// A spot over the same floor (no area light) whose visibility index follows 2 area lights: the
// texels hold V·F_c of the precomputed spot, n·F_c = I·falloff·cosθ/r² (light_falloff.h, the
// shader's), its V read at index 2 + 0; a second spot not precomputed is left out. Injected: the
// index without the area lights' offset (reads the V = 0.9 slot): fails.
TEST(StaticDirectTexels, APrecomputedSpotHoldsVTimesItsIrradianceAtItsOwnIndex) {
  Scene scene = floorUnderOffCentrePanel();
  scene.meshes.pop_back();  // the panel: no area light
  scene.instances.pop_back();
  Light spot;
  spot.type = LightType::Spot;
  spot.position = {0.1f, 0.6f, -0.05f};
  spot.direction = glm::normalize(glm::vec3(-0.2f, -1.0f, 0.1f));
  spot.innerConeAngle = 0.3f;
  spot.outerConeAngle = 0.7f;
  spot.intensity = {2.0f, 1.0f, 0.5f};
  Light other = spot;
  other.position = {-0.3f, 0.4f, 0.2f};
  scene.lights = {spot, other};
  LightmapLayout layout;
  layout.width = layout.height = kSize;
  InstanceLightmapUv region{0, {}};
  for (uint32_t index : scene.meshes[0].indices)
    region.cornerUv.push_back(0.25f + 0.5f * glm::vec2(scene.meshes[0].positions[index].x + 0.5f,
                                                       scene.meshes[0].positions[index].z + 0.5f));
  layout.instances = {region};
  BakedVisibility visibility;
  visibility.width = visibility.height = kSize;
  visibility.lightCount = 2;
  visibility.punctualCount = 2;
  TexelVisibility record;
  record.light = {0, 2, kNoLight, kNoLight};
  record.visible = {0.9f, kV, 1.0f, 1.0f};
  visibility.texels.assign(kSize * kSize, record);
  const std::vector<uint8_t> precomputed{1, 0};
  const std::vector<glm::vec3> f = staticDirectTexels(
      scene, layout, visibility, PrecomputedLights{nullptr, 0, scene.lights, precomputed});
  int lit = 0;
  for (int y = 8; y < 24; ++y)
    for (int x = 8; x < 24; ++x) {
      const std::size_t t = static_cast<std::size_t>(y * kSize + x);
      const glm::vec3 p = floorPoint(glm::vec2(x + 0.5f, y + 0.5f));
      const glm::vec3 toLight = spot.position - p;
      const float r2 = glm::dot(toLight, toLight);
      const glm::vec3 l = toLight / std::sqrt(r2);
      const glm::vec3 expected =
          kV * spot.intensity * spotFalloff(spot, glm::dot(-l, spot.direction)) * l.y / r2;
      const glm::vec3 e(f[t].y, f[kSize * kSize + t].y, f[2 * kSize * kSize + t].y);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(e[c], expected[c], 1e-4f * expected[c] + 1e-7f) << "texel " << x << "," << y;
      lit += expected.b > 0.0f;
    }
  EXPECT_GT(lit, 50);       // inside the cone
  EXPECT_LT(lit, 16 * 16);  // and outside it: the falloff matters
}

}  // namespace
}  // namespace bounce::test
