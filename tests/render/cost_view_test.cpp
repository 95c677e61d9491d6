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
#include <numeric>
#include <random>

#include "image/luminance.h"
#include "lightmap_scenes.h"
#include "render/cluster_grid.h"
#include "render/light_grid.h"
#include "render/light_reach.h"
#include "render/vpl_pass.h"
#include "test_scenes.h"
#include "vpl_cost_scene.h"
#include "vpl_runtime/vpl_groups.h"

namespace bounce::test {
namespace {

constexpr int kSize = 32;

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

// Every dynamic pixel gathering the VPLs itself (VplRenderSettings::perVertex off, the vpl
// modes' way): the quad's pixels evaluate their cell's cut.
TEST(CostView, LightmappedStaticFloorEvaluatesNoVplAndTheDynamicQuadItsCellsCut) {
  testContext();
  const VplCostScene s = vplCostScene();
  RendererSettings settings;
  settings.mode = RenderMode::Cost;
  settings.vpls.perVertex = false;
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

// The quad's pixels under the default vertex light (render/vpl_vertex_light.h): the VPLs each
// evaluated (the cost view's green) and its indirect frame, per pixel wholly on the quad.
struct QuadPixels {
  std::vector<float> vpls, indirect;  // counts; luminance, W/(sr·m²)
  int floorVpls = 0;                  // VPLs the other pixels evaluated, all together
};

QuadPixels quadPixels(const VplCostScene& s, bool perVertex) {
  RendererSettings settings;
  settings.vpls.perVertex = perVertex;
  settings.mode = RenderMode::Cost;
  ForwardRenderer costs(s.scene, gl::shaderDirectory(), settings, &s.bake);
  const Image counts = costs.renderImage(s.camera, kSize, kSize);
  settings.mode = RenderMode::Indirect;
  ForwardRenderer indirect(s.scene, gl::shaderDirectory(), settings, &s.bake);
  const Image light = indirect.renderImage(s.camera, kSize, kSize);
  QuadPixels q;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::vector<glm::vec2> points = pixelPoints(x, y);
      if (std::all_of(points.begin(), points.end(), [&](glm::vec2 p) {
            return insideSquare(planePoint(s.camera, p.x, p.y, 0.5f), 0.1f);
          })) {
        q.vpls.push_back(counts.at(x, y).g);
        q.indirect.push_back(luminance(light.at(x, y)));
      } else {
        q.floorVpls += static_cast<int>(counts.at(x, y).g);
      }
    }
  return q;
}

// The quad in 10 × 10 squares (longest edge 2.8 cm, the nearest VPL about 35 cm away): its
// pixels read the VPLs gathered at its vertices and evaluate none, and nor does the floor. What
// they read is the per-pixel gather interpolated: the interpolation's error on E ∝ 1/d² is at
// most h²/8 · |E''| ≤ (3/4)(h/d)² = 0.5 % relative; asserted ≤ 2 % at every pixel. Injected:
// the vertex light not read (the quad's pixels count their cut); each corner reading the next
// vertex's light (v + 1 in forward.vert; the vertices are stored shuffled: fails by up to 24 %).
TEST(CostView, AFineDynamicQuadReadsItsVerticesAndEvaluatesNoVpl) {
  testContext();
  const VplCostScene s = vplCostScene(10);
  const QuadPixels vertices = quadPixels(s, true), pixels = quadPixels(s, false);
  ASSERT_GT(vertices.vpls.size(), 20u);
  ASSERT_EQ(vertices.vpls.size(), pixels.vpls.size());
  EXPECT_EQ(vertices.floorVpls, 0);
  for (std::size_t i = 0; i < vertices.vpls.size(); ++i) {
    EXPECT_EQ(vertices.vpls[i], 0.0f) << "quad pixel " << i;
    EXPECT_GT(pixels.vpls[i], 0.0f) << "quad pixel " << i << " (the premise: a cut per pixel)";
    ASSERT_GT(pixels.indirect[i], 0.0f);
    EXPECT_NEAR(vertices.indirect[i] / pixels.indirect[i], 1.0f, 0.02f) << "quad pixel " << i;
  }
}

// The same quad in 2 triangles (longest edge 28 cm, over half the nearest VPL's 35 cm): a
// triangle that large is not read from its corners (forward.geom), and each of its pixels
// evaluates its cell's cut, as the per-pixel gather does. Injected: no size rule (0 VPLs).
TEST(CostView, ACoarseDynamicQuadGathersPerPixel) {
  testContext();
  const VplCostScene s = vplCostScene(1);
  const QuadPixels vertices = quadPixels(s, true), pixels = quadPixels(s, false);
  ASSERT_GT(vertices.vpls.size(), 20u);
  for (std::size_t i = 0; i < vertices.vpls.size(); ++i) {
    EXPECT_GT(vertices.vpls[i], 0.0f) << "quad pixel " << i;
    EXPECT_EQ(vertices.vpls[i], pixels.vpls[i]) << "quad pixel " << i;
  }
}

// The light bound (VplRenderSettings::maxLights) reaches the pixels: with a bound of 100 lights
// (above the 64 groups' roots), below the unbounded cut of the quad's cells (checked), every quad
// pixel evaluates at most 100 and exactly its cell's bounded cut.
TEST(CostView, TheDynamicQuadsPixelsEvaluateNoMoreThanTheLightBound) {
  testContext();
  const VplCostScene s = vplCostScene();
  RendererSettings settings;
  settings.mode = RenderMode::Cost;
  settings.vpls.perVertex = false;
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
