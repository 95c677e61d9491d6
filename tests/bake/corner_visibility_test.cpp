// The static lights' visibility per triangle corner of the probe-lit instances
// (baker/bake/corner_visibility_bake.h) against independent quadrature: corner k's
//   V_k = ∫_T b_k(x) E_vis(x) dA / ∫_T b_k(x) E(x) dA,
// E(x) = ∫ cosθ_x cosθ_y / r² dA_y over the light, E_vis the same over the part a blocker does
// not hide, decided by an exact segment–rectangle test (not the ray kernel), on a dense grid
// over the triangle and the light.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "bake/corner_visibility_bake.h"
#include "ray/ray_kernel.h"
#include "scene/area_lights.h"
#include "scene/world_geometry.h"
#include "test_scenes.h"

namespace bounce::test {
namespace {

// A rectangle corner + s·u + t·v, s, t ∈ [0, 1]; lights face u × v.
struct Rectangle {
  glm::dvec3 corner, u, v;
};

bool crosses(glm::dvec3 a, glm::dvec3 b, const Rectangle& r) {
  const glm::dvec3 n = glm::cross(r.u, r.v);
  const double da = glm::dot(n, a - r.corner), db = glm::dot(n, b - r.corner);
  if ((da > 0) == (db > 0) || da == db) return false;
  const glm::dvec3 x = a + (b - a) * (da / (da - db)) - r.corner;
  const double s = glm::dot(x, r.u) / glm::dot(r.u, r.u);
  const double t = glm::dot(x, r.v) / glm::dot(r.v, r.v);
  return s >= 0 && s <= 1 && t >= 0 && t <= 1;
}

// E and E_vis per unit radiance at x (normal +y), midpoint rule on a grid × grid over the light.
glm::dvec2 irradiance(const Rectangle& light, const Rectangle& blocker, glm::dvec3 x,
                      int grid = 100) {
  const glm::dvec3 front = glm::normalize(glm::cross(light.u, light.v));
  const double dA = glm::length(glm::cross(light.u, light.v)) / grid / grid;
  glm::dvec2 e(0.0);
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j) {
      const glm::dvec3 y = light.corner + (i + 0.5) / grid * light.u + (j + 0.5) / grid * light.v;
      const glm::dvec3 d = y - x;
      const double r2 = glm::dot(d, d), cosX = d.y, cosY = -glm::dot(front, d);
      if (cosX <= 0 || cosY <= 0) continue;
      const double w = cosX * cosY / (r2 * r2) * dA;
      e.x += w;
      if (!crosses(x, y, blocker)) e.y += w;
    }
  return e;
}

// ∫_T b_k E_vis and ∫_T b_k E per corner k of triangle (p0, p1, p2), by the midpoint rule over
// its n² equal sub-triangles, each weighted by its area.
struct CornerIntegrals {
  glm::dvec3 visible{0.0}, all{0.0};
};
CornerIntegrals exactCornerIntegrals(const std::array<glm::dvec3, 3>& p, const Rectangle& light,
                                     const Rectangle& blocker, int n = 24) {
  const double cell = 0.5 * glm::length(glm::cross(p[1] - p[0], p[2] - p[0])) / (n * n);
  CornerIntegrals sums;
  glm::dvec3& all = sums.all;
  glm::dvec3& visible = sums.visible;
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j)
      for (int up = 0; up < (i + j + 1 < n ? 2 : 1); ++up) {
        // The sub-triangle's centroid in barycentric coordinates (upright and inverted cells).
        const double a = up == 0 ? (i + 1.0 / 3.0) / n : (i + 2.0 / 3.0) / n;
        const double b = up == 0 ? (j + 1.0 / 3.0) / n : (j + 2.0 / 3.0) / n;
        const glm::dvec3 bary(1.0 - a - b, a, b);
        const glm::dvec3 x = bary.x * p[0] + bary.y * p[1] + bary.z * p[2];
        const glm::dvec2 e = irradiance(light, blocker, x);
        all += bary * e.x * cell;
        visible += bary * e.y * cell;
      }
  return sums;
}

// V_k of a lone triangle.
glm::dvec3 exactCornerVisibility(const std::array<glm::dvec3, 3>& p, const Rectangle& light,
                                 const Rectangle& blocker) {
  const CornerIntegrals sums = exactCornerIntegrals(p, light, blocker);
  return sums.visible / sums.all;
}

// A 0.4 m square light 1 m over the floor, facing down; a blocker at 0.5 m over x < 0, so the
// penumbra on the floor runs over x ∈ [−0.2, 0.2]. A floor triangle with a corner in the umbra
// (x = −0.4), one on the penumbra's middle (x = 0) and one fully lit (x = 0.4), as a static
// instance, and the same mesh mirrored in x (flatten swaps its corners 1 and 2).
TEST(CornerVisibility, EachCornerHoldsTheVisibleFractionOfTheTriangleNearIt) {
  const Rectangle light{{-0.2, 1.0, -0.2}, {0.4, 0, 0}, {0, 0, 0.4}};
  const Rectangle blocker{{-1.0, 0.5, -2.0}, {0, 0, 4.0}, {1.0, 0, 0}};
  ASSERT_LT(glm::cross(light.u, light.v).y, 0.0) << "the light faces down";
  Scene scene;
  addQuad(scene, light.corner, light.corner + light.u, light.corner + light.u + light.v,
          light.corner + light.v, addMaterial(scene, glm::vec3(0.0f), glm::vec3(1.0f)));
  const uint32_t grey = addMaterial(scene, glm::vec3(0.5f));
  addQuad(scene, blocker.corner, blocker.corner + blocker.u, blocker.corner + blocker.u + blocker.v,
          blocker.corner + blocker.v, grey);
  Mesh triangle;
  triangle.positions = {{-0.4f, 0.0f, -0.2f}, {0.0f, 0.0f, 0.3f}, {0.4f, 0.0f, -0.2f}};
  triangle.normals.assign(3, glm::vec3(0, 1, 0));
  triangle.indices = {0, 1, 2};
  triangle.material = grey;
  scene.meshes.push_back(triangle);
  const auto mesh = static_cast<uint32_t>(scene.meshes.size() - 1);
  const glm::mat4 mirror = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 0.8f)),
                                      glm::vec3(-1.0f, 1.0f, 1.0f));
  for (const glm::mat4& transform : {glm::mat4(1.0f), mirror}) {
    Instance instance;
    instance.name = "triangle";
    instance.mesh = mesh;
    instance.transform = transform;
    scene.instances.push_back(instance);
  }
  const auto first = static_cast<uint32_t>(scene.instances.size() - 2);
  const WorldGeometry geometry = flatten(scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  const AreaLightSet lights = sceneAreaLights(scene);
  ASSERT_EQ(lights.staticCount(), 1u);

  CornerVisibilitySettings settings;
  settings.samplesPerLight = 4096;
  const std::vector<uint32_t> traced{first, first + 1};
  const std::vector<uint8_t> mirrored{0, 1};
  const CornerVisibilityBake baked =
      bakeCornerVisibility(lights, {}, geometry, *kernel, traced, mirrored, settings);
  ASSERT_EQ(baked.visibility.corners.size(), 6u);
  EXPECT_EQ(baked.firstCorner, (std::vector<uint32_t>{0, 3}));
  EXPECT_EQ(baked.cornerCount, (std::vector<uint32_t>{3, 3}));
  EXPECT_EQ(baked.rays, 6u * 4096u);

  for (int i = 0; i < 2; ++i) {
    // The mesh's corners at their world places: corner k of the record is the mesh's corner k.
    const glm::mat4 transform = scene.instances[first + static_cast<uint32_t>(i)].transform;
    std::array<glm::dvec3, 3> p;
    for (int k = 0; k < 3; ++k)
      p[static_cast<std::size_t>(k)] = glm::dvec3(transform * glm::vec4(triangle.positions[k], 1));
    const glm::dvec3 exact = exactCornerVisibility(p, light, blocker);
    for (int k = 0; k < 3; ++k) {
      const TexelVisibility& corner = baked.visibility.corners[3 * i + k];
      ASSERT_EQ(corner.light[0], 0u);
      EXPECT_EQ(corner.light[1], kNoLight);
      // A ratio of two estimates over 4096 pairs: the binomial bound on one unstratified
      // fraction, √(V(1−V)/M) ≤ 0.0078, times 4.
      EXPECT_NEAR(corner.visible[0], exact[k], 0.03)
          << "instance " << i << " corner " << k << " at x = " << p[k].x;
    }
    // The three corners differ (umbra, penumbra, lit), so one V for the whole triangle fails.
    EXPECT_LT(std::min(exact[0], exact[2]), 0.4);
    EXPECT_GT(std::max(exact[0], exact[2]), 0.6);
  }
}

// A fan of three floor triangles of unequal areas around a vertex in the penumbra, written as a
// triangle soup (every corner its own mesh vertex, as an OBJ without normals loads): the corners
// at one place are one vertex, and each holds its ring's
//   V_v = Σ_T ∫_T b_v E_vis / Σ_T ∫_T b_v E.
// A wall triangle standing on the fan's centre (normal 90° off) stays a vertex of its own.
TEST(CornerVisibility, CornersAtOnePlaceHoldTheirRingsVisibleFraction) {
  // The first test's light and blocker, and the fan, scaled by kScale = 3/100 (V is unchanged by a
  // scale): only triangles no longer than 2.5 cm weld, and these are 2.2 cm at most.
  constexpr double kScale = 0.03;
  const Rectangle light{glm::dvec3(-0.2, 1.0, -0.2) * kScale, glm::dvec3(0.4, 0, 0) * kScale,
                        glm::dvec3(0, 0, 0.4) * kScale};
  const Rectangle blocker{glm::dvec3(-1.0, 0.5, -2.0) * kScale, glm::dvec3(0, 0, 4.0) * kScale,
                          glm::dvec3(1.0, 0, 0) * kScale};
  Scene scene;
  addQuad(scene, light.corner, light.corner + light.u, light.corner + light.u + light.v,
          light.corner + light.v, addMaterial(scene, glm::vec3(0.0f), glm::vec3(1.0f)));
  const uint32_t grey = addMaterial(scene, glm::vec3(0.5f));
  addQuad(scene, blocker.corner, blocker.corner + blocker.u, blocker.corner + blocker.u + blocker.v,
          blocker.corner + blocker.v, grey);
  // Centre o at x = 0.02·kScale (the penumbra's middle); a wide triangle into the umbra, a middle
  // one, a small one on the lit side. Each wound to face +y.
  const glm::dvec3 o = glm::dvec3(0.02, 0, 0) * kScale, a = glm::dvec3(-0.45, 0, -0.3) * kScale,
                   b = glm::dvec3(-0.1, 0, 0.35) * kScale, c = glm::dvec3(0.2, 0, 0.3) * kScale,
                   d = glm::dvec3(0.3, 0, 0.1) * kScale;
  const std::vector<std::array<glm::dvec3, 3>> fan{{o, a, b}, {o, b, c}, {o, c, d}};
  Mesh soup;
  for (const auto& t : fan)
    for (const glm::dvec3& p : t) {
      soup.indices.push_back(static_cast<uint32_t>(soup.positions.size()));
      soup.positions.emplace_back(p);
      soup.normals.emplace_back(0.0f, 1.0f, 0.0f);
    }
  // The wall: through o, facing +x, its corner 0 at o.
  for (const glm::vec3 p : {glm::vec3(o), glm::vec3(o + glm::dvec3(0, 0.2, -0.1) * kScale),
                            glm::vec3(o + glm::dvec3(0, 0.2, 0.1) * kScale)}) {
    soup.indices.push_back(static_cast<uint32_t>(soup.positions.size()));
    soup.positions.push_back(p);
    soup.normals.emplace_back(1.0f, 0.0f, 0.0f);
  }
  soup.material = grey;
  scene.meshes.push_back(soup);
  Instance instance;
  instance.name = "fan";
  instance.mesh = static_cast<uint32_t>(scene.meshes.size() - 1);
  scene.instances.push_back(instance);
  const WorldGeometry geometry = flatten(scene);
  for (std::size_t t = 0; t < fan.size(); ++t) {
    const glm::dvec3 n = glm::cross(fan[t][1] - fan[t][0], fan[t][2] - fan[t][0]);
    ASSERT_GT(n.y, 0.0) << "triangle " << t << " faces up";
  }
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  const AreaLightSet lights = sceneAreaLights(scene);
  CornerVisibilitySettings settings;
  settings.samplesPerLight = 4096;
  const std::vector<uint32_t> traced{static_cast<uint32_t>(scene.instances.size() - 1)};
  const CornerVisibilityBake baked =
      bakeCornerVisibility(lights, {}, geometry, *kernel, traced, {}, settings);
  ASSERT_EQ(baked.visibility.corners.size(), 12u);
  // o, a, b, c, d on the floor, and the wall's three corners.
  EXPECT_EQ(baked.vertices, 8u);

  std::vector<CornerIntegrals> exact;
  for (const auto& t : fan) exact.push_back(exactCornerIntegrals(t, light, blocker));
  // Each floor place and the fan corners at it.
  const std::vector<std::pair<glm::dvec3, std::vector<std::pair<int, int>>>> places{
      {o, {{0, 0}, {1, 0}, {2, 0}}},
      {a, {{0, 1}}},
      {b, {{0, 2}, {1, 1}}},
      {c, {{1, 2}, {2, 1}}},
      {d, {{2, 2}}}};
  double spread = 0.0;  // how far the ring's V is from its triangles' own corner V
  for (const auto& [place, corners] : places) {
    double visible = 0.0, all = 0.0;
    for (const auto& [t, k] : corners) {
      visible += exact[static_cast<std::size_t>(t)].visible[k];
      all += exact[static_cast<std::size_t>(t)].all[k];
    }
    for (const auto& [t, k] : corners) {
      const TexelVisibility& corner = baked.visibility.corners[3 * t + k];
      ASSERT_EQ(corner.light[0], 0u);
      // As above: 4096 pairs, the binomial bound 0.0078 times 4.
      EXPECT_NEAR(corner.visible[0], visible / all, 0.03)
          << "fan triangle " << t << " corner " << k << " at x = " << place.x;
      const CornerIntegrals& own = exact[static_cast<std::size_t>(t)];
      spread = std::max(spread, std::abs(own.visible[k] / own.all[k] - visible / all));
    }
  }
  // The centre's triangles see the light differently, so one corner alone would be off.
  EXPECT_GT(spread, 0.1);
}

// Each vertex draws its points and pairs from its own keys: any thread count, the same bytes.
// A 1 m floor of 2 × 64² triangles (1.6 cm cells: their corners weld into vertices) under a
// panel and a blocker, so that the threads interleave.
TEST(CornerVisibility, TheSameAtAnyThreadCount) {
  Scene scene;
  addQuad(scene, {-0.2f, 1.0f, -0.2f}, {0.2f, 1.0f, -0.2f}, {0.2f, 1.0f, 0.2f}, {-0.2f, 1.0f, 0.2f},
          addMaterial(scene, glm::vec3(0.0f), glm::vec3(1.0f)));
  const uint32_t grey = addMaterial(scene, glm::vec3(0.5f));
  addQuad(scene, {-1, 0.5f, -1}, {-1, 0.5f, 1}, {0, 0.5f, 1}, {0, 0.5f, -1}, grey);
  Mesh floor;
  constexpr int kCells = 64;
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) {
      floor.positions.emplace_back(-0.5f + 1.0f * i / kCells, 0.0f, -0.5f + 1.0f * j / kCells);
      floor.normals.emplace_back(0.0f, 1.0f, 0.0f);
    }
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      const auto a = static_cast<uint32_t>(j * (kCells + 1) + i), b = a + 1, c = a + kCells + 1,
                 d = c + 1;
      for (const uint32_t k : {a, c, d, a, d, b}) floor.indices.push_back(k);  // facing +y
    }
  floor.material = grey;
  scene.meshes.push_back(floor);
  Instance instance;
  instance.name = "floor";
  instance.mesh = static_cast<uint32_t>(scene.meshes.size() - 1);
  scene.instances.push_back(instance);
  const WorldGeometry geometry = flatten(scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  const AreaLightSet lights = sceneAreaLights(scene);
  const std::vector<uint32_t> traced{static_cast<uint32_t>(scene.instances.size() - 1)};
  CornerVisibilitySettings one, two;
  one.samplesPerLight = two.samplesPerLight = 16;
  one.threads = 1;
  two.threads = 2;
  const CornerVisibilityBake a =
      bakeCornerVisibility(lights, {}, geometry, *kernel, traced, {}, one);
  const CornerVisibilityBake b =
      bakeCornerVisibility(lights, {}, geometry, *kernel, traced, {}, two);
  ASSERT_EQ(a.visibility.corners.size(), 3u * 2 * kCells * kCells);
  int penumbra = 0;
  for (const TexelVisibility& c : a.visibility.corners)
    penumbra += c.light[0] == 0 && c.visible[0] > 0.0f && c.visible[0] < 1.0f ? 1 : 0;
  EXPECT_GT(penumbra, 1000) << "corners in the blocker's penumbra";
  EXPECT_EQ(a.vertices, 65u * 65u) << "the floor's corners, welded";
  EXPECT_EQ(a.visibility, b.visibility);
}

}  // namespace
}  // namespace bounce::test
