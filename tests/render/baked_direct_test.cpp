// Direct light of many area lights over thin casters, the renderer against the path tracer
// (at CI size; also a dynamic box under a static panel, and static instances without a lightmap
// that read their baked visibility per triangle corner): the renderer's
// direct-only frame, 4× supersampled and box-filtered, against bounce-trace's --direct-only
// image over the pixels that see a static surface (indirect_accuracy.h's comparison). Shadow
// maps fail here (at most 6 of the 16 area lights get a cube, and 2 cm rails are thinner than
// their texels); baked visibility does not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <utility>

#include "indirect_accuracy.h"
#include "lightmap_scenes.h"
#include "render/area_shadow_budget.h"
#include "shadow_scenes.h"
#include "test_scenes.h"

namespace bounce::test {
namespace {

constexpr int kWidth = 48, kHeight = 48, kSupersample = 4;

Material matte(const char* name, glm::vec3 albedo) {
  Material m;
  m.name = name;
  m.albedo = albedo;
  return m;
}

// A 2 m floor; 16 small panels (0.16 m, 1.1 m up, facing down, one tilted 20°) written as ONE
// mesh; a grating of 2 cm rails 0.3 m up and four 3 cm posts.
Scene railsUnderSixteenPanels() {
  Scene scene;
  addQuad(scene, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, matte("floor", glm::vec3(0.7f)));
  Mesh panels;
  panels.name = "panels";
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const glm::vec3 c(-0.75f + 0.5f * i - 0.08f, 1.1f, -0.75f + 0.5f * j - 0.08f);
      glm::vec3 u(0.16f, 0, 0), v(0, 0, 0.16f);  // u × v = −y: facing down
      if (i == 3 && j == 0) u = 0.16f * glm::vec3(std::cos(0.35f), std::sin(0.35f), 0);
      const auto base = static_cast<uint32_t>(panels.positions.size());
      const glm::vec3 n = glm::normalize(glm::cross(u, v));
      for (const glm::vec3 p : {c, c + u, c + u + v, c + v}) {
        panels.positions.push_back(p);
        panels.normals.push_back(n);
      }
      for (const uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) panels.indices.push_back(base + k);
    }
  Material glow;
  glow.name = "glow";
  glow.emission = glm::vec3(8.0f, 7.0f, 6.0f);
  addMesh(scene, std::move(panels), glow);
  const Material metal = matte("metal", glm::vec3(0.5f));
  // A grating of 2 cm rails 0.3 m up, 0.4 m apart each way.
  for (const float at : {-0.6f, -0.2f, 0.2f, 0.6f}) {
    addBox(scene, {-1.0f, 0.29f, at - 0.01f}, {1.0f, 0.31f, at + 0.01f}, metal);
    addBox(scene, {at - 0.01f, 0.31f, -1.0f}, {at + 0.01f, 0.33f, 1.0f}, metal);
  }
  for (const glm::vec2 post : {glm::vec2(0.4f, 0.4f), glm::vec2(-0.6f, 0.5f),
                               glm::vec2(0.55f, -0.6f), glm::vec2(-0.5f, -0.55f)})
    addBox(scene, {post.x - 0.015f, 0.0f, post.y - 0.015f},
           {post.x + 0.015f, 0.9f, post.y + 0.015f}, metal);
  return scene;
}

Camera overTheRoom() {
  return lookingAt({0.3f, 1.0f, 1.6f}, {0.0f, 0.0f, -0.1f}, 1.0f);
}

SceneBake bakeVisibility(const Scene& scene) {
  SceneBakeSettings settings = lightmapOnlySettings();
  settings.texelSize = 0.025f;
  settings.maxSpp = 16;  // the direct frame does not read the irradiance
  settings.targetError = 0.0f;
  settings.denoise = false;
  return bakeScene(scene, settings);
}

Image renderDirect(const Scene& scene, const Bake* bake, const Camera& camera,
                   bool bakedPunctualMapsOnlyForDynamic = false) {
  testContext();
  RendererSettings settings;
  settings.mode = RenderMode::Direct;
  settings.shadows.bakedPunctualMapsOnlyForDynamic = bakedPunctualMapsOnlyForDynamic;
  ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, bake);
  return renderAreaAveraged(renderer, camera, kWidth, kHeight, kSupersample);
}

// The tracer's reference, 1024 spp: its noise adds ~1% to the mean error (referenceNoise).
TEST(BakedDirect, SixteenPanelsOverRailsAndPostsWithinFivePercentOfThePathTracer) {
#ifdef __SANITIZE_ADDRESS__
  // About 9.8 s under AddressSanitizer, most of it the path tracer's reference; the same code runs
  // under ASan in the smaller tests. CI's whole run keeps to its 25 minutes.
  GTEST_SKIP() << "an accuracy measurement: run in the release build";
#endif
  const Scene scene = railsUnderSixteenPanels();
  const Camera camera = overTheRoom();
  const SceneBake run = bakeVisibility(scene);
  ASSERT_TRUE(run.folder.visibility.has_value());
  EXPECT_EQ(run.folder.visibility->lightCount, 16u);  // one mesh, sixteen lights
  const Reference reference =
      traceReference(scene, camera, kWidth, kHeight, 1024, PathSet::DirectOnly);
  const IndirectComparison baked =
      compareIndirect(scene, camera, renderDirect(scene, &run.folder, camera), reference);
  const IndirectComparison maps =
      compareIndirect(scene, camera, renderDirect(scene, nullptr, camera), reference);
  std::printf(
      "16 panels over rails: baked visibility %.2f%% (bias %+.2f%%), shadow maps only "
      "%.2f%% (bias %+.2f%%), reference noise %.2f%%, %zu pixels; bake %.2f s\n",
      100 * baked.meanAbsRelError, 100 * baked.bias, 100 * maps.meanAbsRelError, 100 * maps.bias,
      100 * baked.referenceNoise, baked.pixels, run.folder.manifest.measured.seconds.total);
  ASSERT_GT(baked.pixels, static_cast<std::size_t>(kWidth * kHeight / 3));
  EXPECT_LT(baked.meanAbsRelError, 0.05 + baked.referenceNoise);
  // Shadow maps alone cannot (10 lights unshadowed, thin rails): the test scene matters.
  EXPECT_GT(maps.meanAbsRelError, 2 * baked.meanAbsRelError);
}

// A static panel over a static table and a dynamic box on the floor beside it: the box's shadow
// on the static floor comes from its own cube (baked visibility has no dynamic casters), and the
// table's shadow on the box from the all-caster cube.
TEST(BakedDirect, ADynamicBoxCastsAndReceivesShadowsUnderABakedPanel) {
  Scene scene;
  addQuad(scene, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, matte("floor", glm::vec3(0.7f)));
  Material glow;
  glow.name = "glow";
  glow.emission = glm::vec3(10.0f);
  addQuad(scene, {-0.3f, 1.2f, -0.2f}, {0.6f, 0, 0}, {0, 0, 0.4f}, glow);  // facing down
  addBox(scene, {-0.5f, 0.55f, -0.5f}, {0.1f, 0.6f, 0.2f}, matte("table", glm::vec3(0.6f)));
  addBox(scene, {0.0f, 0.0f, 0.0f}, {0.25f, 0.25f, 0.25f}, matte("box", glm::vec3(0.8f)));
  scene.instances.back().mobility = Mobility::Dynamic;
  const Camera camera = overTheRoom();
  // The lightmap and visibility of the static scene, as bounce-bake makes them (the dynamic box
  // left out of the bake).
  const Bake bake = bakeVisibility(scene).folder;
  const Reference reference =
      traceReference(scene, camera, kWidth, kHeight, 1024, PathSet::DirectOnly);
  const Image rendered = renderDirect(scene, &bake, camera);
  // Every pixel that sees a surface, the dynamic box's included.
  const WorldGeometry geometry = flatten(scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  const PixelSurfaces surfaces = findPixelSurfaces(geometry, *kernel, camera, kWidth, kHeight);
  // A pixel disagrees when the renderer is off by more than 20% of the reference plus 3 of its
  // standard errors: a shadow there and not here. Pixels that see one flat piece only (the
  // one-pixel edge band of every silhouette is left out).
  int pixels = 0, disagree = 0;
  for (std::size_t i = 0; i < rendered.pixels.size(); ++i) {
    const double yt = luminance(reference.radiance.pixels[i]);
    if (!surfaces.interior[i] || !(yt > 0.0)) continue;
    const double sigma = luminance(reference.stdError.pixels[i]);
    disagree += std::abs(luminance(rendered.pixels[i]) - yt) > 0.2 * yt + 3 * sigma ? 1 : 0;
    ++pixels;
  }
  ASSERT_GT(pixels, kWidth * kHeight / 2);
  std::printf("dynamic box under a baked panel: %d of %d pixels disagree\n", disagree, pixels);
  EXPECT_LE(disagree, pixels / 100);
}

// A 1.2 m mat on the floor (20 × 20 cells: 6 cm triangles) and a table top, both static and left
// without a lightmap (lightmapScale 0: probe-lit, their visibility baked per triangle corner),
// under a panel; the floor around them lightmapped. `dynamicBox`: a box on the mat, partly under
// the table.
Scene matUnderAProbeLitTable(bool dynamicBox) {
  Scene scene;
  addQuad(scene, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, matte("floor", glm::vec3(0.7f)));
  Material glow;
  glow.name = "glow";
  glow.emission = glm::vec3(10.0f);
  addQuad(scene, {-0.3f, 1.2f, -0.2f}, {0.6f, 0, 0}, {0, 0, 0.4f}, glow);  // facing down
  Mesh mat;
  mat.name = "mat";
  constexpr int kCells = 20;
  const glm::vec3 corner(-0.7f, 0.01f, -0.7f);
  const float cell = 1.2f / kCells;
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) {
      mat.positions.push_back(corner + glm::vec3(cell * i, 0.0f, cell * j));
      mat.normals.emplace_back(0.0f, 1.0f, 0.0f);
    }
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      const auto a = static_cast<uint32_t>(j * (kCells + 1) + i), b = a + 1, c = a + kCells + 1,
                 d = c + 1;
      for (const uint32_t k : {a, c, d, a, d, b}) mat.indices.push_back(k);  // facing +y
    }
  addMesh(scene, std::move(mat), matte("mat", glm::vec3(0.6f, 0.5f, 0.4f)));
  scene.instances.back().lightmapScale = 0.0f;
  addBox(scene, {-0.5f, 0.55f, -0.5f}, {0.1f, 0.6f, 0.2f}, matte("table", glm::vec3(0.6f)));
  scene.instances.back().lightmapScale = 0.0f;
  if (dynamicBox) {
    addBox(scene, {0.0f, 0.01f, 0.05f}, {0.3f, 0.25f, 0.4f}, matte("box", glm::vec3(0.8f)));
    scene.instances.back().mobility = Mobility::Dynamic;
  }
  return scene;
}

// Pixels (interior, lit in the reference) that disagree with it by more than 20% + 3σ + 1% of
// the compared pixels' mean, and how many were compared; `instances`: only those (empty: every
// surface). The mean's 1%: V interpolated linearly over a triangle cannot follow the umbra's
// quadratic onset (the largest miss, h²/8·V'' over 6 cm triangles in a ~0.5 m penumbra, is
// ~0.2% of the unshadowed light), where 20% of a nearly black pixel is no allowance at all.
std::pair<int, int> disagreeingPixels(const Scene& scene, const Camera& camera,
                                      const Image& rendered, const Reference& reference,
                                      const std::vector<uint32_t>& instances) {
  const WorldGeometry geometry = flatten(scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  const PixelSurfaces surfaces = findPixelSurfaces(geometry, *kernel, camera, kWidth, kHeight);
  std::vector<std::size_t> compared;
  double mean = 0.0;
  for (std::size_t i = 0; i < rendered.pixels.size(); ++i) {
    const double yt = luminance(reference.radiance.pixels[i]);
    if (!surfaces.interior[i] || !(yt > 0.0)) continue;
    const uint32_t instance = geometry.triangleInstance[surfaces.triangle[i]];
    if (!instances.empty() &&
        std::find(instances.begin(), instances.end(), instance) == instances.end())
      continue;
    compared.push_back(i);
    mean += yt;
  }
  mean /= std::max<double>(1.0, static_cast<double>(compared.size()));
  int disagree = 0;
  for (const std::size_t i : compared) {
    const double yt = luminance(reference.radiance.pixels[i]);
    const double sigma = luminance(reference.stdError.pixels[i]);
    disagree += std::abs(luminance(rendered.pixels[i]) - yt) > 0.2 * yt + 3 * sigma + 0.01 * mean;
  }
  return {disagree, static_cast<int>(compared.size())};
}

// Every static surface reads baked visibility (the mat and the table per corner) and nothing
// moves: no shadow map is drawn and no pixel takes a shadow-map tap (the cost view), and the
// table's soft shadow on the mat still matches the path tracer.
TEST(BakedDirect, ProbeLitInstancesReadTheirCornersAndNoShadowMapIsDrawn) {
  const Scene scene = matUnderAProbeLitTable(false);
  const Camera camera = overTheRoom();
  const Bake bake = bakeVisibility(scene).folder;
  ASSERT_TRUE(bake.probes.has_value());
  ASSERT_EQ(bake.probes->grids.size(), 2u);  // the mat and the table
  EXPECT_EQ(bake.probes->visibility.corners.size(), 3u * (800u + 12u));
  testContext();
  RendererSettings cost;
  cost.mode = RenderMode::Cost;
  ForwardRenderer counter(scene, gl::shaderDirectory(), cost, &bake);
  const Image counts = counter.renderImage(camera, kWidth, kHeight);
  EXPECT_EQ(counter.shadowDrawCount().views, 0);
  EXPECT_EQ(counter.areaShadowChoice().lights.size(), 0u);
  float taps = 0.0f;
  for (const glm::vec3& c : counts.pixels) taps = std::max(taps, c.b);
  EXPECT_EQ(taps, 0.0f) << "the most shadow-map taps a pixel took";
  // The mat's 6 cm triangles, 1.2 m under the panel, read its light from their corners
  // (render/static_direct_corners.h): no light is evaluated at their pixels.
  const uint32_t mat = 2, table = 3;
  {
    const WorldGeometry geometry = flatten(scene);
    const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
    const PixelSurfaces surfaces = findPixelSurfaces(geometry, *kernel, camera, kWidth, kHeight);
    int matPixels = 0, evaluating = 0;
    for (std::size_t i = 0; i < counts.pixels.size(); ++i) {
      if (!surfaces.interior[i] || geometry.triangleInstance[surfaces.triangle[i]] != mat) continue;
      ++matPixels;
      evaluating += counts.pixels[i].r > 0.0f;
    }
    EXPECT_GT(matPixels, 100);
    EXPECT_EQ(evaluating, 0) << "of " << matPixels << " mat pixels evaluated a light";
  }

  const Reference reference =
      traceReference(scene, camera, kWidth, kHeight, 1024, PathSet::DirectOnly);
  const Image rendered = renderDirect(scene, &bake, camera);
  const auto [disagree, pixels] =
      disagreeingPixels(scene, camera, rendered, reference, {mat, table});
  const auto [onTable, tablePixels] =
      disagreeingPixels(scene, camera, rendered, reference, {table});
  const IndirectComparison all = compareIndirect(scene, camera, rendered, reference);
  std::printf(
      "probe-lit mat and table under a panel: %d of %d of their pixels disagree (table %d of "
      "%d); every surface %.2f%% (bias %+.2f%%, reference noise %.2f%%)\n",
      disagree, pixels, onTable, tablePixels, 100 * all.meanAbsRelError, 100 * all.bias,
      100 * all.referenceNoise);
  ASSERT_GT(pixels, 200);
  EXPECT_LE(disagree, pixels / 100);
  EXPECT_LT(all.meanAbsRelError, 0.05 + all.referenceNoise);
}

// The same with a dynamic box on the mat, half under the probe-lit table: the box's shadow on
// the mat and the floor (static receivers: baked V times the dynamic casters' cube) and the
// table's shadow on the box (a dynamic receiver: the all-caster cube) both appear.
TEST(BakedDirect, ADynamicBoxShadowsTheProbeLitMatAndTakesTheProbeLitTablesShadow) {
  const Scene scene = matUnderAProbeLitTable(true);
  const Camera camera = overTheRoom();
  const Bake bake = bakeVisibility(scene).folder;
  ASSERT_TRUE(bake.probes.has_value());
  const Reference reference =
      traceReference(scene, camera, kWidth, kHeight, 1024, PathSet::DirectOnly);
  const Image rendered = renderDirect(scene, &bake, camera);
  const uint32_t mat = 2, box = 4;
  const auto [onMat, matPixels] = disagreeingPixels(scene, camera, rendered, reference, {mat});
  const auto [onBox, boxPixels] = disagreeingPixels(scene, camera, rendered, reference, {box});
  const auto [disagree, pixels] = disagreeingPixels(scene, camera, rendered, reference, {});
  std::printf(
      "dynamic box on a probe-lit mat under a probe-lit table: %d of %d pixels disagree (mat %d "
      "of %d, box %d of %d)\n",
      disagree, pixels, onMat, matPixels, onBox, boxPixels);
  ASSERT_GT(boxPixels, 20);
  EXPECT_LE(onBox, boxPixels / 20);
  EXPECT_LE(onMat, matPixels / 20);
  EXPECT_LE(disagree, pixels / 100);
}

// With ShadowSettings::bakedPunctualMapsOnlyForDynamic (the default since a chart without points
// is baked dark: fillVisibility):
// a static spot over a static table on a lightmapped floor: the bake names the spot, so with
// nothing dynamic no map is drawn and no pixel takes a tap, and the table's shadow comes from the
// floor's 2.5 cm texels alone: its hard edge blurred over a texel (5.1% off the tracer over the
// frame, against 1.0% with the map; bound 10%: without the baked V the shadow is gone, 128%). A
// dynamic box in the spot's reach brings its map back (all casters: the box's shadow on the
// floor, the table's on the box; static surfaces take min(V_map, V_baked)).
TEST(BakedDirect, ABakedSpotDrawsAMapOnlyWhileADynamicBoxIsInItsReach) {
  const auto spotScene = [](bool box) {
    Scene scene;
    addQuad(scene, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, matte("floor", glm::vec3(0.7f)));
    addBox(scene, {-0.5f, 0.55f, -0.5f}, {0.1f, 0.6f, 0.2f}, matte("table", glm::vec3(0.6f)));
    if (box) {
      addBox(scene, {0.2f, 0.0f, 0.1f}, {0.45f, 0.25f, 0.35f}, matte("box", glm::vec3(0.8f)));
      scene.instances.back().mobility = Mobility::Dynamic;
    }
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0.1f, 1.3f, 0.1f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.intensity = glm::vec3(3.0f);
    spot.innerConeAngle = 0.6f;
    spot.outerConeAngle = 0.9f;
    scene.lights.push_back(spot);
    return scene;
  };
  const Camera camera = overTheRoom();
  testContext();
  RendererSettings cost;
  cost.mode = RenderMode::Cost;
  cost.shadows.bakedPunctualMapsOnlyForDynamic = true;
  {
    const Scene scene = spotScene(false);
    const Bake bake = bakeVisibility(scene).folder;
    ASSERT_TRUE(bake.visibility.has_value());
    ASSERT_EQ(bake.visibility->punctualCount, 1u);
    ForwardRenderer counter(scene, gl::shaderDirectory(), cost, &bake);
    const Image counts = counter.renderImage(camera, kWidth, kHeight);
    EXPECT_EQ(counter.shadowDrawCount().views, 0);
    EXPECT_EQ(counter.punctualShadowSlots()[0], -1);
    float taps = 0.0f;
    for (const glm::vec3& c : counts.pixels) taps = std::max(taps, c.b);
    EXPECT_EQ(taps, 0.0f) << "the most shadow-map taps a pixel took";
    const Reference reference =
        traceReference(scene, camera, kWidth, kHeight, 1024, PathSet::DirectOnly);
    const IndirectComparison all =
        compareIndirect(scene, camera, renderDirect(scene, &bake, camera, true), reference);
    std::printf("baked spot, no map: %.2f%% (bias %+.2f%%, reference noise %.2f%%)\n",
                100 * all.meanAbsRelError, 100 * all.bias, 100 * all.referenceNoise);
    EXPECT_LT(all.meanAbsRelError, 0.10 + all.referenceNoise);
  }
  const Scene scene = spotScene(true);
  const Bake bake = bakeVisibility(scene).folder;
  ForwardRenderer counter(scene, gl::shaderDirectory(), cost, &bake);
  counter.renderImage(camera, kWidth, kHeight);
  EXPECT_GT(counter.shadowDrawCount().views, 0);
  EXPECT_EQ(counter.punctualShadowSlots()[0], 0);
  const Reference reference =
      traceReference(scene, camera, kWidth, kHeight, 1024, PathSet::DirectOnly);
  const Image rendered = renderDirect(scene, &bake, camera, true);
  const uint32_t floor = 0;
  const auto [onFloor, floorPixels] =
      disagreeingPixels(scene, camera, rendered, reference, {floor});
  std::printf("baked spot and a dynamic box: %d of %d floor pixels disagree\n", onFloor,
              floorPixels);
  ASSERT_GT(floorPixels, kWidth * kHeight / 4);
  EXPECT_LE(onFloor, floorPixels / 100);
}

}  // namespace
}  // namespace bounce::test
