// Texel coverage: exact clipping of texel squares against atlas triangles, conservative
// coverage, sample points on the right triangle.
#include <gtest/gtest.h>

#include <cmath>

#include "bake/texel_coverage.h"
#include "bake_scenes.h"

namespace bounce {
namespace {

float area(const std::vector<glm::vec2>& p) {
  float twice = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const glm::vec2 a = p[i], b = p[(i + 1) % p.size()];
    twice += a.x * b.y - a.y * b.x;
  }
  return 0.5f * std::abs(twice);
}

TEST(TexelClip, AreasOfSimpleOverlaps) {
  // A triangle holding the whole texel (1, 1): area 1; the diagonal half: ½; either winding.
  EXPECT_NEAR(area(clipTexelToTriangle(1, 1, {0, 0}, {10, 0}, {0, 10})), 1.0f, 1e-6f);
  EXPECT_NEAR(area(clipTexelToTriangle(1, 1, {1, 1}, {2, 1}, {1, 2})), 0.5f, 1e-6f);
  EXPECT_NEAR(area(clipTexelToTriangle(1, 1, {1, 1}, {1, 2}, {2, 1})), 0.5f, 1e-6f);
  // A sliver touching the texel's corner region still covers it; a far triangle does not.
  EXPECT_GT(area(clipTexelToTriangle(0, 0, {0.9f, 0.9f}, {3, 0.95f}, {0.95f, 3})), 0.0f);
  EXPECT_TRUE(clipTexelToTriangle(5, 5, {0, 0}, {1, 0}, {0, 1}).empty());
}

TEST(TexelCoverage, CoveredAreaSumsToTheTrianglesAtlasArea) {
  // One triangle of an arbitrary shape in a 16×16 atlas: every texel it touches is covered
  // (conservative), the covered areas sum to its area, and each point lies inside it.
  Scene scene;
  const uint32_t m = test::addMaterial(scene, glm::vec3(0.5f));
  test::addQuad(scene, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, m);
  const WorldGeometry geometry = flatten(scene);
  LightmapLayout layout;
  layout.width = layout.height = 16;
  layout.texelSize = 0.1f;
  const glm::vec2 a(1.3f, 2.7f), b(13.2f, 4.1f), c(5.5f, 14.6f), d(0.6f, 14.9f);
  InstanceLightmapUv region;
  region.instance = 0;
  for (const glm::vec2 p : {a, b, c, a, c, d}) region.cornerUv.push_back(p / 16.0f);
  layout.instances.push_back(region);
  const TexelCoverage coverage = buildTexelCoverage(scene, geometry, layout, 8, 1);
  double sum = 0;
  int touched = 0;
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      const std::size_t t = static_cast<std::size_t>(y) * 16 + x;
      sum += coverage.coveredArea[t];
      const bool overlaps = area(clipTexelToTriangle(x, y, a, b, c)) > 0.0f ||
                            area(clipTexelToTriangle(x, y, a, c, d)) > 0.0f;
      EXPECT_EQ(overlaps, coverage.covered(t)) << x << "," << y;
      touched += overlaps;
      EXPECT_LE(coverage.coveredArea[t], 1.0f + 1e-5f);
    }
  }
  const auto cross = [](glm::vec2 u, glm::vec2 v) { return u.x * v.y - u.y * v.x; };
  const double exact = 0.5 * std::abs(cross(b - a, c - a)) + 0.5 * std::abs(cross(c - a, d - a));
  EXPECT_NEAR(sum, exact, 1e-3);
  EXPECT_GT(touched, 100);
  // Each point: on the quad (z = 0, inside [0,1]²), normal +z, and in its texel.
  for (std::size_t t = 0; t < coverage.texelCount(); ++t) {
    for (uint32_t k = coverage.first[t]; k < coverage.first[t + 1]; ++k) {
      const TexelPoint& p = coverage.points[k];
      EXPECT_NEAR(p.position.z, 0.0f, 1e-6f);
      EXPECT_GE(p.position.x, -1e-5f);
      EXPECT_LE(p.position.x, 1.0f + 1e-5f);
      EXPECT_NEAR(p.shadingNormal.z, 1.0f, 1e-6f);
      EXPECT_EQ(static_cast<std::size_t>(std::floor(p.texelPosition.y)) * 16 +
                    static_cast<std::size_t>(std::floor(p.texelPosition.x)),
                t);
    }
  }
}

}  // namespace
}  // namespace bounce
