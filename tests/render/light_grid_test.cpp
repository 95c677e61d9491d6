// GL-free: the light cut-off rule, the view's clusters and which lights each cluster lists
// (render/light_cutoff.h, cluster_grid.h, light_grid.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "image/tonemap.h"
#include "render/cluster_grid.h"
#include "render/light_cutoff.h"
#include "render/light_grid.h"

namespace bounce::test {
namespace {

// A camera at (1, 2, 8) looking towards (−2, 0, −20): not axis-aligned, so view and world differ.
Camera tiltedCamera() {
  Camera camera;
  camera.yfov = 0.9f;
  camera.znear = 0.05f;
  camera.zfar = 200.0f;
  camera.cameraToWorld = glm::inverse(
      glm::lookAt(glm::vec3(1.0f, 2.0f, 8.0f), glm::vec3(-2.0f, 0.0f, -20.0f), glm::vec3(0, 1, 0)));
  return camera;
}

constexpr int kWidth = 200, kHeight = 120;

ClusterGrid tiltedGrid() {
  return makeClusterGrid(tiltedCamera(), kWidth, kHeight, 0.5f, 60.0f);
}

bool contains(const Box& box, glm::vec3 p) {
  return glm::all(glm::greaterThanEqual(p, box.lower)) &&
         glm::all(glm::lessThanEqual(p, box.upper));
}

// The cluster a fragment at view-space point v falls in, as shaders/light_grid.glsl picks it:
// the pixel from the projection (rows from the bottom), the slice from the depth.
int shaderCluster(const ClusterGrid& grid, glm::vec3 v) {
  const float d = -v.z;
  const float px = (v.x / d / grid.tanHalfFov.x + 1.0f) * 0.5f * static_cast<float>(grid.width);
  const float py = (v.y / d / grid.tanHalfFov.y + 1.0f) * 0.5f * static_cast<float>(grid.height);
  const int tx = std::min(static_cast<int>(px) / grid.tilePixels, grid.tilesX - 1);
  const int ty = std::min(static_cast<int>(py) / grid.tilePixels, grid.tilesY - 1);
  return grid.index(tx, ty, grid.sliceOf(d));
}

// A random view-space point inside the grid's frustum between its near and far depths.
glm::vec3 randomViewPoint(const ClusterGrid& grid, std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const float d = grid.nearDepth * std::pow(grid.farDepth / grid.nearDepth, u(rng));
  return {(2.0f * u(rng) - 1.0f) * grid.tanHalfFov.x * d,
          (2.0f * u(rng) - 1.0f) * grid.tanHalfFov.y * d, -d};
}

bool listed(const LightGridLists& lists, int cluster, uint32_t light, bool area) {
  const glm::vec4 header = lists.headers[static_cast<std::size_t>(cluster)];
  const int first = static_cast<int>(header.x) + (area ? static_cast<int>(header.y) : 0);
  const int count = static_cast<int>(area ? header.z : header.y);
  for (int k = first; k < first + count; ++k)
    if (lists.entries[static_cast<std::size_t>(k / 4)][k % 4] == static_cast<float>(light))
      return true;
  return false;
}

TEST(LightCutoff, FloorIsHalfACodeValueOnAWhiteSurfaceAndHalvesPerStop) {
  const float floor0 = irradianceFloorForExposure(0.0f);
  EXPECT_NEAR(irradianceFloorForExposure(1.0f), 0.5f * floor0, 1e-6f * floor0);
  EXPECT_NEAR(irradianceFloorForExposure(-3.0f), 8.0f * floor0, 1e-5f * floor0);
  // A white Lambertian surface under E_floor alone, at the display's steepest point, moves its
  // displayed value by at most half a code value: the slope bound is the true steepest slope
  // (checked here on an independent coarser grid) times ΔL = E_floor/π.
  double steepest = 0.0;
  for (double x = 0.0; x < 0.05; x += 1e-4) {
    const auto display = [](double v) { return srgbEncode(filmicCurve(static_cast<float>(v))); };
    steepest = std::max(steepest, static_cast<double>(display(x + 1e-4) - display(x)) / 1e-4);
  }
  EXPECT_NEAR(steepestDisplaySlope(), steepest, 0.02 * steepest);
  const double pi = 3.14159265358979;
  EXPECT_NEAR(steepestDisplaySlope() * floor0 / pi, 0.5 / 255.0, 1e-6);
  // Reach: an inverse-square source of intensity I gives exactly the floor at the cut-off.
  const float r = cutoffDistance(2.0f, floor0);
  EXPECT_NEAR(2.0f / (r * r), floor0, 1e-6f * floor0);
  EXPECT_EQ(cutoffDistance(0.0f, floor0), 0.0f);
}

// Every point of the frustum lies in the box of the cluster the shader assigns it: a wrong tile
// size, row order or slice formula puts points outside their box.
TEST(ClusterGrid, EveryPointLiesInTheClusterTheShaderPicks) {
  const ClusterGrid grid = tiltedGrid();
  EXPECT_EQ(grid.tilesX, 16);
  EXPECT_EQ(grid.tilePixels, 13);
  EXPECT_EQ(grid.tilesY, 10);
  std::mt19937 rng(7);
  for (int i = 0; i < 20000; ++i) {
    const glm::vec3 v = randomViewPoint(grid, rng);
    const int c = shaderCluster(grid, v);
    const int s = c / (grid.tilesX * grid.tilesY);
    const int y = (c / grid.tilesX) % grid.tilesY;
    const int x = c % grid.tilesX;
    ASSERT_TRUE(contains(grid.clusterBox(x, y, s), v))
        << "view point (" << v.x << ", " << v.y << ", " << v.z << ") in cluster " << x << "," << y
        << "," << s;
  }
}

TEST(ClusterGrid, SliceBoundariesSeparateTheirSlices) {
  const ClusterGrid grid = tiltedGrid();
  EXPECT_EQ(grid.sliceOf(grid.nearDepth), 0);
  EXPECT_EQ(grid.sliceOf(grid.farDepth * 0.9999f), grid.slices - 1);
  for (int s = 1; s < grid.slices; ++s) {
    EXPECT_EQ(grid.sliceOf(grid.sliceDepth(s) * 1.0001f), s);
    EXPECT_EQ(grid.sliceOf(grid.sliceDepth(s) * 0.9999f), s - 1);
  }
}

// A light centred exactly on a tile corner and a slice boundary, reaching 1 cm: the eight
// clusters that meet there all list it, and no other.
TEST(LightGrid, ALightOnAClusterCornerJoinsEveryClusterThatMeetsThere) {
  const ClusterGrid grid = tiltedGrid();
  const int tx = 5, ty = 4, s = 11;
  const float d = grid.sliceDepth(s);
  // The view point at the corner of pixel (tx·T, ty·T) at depth d, then in world space.
  const auto slope = [](int pixel, int size, float tanHalf) {
    return (2.0f * static_cast<float>(pixel) / static_cast<float>(size) - 1.0f) * tanHalf;
  };
  const glm::vec3 v(slope(tx * grid.tilePixels, kWidth, grid.tanHalfFov.x) * d,
                    slope(ty * grid.tilePixels, kHeight, grid.tanHalfFov.y) * d, -d);
  LightReach light;
  light.shape = LightReach::Shape::Sphere;
  light.centre = glm::vec3(glm::inverse(grid.view) * glm::vec4(v, 1.0f));
  light.radius = 0.01f;
  const LightGridLists lists = assignLights(grid, std::span(&light, 1), {});
  int hits = 0;
  for (int z = s - 1; z <= s; ++z)
    for (int y = ty - 1; y <= ty; ++y)
      for (int x = tx - 1; x <= tx; ++x) {
        EXPECT_TRUE(listed(lists, grid.index(x, y, z), 0, false)) << x << "," << y << "," << z;
        ++hits;
      }
  EXPECT_EQ(lists.punctualEntries, static_cast<std::size_t>(hits));
}

// Random spheres, spot cones and area boxes against random points of the frustum: wherever a
// point is within a light's reach, the light is in the list of that point's cluster.
TEST(LightGrid, EveryLightReachingAPointIsInThatPointsCluster) {
  const ClusterGrid grid = tiltedGrid();
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const glm::mat4 toWorld = glm::inverse(grid.view);
  std::vector<LightReach> punctual, area;
  for (int i = 0; i < 60; ++i) {
    LightReach light;
    const glm::vec3 v = randomViewPoint(grid, rng) * glm::vec3(1.2f, 1.2f, 1.0f);
    light.centre = glm::vec3(toWorld * glm::vec4(v, 1.0f));
    light.radius = 0.2f + 6.0f * u(rng);
    if (i % 3 == 2) {
      light.shape = LightReach::Shape::Box;
      light.box = {light.centre, light.centre + glm::vec3(u(rng), 0.05f, u(rng))};
      area.push_back(light);
      continue;
    }
    light.shape = i % 3 == 1 ? LightReach::Shape::Cone : LightReach::Shape::Sphere;
    light.axis = glm::normalize(glm::vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f));
    const float outer = 0.1f + 1.4f * u(rng);
    light.cosOuter = std::cos(outer);
    light.sinOuter = std::sin(outer);
    punctual.push_back(light);
  }
  const LightGridLists lists = assignLights(grid, punctual, area);
  int checked = 0;
  for (int i = 0; i < 20000; ++i) {
    const glm::vec3 v = randomViewPoint(grid, rng);
    const glm::vec3 p = glm::vec3(toWorld * glm::vec4(v, 1.0f));
    const int c = shaderCluster(grid, v);
    for (std::size_t l = 0; l < punctual.size(); ++l) {
      const LightReach& light = punctual[l];
      const glm::vec3 to = p - light.centre;
      if (glm::length(to) > light.radius) continue;
      if (light.shape == LightReach::Shape::Cone &&
          glm::dot(to, light.axis) < light.cosOuter * glm::length(to))
        continue;
      ++checked;
      ASSERT_TRUE(listed(lists, c, static_cast<uint32_t>(l), false)) << "light " << l;
    }
    for (std::size_t l = 0; l < area.size(); ++l) {
      const glm::vec3 nearest = glm::clamp(p, area[l].box.lower, area[l].box.upper);
      if (glm::length(p - nearest) > area[l].radius) continue;
      ++checked;
      ASSERT_TRUE(listed(lists, c, static_cast<uint32_t>(l), true)) << "area light " << l;
    }
  }
  EXPECT_GT(checked, 5000);
  // And the lists are short: culling left most lights out of most clusters.
  EXPECT_LT(static_cast<double>(lists.punctualEntries) / grid.count(), 0.25 * punctual.size());
}

}  // namespace
}  // namespace bounce::test
