// The inspection views texel-density and cascades (render/view_mode_colours.h) against the
// quantities they show, computed GL-free: the lightmap texels per metre of a hand-made atlas
// region (its UV scale over the quad's size) against the layout's texel size, and the cascade
// split and blend depths of render/cascades.h at each pixel's view depth.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "atlas/atlas.h"
#include "lightmap_scenes.h"
#include "render/cascades.h"
#include "render/view_mode_colours.h"
#include "test_scenes.h"

namespace bounce::test {
namespace {

constexpr int kSize = 32;
constexpr int kAtlas = 16;  // texels per side of the hand-made atlas

// A 1 m square floor at y = 0 (x, z in ±0.5) whose atlas region maps (x, z) to
// k·(x + ½, z + ½): k·kAtlas lightmap texels per metre; the layout says `texelSize` metres.
struct DensityScene {
  Scene scene;
  Bake bake;
};

DensityScene densityScene(float k, float texelSize) {
  DensityScene d;
  Material floor;
  floor.name = "floor";
  floor.albedo = glm::vec3(0.5f);
  addQuad(d.scene, {-0.5f, 0, 0.5f}, {1, 0, 0}, {0, 0, -1}, floor);
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::vec3(0, -1, 0);
  sun.irradiance = glm::vec3(1.0f);
  d.scene.lights = {sun};
  d.bake.layout.width = d.bake.layout.height = kAtlas;
  d.bake.layout.texelSize = texelSize;
  const Mesh& mesh = d.scene.meshes[0];
  InstanceLightmapUv region{0, {}};
  for (uint32_t index : mesh.indices)
    region.cornerUv.push_back(
        k * glm::vec2(mesh.positions[index].x + 0.5f, mesh.positions[index].z + 0.5f));
  d.bake.layout.instances = {region};
  d.bake.irradiance = Image(kAtlas, kAtlas, glm::vec3(1.0f));
  d.bake.manifest = minimalManifest(d.scene);
  return d;
}

Image renderMode(const Scene& scene, const Camera& camera, const Bake* bake, RenderMode mode,
                 int width, int height, int samples = 1) {
  testContext();
  RendererSettings settings;
  settings.mode = mode;
  ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, bake);
  return renderer.renderImage(camera, width, height, samples);
}

Camera lookAt(glm::vec3 eye, glm::vec3 target, float yfov) {
  Camera camera;
  camera.yfov = yfov;
  camera.znear = 0.05f;
  camera.zfar = 1000.0f;
  camera.cameraToWorld = glm::inverse(glm::lookAt(eye, target, glm::vec3(0, 1, 0)));
  return camera;
}

// Every floor pixel shows texelDensityColour(k·kAtlas, 1/texelSize) times the checker of the
// texel its centre falls in (1 on even x + y, kTexelCheckerDark on odd), seen from above and
// from a slant (the density is the surface's, not the view's), the slant with 4 samples per pixel
// (where centroid sampling moves a pixel's inputs off its centre along the quad's diagonal, the
// density must stay the triangle's). Densities from a quarter to four
// times the target cover both clamped ends and the ramp between.
TEST(ViewModes, TexelDensityShowsTexelsPerMetreAgainstTheLayoutsTexelSize) {
  const float texelSize = 1.0f / 8.0f;  // target: 8 texels per metre
  const Camera down = downCamera(1.0f);
  const Camera slant = lookAt({0.35f, 0.7f, 0.6f}, {0.0f, 0.0f, 0.0f}, 0.8f);
  for (const float k : {0.125f, 0.5f / std::sqrt(2.0f), 0.5f, 0.5f * std::sqrt(2.0f), 1.0f}) {
    const DensityScene d = densityScene(k, texelSize);
    const float density = k * static_cast<float>(kAtlas);  // texels per metre, by construction
    const glm::vec3 expected = texelDensityColour(density, 1.0f / texelSize);
    for (const auto& [camera, samples] : {std::pair{down, 1}, std::pair{slant, 4}}) {
      const Image image =
          renderMode(d.scene, camera, &d.bake, RenderMode::TexelDensity, kSize, kSize, samples);
      int checked = 0;
      for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
          const glm::vec3 p = floorPoint(camera, kSize, kSize, x, y);
          if (std::max(std::abs(p.x), std::abs(p.z)) > 0.45f) continue;
          const glm::vec2 texel = k * glm::vec2(p.x + 0.5f, p.z + 0.5f) * float(kAtlas);
          const glm::vec2 inside = texel - glm::floor(texel);
          if (glm::any(glm::lessThan(inside, glm::vec2(0.15f))) ||
              glm::any(glm::greaterThan(inside, glm::vec2(0.85f))))
            continue;  // near a texel edge: the checker square is unsure at the pixel's sample
          const int parity = (static_cast<int>(texel.x) + static_cast<int>(texel.y)) & 1;
          const glm::vec3 want = expected * (parity == 0 ? 1.0f : kTexelCheckerDark);
          for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(image.at(x, y)[c], want[c], 2e-3f)
                << "k " << k << " pixel " << x << "," << y << " channel " << c;
          ++checked;
        }
      EXPECT_GT(checked, 50) << "k " << k;
    }
  }
  // The mode needs a bake (its layout) and says so.
  const DensityScene d = densityScene(1.0f, texelSize);
  testContext();
  RendererSettings settings;
  settings.mode = RenderMode::TexelDensity;
  EXPECT_THROW(ForwardRenderer(d.scene, gl::shaderDirectory(), settings), std::invalid_argument);
}

// log₂(d/d₀) read back from a texel-density pixel: the ramp's colour times the checker's 1 or
// kTexelCheckerDark, whose ratios of channels do not depend on the checker.
float densityExponent(glm::vec3 pixel) {
  if (pixel.b > 0.0f) return -pixel.b / (pixel.g + pixel.b);
  return pixel.r / (pixel.r + pixel.g);
}

// The atlas's own layout (baker/atlas) of three 0.8 m quads side by side at lightmapScale 0.7, 1
// and 1.5 (glTF extras.bounce.lightmapScale: texels per metre relative to the scene's), 5 cm
// texels: each quad shows r = log₂(scale) (−0.51, 0, +0.58; a Unreal user's "this one has more
// lightmap resolution than the rest") within 0.05, the atlas rounding its planar charts to whole
// texels by under a few percent.
TEST(ViewModes, TexelDensityShowsEachInstancesLightmapScaleInTheAtlasOwnLayout) {
  Scene scene;
  Material grey;
  grey.name = "grey";
  grey.albedo = glm::vec3(0.5f);
  const std::array<float, 3> scales = {0.7f, 1.0f, 1.5f};
  for (int i = 0; i < 3; ++i) {
    addQuad(scene, {-1.3f + 0.9f * static_cast<float>(i), 0, 0.4f}, {0.8f, 0, 0}, {0, 0, -0.8f},
            grey);
    scene.instances.back().lightmapScale = scales[static_cast<std::size_t>(i)];
  }
  AtlasSettings atlasSettings;
  atlasSettings.texelSize = 0.05f;
  Bake bake;
  bake.layout = buildAtlas(scene, atlasSettings).layout;
  ASSERT_EQ(bake.layout.instances.size(), 3u);
  EXPECT_EQ(bake.layout.texelSize, 0.05f);
  bake.irradiance = Image(bake.layout.width, bake.layout.height, glm::vec3(1.0f));
  bake.manifest = minimalManifest(scene);
  const int width = 96, height = 32;
  const Camera camera = downCamera(1.2f, 0.7f);
  const Image image = renderMode(scene, camera, &bake, RenderMode::TexelDensity, width, height);
  std::array<int, 3> seen{};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::vec3 p = floorPoint(camera, width, height, x, y);
      const float along = p.x + 1.3f;  // from the first quad's left edge
      const int quad = static_cast<int>(std::floor(along / 0.9f));
      const float inside = along - 0.9f * static_cast<float>(quad);
      if (quad < 0 || quad > 2 || inside < 0.03f || inside > 0.77f || std::abs(p.z) > 0.37f)
        continue;  // off the quads or near their edges
      const float expected = std::log2(scales[static_cast<std::size_t>(quad)]);
      EXPECT_NEAR(densityExponent(image.at(x, y)), expected, 0.05f)
          << "quad " << quad << " pixel " << x << "," << y;
      ++seen[static_cast<std::size_t>(quad)];
    }
  for (int i = 0; i < 3; ++i) EXPECT_GT(seen[static_cast<std::size_t>(i)], 20) << "quad " << i;
}

// The view depth of raster point (px, py) on the floor y = 0.
float floorViewDepth(const Camera& camera, int width, int height, float px, float py) {
  const glm::vec3 p = floorPoint(camera, width, height, px, py);
  return glm::dot(p - camera.position(), camera.forward());
}

// The colour the cascades view gives at view depth z (view_mode_colours.h's rule).
glm::vec3 cascadeViewColour(const std::vector<Cascade>& cascades, float z) {
  for (std::size_t i = 0; i < cascades.size(); ++i) {
    const Cascade& c = cascades[i];
    const bool last = i + 1 == cascades.size();
    if (z > c.splitDepth && !last) continue;
    const int index = static_cast<int>(i);
    if (z > c.blendStart && !last) {
      const float w = std::clamp((z - c.blendStart) / (c.splitDepth - c.blendStart), 0.0f, 1.0f);
      return (1.0f - w) * cascadeColour(index) + w * cascadeColour(index + 1);
    }
    return cascadeColour(index);
  }
  return glm::vec3(kNoLightmapGrey);
}

// A 400 m ground seen from 2 m up towards the horizon: every floor pixel shows the colour of the
// cascade fitCascades puts its view depth in (cross-faded in the blend bands), within the range
// the colour takes over the pixel (its corners and centre), and all four cascades show. Without
// a directional light, or with shadows off, there are no cascades: grey.
TEST(ViewModes, CascadesShowTheCascadeOfEachPixelsViewDepth) {
  Scene scene;
  Material ground;
  ground.name = "ground";
  ground.albedo = glm::vec3(0.5f);
  addQuad(scene, {-200, 0, 200}, {400, 0, 0}, {0, 0, -400}, ground);
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f));
  sun.irradiance = glm::vec3(1.0f);
  scene.lights = {sun};
  const int width = 64, height = 96;
  const Camera camera = lookAt({0, 8, 0}, {0, 0, -30}, 1.2f);
  const Image image = renderMode(scene, camera, nullptr, RenderMode::Cascades, width, height);

  const Bounds bounds{{-200, 0, -200}, {200, 0, 200}, false};
  const std::vector<Cascade> cascades =
      fitCascades(camera, static_cast<float>(width) / static_cast<float>(height), sun.direction,
                  bounds, CascadeSettings{});
  ASSERT_EQ(cascades.size(), 4u);
  std::array<int, 4> pure{};
  int checked = 0, blended = 0;  // pixels checked; those wholly inside a blend band
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      glm::vec3 lo(1e9f), hi(-1e9f);
      bool onGround = true;  // the whole pixel sees the ground (not the sky, not past its edge)
      for (const glm::vec2 at :
           {glm::vec2(0.5f), glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(0, 1), glm::vec2(1, 1)}) {
        const float px = static_cast<float>(x) + at.x, py = static_cast<float>(y) + at.y;
        const glm::vec3 p = floorPoint(camera, width, height, px, py);
        if (pixelRay(camera, width, height, px, py).y > -1e-3f ||
            std::max(std::abs(p.x), std::abs(p.z)) > 199.0f) {
          onGround = false;
          break;
        }
        const glm::vec3 c =
            cascadeViewColour(cascades, floorViewDepth(camera, width, height, px, py));
        lo = glm::min(lo, c);
        hi = glm::max(hi, c);
      }
      if (!onGround) continue;
      for (int c = 0; c < 3; ++c) {
        EXPECT_GE(image.at(x, y)[c], lo[c] - 2e-3f) << x << "," << y << " channel " << c;
        EXPECT_LE(image.at(x, y)[c], hi[c] + 2e-3f) << x << "," << y << " channel " << c;
      }
      ++checked;
      if (hi != lo && glm::all(glm::lessThanEqual(hi, glm::vec3(1.0f - 1e-3f)))) ++blended;
      for (int i = 0; i < 4; ++i)
        if (glm::all(glm::lessThan(glm::abs(image.at(x, y) - cascadeColour(i)), glm::vec3(1e-3f))))
          ++pure[static_cast<std::size_t>(i)];
    }
  EXPECT_GT(checked, width * height / 3);
  EXPECT_GT(blended, width / 2) << "too few pixels inside the blend bands to check them";
  for (int i = 0; i < 4; ++i) EXPECT_GT(pure[static_cast<std::size_t>(i)], 0) << "cascade " << i;

  Scene unlit = scene;
  unlit.lights.clear();
  const Image grey = renderMode(unlit, camera, nullptr, RenderMode::Cascades, width, height);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(grey.at(width / 2, height - 2)[c], kNoLightmapGrey, 1e-6f);
}

}  // namespace
}  // namespace bounce::test
