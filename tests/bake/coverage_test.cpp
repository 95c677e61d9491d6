// Texel coverage: exact clipping of texel squares against atlas triangles, conservative
// coverage, sample points on the right triangle.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include <tbb/task_arena.h>

#include "atlas/uv_geometry.h"
#include "bake/texel_coverage.h"
#include "bake_scenes.h"

namespace bounce {
namespace {

float cross2(glm::vec2 a, glm::vec2 b) {
  return a.x * b.y - a.y * b.x;
}

// Written apart from the code under test: the texel square clipped by the triangle's three
// edge half-planes (the atlas clips the triangle by the square's).
std::vector<glm::vec2> referenceClip(int x, int y, glm::vec2 a, glm::vec2 b, glm::vec2 c) {
  const auto fx = static_cast<float>(x), fy = static_cast<float>(y);
  std::vector<glm::vec2> poly = {{fx, fy}, {fx + 1, fy}, {fx + 1, fy + 1}, {fx, fy + 1}};
  // Keep the inside of each edge: the side the opposite corner lies on.
  if (cross2(b - a, c - a) < 0.0f) std::swap(b, c);
  if (!(cross2(b - a, c - a) > 0.0f)) return {};  // degenerate in the atlas
  const std::array<glm::vec2, 3> corner = {a, b, c};
  std::vector<glm::vec2> next;
  for (int e = 0; e < 3 && !poly.empty(); ++e) {
    const glm::vec2 p = corner[e], q = corner[(e + 1) % 3];
    auto side = [&](glm::vec2 v) { return cross2(q - p, v - p); };  // ≥ 0 inside
    next.clear();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const glm::vec2 u = poly[i], v = poly[(i + 1) % poly.size()];
      const float su = side(u), sv = side(v);
      if (su >= 0.0f) next.push_back(u);
      if ((su >= 0.0f) != (sv >= 0.0f)) next.push_back(u + (v - u) * (su / (su - sv)));
    }
    poly.swap(next);
  }
  if (poly.size() < 3) return {};
  return poly;
}

// The production rule (atlas/uv_geometry.h) for texel (x, y).
std::vector<glm::vec2> clipTexelToTriangle(int x, int y, glm::vec2 a, glm::vec2 b, glm::vec2 c) {
  const glm::vec2 lo(static_cast<float>(x), static_cast<float>(y));
  return clipTriangleToBox(a, b, c, lo, lo + 1.0f);
}

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
      const bool overlaps =
          area(referenceClip(x, y, a, b, c)) > 0.0f || area(referenceClip(x, y, a, c, d)) > 0.0f;
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

// Coverage is built in parallel (blocks of 4096 triangles clipped at once, fragments gathered by
// texel in block order, texels sampled at once) and laid out in a fixed order: the same bytes in
// a 1- and a 4-thread arena. A 1 m floor of 120 × 120 cells (28,800 triangles: 8 blocks) in a
// 40 × 40 atlas, so every texel holds fragments of several triangles, some from two blocks.
TEST(TexelCoverage, SameBytesAtAnyThreadCount) {
  Scene scene;
  scene.materials.push_back(Material{});
  Mesh floor;
  constexpr int kCells = 120;
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) {
      floor.positions.emplace_back(static_cast<float>(i) / kCells, 0.0f,
                                   static_cast<float>(j) / kCells);
      floor.normals.emplace_back(0.0f, 1.0f, 0.0f);
    }
  LightmapLayout layout;
  layout.width = layout.height = 40;
  layout.texelSize = 0.025f;
  InstanceLightmapUv region;
  for (uint32_t j = 0; j < kCells; ++j)
    for (uint32_t i = 0; i < kCells; ++i) {
      const uint32_t v = j * (kCells + 1) + i;
      for (const uint32_t corner :
           {v, v + kCells + 1, v + 1, v + 1, v + kCells + 1, v + kCells + 2}) {
        floor.indices.push_back(corner);
        const glm::vec3 p = floor.positions[corner];
        region.cornerUv.emplace_back(0.05f + 0.9f * p.x, 0.05f + 0.9f * p.z);
      }
    }
  scene.meshes.push_back(floor);
  scene.instances.push_back(Instance{"floor", 0, glm::mat4(1.0f), Mobility::Static, 1.0f});
  layout.instances.push_back(region);
  const WorldGeometry geometry = flatten(scene);
  const auto cover = [&](int threads) {
    TexelCoverage coverage;
    tbb::task_arena(threads).execute(
        [&] { coverage = buildTexelCoverage(scene, geometry, layout, 16, 3); });
    return coverage;
  };
  const TexelCoverage a = cover(1), b = cover(4);
  EXPECT_EQ(a.points.size(), 36u * 36u * 16u);  // every texel the floor's image touches
  EXPECT_TRUE(a.first == b.first);
  EXPECT_TRUE(a.coveredArea == b.coveredArea);
  ASSERT_EQ(a.points.size(), b.points.size());
  EXPECT_EQ(0, std::memcmp(a.points.data(), b.points.data(), a.points.size() * sizeof(TexelPoint)));
}

}  // namespace
}  // namespace bounce
