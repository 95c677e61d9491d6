// The cost view (RenderMode::Cost, shaders/cost.glsl): the counts a pixel's fragment evaluated,
// read back raw (one sample per pixel: exact integers) and checked against what the renderer
// decided on the CPU and against closed forms:
//   - a lightmapped static floor under VPLs evaluates no VPL; the dynamic quad over it evaluates
//     exactly the lightcut of its VPL grid cell (VplLightCuts::lightsEvaluated), never more than
//     the largest cut, the renderer's bound (docs/vpl.md, "Lightcuts");
//   - on a floor under point lights of known intensity, a pixel visits exactly the lights its
//     view cluster lists (light_grid.h), which include every light whose closed-form reach
//     d_c = sqrt(I / E_floor) contains the pixel's floor point and none whose reach stays farther
//     than the cluster's size from it; with culling off every light;
//   - the shadow taps of a pixel under one shadowed spot light: 16 Poisson taps, 1 hardware tap.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "lightmap_scenes.h"
#include "render/cluster_grid.h"
#include "render/light_grid.h"
#include "render/light_reach.h"
#include "render/vpl_pass.h"
#include "test_scenes.h"
#include "vpl_runtime/vpl_groups.h"

namespace bounce::test {
namespace {

constexpr int kSize = 32;

// A 1 m lightmapped static floor (atlas u = x + ½, v = z + ½) and a 0.2 m dynamic quad 0.5 m
// over its centre, seen from 1 m above; VPLs on a wall at x = −0.45 and over the floor.
struct VplCostScene {
  Scene scene;
  Camera camera = downCamera(1.0f);
  Bake bake;
};

VplCostScene vplCostScene() {
  VplCostScene s;
  Material floor;
  floor.name = "floor";
  floor.albedo = glm::vec3(0.5f);
  addQuad(s.scene, {-0.5f, 0, 0.5f}, {1, 0, 0}, {0, 0, -1}, floor);
  Material hover;
  hover.name = "hover";
  hover.albedo = glm::vec3(0.7f);
  addQuad(s.scene, {-0.1f, 0.5f, 0.1f}, {0.2f, 0, 0}, {0, 0, -0.2f}, hover);
  s.scene.instances[1].mobility = Mobility::Dynamic;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<Vpl> vpls;
  for (int i = 0; i < 400; ++i) {
    Vpl v;
    const bool wall = i % 2 == 0;
    v.position = wall ? glm::vec3(-0.45f, 0.6f * u(rng), -0.45f + 0.9f * u(rng))
                      : glm::vec3(-0.45f + 0.9f * u(rng), 0.0f, -0.45f + 0.9f * u(rng));
    v.normal = wall ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    v.flux = glm::vec3(1e-3f);
    vpls.push_back(v);
  }
  Bake& bake = s.bake;
  bake.layout.width = bake.layout.height = 8;
  bake.layout.texelSize = 1.0f / 8.0f;
  bake.layout.instances = {unitFloorRegion(s.scene)};
  bake.irradiance = Image(8, 8, glm::vec3(1.0f));
  bake.manifest = minimalManifest(s.scene);
  bake.manifest.vpls = BakeManifest::Vpls{.count = vpls.size(), .clampDistance = 0.05f};
  bake.vpls = vpls;
  return s;
}

// Where the ray through raster point (px, py) meets the plane y = h.
glm::vec3 planePoint(const Camera& camera, float px, float py, float h) {
  const glm::vec3 d = pixelRay(camera, kSize, kSize, px, py);
  const glm::vec3 o = camera.position();
  return o + d * ((h - o.y) / d.y);
}

// The raster points half a pixel off pixel (x, y)'s centre, and the centre.
std::vector<glm::vec2> pixelPoints(int x, int y) {
  const float cx = static_cast<float>(x) + 0.5f, cy = static_cast<float>(y) + 0.5f;
  return {{cx, cy},
          {cx - 0.5f, cy - 0.5f},
          {cx + 0.5f, cy - 0.5f},
          {cx - 0.5f, cy + 0.5f},
          {cx + 0.5f, cy + 0.5f}};
}

bool insideSquare(glm::vec3 p, float half) {
  return std::max(std::abs(p.x), std::abs(p.z)) < half;
}

TEST(CostView, LightmappedStaticFloorEvaluatesNoVplAndTheDynamicQuadItsCellsCut) {
  testContext();
  const VplCostScene s = vplCostScene();
  RendererSettings settings;
  settings.mode = RenderMode::Cost;
  ForwardRenderer renderer(s.scene, gl::shaderDirectory(), settings, &s.bake);
  const Image counts = renderer.renderImage(s.camera, kSize, kSize);
  const VplLightCuts& cuts = renderer.vpls().cuts();
  std::size_t bound = 0;
  for (std::size_t cell = 0; cell < cuts.cellEntries.size(); ++cell)
    bound = std::max(bound, cuts.lightsEvaluated(cell));
  ASSERT_GT(bound, 0u);
  int floorPixels = 0, quadPixels = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const float vpls = counts.at(x, y).g;
      const std::vector<glm::vec2> points = pixelPoints(x, y);
      const auto all = [&](float h, float half, bool inside) {
        return std::all_of(points.begin(), points.end(), [&](glm::vec2 q) {
          return insideSquare(planePoint(s.camera, q.x, q.y, h), half) == inside;
        });
      };
      if (all(0.5f, 0.1f, true)) {
        // The dynamic quad: the cut of the cell it lies in (a cell border may cross the pixel).
        ++quadPixels;
        bool matches = false;
        for (const glm::vec2 q : points)
          matches |= vpls == static_cast<float>(cuts.lightsEvaluated(
                                 cuts.cellOf(planePoint(s.camera, q.x, q.y, 0.5f))));
        EXPECT_TRUE(matches) << "quad pixel (" << x << ", " << y << ") evaluated " << vpls
                             << " VPL-table lights, not its cell's cut";
        EXPECT_LE(vpls, static_cast<float>(bound)) << "pixel (" << x << ", " << y << ")";
      } else if (all(0.5f, 0.1f, false) && all(0.0f, 0.5f, true)) {
        ++floorPixels;
        EXPECT_EQ(vpls, 0.0f) << "lightmapped floor pixel (" << x << ", " << y << ")";
      }
    }
  EXPECT_GT(quadPixels, 20);
  EXPECT_GT(floorPixels, 300);
}

// The light bound (VplRenderSettings::maxLights) reaches the pixels: with a bound of 100 lights
// (above the 64 groups' roots), below the unbounded cut of the quad's cells (checked), every quad
// pixel evaluates at most 100 and exactly its cell's bounded cut.
TEST(CostView, TheDynamicQuadsPixelsEvaluateNoMoreThanTheLightBound) {
  testContext();
  const VplCostScene s = vplCostScene();
  RendererSettings settings;
  settings.mode = RenderMode::Cost;
  settings.vpls.maxLights = 0;
  const std::size_t unbounded = [&] {
    ForwardRenderer renderer(s.scene, gl::shaderDirectory(), settings, &s.bake);
    const VplLightCuts& cuts = renderer.vpls().cuts();
    return cuts.lightsEvaluated(cuts.cellOf({0.0f, 0.5f, 0.0f}));
  }();
  constexpr uint32_t kBound = 100;
  ASSERT_GT(unbounded, kBound) << unbounded;  // the premise: the bound acts where the quad is
  settings.vpls.maxLights = kBound;
  ForwardRenderer renderer(s.scene, gl::shaderDirectory(), settings, &s.bake);
  const Image counts = renderer.renderImage(s.camera, kSize, kSize);
  const VplLightCuts& cuts = renderer.vpls().cuts();
  int quadPixels = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::vector<glm::vec2> points = pixelPoints(x, y);
      if (!std::all_of(points.begin(), points.end(), [&](glm::vec2 q) {
            return insideSquare(planePoint(s.camera, q.x, q.y, 0.5f), 0.1f);
          }))
        continue;
      ++quadPixels;
      const float vpls = counts.at(x, y).g;
      EXPECT_LE(vpls, static_cast<float>(kBound)) << "quad pixel (" << x << ", " << y << ")";
      bool matches = false;
      for (const glm::vec2 q : points)
        matches |= vpls == static_cast<float>(cuts.lightsEvaluated(
                               cuts.cellOf(planePoint(s.camera, q.x, q.y, 0.5f))));
      EXPECT_TRUE(matches) << "quad pixel (" << x << ", " << y << ") evaluated " << vpls;
    }
  EXPECT_GT(quadPixels, 20);
}

// Point lights 0.3 m over the floor in a row along x, 0.25 m apart, each of intensity I with a
// reach of 0.2 m: a floor point is within reach of at most one.
struct LightRow {
  Scene scene;
  Camera camera = downCamera(1.0f);
  float reach = 0.0f;  // m
};

LightRow lightRow(float floor) {
  LightRow r;
  Material white;
  white.name = "floor";
  white.albedo = glm::vec3(0.5f);
  addQuad(r.scene, {-0.5f, 0, 0.5f}, {1, 0, 0}, {0, 0, -1}, white);
  // d_c = sqrt(I / E_floor) (light_cutoff.h): I = E_floor · d_c².
  const float reach = 0.35f;
  for (int i = 0; i < 5; ++i) {
    Light light;
    light.type = LightType::Point;
    light.name = "point " + std::to_string(i);
    light.position = {-0.5f + 0.25f * static_cast<float>(i), 0.3f, 0.0f};
    light.intensity = glm::vec3(floor * reach * reach);
    r.scene.lights.push_back(light);
  }
  r.reach = reach;
  return r;
}

TEST(CostView, LightCountsAreTheClusterListsAndHoldEveryLightWithinItsClosedFormReach) {
  testContext();
  RendererSettings settings;
  settings.mode = RenderMode::Cost;
  settings.shadows.enabled = false;
  const LightRow r = lightRow(settings.lightCulling.irradianceFloor);
  ForwardRenderer renderer(r.scene, gl::shaderDirectory(), settings);
  const Image counts = renderer.renderImage(r.camera, kSize, kSize);
  const ClusterGrid& grid = renderer.clusterGrid();
  std::vector<LightReach> reaches;
  for (const Light& light : r.scene.lights)
    reaches.push_back(punctualReach(light, light.intensity, settings.lightCulling.irradianceFloor));
  const LightGridLists lists = assignLights(grid, reaches, {});
  // A cluster's size at the floor: a tile's diagonal plus the slice's depth (1 m away).
  const float tile = 2.0f * std::tan(0.4f) * static_cast<float>(grid.tilePixels) / kSize;
  const float depth = 1.0f;
  const int slice = grid.sliceOf(depth);
  const float clusterSize =
      std::sqrt(2.0f) * tile * 1.1f + (grid.sliceDepth(slice + 1) - grid.sliceDepth(slice));
  int checked = 0, lit = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const glm::vec3 p = floorPoint(r.camera, kSize, kSize, x, y);
      if (!insideSquare(p, 0.5f - 0.02f)) continue;
      const float visited = counts.at(x, y).r;
      // The pixel's cluster on the CPU (gl_FragCoord counts rows from the bottom).
      const int tx = std::min(x / grid.tilePixels, grid.tilesX - 1);
      const int ty = std::min((kSize - 1 - y) / grid.tilePixels, grid.tilesY - 1);
      const glm::vec4 header =
          lists.headers[static_cast<std::size_t>(grid.index(tx, ty, grid.sliceOf(depth)))];
      EXPECT_EQ(visited, header.y + header.z) << "pixel (" << x << ", " << y << ")";
      int within = 0, near = 0;
      for (const Light& light : r.scene.lights) {
        const float d = glm::length(light.position - p);
        within += d < r.reach ? 1 : 0;
        near += d < r.reach + clusterSize ? 1 : 0;
      }
      EXPECT_GE(visited, static_cast<float>(within)) << "pixel (" << x << ", " << y << ")";
      EXPECT_LE(visited, static_cast<float>(near)) << "pixel (" << x << ", " << y << ")";
      lit += within > 0 ? 1 : 0;
      ++checked;
    }
  EXPECT_GT(checked, 500);
  EXPECT_GT(lit, 100);
  // Culling off: every light at every floor pixel.
  settings.lightCulling.enabled = false;
  ForwardRenderer all(r.scene, gl::shaderDirectory(), settings);
  const Image allCounts = all.renderImage(r.camera, kSize, kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (!insideSquare(floorPoint(r.camera, kSize, kSize, x, y), 0.48f)) continue;
      ASSERT_EQ(allCounts.at(x, y).r, static_cast<float>(r.scene.lights.size()));
    }
}

TEST(CostView, ShadowTapsOfASpotLightAreItsFilterKernel) {
  testContext();
  Scene scene;
  Material white;
  white.name = "floor";
  white.albedo = glm::vec3(0.5f);
  addQuad(scene, {-0.5f, 0, 0.5f}, {1, 0, 0}, {0, 0, -1}, white);
  Light spot;
  spot.type = LightType::Spot;
  spot.name = "spot";
  spot.position = {0.0f, 0.8f, 0.0f};
  spot.direction = {0.0f, -1.0f, 0.0f};
  spot.intensity = glm::vec3(1.0f);
  spot.outerConeAngle = 1.2f;
  spot.innerConeAngle = 1.0f;
  scene.lights = {spot};
  const Camera camera = downCamera(1.0f);
  for (const auto& [filter, taps] :
       {std::pair{ShadowFilter::Poisson, 16.0f}, std::pair{ShadowFilter::Hardware, 1.0f}}) {
    RendererSettings settings;
    settings.mode = RenderMode::Cost;
    settings.shadows.filter = filter;
    settings.lightCulling.enabled = false;
    ForwardRenderer renderer(scene, gl::shaderDirectory(), settings);
    const Image counts = renderer.renderImage(camera, kSize, kSize);
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        if (!insideSquare(floorPoint(camera, kSize, kSize, x, y), 0.48f)) continue;
        ASSERT_EQ(counts.at(x, y).r, 1.0f) << "pixel (" << x << ", " << y << ")";
        ASSERT_EQ(counts.at(x, y).b, taps) << "pixel (" << x << ", " << y << ")";
      }
  }
}

}  // namespace
}  // namespace bounce::test
