// The Conference Room (../shared, 331k triangles): every surface of the camera's view (as the
// renderer draws it) that the path tracer lights has baked light. 14-25 s on 2 cores (atlas, a
// 64-spp bake, 32k traced pixels), so it is disabled in CI; run it with (docs/baker.md)
//   build/release/bin/bake_test --gtest_also_run_disabled_tests --gtest_filter='Conference*'
#include <gtest/gtest.h>

#include <cstdio>

#include "atlas/atlas.h"
#include "bake/lightmap_bake.h"
#include "bake/texel_coverage.h"
#include "scene/load.h"
#include "scene/surface_rules.h"
#include "trace/camera_render.h"
#include "trace/path_tracer.h"
#include "trace/sampling.h"

namespace bounce {
namespace {

TEST(ConferenceLitSurfaces, DISABLED_EverySurfaceThePathTracerLightsHasBakedLight) {
  const Scene scene = loadScene(BOUNCE_SOURCE_DIR "/content/conference/conference.json");
  const WorldGeometry geometry = flatten(scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  const Atlas atlas = buildAtlas(scene, AtlasSettings{.texelBudget = 16384});
  LightmapBakeSettings settings = defaultBakeSettings();
  settings.irradiance.maxSpp = 64;
  settings.irradiance.targetError = 0.0f;
  const LightmapBake bake = bakeLightmap(scene, geometry, *kernel, atlas.layout, settings);
  const LightmapLayout& layout = atlas.layout;
  const std::vector<InstanceBase> bases = instanceBases(scene);

  // What the camera sees first, the tracer's indirect irradiance on the side facing the
  // camera, and the lightmap texel there.
  TraceSettings trace;
  trace.paths = PathSet::IndirectOnly;
  const PathTracer tracer(scene, geometry, *kernel, trace);
  const Camera& camera = scene.cameras.at(scene.findCamera("corner"));
  const int width = 240, height = 135, spp = 32;
  int lit = 0, black = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      // The renderer's view: single-sided faces seen from behind are culled (see past them).
      Ray ray = cameraRay(camera, width, height, x + 0.5f, y + 0.5f);
      Hit hit = kernel->intersect(ray);
      for (int k = 0; k < 16 && hit.valid(); ++k) {
        const bool back = glm::dot(geometry.triangleCross(hit.triangle), ray.direction) > 0.0f;
        if (!back || materialOf(scene, geometry.triangleMaterial[hit.triangle]).doubleSided) break;
        ray.tmin = hit.t + 1e-4f;
        hit = kernel->intersect(ray);
      }
      if (!hit.valid()) continue;
      const uint32_t instance = geometry.triangleInstance[hit.triangle];
      const InstanceLightmapUv* region = layout.find(instance);
      if (region == nullptr) continue;  // dynamic or too small (atlas.h): lit by the VPLs
      glm::vec3 n = glm::normalize(geometry.triangleCross(hit.triangle));
      if (glm::dot(n, ray.direction) > 0.0f) n = -n;
      const glm::vec3 p = ray.origin + hit.t * ray.direction;
      SobolSampler sampler(3, static_cast<uint32_t>(y * width + x));
      int nonZero = 0;
      for (int s = 0; s < spp; ++s) {
        sampler.startSample(static_cast<uint32_t>(s));
        nonZero += luminance(tracer.irradiance(p, n, sampler)) > 0.0f ? 1 : 0;
      }
      // Lit: at least 4 of 32 samples found light, so the bake's 64 samples per texel (over
      // its points) miss it with probability below (1 − 1/8)^64 ≈ 2e-4.
      if (nonZero < 4) continue;
      ++lit;
      const std::size_t local = hit.triangle - bases[instance].triangle;
      const glm::vec2 uv = (1.0f - hit.u - hit.v) * region->cornerUv[3 * local] +
                           hit.u * region->cornerUv[3 * local + 1] +
                           hit.v * region->cornerUv[3 * local + 2];
      const int tx = std::clamp(static_cast<int>(uv.x * layout.width), 0, layout.width - 1);
      const int ty = std::clamp(static_cast<int>(uv.y * layout.height), 0, layout.height - 1);
      if (!(luminance(bake.irradiance.pixels[static_cast<std::size_t>(ty) * layout.width + tx]) >
            0.0f))
        ++black;
    }
  const double fraction = static_cast<double>(black) / std::max(lit, 1);
  std::printf("lit pixels %d, black in the lightmap %d (%.2f%%)\n", lit, black, 100.0 * fraction);
  ASSERT_GT(lit, width * height / 2);
  // What is left is objects smaller than a texel (a 3 cm bracket whose texel holds a face
  // that sees nothing), a matter of texel density, not of the side the lightmap holds.
  EXPECT_LT(fraction, 0.005);
}

}  // namespace
}  // namespace bounce
