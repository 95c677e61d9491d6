// The camera renderer: determinism across thread counts, agreement between ray kernel
// backends, and bad input that must give a defined, finite result.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include <tbb/global_control.h>

#include "trace/sampling.h"
#include "transport_scenes.h"

namespace bounce {
namespace {

bool bitIdentical(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

// A corridor with an area emitter plus a point and a spot light: every estimator path runs.
test::World busyWorld() {
  test::World world = test::corridor();
  Light point;
  point.type = LightType::Point;
  point.position = {3.0f, 1.5f, 1.8f};
  point.intensity = {1, 2, 3};
  Light spot = point;
  spot.type = LightType::Spot;
  spot.position = {3.5f, 0.5f, 1.9f};
  spot.direction = glm::normalize(glm::vec3(-0.5f, 0.2f, -1.0f));
  world.scene.lights = {point, spot};
  return world;
}

TEST(CameraRender, SameSeedIsBitIdenticalWithOneAndTwoThreads) {
  test::World world = busyWorld();
  world.build(RayBackend::Embree);
  const Camera camera = test::corridorCamera();
  TraceSettings settings;
  settings.spp = 16;
  settings.seed = 7;
  settings.threads = 1;
  const auto one =
      traceCamera(world.scene, world.geometry, *world.kernel, camera, 40, 24, settings);
  settings.threads = 2;
  const auto two =
      traceCamera(world.scene, world.geometry, *world.kernel, camera, 40, 24, settings);
  EXPECT_EQ(one.threads, 1);
  EXPECT_TRUE(bitIdentical(one.radiance, two.radiance));
  EXPECT_TRUE(bitIdentical(one.sampleVariance, two.sampleVariance));
  {
    // A global limit of one thread (what a caller's tbb::global_control does) changes nothing.
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    settings.threads = 0;
    const auto global =
        traceCamera(world.scene, world.geometry, *world.kernel, camera, 40, 24, settings);
    EXPECT_TRUE(bitIdentical(one.radiance, global.radiance));
  }
  settings.seed = 8;
  const auto other =
      traceCamera(world.scene, world.geometry, *world.kernel, camera, 40, 24, settings);
  EXPECT_FALSE(bitIdentical(one.radiance, other.radiance));
}

// Embree and our BVH find the same hits up to float ties, so the two images estimate the same
// value: image means within 5 combined standard errors (other seeds, so independent).
TEST(CameraRender, EmbreeAndBvhBackendsAgree) {
  const auto bvh = std::make_unique<test::World>(busyWorld());
  try {
    bvh->build(RayBackend::Bvh);
  } catch (const std::exception& e) {
    GTEST_SKIP() << "BVH backend unavailable: " << e.what();
  }
  test::World embree = busyWorld();
  embree.build(RayBackend::Embree);
  const Camera camera = test::corridorCamera();
  TraceSettings settings;
  settings.spp = 64;
  settings.seed = 1;
  const auto a =
      traceCamera(embree.scene, embree.geometry, *embree.kernel, camera, 16, 16, settings);
  settings.seed = 2;
  const auto b = traceCamera(bvh->scene, bvh->geometry, *bvh->kernel, camera, 16, 16, settings);
  const test::ImageMean ma = test::imageMean(a, settings.spp);
  const test::ImageMean mb = test::imageMean(b, settings.spp);
  EXPECT_TRUE(test::agreeWithin(ma.mean, ma.standardError, mb.mean, mb.standardError, 5.0));
}

// Direct-only and indirect-only split every path's contributions by its number of
// reflections (k ≤ 1, k ≥ 2) using the same sampler dimensions, so with the same seed they
// add up to the full image sample by sample (up to float summation order).
TEST(CameraRender, DirectPlusIndirectIsTheFullImage) {
  test::World world = test::slitRooms(false);
  Light point;
  point.position = {3.0f, 1.0f, 1.5f};
  point.intensity = glm::vec3(0.5f);
  world.scene.lights.push_back(point);
  world.build();
  const Camera camera = test::slitCamera();
  TraceSettings settings;
  settings.spp = 8;
  const Image full =
      renderCamera(world.scene, world.geometry, *world.kernel, camera, 16, 16, settings);
  settings.paths = PathSet::DirectOnly;
  const Image direct =
      renderCamera(world.scene, world.geometry, *world.kernel, camera, 16, 16, settings);
  settings.paths = PathSet::IndirectOnly;
  const Image indirect =
      renderCamera(world.scene, world.geometry, *world.kernel, camera, 16, 16, settings);
  double directSum = 0.0, indirectSum = 0.0;
  for (std::size_t i = 0; i < full.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const float sum = direct.pixels[i][c] + indirect.pixels[i][c];
      ASSERT_NEAR(sum, full.pixels[i][c], 1e-5f * full.pixels[i][c] + 1e-9f) << i;
    }
    directSum += direct.pixels[i].g;
    indirectSum += indirect.pixels[i].g;
  }
  EXPECT_GT(directSum, 0.0);
  EXPECT_GT(indirectSum, 0.0);
}

TraceSettings quick() {
  TraceSettings settings;
  settings.spp = 4;
  return settings;
}

TEST(BadInput, SceneWithoutLightsIsBlack) {
  test::World world;
  test::addInwardBox(world.scene, glm::vec3(-1), glm::vec3(1),
                     test::addMaterial(world.scene, glm::vec3(0.8f)));
  world.build();
  const PathTracer tracer(world.scene, world.geometry, *world.kernel, quick());
  EXPECT_FALSE(tracer.hasLights());
  const Image image = renderCamera(world.scene, world.geometry, *world.kernel,
                                   test::furnaceCamera(), 8, 8, quick());
  for (const glm::vec3& p : image.pixels) ASSERT_EQ(p, glm::vec3(0.0f));
}

TEST(BadInput, ZeroAreaEmitterIsIgnored) {
  test::World world;
  test::addInwardBox(world.scene, glm::vec3(-1), glm::vec3(1),
                     test::addMaterial(world.scene, glm::vec3(0.8f)));
  // A degenerate (collinear) emissive quad: it has no area, hence emits no power.
  test::addQuad(world.scene, {0, 0, -0.5f}, {0.5f, 0, -0.5f}, {1, 0, -0.5f}, {0.2f, 0, -0.5f},
                test::addMaterial(world.scene, glm::vec3(0.5f), glm::vec3(100.0f)));
  world.build();
  const PathTracer tracer(world.scene, world.geometry, *world.kernel, quick());
  EXPECT_TRUE(tracer.emitters().empty());
  const Image image = renderCamera(world.scene, world.geometry, *world.kernel,
                                   test::furnaceCamera(), 8, 8, quick());
  for (const glm::vec3& p : image.pixels) ASSERT_EQ(p, glm::vec3(0.0f));
}

// NaN positions, normals, albedo, emission and light values in an otherwise valid lit scene:
// every pixel stays finite and the valid light still shows.
TEST(BadInput, NonFiniteDataGivesFinitePixels) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  test::World world = test::furnace(0.5f, glm::vec3(1.0f));
  test::addQuad(world.scene, {nan, 0, 0}, {0.5f, 0, 0}, {0.5f, 0.5f, 0}, {0, 0.5f, 0},
                test::addMaterial(world.scene, glm::vec3(0.5f), glm::vec3(nan)));
  test::addQuad(world.scene, {-0.5f, -0.5f, -0.9f}, {0.5f, -0.5f, -0.9f}, {0.5f, 0.5f, -0.9f},
                {-0.5f, 0.5f, -0.9f},
                test::addMaterial(world.scene, glm::vec3(nan), glm::vec3(inf)));
  world.scene.meshes.back().normals[0] = glm::vec3(nan);
  Light broken;
  broken.position = {nan, 0, 0};
  broken.intensity = {1, 1, 1};
  world.scene.lights.push_back(broken);
  Light infinite;
  infinite.type = LightType::Directional;
  infinite.direction = {0, 0, 0};
  infinite.irradiance = glm::vec3(inf);
  world.scene.lights.push_back(infinite);
  world.build();
  const Image image = renderCamera(world.scene, world.geometry, *world.kernel,
                                   test::furnaceCamera(), 16, 16, quick());
  EXPECT_TRUE(image.allFinite());
  double sum = 0.0;
  for (const glm::vec3& p : image.pixels) sum += static_cast<double>(p.g);
  EXPECT_GT(sum, 0.0);

  // A camera with a NaN transform: black, finite.
  Camera camera = test::furnaceCamera();
  camera.cameraToWorld[3][0] = nan;
  const Image black =
      renderCamera(world.scene, world.geometry, *world.kernel, camera, 4, 4, quick());
  for (const glm::vec3& p : black.pixels) ASSERT_EQ(p, glm::vec3(0.0f));
}

// Emission that is finite but absurd (3·10³⁸ W/(sr·m²), near FLT_MAX) in a furnace of albedo
// 0.9: the exact radiance Le/(1 − ρ) = 3·10³⁹ exceeds the float range, so the estimates
// overflow to infinity (the seen emission plus any reflected light already does). Those
// samples are returned as black and counted: the count is positive, never above the
// samples taken, and the image stays finite. The same furnace with Le = 1 counts none.
TEST(BadInput, NonFiniteSamplesAreCounted) {
  TraceSettings settings = quick();
  settings.maxDepth = 8;
  test::World huge = test::furnace(0.9f, glm::vec3(3e38f));
  huge.build();
  const CameraRender bad =
      traceCamera(huge.scene, huge.geometry, *huge.kernel, test::furnaceCamera(), 8, 8, settings);
  std::printf("overflowing furnace: %llu of %llu samples non-finite\n",
              static_cast<unsigned long long>(bad.nonFiniteSamples),
              static_cast<unsigned long long>(bad.samples));
  EXPECT_TRUE(bad.radiance.allFinite());
  EXPECT_GT(bad.nonFiniteSamples, 0u);
  EXPECT_LE(bad.nonFiniteSamples, bad.samples);

  test::World sane = test::furnace(0.9f, glm::vec3(1.0f));
  sane.build();
  const CameraRender good =
      traceCamera(sane.scene, sane.geometry, *sane.kernel, test::furnaceCamera(), 8, 8, settings);
  EXPECT_EQ(good.nonFiniteSamples, 0u);
}

// The baker's entry point counts the same way: irradiance in the overflowing furnace (at its
// centre, facing +z) comes back finite and flagged; in a sane furnace nothing is flagged and
// the flag is cleared on every call.
TEST(BadInput, NonFiniteIrradianceSamplesAreCounted) {
  TraceSettings settings = quick();
  settings.maxDepth = 8;
  test::World huge = test::furnace(0.9f, glm::vec3(3e38f));
  huge.build();
  const PathTracer bad(huge.scene, huge.geometry, *huge.kernel, settings);
  test::World sane = test::furnace(0.9f, glm::vec3(1.0f));
  sane.build();
  const PathTracer good(sane.scene, sane.geometry, *sane.kernel, settings);
  SobolSampler sampler(1u, 2u);
  int badCount = 0, goodCount = 0;
  const int n = 64;
  for (int i = 0; i < n; ++i) {
    sampler.startSample(static_cast<uint32_t>(i));
    bool flagged = false;
    const glm::vec3 e = bad.irradiance({0, 0, 0}, {0, 0, 1}, sampler, &flagged);
    EXPECT_TRUE(isFinite(e));
    if (flagged) {
      ++badCount;
      EXPECT_EQ(e, glm::vec3(0.0f)) << "a non-finite estimate is returned as black";
    }
    sampler.startSample(static_cast<uint32_t>(i));
    flagged = true;  // must be cleared
    const glm::vec3 fine = good.irradiance({0, 0, 0}, {0, 0, 1}, sampler, &flagged);
    EXPECT_TRUE(isFinite(fine));
    if (flagged) ++goodCount;
    sampler.startSample(static_cast<uint32_t>(i));
    EXPECT_EQ(fine, good.irradiance({0, 0, 0}, {0, 0, 1}, sampler)) << "the flag is optional";
  }
  std::printf("overflowing furnace: %d of %d irradiance samples non-finite\n", badCount, n);
  EXPECT_GT(badCount, 0);
  EXPECT_EQ(goodCount, 0);
}

TEST(BadInput, InvalidSettingsThrow) {
  test::World world = test::furnace(0.5f, glm::vec3(1.0f));
  world.build();
  TraceSettings settings;
  settings.spp = 0;
  EXPECT_THROW(renderCamera(world.scene, world.geometry, *world.kernel, test::furnaceCamera(), 4, 4,
                            settings),
               std::invalid_argument);
  EXPECT_THROW(renderCamera(world.scene, world.geometry, *world.kernel, test::furnaceCamera(), 0, 4,
                            quick()),
               std::invalid_argument);
}

}  // namespace
}  // namespace bounce
