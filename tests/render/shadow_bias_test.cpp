// The shadow bias of shaders/shadow_common.glsl, term by term, each where it matters
// (docs/shadows.md, "Bias"): R = filter radius in texels, w = texel edge (m), θ = incidence.
//   1. The normal offset o = (R + 1.5)·w·sinθ vanishes at normal incidence: a slab one texel
//      thick on the floor under a light straight above keeps its shadow. A constant offset, or a
//      depth bias of a texel, lifts the lookup above the slab and light leaks under it.
//   2. The Poisson taps lie within R texels (the kernel is in the unit circle), so R + 1.5 covers
//      every texel a lookup reads: a plane at grazing incidence under a wide kernel has no acne.
//   3. Concave receivers: a 32-sided half-pipe under a sun up to 85° from its wall's normal has
//      no acne; it needs the constant quarter texel of depth bias (beyond a crease the next
//      facet rises towards the light above this facet's plane).
// Visibility is analytic: 1 on unoccluded surfaces, the slab's footprint seen from the light.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "render/shadow_map_geometry.h"
#include "shadow_scenes.h"

namespace bounce::test {
namespace {

constexpr float kPi = 3.14159265358979f;

// V_map per pixel: the frame with shadows over the frame without (one light), −1 where the
// light does not reach the surface unshadowed (below 1e-3 of the brightest pixel).
std::vector<float> mappedVisibility(const Scene& scene, const Camera& camera, int size,
                                    const ShadowSettings& shadows) {
  const Image with = renderWith(scene, camera, size, size, shadows);
  ShadowSettings off;
  off.enabled = false;
  const Image without = renderWith(scene, camera, size, size, off);
  float brightest = 0.0f;
  for (const glm::vec3& p : without.pixels) brightest = std::max(brightest, sum(p));
  std::vector<float> v(with.pixels.size(), -1.0f);
  for (std::size_t i = 0; i < v.size(); ++i)
    if (sum(without.pixels[i]) > 1e-3f * brightest)
      v[i] = sum(with.pixels[i]) / sum(without.pixels[i]);
  return v;
}

ShadowSettings withFilter(ShadowFilter filter, float radius = 1.5f) {
  ShadowSettings settings;
  settings.filter = filter;
  settings.filterRadius = radius;
  return settings;
}

// ---- 1. A one-texel slab at normal incidence keeps its shadow --------------------------------

struct SlabCase {
  const char* name;
  LightType type;
  ShadowFilter filter;
};

class ThinSlab : public testing::TestWithParam<SlabCase> {};

// A 40×40 cm slab one shadow texel thick (w at its edge under the default map: 1.0 mm for the
// spot, 2.3 mm for the point light's cube) on a 2 m floor; the light 1.2 m straight above the
// slab's +x edge (x = 0.2 m), so the floor around it is lit at θ < 1°. The map cannot tell the
// slab from its top and sides alone, which is what is drawn, wound inwards: the camera (looking
// down at the edge, 0.23 mm pixels) sees through them to the floor under the slab, which the
// slab hides from the light. The true visibility is the slab's top seen from the light; pixels
// within one texel plus one pixel of its edge are left out (the map's edge lies within a texel).
// Every other pixel must agree (|V_map − V| ≤ ½): under the slab dark, beyond it lit.
TEST_P(ThinSlab, OneTexelSlabKeepsItsShadowAtNormalIncidence) {
  const glm::vec3 edge(0.2f, 0.0f, 0.0f);
  const glm::vec3 position = edge + glm::vec3(0.0f, 1.2f, 0.0f);
  const bool point = GetParam().type == LightType::Point;
  const Light light = point ? pointAt(position, 3.0f) : spotAt(position, edge, 0.3f, 0.4f, 3.0f);
  const ShadowSettings shadows = withFilter(GetParam().filter);
  Box box;  // the floor decides the map's resolution; the slab is thin
  box.grow({-1.0f, 0.0f, -1.0f});
  box.grow({1.0f, 0.01f, 1.0f});
  const float texelAngle =
      point ? 2.0f / static_cast<float>(pointShadowResolutionFor(light.position, box, shadows))
            : spotShadowViewFor(light, box, shadows).texelAngle;
  const float texel = texelAngle * glm::length(light.position - edge);

  Scene scene;
  Material floor;
  floor.name = "floor";
  floor.albedo = glm::vec3(0.5f);
  addQuad(scene, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, floor);
  Material slab = floor;
  slab.name = "slab";
  const float half = 0.2f;
  addBox(scene, {-half, 0, -half}, {half, texel, half}, slab);
  Mesh& box6 = scene.meshes.back();
  box6.indices.resize(box6.indices.size() - 6);  // no bottom face (−y, the last)
  for (std::size_t t = 0; t < box6.indices.size(); t += 3)
    std::swap(box6.indices[t + 1], box6.indices[t + 2]);  // wound inwards
  for (glm::vec3& n : box6.normals) n = -n;
  scene.lights = {light};

  constexpr int kSize = 128;
  Camera camera = downCamera(0.25f, 2.0f * std::atan(0.015f / 0.25f));
  camera.cameraToWorld[3] = glm::vec4(0.2f, 0.25f, 0.0f, 1.0f);
  const std::vector<float> mapped = mappedVisibility(scene, camera, kSize, shadows);
  const float pixel = 2.0f * 0.015f / kSize;

  int under = 0, beyond = 0, wrong = 0;
  Image shown(kSize, kSize);  // V_map in grey, the edge band dark green, disagreements red
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const float v = mapped[static_cast<std::size_t>(y * kSize + x)];
      if (v < 0.0f) continue;
      const glm::vec3 p = floorPoint(camera, kSize, kSize, x, y);
      const glm::vec3 q = p + (light.position - p) * (texel / light.position.y);  // on the top
      const float outside = std::max(std::abs(q.x), std::abs(q.z)) - half;  // < 0: in the shadow
      glm::vec3& shade = shown.at(x, y);
      shade = glm::vec3(v);
      if (std::abs(outside) < texel + pixel) {
        shade = {0.0f, 0.2f, 0.0f};
        continue;
      }
      const float truth = outside < 0.0f ? 0.0f : 1.0f;
      ++(outside < 0.0f ? under : beyond);
      if (std::abs(v - truth) > 0.5f) {
        ++wrong;
        shade = {1.0f, 0.0f, 0.0f};
      }
    }
  if (wrong > 0 || std::getenv("BOUNCE_SHADOW_MAPS"))
    writePng(std::filesystem::temp_directory_path() /
                 (std::string("bounce-thin-slab-") + GetParam().name + ".png"),
             shown, 0.0f);
  std::printf("%s: %d of %d pixels under the slab and %d beyond disagree; texel %.3f mm\n",
              GetParam().name, wrong, under, beyond, 1e3f * texel);
  ASSERT_GT(under, kSize * kSize / 4);
  ASSERT_GT(beyond, kSize * kSize / 4);
  EXPECT_EQ(wrong, 0);
}

INSTANTIATE_TEST_SUITE_P(
    Lights, ThinSlab,
    testing::Values(SlabCase{"spot_poisson", LightType::Spot, ShadowFilter::Poisson},
                    SlabCase{"spot_hardware", LightType::Spot, ShadowFilter::Hardware},
                    SlabCase{"point_poisson", LightType::Point, ShadowFilter::Poisson},
                    SlabCase{"point_hardware", LightType::Point, ShadowFilter::Hardware}),
    [](const testing::TestParamInfo<SlabCase>& param) { return std::string(param.param.name); });

// ---- 2. A wide Poisson kernel on a plane at grazing incidence -------------------------------

// Pixels of `mapped` darker than 99% (V must be 1 everywhere), and how many were considered.
std::pair<int, int> acnePixels(const std::vector<float>& mapped, float* darkest) {
  int lit = 0, dark = 0;
  *darkest = 1.0f;
  for (const float v : mapped) {
    if (v < 0.0f) continue;
    ++lit;
    *darkest = std::min(*darkest, v);
    if (v < 0.99f) ++dark;
  }
  return {dark, lit};
}

Light sunTowards(glm::vec3 l) {
  Light sun;
  sun.name = "sun";
  sun.type = LightType::Directional;
  sun.direction = -glm::normalize(l);
  sun.irradiance = glm::vec3(1.0f);
  return sun;
}

// The 20 m floor seen from 1 m straight above, lit at 80° incidence at the frame's centre (79°
// to 81° across it) by a spot, a point light and the sun, through a Poisson kernel of 6 texels.
TEST(WideKernel, GrazingPlaneHasNoAcne) {
  const float incidence = glm::radians(80.0f);
  const glm::vec3 position(-std::tan(incidence), 1.0f, 0.0f);
  for (const Light& light : {spotAt(position, {0, 0, 0}, 0.2f, 0.3f, 2.0f), pointAt(position, 2.0f),
                             sunTowards(position)}) {
    Scene scene;
    addFloor(scene, glm::vec3(0.5f));
    scene.lights = {light};
    float darkest = 1.0f;
    const auto [dark, lit] = acnePixels(
        mappedVisibility(scene, downCamera(1.0f), 96, withFilter(ShadowFilter::Poisson, 6.0f)),
        &darkest);
    std::printf("%s, R = 6: %d of %d pixels darker than 99%%, darkest %.4f\n", light.name.c_str(),
                dark, lit, darkest);
    EXPECT_GT(lit, 96 * 96 / 4);
    EXPECT_EQ(dark, 0) << light.name << ": darkest " << darkest;
  }
}

// ---- 3. A concave receiver: a half-pipe under a high sun ------------------------------------

// The lower half of a cylinder along z (radius rho, axis on y = 0, z within ±length/2) as
// `sides` flat facets, facing inwards.
void addHalfPipe(Scene& scene, float rho, float length, int sides, const Material& material) {
  Mesh mesh;
  mesh.name = material.name;
  for (int i = 0; i <= sides; ++i) {
    const float phi = kPi * (1.0f + static_cast<float>(i) / static_cast<float>(sides));
    const glm::vec3 r(std::cos(phi), std::sin(phi), 0.0f);
    for (const float z : {-0.5f * length, 0.5f * length}) {
      mesh.positions.push_back(rho * r + glm::vec3(0, 0, z));
      mesh.normals.push_back(-r);
    }
  }
  for (uint32_t i = 0; i < static_cast<uint32_t>(2 * sides); i += 2)
    for (const uint32_t k : {0u, 1u, 2u, 2u, 1u, 3u}) mesh.indices.push_back(i + k);
  addMesh(scene, std::move(mesh), material);
}

// A 1 m half-pipe with 32 facets (5.6° creases) under the sun 85° above the horizon: its +x wall
// is lit from 5° (bottom) to 85° (rim) of incidence and nothing shadows it (the −x rim's shadow
// ends at x = −0.985 m). Seen from above the −x rim, both filters.
TEST(ConcaveReceiver, HalfPipeUnderAHighSunHasNoAcne) {
  const float rho = 1.0f, elevation = glm::radians(85.0f);
  Scene scene;
  Material pipe;
  pipe.name = "pipe";
  pipe.albedo = glm::vec3(0.5f);
  addHalfPipe(scene, rho, 4.0f * rho, 32, pipe);
  scene.lights = {sunTowards({-std::cos(elevation), std::sin(elevation), 0.0f})};
  const Camera camera = lookingAt({-0.6f, 0.6f, 0.3f}, {0.8f, -0.4f, 0.0f}, 0.9f);
  constexpr int kSize = 128;
  for (const ShadowFilter filter : {ShadowFilter::Poisson, ShadowFilter::Hardware}) {
    std::vector<float> mapped = mappedVisibility(scene, camera, kSize, withFilter(filter));
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        // The wall the pixel sees: the far root of the ray with the cylinder x² + y² = rho².
        const glm::vec3 o = camera.position();
        const glm::vec3 d = glm::normalize(pixelRay(camera, kSize, kSize, x, y));
        const float a = d.x * d.x + d.y * d.y, b = o.x * d.x + o.y * d.y,
                    c = o.x * o.x + o.y * o.y - rho * rho;
        const glm::vec3 p = o + d * ((-b + std::sqrt(b * b - a * c)) / a);
        if (p.x < 0.0f || std::abs(p.z) > 1.8f * rho)
          mapped[static_cast<std::size_t>(y * kSize + x)] = -1.0f;
      }
    float darkest = 1.0f;
    const auto [dark, lit] = acnePixels(mapped, &darkest);
    const std::string name = filter == ShadowFilter::Poisson ? "poisson" : "hardware";
    std::printf("%s: %d of %d wall pixels darker than 99%%, darkest %.4f\n", name.c_str(), dark,
                lit, darkest);
    if (dark > 0 || std::getenv("BOUNCE_SHADOW_MAPS")) {
      Image shown(kSize, kSize);  // V_map in grey, below 99% red
      for (std::size_t i = 0; i < mapped.size(); ++i)
        shown.pixels[i] = mapped[i] < 0.99f && mapped[i] >= 0.0f
                              ? glm::vec3(1, 0, 0)
                              : glm::vec3(std::max(mapped[i], 0.0f));
      writePng(std::filesystem::temp_directory_path() / ("bounce-half-pipe-" + name + ".png"),
               shown, 0.0f);
    }
    EXPECT_GT(lit, kSize * kSize / 2);
    EXPECT_EQ(dark, 0) << "darkest " << darkest;
  }
}

}  // namespace
}  // namespace bounce::test
