// The renderer's lightmap term against closed forms, on synthetic bakes (no baker involved):
// a constant irradiance E gives ρ/π·E exactly (textured albedo included), dynamic instances
// get none, `full` is `direct` plus `indirect`, `lightmap` shows E/π, and a lightmap whose rows
// fall top to bottom renders the right way up.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "bake_folder/texel_error.h"
#include "lightmap_scenes.h"
#include "test_scenes.h"

namespace bounce::test {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr int kSize = 32;

// A 1 m square floor at y = 0 (corners x, z = ±0.5, facing +y) filling the down camera's view
// at 1 m (half-width tan 0.4 = 0.42 m), textured with one texel, and a small dynamic quad
// hovering over its centre. The floor's atlas region maps (x, z) to u = x + 0.5,
// v = z + 0.5: the far edge z = −0.5 (the image's top row, downCamera's up is −z) is v = 0,
// the lightmap's top row.
struct PlaneScene {
  Scene scene;
  Camera camera = downCamera(1.0f);
  glm::vec3 floorReflectance{0.0f};  // ρ = albedo ⊙ texel
};

PlaneScene planeScene() {
  PlaneScene p;
  Material floor;
  floor.name = "floor";
  floor.albedo = {0.8f, 0.5f, 0.9f};
  floor.albedoTexture = 0;
  Texture texel;
  texel.name = "one texel";
  texel.width = texel.height = 1;
  texel.texels = {{0.5f, 1.0f, 0.25f}};
  p.scene.textures = {texel};
  p.floorReflectance = floor.albedo * texel.texels[0];
  addQuad(p.scene, {-0.5f, 0, 0.5f}, {1, 0, 0}, {0, 0, -1}, floor);
  Material hover;
  hover.name = "hover";
  hover.albedo = glm::vec3(0.7f);
  addQuad(p.scene, {-0.1f, 0.5f, 0.1f}, {0.2f, 0, 0}, {0, 0, -0.2f}, hover);
  p.scene.instances[1].mobility = Mobility::Dynamic;
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  sun.irradiance = {1.0f, 2.0f, 3.0f};
  p.scene.lights = {sun};
  return p;
}

// The floor quad's corners are c, c+u, c+u+v, c+v with indices 0 1 2, 0 2 3; atlas (x+½, z+½).
Bake planeBake(const Scene& scene, const Image& irradiance) {
  Bake bake;
  bake.layout.width = irradiance.width;
  bake.layout.height = irradiance.height;
  bake.layout.texelSize = 1.0f / static_cast<float>(irradiance.width);
  const Mesh& floor = scene.meshes[scene.instances[0].mesh];
  InstanceLightmapUv region{0, {}};
  for (uint32_t index : floor.indices)
    region.cornerUv.push_back({floor.positions[index].x + 0.5f, floor.positions[index].z + 0.5f});
  bake.layout.instances = {region};
  bake.irradiance = irradiance;
  bake.manifest = minimalManifest(scene);
  return bake;
}

Image renderMode(const Scene& scene, const Camera& camera, const Bake& bake, RenderMode mode) {
  testContext();
  RendererSettings settings;
  settings.mode = mode;
  ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, &bake);
  return renderer.renderImage(camera, kSize, kSize);
}

// Whether pixel (x, y) sees the hovering dynamic quad (|x|, |z| < 0.1 at y = 0.5), with a
// half-pixel margin either way (the answer is then "unsure" and the pixel is skipped).
enum class Sees { Floor, Hover, Unsure };
Sees whatPixelSees(const Camera& camera, int x, int y) {
  const glm::vec3 d = pixelRay(camera, kSize, kSize, x, y);
  const glm::vec3 o = camera.position();
  const glm::vec3 h = o + d * ((0.5f - o.y) / d.y);
  const float margin = 0.5f * 2.0f * std::tan(0.4f) * 0.5f / kSize;  // half a pixel at 0.5 m
  const float m = std::max(std::abs(h.x), std::abs(h.z));
  if (m < 0.1f - margin) return Sees::Hover;
  if (m > 0.1f + margin) return Sees::Floor;
  return Sees::Unsure;
}

TEST(Lightmap, ConstantIrradianceGivesReflectanceOverPiTimesE) {
  const PlaneScene p = planeScene();
  const glm::vec3 e(2.0f, 3.0f, 5.0f);  // W/m²
  const Bake bake = planeBake(p.scene, Image(8, 8, e));
  const Image indirect = renderMode(p.scene, p.camera, bake, RenderMode::Indirect);
  const glm::vec3 expected = p.floorReflectance / kPi * e;
  int floorPixels = 0, hoverPixels = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const Sees sees = whatPixelSees(p.camera, x, y);
      const glm::vec3 l = indirect.at(x, y);
      for (int c = 0; c < 3; ++c) {
        if (sees == Sees::Floor) {
          EXPECT_NEAR(l[c], expected[c], 1e-3f * expected[c]) << x << "," << y;
        }
        if (sees == Sees::Hover) {
          EXPECT_EQ(l[c], 0.0f) << "dynamic instance at " << x << "," << y;
        }
      }
      floorPixels += sees == Sees::Floor;
      hoverPixels += sees == Sees::Hover;
    }
  EXPECT_GT(floorPixels, 700);
  EXPECT_GT(hoverPixels, 150);
}

TEST(Lightmap, FullIsDirectPlusIndirectAndLightmapShowsEOverPi) {
  const PlaneScene p = planeScene();
  const glm::vec3 e(2.0f, 3.0f, 5.0f);
  const Bake bake = planeBake(p.scene, Image(8, 8, e));
  const Image full = renderMode(p.scene, p.camera, bake, RenderMode::Full);
  const Image direct = renderMode(p.scene, p.camera, bake, RenderMode::Direct);
  const Image indirect = renderMode(p.scene, p.camera, bake, RenderMode::Indirect);
  const Image lightmap = renderMode(p.scene, p.camera, bake, RenderMode::Lightmap);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const Sees sees = whatPixelSees(p.camera, x, y);
      if (sees == Sees::Unsure) continue;
      for (int c = 0; c < 3; ++c) {
        const float sum = direct.at(x, y)[c] + indirect.at(x, y)[c];
        EXPECT_NEAR(full.at(x, y)[c], sum, 1e-5f * (1.0f + sum)) << x << "," << y;
        const float shown = sees == Sees::Floor ? e[c] / kPi : 0.0f;
        EXPECT_NEAR(lightmap.at(x, y)[c], shown, 1e-3f * shown) << x << "," << y;
      }
    }
}

// Rows of E from the top: 8, 4, 2, 1 W/m² (grey). The image's top rows (world −z, atlas v = 0)
// must be the bright ones, each pixel the bilinear lookup at its own v: E(v) interpolated
// between texel centres (k + ½)/4, clamped at the borders.
TEST(Lightmap, TopRowOfTheLightmapIsAtlasVZero) {
  const PlaneScene p = planeScene();
  Image ramp(4, 4);
  const float rows[4] = {8, 4, 2, 1};
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) ramp.at(x, y) = glm::vec3(rows[y]);
  const Bake bake = planeBake(p.scene, ramp);
  const Image lightmap = renderMode(p.scene, p.camera, bake, RenderMode::Lightmap);
  for (int y = 0; y < kSize; ++y) {
    const int x = 2;  // a column clear of the hovering quad
    const float v = floorPoint(p.camera, kSize, kSize, x, y).z + 0.5f;
    const float t = std::clamp(v * 4.0f - 0.5f, 0.0f, 3.0f);
    const int k = std::min(static_cast<int>(t), 2);
    const float f = t - static_cast<float>(k);
    const float expected = ((1 - f) * rows[k] + f * rows[k + 1]) / kPi;
    // GL's bilinear weights carry 8 fractional bits on llvmpipe: 1/256 of a step between rows.
    const float tolerance = (rows[k] - rows[k + 1]) / kPi / 128.0f;
    EXPECT_NEAR(lightmap.at(x, y).g, expected, tolerance) << "row " << y << " v " << v;
  }
  EXPECT_GT(lightmap.at(2, 0).g, 2.0f * lightmap.at(2, kSize - 1).g);
}

// The lookup is clamped into the fragment's own triangle (forward.geom, forward.frag), and a
// point inside it is left where it is, whichever way round the chart lies in the atlas. E rises
// by 1 W/m² a column and 8 a row of an 8 × 8 map, so the bilinear lookup at (u, v) is the
// linear E = 1 + t_u + 8·t_v (t the texel coordinate u·8 − ½, clamped to [0, 7]) and any
// lookup moved off its own point shows. The floor's region is laid out as written (u = x + ½: its
// triangles clockwise in the atlas, as in every other test here) and mirrored (u = ½ − x:
// counter-clockwise). ThinWallLeak checks only that the lookup stays on its chart. Injected: the
// clamp's inside test written for clockwise triangles only (a counter-clockwise triangle's own
// points moved onto its edges): fails here, passes ThinWallLeak and the other lightmap tests;
// a corner of the clamp's triangle taken from the wrong vertex (forward.geom): fails here and in
// TopRowOfTheLightmapIsAtlasVZero, ErrorModeShows… and BakedVisibility.TheAtlasIsRead…
TEST(Lightmap, TheLookupClampLeavesEveryPointOfItsTriangleWhereItIs) {
  const PlaneScene p = planeScene();
  constexpr int kMap = 8;
  Image ramp(kMap, kMap);
  for (int y = 0; y < kMap; ++y)
    for (int x = 0; x < kMap; ++x)
      ramp.at(x, y) = glm::vec3(1.0f + static_cast<float>(x) + 8.0f * static_cast<float>(y));
  for (const bool mirrored : {false, true}) {
    Bake bake = planeBake(p.scene, ramp);
    if (mirrored)
      for (glm::vec2& uv : bake.layout.instances[0].cornerUv) uv.x = 1.0f - uv.x;
    const Image lightmap = renderMode(p.scene, p.camera, bake, RenderMode::Lightmap);
    int checked = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        if (whatPixelSees(p.camera, x, y) != Sees::Floor) continue;
        const glm::vec3 point = floorPoint(p.camera, kSize, kSize, x, y);
        const float u = mirrored ? 0.5f - point.x : point.x + 0.5f, v = point.z + 0.5f;
        const float tu = std::clamp(u * kMap - 0.5f, 0.0f, kMap - 1.0f);
        const float tv = std::clamp(v * kMap - 0.5f, 0.0f, kMap - 1.0f);
        const float expected = (1.0f + tu + 8.0f * tv) / kPi;
        // One sample a pixel, at its centre. GL's bilinear weights carry 8 fractional bits on
        // llvmpipe: 1/256 of a step each way, doubled for margin.
        const float tolerance = (1.0f + 8.0f) / 128.0f / kPi;
        EXPECT_NEAR(lightmap.at(x, y).g, expected, tolerance)
            << (mirrored ? "mirrored" : "as written") << " chart, pixel " << x << "," << y;
        ++checked;
      }
    EXPECT_GT(checked, 700);
  }
}

// A baked-only light (Light::bakeDirect) is in the lightmap: with a bake the renderer draws it
// nowhere live (full = indirect), without one it is drawn live like any light.
TEST(Lightmap, BakedOnlyLightIsNotDrawnLiveOnceABakeIsAttached) {
  PlaneScene p = planeScene();
  p.scene.lights[0].bakeDirect = true;
  const Bake bake = planeBake(p.scene, Image(8, 8, glm::vec3(1.0f)));
  const Image full = renderMode(p.scene, p.camera, bake, RenderMode::Full);
  const Image indirect = renderMode(p.scene, p.camera, bake, RenderMode::Indirect);
  for (std::size_t i = 0; i < full.pixels.size(); ++i)
    EXPECT_EQ(full.pixels[i], indirect.pixels[i]) << i;
  testContext();
  ForwardRenderer unbaked(p.scene, gl::shaderDirectory());
  const Image live = unbaked.renderImage(p.camera, kSize, kSize);
  EXPECT_GT(live.at(2, 2).g, 0.1f);
}

// Mode error: each texel's estimated relative error e against the bake's target (bake.json
// "estimatedError"."target" = 0.2) as blue (0) → green (target) → red (twice it or more), dark
// grey where a texel has no estimate, mid grey on surfaces without a lightmap. A 2×2 error map
// over the floor: one pixel in each quadrant (clear of the hovering quad) shows its texel.
TEST(Lightmap, ErrorModeShowsEachTexelsErrorAgainstTheTarget) {
  const PlaneScene p = planeScene();
  Bake bake = planeBake(p.scene, Image(2, 2, glm::vec3(1.0f)));
  bake.manifest.estimatedError.target = 0.2;
  bake.relativeError = Image(2, 2);
  bake.relativeError->at(0, 0) = glm::vec3(0.1f);              // half the target
  bake.relativeError->at(1, 0) = glm::vec3(0.3f);              // 1.5 × the target
  bake.relativeError->at(0, 1) = glm::vec3(kNoErrorEstimate);  // none
  bake.relativeError->at(1, 1) = glm::vec3(0.8f);              // 4 × the target
  const Image error = renderMode(p.scene, p.camera, bake, RenderMode::Error);
  const auto expectPixel = [&](int x, int y, glm::vec3 expected) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(error.at(x, y)[c], expected[c], 1e-6f) << x << "," << y;
  };
  expectPixel(4, 4, {0.0f, 0.5f, 0.5f});
  expectPixel(kSize - 5, 4, {0.5f, 0.5f, 0.0f});
  expectPixel(4, kSize - 5, glm::vec3(0.05f));
  expectPixel(kSize - 5, kSize - 5, {1.0f, 0.0f, 0.0f});
  expectPixel(kSize / 2, kSize / 2, glm::vec3(0.18f));  // the dynamic quad: no lightmap
  // Validity: the texel without an estimate is covered by the floor's chart: filled (orange).
  const Image validity = renderMode(p.scene, p.camera, bake, RenderMode::Validity);
  for (const auto& [x, y, colour] :
       {std::tuple{4, 4, kValidTexel}, std::tuple{kSize - 5, 4, kValidTexel},
        std::tuple{4, kSize - 5, kFilledTexel}, std::tuple{kSize - 5, kSize - 5, kValidTexel}})
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(validity.at(x, y)[c], colour[c], 1e-6f) << x << "," << y;

  bake.relativeError.reset();  // a bake without error.exr: the mode is refused, saying why
  testContext();
  ForwardRenderer renderer(p.scene, gl::shaderDirectory(), {}, &bake);
  try {
    renderer.setMode(RenderMode::Error);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no error.exr"), std::string::npos) << e.what();
  }
}

TEST(Lightmap, ModesThatNeedABakeRefuseToStartWithoutOne) {
  const PlaneScene p = planeScene();
  testContext();
  RendererSettings settings;
  settings.mode = RenderMode::Indirect;
  EXPECT_THROW(ForwardRenderer(p.scene, gl::shaderDirectory(), settings), std::invalid_argument);
  ForwardRenderer renderer(p.scene, gl::shaderDirectory());
  EXPECT_THROW(renderer.setMode(RenderMode::Full), std::invalid_argument);
}

}  // namespace
}  // namespace bounce::test
