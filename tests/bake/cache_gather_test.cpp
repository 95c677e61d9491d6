// The cache gather (bake/irradiance_cache.h, LightmapBakeSettings::gather): paths that end at a
// short bake's map after one reflection, against closed forms and against whole paths, and its
// guards each in a room where reading the cache would be wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "bake_folder/gather.h"
#include "bake_scenes.h"
#include "trace/sampling.h"

namespace bounce {
namespace {

LightmapBakeSettings cacheSettings(int spp, int cacheSpp, int threads = 0) {
  LightmapBakeSettings settings = test::testBakeSettings(spp, 7, threads);
  settings.gather = Gather::Cache;
  settings.cacheSpp = cacheSpp;
  return settings;
}

// Mean of the luminance over `texels` and its standard error from the texels' own estimates.
struct TexelMean {
  double mean = 0.0, standardError = 0.0;
};
TexelMean texelMean(const LightmapBake& bake, const std::vector<std::size_t>& texels) {
  double sum = 0.0, variance = 0.0;
  for (const std::size_t t : texels) {
    const double e = luminance(bake.irradiance.pixels[t]);
    const double se = bake.relativeError[t] * e;
    sum += e;
    variance += se * se;
  }
  const double n = static_cast<double>(texels.size());
  return {sum / n, std::sqrt(variance) / n};
}

// The closed furnace of BakePhysics.FurnaceIndirectIrradianceIsExact (ρ = 0.5, Le = 1 on every
// face: E_indirect = π·Le·ρ/(1 − ρ) = π everywhere), gathered with a 32-sample cache. A texel's
// estimate is ρ/π·(E_direct(y) + E_cache(y)) over cosine directions: the final samples' noise
// plus the cache's error carried by ρ (at most ρ × the cache map's own standard error of the
// same mean; its texels are independent of the final pass's samples: another seed).
TEST(CacheGather, ClosedFurnaceGivesTheExactIrradiance) {
  const test::ClosedFurnace furnace(0.5f, 1.0f);
  const test::World& world = furnace.world;
  const double rho = furnace.rho;
  const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.125f, 40);
  const LightmapBake cached =
      bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, cacheSettings(64, 32));
  const LightmapBake cacheAlike = bakeLightmap(world.scene, world.geometry, *world.kernel,
                                               atlas.layout, test::testBakeSettings(32, 8));
  std::vector<std::size_t> texels;
  for (std::size_t t = 0; t < cached.covered.size(); ++t)
    if (cached.covered[t]) texels.push_back(t);
  ASSERT_EQ(texels.size(), 6u * 64u);
  EXPECT_EQ(cached.cacheSamples, 32u * texels.size());
  const double exact = furnace.exactIndirectIrradiance();
  const TexelMean final = texelMean(cached, texels);
  const double cacheError = rho * texelMean(cacheAlike, texels).standardError;
  const double tolerance = 5.0 * std::hypot(final.standardError, cacheError);
  EXPECT_NEAR(final.mean, exact, tolerance)
      << "final pass SE " << final.standardError << ", cache's share " << cacheError;
  // Every texel too, against its own noise and the cache's.
  int outliers = 0;
  for (const std::size_t t : texels) {
    const double e = luminance(cached.irradiance.pixels[t]);
    if (std::abs(e - exact) > 5.0 * std::hypot(cached.relativeError[t] * e, cacheError * 8.0))
      ++outliers;
  }
  EXPECT_LE(outliers, static_cast<int>(texels.size()) / 100);
  // One reflection and its emission instead of whole paths: fewer rays per sample.
  const double raysPerSample = static_cast<double>(cached.rays + cached.cacheRays) /
                               static_cast<double>(cached.totalSamples + cached.cacheSamples);
  const double pathRaysPerSample =
      static_cast<double>(cacheAlike.rays) / static_cast<double>(cacheAlike.totalSamples);
  EXPECT_LT(raysPerSample, pathRaysPerSample);
  std::printf(
      "furnace: %.4f W/m² (exact %.4f, tolerance %.4f), rays per sample %.2f (paths %.2f)\n",
      final.mean, exact, tolerance, raysPerSample, pathRaysPerSample);
}

// The error the bake reports holds the cache's noise (delivered_error.h, irradiance_cache.h):
// each final half reads its own half cache, so the half difference D carries the cache's error
// with the final samples'. The closed furnace above at 25 cm texels (96), 512 final samples and
// a 2-sample cache (one path a half), where the cache's error is most of the map's: pooled over
// six seeds, RMS of the reported draw |D| against the RMS of |E − exact| / exact, within issue
// 28's factor 1.5 (seeds 10–15, 30–35, 50–55, 70–75: 1.20, 1.36, 1.01, 1.05). Pooled because a
// map's cache error is one draw shared by the texels that read the same cache texels. Injected,
// the halves reading one shared cache: 0.39, 0.50, 0.44, 0.54 (fails).
TEST(CacheGather, ReportedErrorHoldsTheCachesNoise) {
  const test::ClosedFurnace furnace(0.5f, 1.0f);
  const test::World& world = furnace.world;
  const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.25f, 40);
  const double exact = furnace.exactIndirectIrradiance();
  double reported2 = 0.0, measured2 = 0.0;
  for (uint32_t seed = 10; seed < 16; ++seed) {
    LightmapBakeSettings settings = cacheSettings(512, 2);
    settings.irradiance.seed = seed;
    const LightmapBake bake =
        bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, settings);
    for (std::size_t t = 0; t < bake.covered.size(); ++t) {
      if (bake.delivered.perTexel[t] < 0.0f) continue;
      const double e = luminance(bake.irradiance.pixels[t]);
      const double measured = (e - exact) / exact;
      const double reported = bake.delivered.perTexel[t] * e / exact;  // |D| / exact
      measured2 += measured * measured;
      reported2 += reported * reported;
    }
  }
  const double ratio = std::sqrt(reported2 / measured2);
  std::printf("furnace, 2-sample cache: reported / measured RMS %.3f\n", ratio);
  EXPECT_LT(ratio, 1.5);
  EXPECT_GT(ratio, 1.0 / 1.5);
}

// A 90 cm square slab hovering 1 cm over the floor of a lit room, its underside facing the floor:
// a slot far narrower than the 10 cm texels. The slab's edges lie in the middle of floor texels,
// so the floor texel under each edge averages the bright floor outside with the dark floor
// inside the slot. A path from the slab's underside meets the floor 1 cm below: reading that
// texel there would bring the outside's light into the slot. The close guard (hits nearer than
// two texel edges go on as whole paths) keeps the slab's underside at what whole paths give.
TEST(CacheGather, CloseGuardKeepsANarrowSlotAsWholePathsLightIt) {
#ifdef __SANITIZE_ADDRESS__
  // About 17.1 s under AddressSanitizer, most of it the whole-path bake it is compared with; the
  // same code runs under ASan in the smaller tests. CI's whole run keeps to its 25 minutes.
  GTEST_SKIP() << "an accuracy measurement: run in the release build";
#endif
  test::World world;
  const uint32_t white = test::addMaterial(world.scene, glm::vec3(0.6f));
  const uint32_t lamp = test::addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(20.0f));
  test::addInwardBox(world.scene, {0, 0, 0}, {2, 1, 2}, white);
  const float h = 0.01f, lo = 0.55f, hi = 1.45f;  // the slab, facing down
  test::addQuad(world.scene, {lo, h, lo}, {hi, h, lo}, {hi, h, hi}, {lo, h, hi}, white);
  test::addQuad(world.scene, {0.8f, 0.98f, 0.8f}, {1.2f, 0.98f, 0.8f}, {1.2f, 0.98f, 1.2f},
                {0.8f, 0.98f, 1.2f}, lamp);  // faces down
  world.build();
  ASSERT_LT(world.scene.instances.size(), 9u);
  const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.1f, 64);
  const LightmapBake cached = bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout,
                                           cacheSettings(256, 64));
  const LightmapBake paths = bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout,
                                          test::testBakeSettings(1024, 8));
  const LightmapBake cacheAlike = bakeLightmap(world.scene, world.geometry, *world.kernel,
                                               atlas.layout, test::testBakeSettings(64, 9));
  // The slab's underside texels (instance 6).
  std::vector<std::size_t> slab;
  for (int y = 0; y < atlas.layout.height; ++y)
    for (int x = 0; x < atlas.layout.width; ++x) {
      glm::vec3 p;
      uint32_t instance;
      const std::size_t t = cached.irradiance.index(x, y);
      if (cached.covered[t] && !cached.invalid[t] && atlas.texelCentre(x, y, p, instance) &&
          instance == 6)
        slab.push_back(t);
    }
  ASSERT_EQ(slab.size(), 81u);
  const TexelMean c = texelMean(cached, slab), r = texelMean(paths, slab);
  const double cacheError = 0.6 * texelMean(cacheAlike, slab).standardError;
  const double tolerance =
      5.0 * std::sqrt(c.standardError * c.standardError + r.standardError * r.standardError +
                      cacheError * cacheError);
  EXPECT_NEAR(c.mean, r.mean, tolerance) << "whole paths " << r.mean << " W/m²";
  std::printf(
      "slot: slab underside %.4f W/m² with the cache, %.4f with whole paths (tolerance "
      "%.4f)\n",
      c.mean, r.mean, tolerance);
}

// A room cut in two by a double-sided partition whose front faces the lamp's half: no light
// reaches the other half, so its texels are exactly 0. Its paths meet the partition's back face,
// whose texels hold the lit front side: the back-face guard never reads them from behind.
TEST(CacheGather, BackFaceGuardKeepsTheDarkSideOfAPartitionBlack) {
  test::World world;
  const uint32_t white = test::addMaterial(world.scene, glm::vec3(0.8f));
  const uint32_t sheet = test::addMaterial(world.scene, glm::vec3(0.8f), glm::vec3(0.0f), true);
  const uint32_t lamp = test::addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(20.0f));
  test::addInwardBox(world.scene, {0, 0, 0}, {2, 1, 1}, white);
  test::addQuad(world.scene, {1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}, sheet);  // faces −x
  test::addQuad(world.scene, {0.3f, 0.95f, 0.35f}, {0.6f, 0.95f, 0.35f}, {0.6f, 0.95f, 0.65f},
                {0.3f, 0.95f, 0.65f}, lamp);  // faces down
  world.build();
  const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.1f, 64);
  const LightmapBake bake =
      bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, cacheSettings(64, 32));
  int dark = 0, lit = 0;
  for (int y = 0; y < atlas.layout.height; ++y)
    for (int x = 0; x < atlas.layout.width; ++x) {
      const std::size_t t = bake.irradiance.index(x, y);
      glm::vec3 p;
      uint32_t instance;
      if (!bake.covered[t] || !atlas.texelCentre(x, y, p, instance) || instance >= 6) continue;
      if (p.x > 1.0f) {
        EXPECT_EQ(bake.irradiance.pixels[t], glm::vec3(0.0f))
            << "dark half's texel (" << x << "," << y << ") at " << p.x << "," << p.y << "," << p.z;
        ++dark;
      } else if (luminance(bake.irradiance.pixels[t]) > 0.0f) {
        ++lit;
      }
    }
  EXPECT_GT(dark, 150);
  EXPECT_GT(lit, 150);
}

// The cache pass is a whole-map stage of its own seed: the map is the same bytes at any thread
// count and tile size.
TEST(CacheGather, SameBytesAtOneAndTwoThreadsAndAnyTileSize) {
  test::World world;
  const uint32_t white = test::addMaterial(world.scene, glm::vec3(0.7f));
  const uint32_t lamp = test::addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(10.0f));
  test::addInwardBox(world.scene, {0, 0, 0}, {1, 1, 1}, white);
  test::addQuad(world.scene, {0.4f, 0.95f, 0.4f}, {0.6f, 0.95f, 0.4f}, {0.6f, 0.95f, 0.6f},
                {0.4f, 0.95f, 0.6f}, lamp);
  world.build();
  const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.05f, 64);
  LightmapBakeSettings one = cacheSettings(64, 16, 1);
  one.irradiance.targetError = 0.1f;
  one.denoise = true;
  one.tiles.size = 7;
  LightmapBakeSettings two = cacheSettings(64, 16, 2);
  two.irradiance.targetError = 0.1f;
  two.denoise = true;
  const LightmapBake a =
      bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, one);
  const LightmapBake b =
      bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, two);
  test::expectSameLightmap(a, b);
  EXPECT_GT(a.cacheSamples, 0u);
}

}  // namespace
}  // namespace bounce
