// Exact single-triangle queries, ray validation and degenerate triangles, for both backends.
#include "ray/ray_kernel.h"
#include "both_backends.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace bounce {
namespace {

// One unit right triangle in the z = 1 plane: p0 = (0,0,1), p1 = (1,0,1), p2 = (0,1,1); its
// (p1−p0)×(p2−p0) normal is +z.
WorldGeometry oneTriangle() {
  WorldGeometry g;
  g.positions = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  g.triangles = {{0, 1, 2}};
  return g;
}

class RayKernelTest : public ::testing::TestWithParam<RayBackend> {};

TEST_P(RayKernelTest, HitsTriangleWithExactDistanceBarycentricsAndNormal) {
  const WorldGeometry g = oneTriangle();
  const auto kernel = makeRayKernel(g, GetParam());
  // From (0.25, 0.5, 0) along +z with a non-unit direction of length 2: t = 0.5.
  const Hit hit = kernel->intersect(Ray{{0.25f, 0.5f, 0.0f}, 0.0f, {0, 0, 2}});
  ASSERT_TRUE(hit.valid());
  EXPECT_EQ(hit.triangle, 0u);
  EXPECT_NEAR(hit.t, 0.5f, 1e-6f);
  EXPECT_NEAR(hit.u, 0.25f, 1e-6f);  // p = (1−u−v)p0 + u·p1 + v·p2
  EXPECT_NEAR(hit.v, 0.5f, 1e-6f);
  EXPECT_NEAR(hit.geometricNormal.x, 0.0f, 1e-6f);
  EXPECT_NEAR(hit.geometricNormal.y, 0.0f, 1e-6f);
  EXPECT_NEAR(hit.geometricNormal.z, 1.0f, 1e-6f);
  // The back face is hit too (no culling), with the same normal.
  const Hit back = kernel->intersect(Ray{{0.25f, 0.5f, 3.0f}, 0.0f, {0, 0, -1}});
  ASSERT_TRUE(back.valid());
  EXPECT_NEAR(back.t, 2.0f, 1e-6f);
  EXPECT_NEAR(back.geometricNormal.z, 1.0f, 1e-6f);
  // Outside the triangle (u + v > 1) and behind the origin: misses.
  EXPECT_FALSE(kernel->intersect(Ray{{0.75f, 0.5f, 0.0f}, 0.0f, {0, 0, 1}}).valid());
  EXPECT_FALSE(kernel->intersect(Ray{{0.25f, 0.25f, 2.0f}, 0.0f, {0, 0, 1}}).valid());
}

TEST_P(RayKernelTest, OcclusionRespectsTheRayInterval) {
  const WorldGeometry g = oneTriangle();
  const auto kernel = makeRayKernel(g, GetParam());
  const glm::vec3 o{0.25f, 0.25f, 0.0f}, d{0, 0, 1};
  EXPECT_TRUE(kernel->occluded(Ray{o, 0.0f, d, 1.01f}));
  EXPECT_FALSE(kernel->occluded(Ray{o, 0.0f, d, 0.99f}));  // the light sits before the triangle
  EXPECT_FALSE(kernel->occluded(Ray{o, 1.01f, d, 5.0f}));  // the interval starts past it
  EXPECT_FALSE(kernel->intersect(Ray{o, 0.0f, d, 0.99f}).valid());
  EXPECT_FALSE(kernel->intersect(Ray{o, 1.01f, d}).valid());
}

TEST_P(RayKernelTest, UntraceableRaysMissWithoutAborting) {
  const WorldGeometry g = oneTriangle();
  const auto kernel = makeRayKernel(g, GetParam());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const Ray bad[] = {
      Ray{{nan, 0.25f, 0}, 0.0f, {0, 0, 1}},      Ray{{0.25f, 0.25f, 0}, 0.0f, {0, nan, 1}},
      Ray{{0.25f, 0.25f, -inf}, 0.0f, {0, 0, 1}}, Ray{{0.25f, 0.25f, 0}, 0.0f, {0, 0, inf}},
      Ray{{0.25f, 0.25f, 0}, nan, {0, 0, 1}},     Ray{{0.25f, 0.25f, 0}, 0.0f, {0, 0, 1}, nan},
      Ray{{0.25f, 0.25f, 0}, -1.0f, {0, 0, 1}},   Ray{{0.25f, 0.25f, 0}, 0.0f, {0, 0, 0}},
  };
  for (const Ray& ray : bad) {
    EXPECT_FALSE(kernel->intersect(ray).valid());
    EXPECT_FALSE(kernel->occluded(ray));
  }
  Hit hits[std::size(bad)];
  uint8_t occluded[std::size(bad)];
  kernel->intersect(bad, hits);
  kernel->occluded(bad, occluded);
  for (std::size_t i = 0; i < std::size(bad); ++i) {
    EXPECT_FALSE(hits[i].valid());
    EXPECT_EQ(occluded[i], 0);
  }
}

TEST_P(RayKernelTest, DegenerateTrianglesNeverHit) {
  // Triangle 0 collinear, 1 with a repeated vertex, 2 with a NaN vertex, all in the z = 0.5
  // plane in front of the valid triangle 3 at z = 1. Rays must pass them and hit triangle 3.
  WorldGeometry g;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  g.positions = {{0, 0, 0.5f},   {1, 1, 0.5f}, {0.5f, 0.5f, 0.5f}, {0, 0, 0.5f}, {1, 0, 0.5f},
                 {nan, 0, 0.5f}, {0, 0, 1},    {1, 0, 1},          {0, 1, 1}};
  g.triangles = {{0, 1, 2}, {3, 3, 4}, {0, 4, 5}, {6, 7, 8}};
  const auto kernel = makeRayKernel(g, GetParam());
  for (const glm::vec3 o :
       {glm::vec3(0.25f, 0.25f, 0), glm::vec3(0.5f, 0.0f, 0), glm::vec3(0.1f, 0.1f, 0)}) {
    const Hit hit = kernel->intersect(Ray{o, 0.0f, {0, 0, 1}});
    ASSERT_TRUE(hit.valid());
    EXPECT_EQ(hit.triangle, 3u);
    EXPECT_NEAR(hit.t, 1.0f, 1e-6f);
    EXPECT_FALSE(kernel->occluded(Ray{o, 0.0f, {0, 0, 1}, 0.9f}));
  }
}

TEST_P(RayKernelTest, EmptySceneMisses) {
  const WorldGeometry g;
  const auto kernel = makeRayKernel(g, GetParam());
  EXPECT_FALSE(kernel->intersect(Ray{}).valid());
  EXPECT_FALSE(kernel->occluded(Ray{}));
}

INSTANTIATE_TEST_SUITE_P(Backends, RayKernelTest, kBothBackends, backendName);

TEST(ParseRayBackend, AcceptsTheTwoNamesAndRejectsOthers) {
  EXPECT_EQ(parseRayBackend("embree"), RayBackend::Embree);
  EXPECT_EQ(parseRayBackend("bvh"), RayBackend::Bvh);
  EXPECT_THROW(parseRayBackend("optix"), std::invalid_argument);
  EXPECT_THROW(parseRayBackend(""), std::invalid_argument);
  try {
    parseRayBackend("Embree3");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("Embree3"), std::string::npos);  // names the input
  }
}

TEST(OffsetRayOrigin, MovesAlongTheNormalToTheRequestedSideScaledWithMagnitude) {
  const glm::vec3 n{0, 0, 1};
  const glm::vec3 up = offsetRayOrigin({1000, 0, 0}, n, {0.3f, 0, 1});
  const glm::vec3 down = offsetRayOrigin({1000, 0, 0}, n, {0.3f, 0, -1});
  EXPECT_GT(up.z, 0.0f);
  EXPECT_LT(down.z, 0.0f);
  EXPECT_EQ(up.x, 1000.0f);  // only along n
  // The offset grows with |p| (1000 m vs 1 m) and never vanishes at the origin.
  EXPECT_GT(up.z, 100.0f * offsetRayOrigin({1, 0, 0}, n, n).z);
  EXPECT_GT(offsetRayOrigin({0, 0, 0}, n, n).z, 0.0f);
}

}  // namespace
}  // namespace bounce
