// GL-free: the outline of a planar area light (scene/area_light_outline.h), the polygon the
// renderer evaluates in place of its triangles. What must hold is the physics: Lambert's contour
// integral over the outline, clipped to a receiver's horizon, equals the sum over the light's
// triangles each clipped the same way (support/polygon_form_factor.h, written apart), at
// receivers above, beside and across the light's plane; and lights whose triangles are no one
// loop keep their triangles.
#include "scene/area_light_outline.h"

#include <gtest/gtest.h>

#include <random>

#include "support/polygon_form_factor.h"

namespace bounce {
namespace {

// Unit squares (x, z) of the plane y = h as two counter-clockwise triangles each about `up`
// (+y or −y), sharing their corners bit for bit as one mesh's triangles do.
std::vector<EmitterTriangle> squares(const std::vector<glm::vec2>& cells, float h, bool up) {
  std::vector<EmitterTriangle> out;
  for (const glm::vec2 c : cells) {
    const glm::vec3 a(c.x, h, c.y), b(c.x + 1, h, c.y), d(c.x + 1, h, c.y + 1), e(c.x, h, c.y + 1);
    // (e − a) × (b − a) = (0,0,1) × (1,0,0) = +y: the order a, e, d, b faces up.
    if (up) {
      out.push_back({a, e, d, glm::vec3(2.0f)});
      out.push_back({a, d, b, glm::vec3(2.0f)});
    } else {
      out.push_back({a, b, d, glm::vec3(2.0f)});
      out.push_back({a, d, e, glm::vec3(2.0f)});
    }
  }
  return out;
}

// The set holding `triangles` as one light (what splitAreaLights would give a planar piece).
AreaLightSet oneLight(std::vector<EmitterTriangle> triangles) {
  AreaLightSet set;
  AreaLight light;
  light.count = static_cast<uint32_t>(triangles.size());
  glm::vec3 weighted(0.0f), centre(0.0f);
  for (const EmitterTriangle& t : triangles) {
    const glm::vec3 c = 0.5f * glm::cross(t.v1 - t.v0, t.v2 - t.v0);
    weighted += c;
    light.area += glm::length(c);
    centre += glm::length(c) * (t.v0 + t.v1 + t.v2) / 3.0f;
  }
  light.normal = glm::normalize(weighted);
  light.centre = centre / light.area;
  for (const EmitterTriangle& t : triangles)
    for (const glm::vec3& v : {t.v0, t.v1, t.v2})
      light.radius = std::max(light.radius, glm::length(v - light.centre));
  set.triangles = std::move(triangles);
  set.lights.push_back(light);
  return set;
}

std::vector<glm::dvec3> dvec(const std::vector<glm::vec3>& v) {
  return std::vector<glm::dvec3>(v.begin(), v.end());
}

// Σ over the triangles of the clipped triangle's form factor, and the clipped outline's.
void expectSameFormFactor(const AreaLightSet& set, const std::vector<glm::vec3>& outline) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int straddling = 0;
  for (int i = 0; i < 200; ++i) {
    // Receivers around the light, at any tilt; a light in front of its own face only.
    const glm::dvec3 x(1.0 + 2.0 * u(random), 0.6 * u(random), 1.0 + 2.0 * u(random));
    const glm::dvec3 n = glm::normalize(glm::dvec3(u(random), u(random), u(random)));
    const glm::dvec3 front(set.lights[0].normal);
    if (glm::dot(front, x - glm::dvec3(set.triangles[0].v0)) <= 1e-3) continue;
    double triangles = 0.0;
    bool clipped = false;
    for (const EmitterTriangle& t : set.triangles) {
      const auto piece = test::clipPolygon(dvec({t.v0, t.v1, t.v2}), x, n);
      clipped = clipped || (piece.size() != 3 && !piece.empty());
      if (piece.size() >= 3) triangles += test::polygonFormFactor(piece, x, n);
    }
    straddling += clipped;
    const auto piece = test::clipPolygon(dvec(outline), x, n);
    const double polygon = piece.size() >= 3 ? test::polygonFormFactor(piece, x, n) : 0.0;
    EXPECT_NEAR(polygon, triangles, 1e-9 + 1e-6 * std::abs(triangles))
        << "receiver (" << x.x << ", " << x.y << ", " << x.z << ")";
  }
  EXPECT_GT(straddling, 10);  // the horizon crossed the light at many of them
}

TEST(AreaLightOutline, ARectangleOfTwoTrianglesIsItsFourCorners) {
  for (const bool up : {true, false}) {
    const AreaLightSet set = oneLight(squares({{0, 0}}, 0.0f, up));
    const auto outline = areaLightOutline(set, set.lights[0]);
    ASSERT_TRUE(outline);
    EXPECT_EQ(outline->size(), 4u);
    expectSameFormFactor(set, *outline);
  }
}

// Three squares in an L: a concave hexagon (the corners where two squares meet along a straight
// side are dropped). Clipped by a horizon it can fall into two pieces joined along the horizon:
// the contour integral is still the sum.
TEST(AreaLightOutline, AnLOfThreeSquaresIsAConcaveHexagon) {
  const AreaLightSet set = oneLight(squares({{0, 0}, {1, 0}, {0, 1}}, 0.0f, false));
  const auto outline = areaLightOutline(set, set.lights[0]);
  ASSERT_TRUE(outline);
  EXPECT_EQ(outline->size(), 6u);
  expectSameFormFactor(set, *outline);
}

TEST(AreaLightOutline, LightsThatAreNoOneLoopKeepTheirTriangles) {
  // Two squares apart, four around a hole, and two touching at one corner only.
  for (const auto& cells : std::vector<std::vector<glm::vec2>>{
           {{0, 0}, {2, 0}},
           {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {2, 1}, {0, 2}, {1, 2}, {2, 2}},
           {{0, 0}, {1, 1}}}) {
    const AreaLightSet set = oneLight(squares(cells, 0.0f, true));
    EXPECT_FALSE(areaLightOutline(set, set.lights[0])) << cells.size() << " squares";
  }
  // A T-junction: one square beside two half squares.
  std::vector<EmitterTriangle> t = squares({{0, 0}}, 0.0f, true);
  const glm::vec3 a(1, 0, 0), b(2, 0, 0), c(2, 0, 0.5f), d(1, 0, 0.5f), e(2, 0, 1), f(1, 0, 1);
  for (const auto& [p, q, r] : {std::array{a, d, c}, {a, c, b}, {d, f, e}, {d, e, c}})
    t.push_back({p, q, r, glm::vec3(2.0f)});
  AreaLightSet junction = oneLight(t);
  EXPECT_FALSE(areaLightOutline(junction, junction.lights[0]));
  // A square folded along its diagonal: no plane.
  std::vector<EmitterTriangle> folded = squares({{0, 0}}, 0.0f, true);
  folded[1].v2.y = 0.3f;
  const AreaLightSet bent = oneLight(folded);
  EXPECT_FALSE(areaLightOutline(bent, bent.lights[0]));
  // Two radiances in one plane.
  std::vector<EmitterTriangle> unequal = squares({{0, 0}}, 0.0f, true);
  unequal[1].radiance = glm::vec3(3.0f);
  const AreaLightSet twoColours = oneLight(unequal);
  EXPECT_FALSE(areaLightOutline(twoColours, twoColours.lights[0]));
}

}  // namespace
}  // namespace bounce
