// GL-free: grouping emissive triangles into area lights, picking which get shadow maps, and the
// points the soft-shadow filter spreads over each light.
#include "render/area_lights.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace bounce {
namespace {

// A rectangle c, c+u, c+u+v, c+v as two counter-clockwise triangles (front: u×v).
void addRectangle(std::vector<EmitterTriangle>& out, glm::vec3 c, glm::vec3 u, glm::vec3 v,
                  glm::vec3 radiance, uint32_t instance, uint32_t material) {
  out.push_back({c, c + u, c + u + v, radiance, false, instance, material});
  out.push_back({c, c + u + v, c + v, radiance, false, instance, material});
}

TEST(AreaLights, OneRectanglePerInstanceAndMaterial) {
  std::vector<EmitterTriangle> emitters;
  // The Cornell box's light: 0.13 m × 0.105 m facing down at y = 0.5487 m.
  addRectangle(emitters, {0.213f, 0.5487f, 0.227f}, {0.13f, 0, 0}, {0, 0, 0.105f}, glm::vec3(10.0f),
               5, 3);
  addRectangle(emitters, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}, glm::vec3(1.0f), 6, 3);
  const std::vector<AreaLight> lights = groupAreaLights(emitters);
  ASSERT_EQ(lights.size(), 2u);
  const AreaLight& cornell = lights[0];
  EXPECT_EQ(cornell.triangles, (std::vector<uint32_t>{0, 1}));
  EXPECT_NEAR(cornell.area, 0.13f * 0.105f, 1e-7f);
  EXPECT_NEAR(cornell.centre.x, 0.278f, 1e-6f);
  EXPECT_NEAR(cornell.centre.z, 0.2795f, 1e-6f);
  EXPECT_NEAR(cornell.normal.y, -1.0f, 1e-6f);  // (x × z) = −y: it faces the floor
  EXPECT_NEAR(cornell.radius, 0.5f * std::hypot(0.13f, 0.105f), 1e-6f);
  EXPECT_NEAR(cornell.flux.r, std::numbers::pi * 10.0 * 0.13 * 0.105, 1e-5);
  EXPECT_NEAR(lights[1].normal.y, 1.0f, 1e-6f);  // (z × x) = +y
}

TEST(AreaLights, ShadowMapsGoToTheLargestFluxFirst) {
  std::vector<EmitterTriangle> emitters;
  addRectangle(emitters, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, glm::vec3(1.0f), 0, 0);  // π W
  addRectangle(emitters, {0, 0, 0}, {2, 0, 0}, {0, 0, 2}, glm::vec3(1.0f), 1, 0);  // 4π W
  addRectangle(emitters, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, glm::vec3(3.0f), 2, 0);  // 3π W
  const std::vector<AreaLight> lights = groupAreaLights(emitters);
  EXPECT_EQ(pickShadowedAreaLights(lights, 2), (std::vector<uint32_t>{1, 2}));
  EXPECT_EQ(pickShadowedAreaLights(lights, 5), (std::vector<uint32_t>{1, 2, 0}));
  EXPECT_TRUE(pickShadowedAreaLights(lights, 0).empty());
}

// The points cover the light evenly: on its plane, inside it, with the light's centroid as their
// mean, and with as many in each half as the halves' areas ask.
TEST(AreaLights, SamplePointsSpreadEvenlyOverTheLight) {
  std::vector<EmitterTriangle> emitters;
  const glm::vec3 c(1, 2, 3), u(0.4f, 0, 0), v(0, 0.1f, 0.2f);
  addRectangle(emitters, c, u, v, glm::vec3(1.0f), 0, 0);
  const AreaLight light = groupAreaLights(emitters)[0];
  const int count = 32;
  const std::vector<glm::vec3> points = samplePoints(light, emitters, count);
  ASSERT_EQ(points.size(), static_cast<std::size_t>(count));
  glm::vec3 mean(0.0f);
  int leftHalf = 0;
  for (const glm::vec3& p : points) {
    const glm::vec3 d = p - c;
    const float s = glm::dot(d, u) / glm::dot(u, u), t = glm::dot(d, v) / glm::dot(v, v);
    EXPECT_NEAR(glm::dot(d, light.normal), 0.0f, 1e-5f);
    EXPECT_GE(s, -1e-5f);
    EXPECT_LE(s, 1 + 1e-5f);
    EXPECT_GE(t, -1e-5f);
    EXPECT_LE(t, 1 + 1e-5f);
    leftHalf += s < 0.5f;
    mean += p / static_cast<float>(count);
  }
  // A grid-like set: the mean within 1/count of the rectangle's extent of the centroid.
  EXPECT_NEAR(glm::length(mean - light.centre), 0.0f, glm::length(u + v) / count * 2);
  EXPECT_NEAR(leftHalf, count / 2, 2);
}

}  // namespace
}  // namespace bounce
