// GL-free: the CPU twin of the shader's area-light irradiance (scene/emitter_irradiance.h),
// which the renderer evaluates once per lightmap texel. Checked against Lambert's contour
// formula written apart (support/polygon_form_factor.h), E = π·L·F of the triangle clipped to
// the receiver's horizon, for a tilted triangle of unequal RGB radiance at receivers under it,
// beside it with its horizon cutting it, and behind it (single- and double-sided); and the
// irradiance vector: n·F_c is E_c at the normal it was clipped for, and at another normal whose
// horizon cuts nothing the first one kept.
#include "scene/emitter_irradiance.h"

#include <gtest/gtest.h>

#include <numbers>

#include "support/polygon_form_factor.h"

namespace bounce {
namespace {

// A triangle 1 m up, tilted about x by 30°, facing down (towards −y, a little towards +z).
EmitterTriangle tiltedTriangle(bool doubleSided = false) {
  const float c = std::cos(0.5236f), s = std::sin(0.5236f);
  const auto at = [&](float x, float z) { return glm::vec3(x, 1.0f + z * s, z * c); };
  EmitterTriangle t;
  t.v0 = at(-0.3f, -0.2f);
  t.v1 = at(0.4f, -0.2f);
  t.v2 = at(0.0f, 0.35f);
  if (glm::dot(glm::cross(t.v1 - t.v0, t.v2 - t.v0), glm::vec3(0, -1, 0)) < 0.0f)
    std::swap(t.v1, t.v2);  // front face (counter-clockwise) looking down
  t.radiance = glm::vec3(3.0f, 1.5f, 0.5f);
  t.doubleSided = doubleSided;
  return t;
}

// E (W/m², per channel) by the independent formula: π·L·F of the triangle clipped to n's side.
glm::vec3 reference(const EmitterTriangle& t, glm::vec3 p, glm::vec3 n) {
  const std::vector<glm::dvec3> polygon{glm::dvec3(t.v0), glm::dvec3(t.v1), glm::dvec3(t.v2)};
  const std::vector<glm::dvec3> clipped = test::clipPolygon(polygon, glm::dvec3(p), glm::dvec3(n));
  if (clipped.size() < 3) return glm::vec3(0.0f);
  const double f = std::abs(test::polygonFormFactor(clipped, glm::dvec3(p), glm::dvec3(n)));
  return t.radiance * static_cast<float>(std::numbers::pi * f);
}

void expectNear(glm::vec3 a, glm::vec3 b, const char* what) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(a[c], b[c], 1e-5f * b[c] + 1e-7f) << what << " channel " << c;
}

TEST(EmitterIrradiance, EqualsLambertsFormulaUnderBesideAndAcrossTheHorizon) {
  const EmitterTriangle t = tiltedTriangle();
  const struct {
    const char* what;
    glm::vec3 p, n;
  } receivers[] = {
      {"under it, facing up", {0.05f, 0.0f, 0.1f}, {0, 1, 0}},
      {"under it, tilted", {0.3f, 0.2f, -0.4f}, glm::normalize(glm::vec3(0.4f, 1.0f, 0.3f))},
      // A wall whose horizon cuts the triangle: only the part on its +x side lights it.
      {"beside it, horizon through it", {0.1f, 0.9f, 0.0f}, {1, 0, 0}},
      {"beside it, other side", {0.1f, 0.9f, 0.0f}, {-1, 0, 0}},
  };
  int lit = 0, cut = 0;
  for (const auto& r : receivers) {
    const glm::vec3 e = emitterTriangleIrradiance(t, r.p, r.n);
    expectNear(e, reference(t, r.p, r.n), r.what);
    lit += e.g > 0.0f;
    // The horizon cuts the triangle: some corners on each side of the receiver's plane.
    const float d[] = {glm::dot(r.n, t.v0 - r.p), glm::dot(r.n, t.v1 - r.p),
                       glm::dot(r.n, t.v2 - r.p)};
    cut += (d[0] > 0 || d[1] > 0 || d[2] > 0) && (d[0] < 0 || d[1] < 0 || d[2] < 0);
  }
  EXPECT_EQ(lit, 4);
  EXPECT_GE(cut, 2);  // the clipping is exercised, not only whole triangles
}

TEST(EmitterIrradiance, ASingleSidedTriangleLightsOnlyItsFrontSide) {
  const glm::vec3 above(0.05f, 2.0f, 0.1f), down(0, -1, 0);
  EXPECT_EQ(emitterTriangleIrradiance(tiltedTriangle(false), above, down), glm::vec3(0.0f));
  const glm::vec3 e = emitterTriangleIrradiance(tiltedTriangle(true), above, down);
  expectNear(e, reference(tiltedTriangle(true), above, down), "double-sided, from behind");
  EXPECT_GT(e.g, 0.0f);
}

// F_c of a light: n·F_c = E_c at the normal it was clipped for, and at a normal tilted 40° away
// whose horizon still keeps the whole triangle; a normal whose horizon cuts it is not claimed.
TEST(EmitterIrradiance, TheIrradianceVectorGivesEAtNearbyNormals) {
  AreaLightSet set;
  set.triangles = {tiltedTriangle()};
  AreaLight light;
  light.count = 1;
  set.lights = {light};
  const glm::vec3 p(0.05f, 0.0f, 0.1f), n(0, 1, 0);
  const std::array<glm::vec3, 3> f = areaLightIrradianceVectors(set, 0, p, n);
  const glm::vec3 tilted = glm::normalize(glm::vec3(std::sin(0.70f), std::cos(0.70f), 0.0f));
  for (const glm::vec3 normal : {n, tilted}) {
    const glm::vec3 e = reference(set.triangles[0], p, normal);
    ASSERT_GT(e.b, 0.0f);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(glm::dot(normal, f[static_cast<std::size_t>(c)]), e[c], 1e-5f * e[c])
          << "channel " << c << " normal " << normal.x << "," << normal.y;
  }
  expectNear(areaLightIrradiance(set, 0, p, n), reference(set.triangles[0], p, n), "the light");
}

}  // namespace
}  // namespace bounce
