// CI-sized version of bench_bake's accuracy measurement: the Cornell box baked on a small atlas
// with few samples, each texel against independent path-traced irradiance over its area, the
// tolerance from both estimates' standard errors.
#include <gtest/gtest.h>

#include <cmath>

#include "atlas/atlas.h"
#include "bake/lightmap_bake.h"
#include "bake/texel_coverage.h"
#include "scene/load.h"
#include "trace/path_tracer.h"
#include "trace/sampling.h"

namespace bounce {
namespace {

TEST(CornellBake, TexelsAgreeWithPathTracedIrradianceWithinTheirErrors) {
  const Scene scene = loadScene(BOUNCE_SOURCE_DIR "/content/cornell_box/cornell_box.gltf");
  const WorldGeometry geometry = flatten(scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  AtlasSettings atlasSettings;
  atlasSettings.texelBudget = 1024;
  const Atlas atlas = buildAtlas(scene, atlasSettings);
  LightmapBakeSettings settings = defaultBakeSettings();
  settings.irradiance.targetError = 0.2f;
  settings.denoise = false;  // so that each texel's estimated error describes it
  const LightmapBake bake = bakeLightmap(scene, geometry, *kernel, atlas.layout, settings);

  // Reference: 1024 indirect-only samples per texel over 32 points of its own pattern (the same
  // coverage rule, an independent seed), for every 8th valid texel.
  TexelCoverage coverage = buildTexelCoverage(scene, geometry, atlas.layout, 32, 4321);
  guardAgainstLeaks(scene, geometry, *kernel, atlas.layout.texelSize, LeakGuardSettings{},
                    coverage);
  TraceSettings trace;
  trace.paths = PathSet::IndirectOnly;
  const PathTracer tracer(scene, geometry, *kernel, trace);
  int compared = 0, outside = 0;
  double sumRel = 0;
  std::size_t valid = 0;
  for (std::size_t t = 0; t < coverage.texelCount(); ++t) {
    if (!coverage.covered(t) || bake.invalid[t] || (valid++ % 8) != 0) continue;
    SobolSampler sampler(99, static_cast<uint32_t>(t));
    const int n = 1024;
    double sum = 0, sum2 = 0;
    for (int s = 0; s < n; ++s) {
      sampler.startSample(static_cast<uint32_t>(s));
      const uint32_t k = std::min(
          coverage.pointCount(t) - 1,
          static_cast<uint32_t>(sampler.get1D() * static_cast<float>(coverage.pointCount(t))));
      const TexelPoint& p = coverage.points[coverage.first[t] + k];
      const double e = luminance(tracer.irradiance(p.position, p.shadingNormal, sampler));
      sum += e;
      sum2 += e * e;
    }
    const double ref = sum / n;
    const double seRef = std::sqrt(std::max(0.0, sum2 / n - ref * ref) / (n - 1));
    const double e = luminance(bake.irradiance.pixels[t]);
    const double seBake = bake.relativeError[t] * e;
    ASSERT_GT(ref, 0.0);
    if (std::abs(e - ref) > 4.0 * std::sqrt(seRef * seRef + seBake * seBake)) ++outside;
    sumRel += std::abs(e - ref) / ref;
    ++compared;
  }
  ASSERT_GT(compared, 60);
  // 4 standard errors: ≤ 0.01% of texels by chance; allow 2 of them (quadrature of 8 points
  // against 32 is not in the standard error).
  EXPECT_LE(outside, 2) << "of " << compared;
  // Target 20%: mean |relative error| ≈ 0.8 × (the bake's ≈ 0.2 ⊕ the reference's) ≲ 20%.
  EXPECT_LT(sumRel / compared, 0.2);
}

}  // namespace
}  // namespace bounce
