// The error a bake reports is the error of the map it delivers (bake/delivered_error.h): the
// reported mean and p95 against the measured |E − E_conv| / E_conv of a default bake (denoised,
// filled, dilated, stitched) against a converged bake of the same texels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "bake/error_summary.h"
#include "bake_scenes.h"
#include "trace/sampling.h"

namespace bounce {
namespace {

// The corner lamp room at 6.25 cm texels (1.6k texels, every filter at work: the denoiser's
// steps 1–8, dilation under the lamp, seams between the walls), bounce-bake's defaults (10%
// target, 4096 cap, denoiser on), against a 4096-spp denoised bake of another seed. The error
// here is noise and bias alike: the adaptive stop leaves the map 3% low (the undenoised map's
// mean signed error −3.1%), which the halves alone cannot see. The measured error includes the
// converged bake's own (its estimate 1.8% mean, in quadrature about 1/12 of the measured mean).
// Both sides are means over 1.6k texels whose errors the denoiser correlates over a few texels:
// with the denoised cache of before, seeds 1, 2, 3, 5, 6 gave reported/measured 0.96, 0.87, 0.77,
// 0.84, 0.93 (mean) and 0.89, 0.84, 0.75, 0.81, 0.85 (p95); with the raw half caches (each final
// half reads its own), seed 3 gives 0.0297 / 0.0724 against 0.0403 / 0.0866 (0.74 / 0.84). The
// bound is issue 28's factor 1.5. Injected, each fails: the per-texel figure before the filters
// reported (0.098 against the measured 0.045), the halves not denoised (0.081), the halves
// filtered with the map's weights instead of their own (0.027). The halves reading one shared
// cache does not fail here (0.73 / 0.80: the 32-sample cache's error is a small part of this
// room's); CacheGather.ReportedErrorHoldsTheCachesNoise guards that.
TEST(DeliveredError, ReportedErrorIsTheDeliveredMapsAgainstAConvergedBake) {
#ifdef __SANITIZE_ADDRESS__
  // About 26.5 s under AddressSanitizer, most of it the converged bake's samples; the same code
  // runs under ASan in the smaller tests. CI's whole run keeps to its 25 minutes.
  GTEST_SKIP() << "an accuracy measurement: run in the release build";
#endif
  test::World world;
  test::buildCornerLampRoom(world);
  const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.0625f, 80);
  LightmapBakeSettings settings = defaultBakeSettings();
  settings.irradiance.seed = 3;
  LightmapBakeSettings converged = defaultBakeSettings();
  converged.irradiance.seed = 4;
  converged.irradiance.targetError = 0.0f;
  converged.irradiance.maxSpp = 4096;
  const LightmapBake bake =
      bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, settings);
  const LightmapBake reference =
      bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, converged);
  std::vector<float> measured;
  for (std::size_t t = 0; t < bake.covered.size(); ++t) {
    const double c = luminance(reference.irradiance.pixels[t]);
    // The texels the figures are over: samples of their own, lit, not filled from neighbours.
    if (bake.delivered.perTexel[t] < 0.0f || bake.zeroFilled[t] || !(c > 0.0)) continue;
    measured.push_back(static_cast<float>(std::abs(luminance(bake.irradiance.pixels[t]) - c) / c));
  }
  ASSERT_GT(measured.size(), 1000u);
  const ErrorSummary actual = summariseErrors(measured);
  std::printf(
      "%zu texels: measured mean %.4f p95 %.4f; reported mean %.4f p95 %.4f (before the filters "
      "%.4f / %.4f); the converged bake's own %.4f / %.4f\n",
      measured.size(), actual.mean, actual.p95, bake.delivered.mean, bake.delivered.p95,
      bake.meanRelativeError, bake.p95RelativeError, reference.delivered.mean,
      reference.delivered.p95);
  EXPECT_LT(bake.delivered.mean, 1.5 * actual.mean);
  EXPECT_GT(bake.delivered.mean, actual.mean / 1.5);
  EXPECT_LT(bake.delivered.p95, 1.5 * actual.p95);
  EXPECT_GT(bake.delivered.p95, actual.p95 / 1.5);
}

}  // namespace
}  // namespace bounce
