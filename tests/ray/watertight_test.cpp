// Closed meshes seen from inside: rays aimed exactly at shared edges and vertices must never
// escape (a hole would be a light leak in the baker), for both backends.
#include <gtest/gtest.h>

#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "both_backends.h"
#include "ray/ray_kernel.h"
#include "test_geometry.h"

namespace bounce {
namespace {

using testing::addCube;
using testing::addIcosphere;

// Sum over triangles of p0·(p1×p2)/6: the enclosed volume, positive when faces point outward.
double signedVolume(const WorldGeometry& g) {
  double volume = 0.0;
  for (const glm::uvec3 t : g.triangles)
    volume += glm::dot(glm::dvec3(g.positions[t.x]),
                       glm::cross(glm::dvec3(g.positions[t.y]), glm::dvec3(g.positions[t.z]))) /
              6.0;
  return volume;
}

struct Escapes {
  int rays = 0, escaped = 0, inwardNormals = 0;
};

// From `inside`, aims at every vertex and at 16 points (ends, midpoint, random) of every edge.
Escapes fireAtEdgesAndVertices(const WorldGeometry& g, const RayKernel& kernel, glm::vec3 inside,
                               uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Escapes result;
  const auto fire = [&](glm::vec3 target) {
    const Ray ray{inside, 0.0f, target - inside};  // t = 1 at the target
    const Hit hit = kernel.intersect(ray);
    ++result.rays;
    // The ray must stop on the surface at about t = 1 (it is aimed at a surface point, and
    // the mesh is convex), and leave through a front (outward) face.
    if (!hit.valid() || std::abs(hit.t - 1.0f) > 1e-3f ||
        !kernel.occluded(Ray{inside, 0.0f, target - inside, 2.0f}))
      ++result.escaped;
    else if (glm::dot(hit.geometricNormal, ray.direction) <= 0.0f)
      ++result.inwardNormals;
  };
  for (const glm::vec3 p : g.positions) fire(p);
  for (const glm::uvec3 t : g.triangles)
    for (int e = 0; e < 3; ++e) {
      const glm::vec3 a = g.positions[t[e]], b = g.positions[t[(e + 1) % 3]];
      fire(0.5f * (a + b));
      for (int k = 0; k < 14; ++k) fire(glm::mix(a, b, u(rng)));
    }
  return result;
}

class WatertightTest : public ::testing::TestWithParam<RayBackend> {};

TEST_P(WatertightTest, RaysAtEdgesAndVerticesOfARotatedCubeNeverEscape) {
  WorldGeometry g;
  glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(3.0f, -2.0f, 5.0f));
  m = glm::rotate(m, 0.7f, glm::normalize(glm::vec3(1, 2, 3)));
  m = glm::scale(m, glm::vec3(1.5f, 0.5f, 2.0f));
  addCube(g, m);
  testing::finish(g);
  ASSERT_GT(signedVolume(g), 0.0);
  const auto kernel = makeRayKernel(g, GetParam());
  const glm::vec3 centre(m * glm::vec4(0, 0, 0, 1));
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-0.9f, 0.9f);
  int rays = 0;
  for (uint32_t i = 0; i < 40; ++i) {
    const glm::vec3 inside = i == 0 ? centre : glm::vec3(m * glm::vec4(u(rng), u(rng), u(rng), 1));
    const Escapes e = fireAtEdgesAndVertices(g, *kernel, inside, i);
    EXPECT_EQ(e.escaped, 0) << "from " << inside.x << " " << inside.y << " " << inside.z;
    EXPECT_EQ(e.inwardNormals, 0);
    rays += e.rays;
  }
  EXPECT_GT(rays, 20000);
}

TEST_P(WatertightTest, RaysAtEdgesAndVerticesOfAnIcosphereNeverEscape) {
  WorldGeometry g;
  addIcosphere(g, 3, glm::vec3(-20.0f, 7.0f, 11.0f), 3.0f);  // 1280 triangles
  testing::finish(g);
  ASSERT_GT(signedVolume(g), 0.0);
  const auto kernel = makeRayKernel(g, GetParam());
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.5f, 1.5f);
  for (uint32_t i = 0; i < 3; ++i) {
    const glm::vec3 inside = glm::vec3(-20.0f, 7.0f, 11.0f) + glm::vec3(u(rng), u(rng), u(rng));
    const Escapes e = fireAtEdgesAndVertices(g, *kernel, inside, i);
    EXPECT_EQ(e.escaped, 0);
    EXPECT_EQ(e.inwardNormals, 0);
    EXPECT_GT(e.rays, 50000);
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, WatertightTest, kBothBackends, backendName);

}  // namespace
}  // namespace bounce
