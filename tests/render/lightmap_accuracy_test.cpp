// End to end, CI-sized: the baker's lightmap drawn by the renderer against the reference path
// tracer (the Cornell box's indirect-only frame), and seams on a curved object.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "indirect_accuracy.h"
#include "lightmap_scenes.h"
#include "scene/load.h"
#include "test_scenes.h"

namespace bounce::test {
namespace {

// The Cornell box with a small bake (4096 texels of 2.2 cm, 10% target error per texel, at most
// 1024 samples; bounce-bake's defaults otherwise, but not denoised: at this coarse texel size
// the denoiser does not help, 4.6% with it against 4.2% without in the full-size sweep,
// docs/renderer.md "Baked light") and a 32×32 frame whose reference has 4096 samples per pixel
// (mean relative standard error ~3%). Goal: mean |ΔY|/Y ≤ 5% over the static, non-emissive,
// edge-free pixels; the reference's own noise can add up to referenceNoise (≈ 2.4%) to the
// measured mean, so that is the allowance.
TEST(LightmapAccuracy, CornellIndirectFrameMatchesThePathTracer) {
#ifdef __SANITIZE_ADDRESS__
  // About 23 s under AddressSanitizer, most of it the path tracer's reference or the bake's
  // samples; the same code runs under ASan in the smaller tests. CI's sanitizer stage keeps to
  // its 30 minutes.
  GTEST_SKIP() << "an accuracy measurement: run in the release build";
#endif
  const Scene scene =
      loadScene(std::filesystem::path(BOUNCE_SOURCE_DIR) / "content/cornell_box/cornell_box.gltf");
  SceneBakeSettings settings = lightmapOnlySettings();
  settings.texelBudget = 4096;
  settings.maxSpp = 1024;
  settings.targetError = 0.1f;
  settings.denoise = false;
  const Bake baked = bakeScene(scene, settings).folder;
  testContext();
  const Camera& camera = scene.cameras.at(0);
  const Image rendered = renderIndirect(scene, baked, camera, 32, 32);
  const IndirectComparison c =
      compareIndirect(scene, camera, rendered, traceIndirectReference(scene, camera, 32, 32, 4096));
  std::printf(
      "Cornell indirect, %dx%d lightmap: mean |dY|/Y = %.4f over %zu pixels (bias %+.4f); "
      "reference mean relative standard error %.4f, noise allowance %.4f; bake %.2f s, "
      "estimated texel error mean %.4f\n",
      baked.layout.width, baked.layout.height, c.meanAbsRelError, c.pixels, c.bias,
      c.meanRelStdError, c.referenceNoise, baked.manifest.measured.seconds.total,
      baked.manifest.estimatedError.mean);
  EXPECT_GT(c.pixels, 500u);  // most of the 1024 pixels see walls and blocks
  EXPECT_LT(c.meanRelStdError, 0.04);
  EXPECT_LE(c.meanAbsRelError, 0.05 + c.referenceNoise);
}

// A sphere (smooth normals, 32 × 16 facets, so the atlas cuts it into several charts) over a
// white floor under a square emitter: its lower half gets light bounced off the floor, its upper
// half almost none, so the baked irradiance varies strongly across it. Seen from 0.7 m with a
// lightmap texel spanning several pixels, the largest jump in rendered radiance between two
// neighbouring pixels in different charts must be no larger than the largest between
// neighbours inside one chart, i.e. whose bilinear lookups (and one texel around them) read
// only texels of their own chart: near a chart's border the lookup reads border and padding
// texels, which is what seam stitching is about, so those pairs are not the reference.
// Without stitching the two sides of a seam read independent, noisy texels.
TEST(LightmapAccuracy, NoSeamJumpsLargerThanInsideAChart) {
  Scene scene;
  Material floor;
  floor.name = "floor";
  floor.albedo = glm::vec3(0.8f);
  addQuad(scene, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, floor);  // 2 m square, faces up
  Material emitter;
  emitter.name = "emitter";
  emitter.albedo = glm::vec3(0.0f);
  emitter.emission = glm::vec3(20.0f);
  addQuad(scene, {-0.3f, 1.2f, -0.3f}, {0.6f, 0, 0}, {0, 0, 0.6f}, emitter);  // faces down
  Material white;
  white.name = "sphere";
  white.albedo = glm::vec3(0.7f);
  const uint32_t sphere = addInstance(scene, uvSphere(0.25f, 16, 32), white,
                                      glm::translate(glm::mat4(1.0f), glm::vec3(0, 0.35f, 0)));
  Camera camera;
  camera.name = "sphere";
  camera.yfov = 0.8f;
  camera.cameraToWorld =
      glm::inverse(glm::lookAt(glm::vec3(0.0f, 0.2f, 0.7f), glm::vec3(0, 0.33f, 0), {0, 1, 0}));
  scene.cameras = {camera};

  SceneBakeSettings settings = lightmapOnlySettings();
  settings.texelBudget = 4096;
  settings.maxSpp = 512;
  settings.targetError = 0.1f;
  const Bake baked = bakeScene(scene, settings).folder;
  const LightmapCharts charts = findCharts(baked.layout);

  constexpr int kSize = 160;
  testContext();
  RendererSettings indirect;
  indirect.mode = RenderMode::Indirect;
  ForwardRenderer renderer(scene, gl::shaderDirectory(), indirect, &baked);
  const Image image = renderer.renderImage(camera, kSize, kSize);

  const WorldGeometry geometry = flatten(scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  const PixelSurfaces surfaces = findPixelSurfaces(geometry, *kernel, camera, kSize, kSize);
  const std::vector<uint32_t> chart = pixelCharts(scene, geometry, baked.layout, charts, surfaces);
  const LightmapLayout& layout = baked.layout;
  const std::vector<int32_t> texelChart = chartIdImage(layout, charts);
  const InstanceLightmapUv& region = *layout.find(sphere);
  uint32_t firstTriangle = 0;
  while (geometry.triangleInstance[firstTriangle] != sphere) ++firstTriangle;
  // The atlas position (texels) of each pixel-centre lookup. The sphere is not mirrored, so
  // world triangle corners follow its mesh's index order (the order of cornerUv).
  const auto atlasTexel = [&](int x, int y) {
    const Hit h = kernel->intersect(cameraRay(camera, kSize, kSize, x + 0.5f, y + 0.5f));
    const std::size_t corner = 3 * static_cast<std::size_t>(h.triangle - firstTriangle);
    const glm::vec2 uv = (1 - h.u - h.v) * region.cornerUv[corner] +
                         h.u * region.cornerUv[corner + 1] + h.v * region.cornerUv[corner + 2];
    return uv * glm::vec2(layout.width, layout.height);
  };
  // Whether the lookup's 2×2 bilinear footprint, grown by one texel, lies in `pixelChart`.
  const auto deepInsideChart = [&](glm::vec2 texel, uint32_t pixelChart) {
    const glm::ivec2 base(glm::floor(texel - 0.5f));
    for (int ty = base.y - 1; ty <= base.y + 2; ++ty)
      for (int tx = base.x - 1; tx <= base.x + 2; ++tx) {
        if (tx < 0 || ty < 0 || tx >= layout.width || ty >= layout.height) return false;
        if (texelChart[static_cast<std::size_t>(ty) * layout.width + tx] !=
            static_cast<int32_t>(pixelChart))
          return false;
      }
    return true;
  };
  std::vector<glm::vec2> texel(surfaces.triangle.size(), glm::vec2(0.0f));
  // On the sphere and away from its silhouette: the pixel's centre and corner rays all hit it.
  std::vector<uint8_t> onSphere(surfaces.triangle.size(), 0), deep(onSphere);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * kSize + x;
      bool all = true;
      for (const auto& [dx, dy] :
           {std::pair{0.02f, 0.02f}, {0.98f, 0.02f}, {0.02f, 0.98f}, {0.98f, 0.98f}}) {
        const Hit h = kernel->intersect(cameraRay(camera, kSize, kSize, x + dx, y + dy));
        all = all && h.valid() && geometry.triangleInstance[h.triangle] == sphere;
      }
      onSphere[i] = all && surfaces.triangle[i] != kNoHit &&
                    geometry.triangleInstance[surfaces.triangle[i]] == sphere;
      if (!onSphere[i]) continue;
      texel[i] = atlasTexel(x, y);
      deep[i] = deepInsideChart(texel[i], chart[i]);
    }

  float insideJump = 0.0f, seamJump = 0.0f;
  std::size_t insidePairs = 0, seamPairs = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (const auto& [dx, dy] : {std::pair{1, 0}, {0, 1}}) {
        if (x + dx >= kSize || y + dy >= kSize) continue;
        const std::size_t a = static_cast<std::size_t>(y) * kSize + x;
        const std::size_t b = static_cast<std::size_t>(y + dy) * kSize + (x + dx);
        if (!onSphere[a] || !onSphere[b]) continue;
        const float jump = std::abs(luminance(image.pixels[a]) - luminance(image.pixels[b]));
        // A seam: neighbours whose lookups lie apart in the atlas (inside a chart they are
        // ~1/7 texel apart), between charts or across a cut of one chart.
        if (glm::length(texel[a] - texel[b]) < 1.5f) {
          if (!deep[a] || !deep[b]) continue;
          insideJump = std::max(insideJump, jump);
          ++insidePairs;
        } else {
          seamJump = std::max(seamJump, jump);
          ++seamPairs;
        }
      }
  std::set<uint32_t> sphereCharts;
  for (std::size_t i = 0; i < chart.size(); ++i)
    if (onSphere[i]) sphereCharts.insert(chart[i]);
  std::printf(
      "sphere: %zu charts in view, texel %.4f m; largest neighbour jump in luminance: %.5f across "
      "a seam (%zu pairs), %.5f inside a chart, away from its border (%zu pairs), W/(sr·m²)\n",
      sphereCharts.size(), baked.layout.texelSize, seamJump, seamPairs, insideJump, insidePairs);
  // The sphere must show seams (two charts at least: it was about ten before charts merged
  // along one run of their shared edges, docs/lightmap_atlas.md step 5).
  EXPECT_GE(sphereCharts.size(), 2u);
  EXPECT_GT(seamPairs, 50u);
  EXPECT_GT(insideJump, 0.0f);
  EXPECT_LE(seamJump, insideJump);
}

}  // namespace
}  // namespace bounce::test
