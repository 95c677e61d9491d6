// GL-free: emissive triangles cut into area lights by their shape (scene/area_lights.h), which
// lights get shadow maps, and the points the soft-shadow filter spreads over each light.
#include "scene/area_lights.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace bounce {
namespace {

// A rectangle c, c+u, c+u+v, c+v as two counter-clockwise triangles (front: u×v), sharing the
// diagonal edge, as a mesh stores it.
void addRectangle(std::vector<EmitterTriangle>& out, glm::vec3 c, glm::vec3 u, glm::vec3 v,
                  glm::vec3 radiance, uint32_t instance, uint32_t material) {
  out.push_back({c, c + u, c + u + v, radiance, false, instance, material});
  out.push_back({c, c + u + v, c + v, radiance, false, instance, material});
}

double area(const EmitterTriangle& e) {
  return 0.5 * glm::length(glm::cross(glm::dvec3(e.v1 - e.v0), glm::dvec3(e.v2 - e.v0)));
}

double totalArea(const std::vector<EmitterTriangle>& triangles) {
  double a = 0.0;
  for (const EmitterTriangle& e : triangles) a += area(e);
  return a;
}

// Largest extent of light `l` along `axis` (unit), metres.
float extentAlong(const AreaLightSet& set, std::size_t l, glm::vec3 axis) {
  float lo = INFINITY, hi = -INFINITY;
  const AreaLight& light = set.lights[l];
  for (uint32_t t = light.first; t < light.first + light.count; ++t)
    for (const glm::vec3& p : {set.triangles[t].v0, set.triangles[t].v1, set.triangles[t].v2}) {
      lo = std::min(lo, glm::dot(p, axis));
      hi = std::max(hi, glm::dot(p, axis));
    }
  return hi - lo;
}

TEST(AreaLights, ASingleQuadStaysOneLight) {
  std::vector<EmitterTriangle> emitters;
  // The Cornell box's light: 0.13 m × 0.105 m facing down at y = 0.5487 m.
  addRectangle(emitters, {0.213f, 0.5487f, 0.227f}, {0.13f, 0, 0}, {0, 0, 0.105f}, glm::vec3(10.0f),
               5, 3);
  addRectangle(emitters, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}, glm::vec3(1.0f), 6, 3);
  const AreaLightSet set = splitAreaLights(emitters);
  ASSERT_EQ(set.lights.size(), 2u);
  const AreaLight& cornell = set.lights[0];
  EXPECT_EQ(cornell.first, 0u);
  EXPECT_EQ(cornell.count, 2u);
  EXPECT_EQ(cornell.instance, 5u);
  EXPECT_NEAR(cornell.area, 0.13f * 0.105f, 1e-7f);
  EXPECT_NEAR(cornell.centre.x, 0.278f, 1e-6f);
  EXPECT_NEAR(cornell.centre.z, 0.2795f, 1e-6f);
  EXPECT_NEAR(cornell.normal.y, -1.0f, 1e-6f);  // (x × z) = −y: it faces the floor
  EXPECT_NEAR(cornell.radius, 0.5f * std::hypot(0.13f, 0.105f), 1e-6f);
  EXPECT_NEAR(cornell.flux.r, std::numbers::pi * 10.0 * 0.13 * 0.105, 1e-5);
  EXPECT_NEAR(set.lights[1].normal.y, 1.0f, 1e-6f);  // (z × x) = +y
}

// Eight 1.2 m × 0.6 m ceiling panels written as one mesh (one instance, one material), as
// exporters write light fixtures: eight lights, each its own panel, none merged.
TEST(AreaLights, MergedPanelsBecomeOneLightEach) {
  std::vector<EmitterTriangle> emitters;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 2; ++j)
      addRectangle(emitters, {-2.0f + 1.5f * i, 1.95f, -1.5f + 2.0f * j}, {1.2f, 0, 0},
                   {0, 0, 0.6f}, glm::vec3(5.0f), 0, 0);
  // Two more that touch at one corner only: apart, so two lights.
  addRectangle(emitters, {4, 1.95f, 4}, {0.5f, 0, 0}, {0, 0, 0.5f}, glm::vec3(5.0f), 0, 0);
  addRectangle(emitters, {4.5f, 1.95f, 4.5f}, {0.5f, 0, 0}, {0, 0, 0.5f}, glm::vec3(5.0f), 0, 0);
  const AreaLightSet set = splitAreaLights(emitters);
  ASSERT_EQ(set.lights.size(), 10u);
  for (std::size_t l = 0; l < 8; ++l) {
    EXPECT_EQ(set.lights[l].count, 2u);
    EXPECT_NEAR(set.lights[l].area, 0.72f, 1e-5f);
    const int i = static_cast<int>(l) / 2, j = static_cast<int>(l) % 2;
    EXPECT_NEAR(set.lights[l].centre.x, -2.0f + 1.5f * i + 0.6f, 1e-5f);
    EXPECT_NEAR(set.lights[l].centre.z, -1.5f + 2.0f * j + 0.3f, 1e-5f);
  }
  EXPECT_NEAR(totalArea(set.triangles), totalArea(emitters), 1e-9);
}

// A 6 m × 0.1 m strip along a tilted direction: cut into ⌈6 / 1.5⌉ = 4 lights along its length,
// each at most 1.5 m long, none across its width, tiling the strip exactly.
TEST(AreaLights, ALongStripIsCutAlongItsLength) {
  std::vector<EmitterTriangle> emitters;
  const glm::vec3 along = glm::normalize(glm::vec3(1, 0.3f, 0.2f));
  const glm::vec3 across = glm::normalize(glm::cross(along, glm::vec3(0, 1, 0)));
  // Several triangles a metre, as a tessellated strip is stored.
  for (int k = 0; k < 12; ++k)
    addRectangle(emitters, 0.5f * k * along, 0.5f * along, 0.1f * across, glm::vec3(2.0f), 0, 0);
  const AreaLightSet set = splitAreaLights(emitters);
  ASSERT_EQ(set.lights.size(), 4u);
  for (std::size_t l = 0; l < set.lights.size(); ++l) {
    EXPECT_LE(extentAlong(set, l, along), 1.5f + 1e-4f);
    EXPECT_NEAR(extentAlong(set, l, across), 0.1f, 1e-4f);
    EXPECT_NEAR(set.lights[l].area, 0.15f, 1e-4f);
  }
  EXPECT_NEAR(totalArea(set.triangles), 0.6, 1e-5);
  // Two triangles, cut through: the rule does not depend on how finely the strip is meshed.
  std::vector<EmitterTriangle> coarse;
  addRectangle(coarse, glm::vec3(0.0f), 6.0f * along, 0.1f * across, glm::vec3(2.0f), 0, 0);
  const AreaLightSet cut = splitAreaLights(coarse);
  ASSERT_EQ(cut.lights.size(), 4u);
  for (std::size_t l = 0; l < cut.lights.size(); ++l) {
    EXPECT_NEAR(extentAlong(cut, l, along), 1.5f, 1e-4f);
    EXPECT_NEAR(cut.lights[l].area, 0.15f, 1e-4f);
  }
}

// A half cylinder (a curved diffuser, radius 0.2 m, 0.6 m long, 24 facets of 7.5°): cut into
// pieces whose triangle normals stay within 15° of each piece's seed, so within 30° of each
// other; together they keep every triangle and the whole flux.
TEST(AreaLights, ACurvedEmitterIsCutIntoNearlyPlanarPieces) {
  std::vector<EmitterTriangle> emitters;
  const int facets = 24;
  for (int k = 0; k < facets; ++k) {
    const double a0 = std::numbers::pi * k / facets, a1 = std::numbers::pi * (k + 1) / facets;
    const glm::vec3 p0(0.2 * std::cos(a0), -0.2 * std::sin(a0), 0);
    const glm::vec3 p1(0.2 * std::cos(a1), -0.2 * std::sin(a1), 0);
    addRectangle(emitters, p0, glm::vec3(0, 0, 0.6f), p1 - p0, glm::vec3(3.0f), 0, 0);
  }
  const AreaLightSet set = splitAreaLights(emitters);
  EXPECT_GE(set.lights.size(), 6u);  // 180° in pieces spanning at most 30°
  EXPECT_LE(set.lights.size(), 12u);
  double flux = 0.0;
  for (std::size_t l = 0; l < set.lights.size(); ++l) {
    const AreaLight& light = set.lights[l];
    flux += light.flux.r;
    for (uint32_t t = light.first; t < light.first + light.count; ++t) {
      const EmitterTriangle& e = set.triangles[t];
      const glm::vec3 n = glm::normalize(glm::cross(e.v1 - e.v0, e.v2 - e.v0));
      EXPECT_GE(glm::dot(n, light.normal), std::cos(15.0 * std::numbers::pi / 180) - 1e-5)
          << "light " << l;
    }
  }
  EXPECT_NEAR(flux, std::numbers::pi * 3.0 * totalArea(emitters), 1e-4);
}

// Touching emitters of other instances or materials never join; static lights come first.
TEST(AreaLights, InstancesAndMaterialsNeverShareALight) {
  std::vector<EmitterTriangle> emitters;
  addRectangle(emitters, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, glm::vec3(1.0f), 0, 0);
  addRectangle(emitters, {1, 0, 0}, {1, 0, 0}, {0, 0, 1}, glm::vec3(1.0f), 1, 0);
  addRectangle(emitters, {2, 0, 0}, {1, 0, 0}, {0, 0, 1}, glm::vec3(2.0f), 1, 1);
  const std::vector<Mobility> mobility{Mobility::Dynamic, Mobility::Static};
  const AreaLightSet set = splitAreaLights(emitters, mobility);
  ASSERT_EQ(set.lights.size(), 3u);
  EXPECT_EQ(set.staticCount(), 2u);
  EXPECT_EQ(set.lights[0].instance, 1u);
  EXPECT_EQ(set.lights[1].material, 1u);
  EXPECT_EQ(set.lights[2].instance, 0u);
  EXPECT_EQ(set.lights[2].mobility, Mobility::Dynamic);
}

TEST(AreaLights, ShadowMapsGoToTheLargestFluxFirst) {
  std::vector<EmitterTriangle> emitters;
  addRectangle(emitters, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, glm::vec3(1.0f), 0, 0);  // π W
  addRectangle(emitters, {0, 0, 0}, {2, 0, 0}, {0, 0, 2}, glm::vec3(1.0f), 1, 0);  // 4π W
  addRectangle(emitters, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, glm::vec3(3.0f), 2, 0);  // 3π W
  const std::vector<AreaLight> lights = splitAreaLights(emitters, {}, {15.0f, 10.0f}).lights;
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
  const AreaLightSet set = splitAreaLights(emitters);
  const AreaLight& light = set.lights[0];
  const int count = 32;
  const std::vector<glm::vec3> points = samplePoints(set, 0, count);
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
