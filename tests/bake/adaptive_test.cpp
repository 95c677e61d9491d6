// Adaptive sampling reaches its target; the estimated error matches the actual error against a
// long bake; the bake is bit-identical at 1 and 2 threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "bake_scenes.h"
#include "trace/sampling.h"

namespace bounce {
namespace {

std::vector<std::size_t> validLitTexels(const LightmapBake& bake) {
  std::vector<std::size_t> out;
  for (std::size_t t = 0; t < bake.covered.size(); ++t)
    if (bake.covered[t] && !bake.invalid[t] && luminance(bake.irradiance.pixels[t]) > 0.0f)
      out.push_back(t);
  return out;
}

// The corner-lamp room's 12.5 cm atlas baked to a 5 % target with at most `spp` samples a texel
// and the texels' floor `errorFloor` (W/m²).
LightmapBake cornerLampBake(int spp, double errorFloor = 0.0) {
  test::World world;
  test::buildCornerLampRoom(world);
  const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.125f, 40);
  LightmapBakeSettings settings = test::testBakeSettings(spp);
  settings.irradiance.targetError = 0.05f;
  settings.irradiance.errorFloor = errorFloor;
  settings.stitch = false;
  return bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, settings);
}

TEST(AdaptiveSampling, ReachesTheTargetAndSpendsSamplesOnDimTexels) {
  const LightmapBake bake = cornerLampBake(4096);
  const std::vector<std::size_t> texels = validLitTexels(bake);
  ASSERT_GT(texels.size(), 300u);
  int reached = 0;
  for (const std::size_t t : texels) {
    EXPECT_TRUE(bake.relativeError[t] < 0.05f || bake.samples[t] == 4096u) << t;
    reached += bake.relativeError[t] < 0.05f;
    EXPECT_EQ(bake.samples[t] % kIrradianceBatch, 0u);
  }
  EXPECT_GE(reached, static_cast<int>(texels.size() * 95 / 100));
  // Samples follow each texel's own variance: counts spread over more than a factor 4.
  uint32_t fewest = 4096, most = 0;
  for (const std::size_t t : texels) {
    fewest = std::min(fewest, bake.samples[t]);
    most = std::max(most, bake.samples[t]);
  }
  EXPECT_GE(most, 4 * fewest);
  EXPECT_LT(bake.meanRelativeError, 0.05f);
}

// An error floor (IrradianceSettings::errorFloor, W/m²; bounce-bake --error-floor sets it from
// the cache's mean) changes only texels dimmer than it: such a texel may stop once its standard
// error is under target × floor, an absolute error; every texel whose mean stays at or above the
// floor takes the same samples and value bit for bit (each texel's pattern is its own). The floor
// here is the lit texels' median luminance. Injected: the floor applied to the brighter texels
// (they change), the floor ignored (no texel stops earlier): both fail.
TEST(AdaptiveSampling, AnErrorFloorStopsOnlyTexelsDimmerThanItAtItsAbsoluteError) {
  const LightmapBake base = cornerLampBake(512);
  const std::vector<std::size_t> texels = validLitTexels(base);
  ASSERT_GT(texels.size(), 300u);
  std::vector<float> lum;
  for (const std::size_t t : texels) lum.push_back(luminance(base.irradiance.pixels[t]));
  std::nth_element(lum.begin(), lum.begin() + static_cast<std::ptrdiff_t>(lum.size() / 2),
                   lum.end());
  const double floor = lum[lum.size() / 2];
  const LightmapBake floored = cornerLampBake(512, floor);
  int earlier = 0, unchanged = 0;
  for (const std::size_t t : texels) {
    const double mean = luminance(floored.irradiance.pixels[t]);
    if (mean >= floor) {
      EXPECT_EQ(floored.samples[t], base.samples[t]) << "texel " << t << " at " << mean;
      EXPECT_EQ(floored.irradiance.pixels[t], base.irradiance.pixels[t]) << "texel " << t;
      ++unchanged;
      continue;
    }
    EXPECT_LE(floored.samples[t], base.samples[t]) << "texel " << t;
    if (floored.samples[t] < base.samples[t]) {
      ++earlier;
      EXPECT_LT(floored.relativeError[t] * mean, 0.05 * floor * 1.0001) << "texel " << t;
    }
  }
  EXPECT_GT(earlier, 20);
  EXPECT_GT(unchanged, 100);
}

// The per-texel estimate sqrt(s²/n)/mean against the actual relative error of a 64-spp bake
// measured against a 4096-spp bake (whose own error is 8× smaller): their root-mean-squares
// agree within a factor of 2 (the estimate ignores the low-discrepancy sampler's gain, so it
// may only err high).
TEST(AdaptiveSampling, EstimatedErrorMatchesTheActualErrorAndTheTargetIsMet) {
#ifdef __SANITIZE_ADDRESS__
  // About 17.8 s under AddressSanitizer, most of it the converged bake's samples; the same code
  // runs under ASan in the smaller tests. CI's whole run keeps to its 25 minutes.
  GTEST_SKIP() << "an accuracy measurement: run in the release build";
#endif
  test::World world;
  test::buildCornerLampRoom(world);
  const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.125f, 40);
  LightmapBakeSettings quick = test::testBakeSettings(64, 11);
  LightmapBakeSettings longBake = test::testBakeSettings(4096, 12);
  quick.stitch = longBake.stitch = false;
  const LightmapBake a =
      bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, quick);
  const LightmapBake ref =
      bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, longBake);
  double estimated2 = 0, actual2 = 0;
  int n = 0;
  for (const std::size_t t : validLitTexels(ref)) {
    const double r = luminance(ref.irradiance.pixels[t]);
    const double e = luminance(a.irradiance.pixels[t]);
    actual2 += (e - r) * (e - r) / (r * r);
    estimated2 += static_cast<double>(a.relativeError[t]) * a.relativeError[t];
    ++n;
  }
  const double estimated = std::sqrt(estimated2 / n), actual = std::sqrt(actual2 / n);
  // An adaptive bake at target 5% is within it in fact, not only by its own estimate.
  LightmapBakeSettings adaptive = test::testBakeSettings(4096, 13);
  adaptive.irradiance.targetError = 0.05f;
  adaptive.stitch = false;
  const LightmapBake b =
      bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, adaptive);
  double adaptive2 = 0;
  for (const std::size_t t : validLitTexels(ref)) {
    const double r = luminance(ref.irradiance.pixels[t]);
    const double e = luminance(b.irradiance.pixels[t]);
    adaptive2 += (e - r) * (e - r) / (r * r);
  }
  // Stopping on an estimate (its own relative uncertainty at 32 samples is 1/√62 ≈ 13%) lets
  // the actual error exceed the target a little: allow 1.25×.
  const double adaptiveActual = std::sqrt(adaptive2 / n);
  EXPECT_LT(adaptiveActual, 1.25 * 0.05);
  std::printf("64 spp: estimated %.4f actual %.4f; target 0.05: actual %.4f (%.1f spp mean)\n",
              estimated, actual, adaptiveActual,
              static_cast<double>(b.totalSamples) / static_cast<double>(b.coveredTexels));
  EXPECT_GT(estimated, 0.01);
  EXPECT_LT(estimated, 2.0 * actual) << "estimated " << estimated << " actual " << actual;
  EXPECT_GT(estimated, 0.5 * actual) << "estimated " << estimated << " actual " << actual;
}

// A floor whose only indirect light is a small lit board 1 m above it: a cosine-distributed
// first direction meets the board with probability p = (board's projected solid angle)/π,
// 1.1% (floor corners) to 2.6% (centre), so 16 samples all miss it with probability 0.65 to
// 0.84. Every floor texel sees the board, so its irradiance is positive; a texel that stops
// sampling because its first samples found nothing keeps 0 instead (biased low). At 1024 spp
// all miss with probability below (1 − 0.011)^1024 ≈ 1e-5 per texel.
void buildFloorUnderALitBoard(test::World& world) {
  const uint32_t white = test::addMaterial(world.scene, glm::vec3(0.8f));
  const uint32_t lamp = test::addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(100.0f));
  test::addQuad(world.scene, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, white);  // faces +y
  test::addQuad(world.scene, {0.35f, 1, 0.35f}, {0.65f, 1, 0.35f}, {0.65f, 1, 0.65f},
                {0.35f, 1, 0.65f}, white);  // the board, faces −y
  test::addQuad(world.scene, {0.45f, 0.9f, 0.45f}, {0.45f, 0.9f, 0.55f}, {0.55f, 0.9f, 0.55f},
                {0.55f, 0.9f, 0.45f}, lamp);  // faces +y: lights the board, not the floor
  world.build();
}

void expectNoBlackFloorTexel(const test::QuadAtlas& atlas, const LightmapBake& bake) {
  int floorTexels = 0;
  for (int y = 0; y < atlas.layout.height; ++y) {
    for (int x = 0; x < atlas.layout.width; ++x) {
      const std::size_t t = static_cast<std::size_t>(y) * atlas.layout.width + x;
      glm::vec3 p;
      uint32_t instance = 0;
      if (!bake.covered[t] || !atlas.texelCentre(x, y, p, instance) || instance != 0) continue;
      ++floorTexels;
      EXPECT_GT(luminance(bake.irradiance.pixels[t]), 0.0f)
          << "floor texel (" << x << ", " << y << ") at " << p.x << ", " << p.z << " after "
          << bake.samples[t] << " samples";
    }
  }
  EXPECT_EQ(floorTexels, 64);
}

TEST(AdaptiveSampling, RarelyReachedTexelsAreNotLeftBlack) {
  test::World world;
  buildFloorUnderALitBoard(world);
  const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.125f, 32);
  for (const float target : {0.0f, 0.1f}) {
    SCOPED_TRACE(target);
    LightmapBakeSettings settings = test::testBakeSettings(1024);
    settings.irradiance.targetError = target;
    settings.stitch = false;
    const LightmapBake bake =
        bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, settings);
    expectNoBlackFloorTexel(atlas, bake);
  }
}

// A closed 1 m room whose only light is a narrow spot on the floor lighting a 0.3 m pool on the
// ceiling: every texel's indirect light comes through that pool, which few of a texel's samples
// find, so for some texels the first 128 samples are all zero and the zero rule
// (zeroSamplesToStop) stops them at exactly 0: black specks among lit neighbours. Every texel has
// light (E > 0: the pool is seen from every point of the floor and walls, and reflected onto the
// ceiling), so none may end black (fillUnresolvedZeros). Without the fill 28 and 25 of the 2400
// texels end black (seeds 7 and 8); with it none (seeds 7, 8, 9).
TEST(AdaptiveSampling, DimClosedRoomHasNoBlackSpecks) {
  test::World world;
  const uint32_t white = test::addMaterial(world.scene, glm::vec3(0.5f));
  test::addInwardBox(world.scene, {0, 0, 0}, {1, 1, 1}, white);
  Light spot;
  spot.type = LightType::Spot;
  spot.position = {0.5f, 0.02f, 0.5f};
  spot.direction = {0, 1, 0};
  spot.intensity = glm::vec3(10.0f);
  spot.innerConeAngle = 0.13f;
  spot.outerConeAngle = 0.15f;
  world.scene.lights.push_back(spot);
  world.build();
  const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.05f, 128);
  LightmapBakeSettings settings = test::testBakeSettings(512);
  settings.irradiance.targetError = 0.1f;
  const LightmapBake bake =
      bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, settings);
  int texels = 0, black = 0;
  for (std::size_t t = 0; t < bake.covered.size(); ++t) {
    if (!bake.covered[t] || bake.invalid[t]) continue;
    ++texels;
    black += bake.irradiance.pixels[t] == glm::vec3(0.0f) ? 1 : 0;
  }
  EXPECT_EQ(texels, 6 * 400);
  EXPECT_EQ(black, 0) << "of " << texels << " texels; " << bake.zerosFilled << " were filled";
}

// Texels no light reaches stop early (texel_irradiance.h zeroSamplesToStop): the inside of a
// closed unlit box (every sample meets its dark walls) after 128 samples, a quad facing empty
// space (every sample leaves the scene) after a quarter of the cap; the lamp room's texels do
// not stop on zeros. The floor under the lit board above keeps its rare light with the same rule.
TEST(AdaptiveSampling, TexelsNoLightReachesStopEarly) {
  test::World world;
  test::buildCornerLampRoom(world);
  const uint32_t dark = test::addMaterial(world.scene, glm::vec3(0.6f));
  test::addInwardBox(world.scene, {3, 0, 0}, {3.5f, 0.5f, 0.5f}, dark);  // closed, no light
  test::addQuad(world.scene, {-3, 2, 0}, {-3, 2, 0.5f}, {-2.5f, 2, 0.5f}, {-2.5f, 2, 0},
                dark);  // faces +y, away from everything
  world.build();
  const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.125f, 40);
  LightmapBakeSettings settings = test::testBakeSettings(4096);
  settings.irradiance.targetError = 0.1f;
  settings.stitch = false;
  ASSERT_EQ(zeroSamplesToStop(0.1f, 4096), kMinAdaptiveSpp);
  const LightmapBake bake =
      bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, settings);
  int boxTexels = 0, quadTexels = 0, roomTexels = 0;
  for (int y = 0; y < atlas.layout.height; ++y) {
    for (int x = 0; x < atlas.layout.width; ++x) {
      const std::size_t t = static_cast<std::size_t>(y) * atlas.layout.width + x;
      glm::vec3 p;
      uint32_t instance = 0;
      if (!bake.covered[t] || bake.invalid[t] || !atlas.texelCentre(x, y, p, instance)) continue;
      if (p.x > 2.9f) {
        ++boxTexels;
        EXPECT_EQ(bake.samples[t], kMinAdaptiveSpp) << "box texel " << x << ", " << y;
        EXPECT_EQ(luminance(bake.irradiance.pixels[t]), 0.0f);
      } else if (p.x < -2.0f) {
        ++quadTexels;
        EXPECT_EQ(bake.samples[t], 1024u) << "quad texel " << x << ", " << y;
      } else if (luminance(bake.irradiance.pixels[t]) > 0.0f) {
        ++roomTexels;
      }
    }
  }
  EXPECT_GT(boxTexels, 50);
  EXPECT_EQ(quadTexels, 16);
  EXPECT_GT(roomTexels, 300);
}

TEST(Determinism, SameSeedGivesBitIdenticalLightmapsAtOneAndTwoThreads) {
  test::World world;
  test::buildCornerLampRoom(world);
  const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.125f, 40);
  LightmapBakeSettings one = test::testBakeSettings(256, 5, 1);
  LightmapBakeSettings two = test::testBakeSettings(256, 5, 2);
  one.irradiance.targetError = two.irradiance.targetError = 0.1f;
  one.denoise = two.denoise = true;
  const LightmapBake a =
      bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, one);
  const LightmapBake b =
      bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, two);
  test::expectSameLightmap(a, b);
  EXPECT_EQ(a.rays, b.rays);
  // A different seed gives a different lightmap (the seed reaches the sampler).
  LightmapBakeSettings other = one;
  other.irradiance.seed = 6;
  const LightmapBake c =
      bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, other);
  EXPECT_NE(0, std::memcmp(a.irradiance.pixels.data(), c.irradiance.pixels.data(),
                           a.irradiance.pixels.size() * sizeof(glm::vec3)));
}

}  // namespace
}  // namespace bounce
