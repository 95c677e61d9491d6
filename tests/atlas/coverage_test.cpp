// Conservative texel coverage (atlas/uv_geometry.h) against the exact area of triangle ∩ texel,
// computed here by clipping (Sutherland–Hodgman), independently of the separating-axis test.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "atlas/uv_geometry.h"
#include "support/clipped_area.h"

namespace bounce::test {
namespace {

TEST(TexelCoverage, TouchedTexelsAreThoseTheTriangleOverlaps) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> coordinate(0.0f, 12.0f);
  const int size = 12;
  int slivers = 0;
  for (int trial = 0; trial < 300; ++trial) {
    glm::vec2 p[3];
    for (glm::vec2& c : p) c = {coordinate(rng), coordinate(rng)};
    if (trial % 3 == 0) p[2] = p[0] + (p[1] - p[0]) * 0.5f + glm::vec2(0.01f, -0.02f);  // slivers
    std::set<std::pair<int, int>> touched;
    forEachTouchedTexel(p[0], p[1], p[2], size, size, [&](int x, int y) { touched.emplace(x, y); });
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const double area = clippedArea({glm::dvec2(p[0]), glm::dvec2(p[1]), glm::dvec2(p[2])},
                                        glm::dvec2(x, y), glm::dvec2(x + 1, y + 1));
        const bool isTouched = touched.count({x, y}) > 0;
        // Any overlap deeper than the coverage epsilon counts; no overlap does not.
        if (area > 1e-4) {
          EXPECT_TRUE(isTouched) << trial << " texel " << x << "," << y << " area " << area;
        }
        if (area == 0.0) {
          EXPECT_FALSE(isTouched) << trial << " texel " << x << "," << y;
        }
        slivers += area > 0.0 && area < 1e-2 && isTouched;
      }
  }
  EXPECT_GT(slivers, 0);  // the conservative cases were exercised
}

TEST(TexelCoverage, EdgeOnATexelBoundaryTouchesOneSide) {
  // The square [2,5]² as two triangles: exactly 9 texels, none of its neighbours.
  std::set<std::pair<int, int>> touched;
  const glm::vec2 a(2, 2), b(5, 2), c(5, 5), d(2, 5);
  for (const auto& t : {std::array<glm::vec2, 3>{a, b, c}, std::array<glm::vec2, 3>{a, c, d}})
    forEachTouchedTexel(t[0], t[1], t[2], 8, 8, [&](int x, int y) { touched.emplace(x, y); });
  EXPECT_EQ(touched.size(), 9u);
  for (const auto& [x, y] : touched) {
    EXPECT_TRUE(x >= 2 && x < 5 && y >= 2 && y < 5) << x << "," << y;
  }
}

// The texel parts of a triangle tile it: their areas sum to its area, each lies inside its
// texel and inside the triangle, and a part has area exactly where the texel is touched.
TEST(TexelCoverage, TexelPartsTileTheTriangle) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> coordinate(0.0f, 9.0f);
  for (int trial = 0; trial < 200; ++trial) {
    glm::vec2 p[3];
    for (glm::vec2& c : p) c = {coordinate(rng), coordinate(rng)};
    const float area = std::abs(signedArea(p[0], p[1], p[2]));
    double sum = 0.0;
    for (int y = 0; y < 9; ++y)
      for (int x = 0; x < 9; ++x) {
        const glm::vec2 lo(static_cast<float>(x), static_cast<float>(y));
        const std::vector<glm::vec2> part = clipTriangleToBox(p[0], p[1], p[2], lo, lo + 1.0f);
        const double partArea = polygonArea(part);
        const double exact = clippedArea({glm::dvec2(p[0]), glm::dvec2(p[1]), glm::dvec2(p[2])},
                                         glm::dvec2(lo), glm::dvec2(lo + 1.0f));
        EXPECT_NEAR(partArea, exact, 1e-4) << trial << " texel " << x << "," << y;
        for (const glm::vec2 q : part) {
          EXPECT_GE(q.x, lo.x - 1e-5f);
          EXPECT_LE(q.x, lo.x + 1.0f + 1e-5f);
          EXPECT_GE(q.y, lo.y - 1e-5f);
          EXPECT_LE(q.y, lo.y + 1.0f + 1e-5f);
        }
        sum += partArea;
      }
    EXPECT_NEAR(sum, area, 1e-4 * std::max(1.0f, area)) << trial;
  }
}

TEST(UvOverlap, SharedEdgesAreNotOverlapsCrossingsAre) {
  const std::vector<glm::vec2> fan = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
  EXPECT_FALSE(findOverlappingTriangles(fan, 1e-4f).has_value());
  std::vector<glm::vec2> folded = fan;
  folded[5] = {1.0f, 0.5f};  // the second triangle now lies over the first
  EXPECT_TRUE(findOverlappingTriangles(folded, 1e-4f).has_value());
  std::vector<glm::vec2> inside = fan;
  inside.insert(inside.end(), {{0.6f, 0.1f}, {0.9f, 0.1f}, {0.9f, 0.3f}});  // within triangle 0
  EXPECT_TRUE(findOverlappingTriangles(inside, 1e-4f).has_value());
}

}  // namespace
}  // namespace bounce::test
