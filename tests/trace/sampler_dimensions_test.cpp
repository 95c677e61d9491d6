// The sampler's dimension allocation: within one sample, every sampling decision (pixel jitter
// or the point in a texel, then per path vertex the emitter pick, the point on the emitter,
// the BRDF direction and Russian roulette) must draw its own dimension pair. Two decisions on
// one pair get the same numbers: perfectly correlated (e.g. roulette that survives only for
// some BRDF directions, or a point on the emitter that depends on which emitter was picked),
// which biases the estimate or at best wastes samples. Distinct pairs are independent
// (SobolSampler.DimensionPairsAreUncorrelated), so distinctness is the property to check; the
// sampler's log of the pairs drawn shows it directly, through Li and through irradiance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "test_scenes.h"
#include "trace/rng.h"

namespace bounce {
namespace {

using test::addMaterial;
using test::addQuad;

// A closed box [−1,1]³ of albedo ρ lit by two unequal ceiling emitters and a point light:
// every vertex draws an emitter pick, a point and a direction, and roulette acts from
// `rouletteDepth` on (with survival ρ, once the throughput is ρ^k·ρ^−k).
test::World litBox(float albedo) {
  test::World world;
  test::addInwardBox(world.scene, glm::vec3(-1.0f), glm::vec3(1.0f),
                     addMaterial(world.scene, glm::vec3(albedo)));
  const uint32_t bright = addMaterial(world.scene, glm::vec3(0.0f), {20, 10, 30});
  const uint32_t dim = addMaterial(world.scene, glm::vec3(0.0f), {1, 2, 0.5f});
  // Facing down, just under the ceiling.
  addQuad(world.scene, {0.2f, -0.1f, 0.99f}, {0.2f, 0.1f, 0.99f}, {0.4f, 0.1f, 0.99f},
          {0.4f, -0.1f, 0.99f}, bright);
  addQuad(world.scene, {-0.9f, -0.8f, 0.99f}, {-0.9f, 0.8f, 0.99f}, {-0.1f, 0.8f, 0.99f},
          {-0.1f, -0.8f, 0.99f}, dim);
  Light point;
  point.position = {0.5f, 0.5f, 0.5f};
  point.intensity = {1, 1, 1};
  world.scene.lights.push_back(point);
  return world;
}

// Whether one sample's log of pairs drew a pair twice, and which.
struct LogCheck {
  bool repeated = false;
  uint32_t pair = 0;
};

LogCheck firstRepeat(std::vector<uint32_t> log) {
  std::sort(log.begin(), log.end());
  const auto it = std::adjacent_find(log.begin(), log.end());
  return it == log.end() ? LogCheck{} : LogCheck{true, *it};
}

// Runs `n` samples of `one` (which draws the caller's pair first, as the camera's pixel
// jitter or the baker's point in the texel, then calls the tracer) and checks that no sample
// drew a pair twice; returns the most pairs one sample drew.
template <typename OneSample>
size_t expectDistinctPairs(const char* what, int n, OneSample one) {
  SobolSampler sampler(7u, 3u);
  std::vector<uint32_t> log;
  sampler.logDimensions(&log);
  size_t longest = 0;
  int failures = 0;
  for (int i = 0; i < n; ++i) {
    log.clear();
    sampler.startSample(static_cast<uint32_t>(i));
    sampler.get2D();  // the caller's own pair (pixel jitter / point in the texel)
    one(sampler);
    longest = std::max(longest, log.size());
    const LogCheck check = firstRepeat(log);
    if (check.repeated && ++failures <= 3) {
      ADD_FAILURE() << what << ": sample " << i << " draws pair " << check.pair << " twice ("
                    << log.size() << " pairs drawn)";
    }
  }
  std::printf("%s: %d of %d samples draw a pair twice; longest sample draws %zu pairs\n", what,
              failures, n, longest);
  EXPECT_EQ(failures, 0) << what;
  return longest;
}

TEST(SamplerDimensions, EveryDecisionOfASampleDrawsItsOwnPair) {
  test::World world = litBox(0.8f);  // long paths
  world.build();
  Ray ray;
  ray.origin = {0.1f, 0.2f, 0.0f};
  ray.direction = glm::normalize(glm::vec3(0.3f, -0.2f, -1.0f));
  for (int rouletteDepth : {0, 1, 3}) {
    for (PathSet paths : {PathSet::All, PathSet::IndirectOnly}) {
      TraceSettings settings;
      settings.rouletteDepth = rouletteDepth;
      settings.paths = paths;
      settings.maxDepth = 12;
      const PathTracer tracer(world.scene, world.geometry, *world.kernel, settings);
      SCOPED_TRACE(testing::Message() << "roulette from depth " << rouletteDepth << ", paths "
                                      << static_cast<int>(paths));
      const size_t li =
          expectDistinctPairs("Li", 2048, [&](SobolSampler& sampler) { tracer.Li(ray, sampler); });
      const size_t e = expectDistinctPairs("irradiance", 2048, [&](SobolSampler& sampler) {
        tracer.irradiance({0.0f, 0.0f, -1.0f}, {0, 0, 1}, sampler);
      });
      // The check means something only if paths ran through many vertices: at least 8
      // (the caller's pair, then up to 4 per vertex).
      EXPECT_GE(li, 1u + 4u * 7u);
      EXPECT_GE(e, 1u + 4u * 7u);
    }
  }
}

// The same, seen in the estimate. Two grey (ρ = 0.3) planes 1 m apart, floor and ceiling, and
// a long emitter on the floor at x ∈ [0.3, 2.3] facing up: light reaching the floor or a
// point under the ceiling's centre after bouncing off the ceiling comes from the +x side.
// Russian roulette from the first reflection on (survival 0.3) and no roulette are two
// unbiased estimators of the same light, so their means agree within 5 combined standard
// errors (independent patterns; IndirectOnly, so every counted path has passed a roulette
// decision). If roulette shares a pair with the BRDF direction, survivors leave towards −x
// only (BRDF-only strategy: the emitter is then rarely hit); if it shares one with the next
// vertex's emitter pick, survivors pick the emitter triangle nearer the origin (light-only).
TEST(SamplerDimensions, RouletteFromTheFirstReflectionIsUnbiased) {
  test::World world;
  const uint32_t grey = addMaterial(world.scene, glm::vec3(0.3f));
  addQuad(world.scene, {-100, -100, 0}, {100, -100, 0}, {100, 100, 0}, {-100, 100, 0}, grey);
  addQuad(world.scene, {-100, -100, 1}, {-100, 100, 1}, {100, 100, 1}, {100, -100, 1}, grey);
  addQuad(world.scene, {0.3f, -0.2f, 0.01f}, {2.3f, -0.2f, 0.01f}, {2.3f, 0.2f, 0.01f},
          {0.3f, 0.2f, 0.01f}, addMaterial(world.scene, glm::vec3(0.0f), {5, 5, 5}));
  world.build();
  Ray ray;
  ray.origin = {0.0f, 0.0f, 0.5f};
  ray.direction = {0, 0, -1};
  uint32_t pattern = 500;
  for (LightStrategy strategy : {LightStrategy::BrdfOnly, LightStrategy::LightOnly}) {
    TraceSettings withRoulette;
    withRoulette.strategy = strategy;
    withRoulette.paths = PathSet::IndirectOnly;
    withRoulette.maxDepth = 6;
    withRoulette.rouletteDepth = 0;
    TraceSettings without = withRoulette;
    without.rouletteDepth = 100;
    const PathTracer a(world.scene, world.geometry, *world.kernel, withRoulette);
    const PathTracer b(world.scene, world.geometry, *world.kernel, without);
    const char* name = strategy == LightStrategy::BrdfOnly ? "BRDF-only" : "light-only";
    const int n = 8192;
    const test::Estimate liA = test::estimateLi(a, ray, pattern, pattern, n);
    const test::Estimate liB = test::estimateLi(b, ray, pattern + 1, pattern + 1, n);
    std::printf("%s Li, roulette from depth 0: %.5f, none: %.5f (%+.2f%%, SE %.5f, %.5f)\n", name,
                liA.mean.g, liB.mean.g, 100.0 * (liA.mean.g / liB.mean.g - 1.0),
                liA.standardError().g, liB.standardError().g);
    EXPECT_TRUE(
        test::agreeWithin(liA.mean, liA.standardError(), liB.mean, liB.standardError(), 5.0))
        << name << " Li";
    const glm::vec3 p(0.0f, 0.0f, 0.5f), up(0, 0, 1);
    const test::Estimate eA = test::estimateIrradiance(a, p, up, pattern + 2, pattern + 2, n);
    const test::Estimate eB = test::estimateIrradiance(b, p, up, pattern + 3, pattern + 3, n);
    std::printf("%s irradiance, roulette from depth 0: %.5f, none: %.5f (%+.2f%%, SE %.5f, %.5f)\n",
                name, eA.mean.g, eB.mean.g, 100.0 * (eA.mean.g / eB.mean.g - 1.0),
                eA.standardError().g, eB.standardError().g);
    EXPECT_TRUE(test::agreeWithin(eA.mean, eA.standardError(), eB.mean, eB.standardError(), 5.0))
        << name << " irradiance";
    pattern += 4;
  }
}

// The camera's pixel jitter against the decisions of the path it starts, through
// traceCamera itself: one wide pixel looks down on a plane lit by two equal emitters, A over
// +x (alias bins 0 and 1: picked when the pick's first number is < 0.5) and B over −x (bins 2
// and 3). The left half of the pixel (jitter x < 0.5) sees the −x side, lit mostly by B. If
// the path's emitter pick reused the jitter's pair, the left half would always sample A and
// the right half B: each side would sample the emitter far from it. The reference is computed
// apart: the same tracer's Li on camera rays jittered by independent hashed numbers
// (trace/rng.h). Light-only and MIS, 5 combined SE.
TEST(SamplerDimensions, PixelJitterIsIndependentOfThePath) {
  test::World world;
  addQuad(world.scene, {-100, -100, 0}, {100, -100, 0}, {100, 100, 0}, {-100, 100, 0},
          addMaterial(world.scene, glm::vec3(0.5f)));
  const uint32_t light = addMaterial(world.scene, glm::vec3(0.0f), {4, 4, 4});
  addQuad(world.scene, {0.3f, -0.3f, 0.5f}, {0.3f, 0.3f, 0.5f}, {0.9f, 0.3f, 0.5f},
          {0.9f, -0.3f, 0.5f}, light);  // A, facing down
  addQuad(world.scene, {-0.9f, -0.3f, 0.5f}, {-0.9f, 0.3f, 0.5f}, {-0.3f, 0.3f, 0.5f},
          {-0.3f, -0.3f, 0.5f}, light);  // B, facing down
  world.build();
  // From (0, 0, 0.4) straight down, image x along world +x; the pixel spans x ∈ [−1.2, 1.2].
  const Camera camera = test::lookAt({0, 0, 0.4f}, {0, 0, 0}, {0, 1, 0}, 2.0f * std::atan(3.0f));
  uint32_t seed = 20;
  for (LightStrategy strategy : {LightStrategy::LightOnly, LightStrategy::Mis}) {
    TraceSettings settings;
    settings.strategy = strategy;
    settings.maxDepth = 1;
    settings.spp = 8192;
    settings.seed = ++seed;
    const CameraRender render =
        traceCamera(world.scene, world.geometry, *world.kernel, camera, 1, 1, settings);
    const test::ImageMean pixel = test::imageMean(render, settings.spp);

    const PathTracer tracer(world.scene, world.geometry, *world.kernel, settings);
    SobolSampler sampler(++seed, 0u);
    test::Estimate reference;
    glm::dvec3 m2(0.0);
    const int n = settings.spp;
    for (int i = 0; i < n; ++i) {
      const auto k = static_cast<uint32_t>(i);
      const Ray ray =
          cameraRay(camera, 1, 1, uniformFloat(seed, 2 * k), uniformFloat(seed, 2 * k + 1));
      sampler.startSample(k);
      sampler.setDimension(1);
      const glm::dvec3 value(tracer.Li(ray, sampler));
      const glm::dvec3 delta = value - reference.mean;
      reference.mean += delta / static_cast<double>(i + 1);
      m2 += delta * (value - reference.mean);
    }
    reference.n = n;
    reference.variance = m2 / static_cast<double>(n - 1);
    const char* name = strategy == LightStrategy::Mis ? "MIS" : "light-only";
    std::printf("%s pixel: traceCamera %.5f, independent jitter %.5f (%+.2f%%, SE %.5f, %.5f)\n",
                name, pixel.mean.g, reference.mean.g,
                100.0 * (pixel.mean.g / reference.mean.g - 1.0), pixel.standardError.g,
                reference.standardError().g);
    EXPECT_TRUE(test::agreeWithin(pixel.mean, pixel.standardError, reference.mean,
                                  reference.standardError(), 5.0))
        << name;
  }
}

}  // namespace
}  // namespace bounce
