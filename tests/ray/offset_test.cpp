// offsetRayOrigin keeps secondary rays off the surface they start on at every scale: from a
// convex closed mesh, an outward ray can hit nothing and an inward ray can only hit another
// triangle, whatever the mesh's size and distance from the world origin.
#include <gtest/gtest.h>

#include <random>

#include "ray/ray_kernel.h"
#include "test_geometry.h"

namespace bounce {
namespace {

class OffsetTest : public ::testing::TestWithParam<RayBackend> {};

TEST_P(OffsetTest, SecondaryRaysNeverHitTheirOwnSurface) {
  struct Placement {
    glm::vec3 centre;
    float radius;
  };
  const Placement placements[] = {{{0, 0, 0}, 1e-2f},
                                  {{0.3f, -0.1f, 0.2f}, 1.0f},
                                  {{1e3f, 0, -5e2f}, 2.0f},
                                  {{0, 0, 0}, 1e3f},
                                  {{-3e4f, 2e4f, 0}, 50.0f}};
  for (const Placement& at : placements) {
    WorldGeometry g;
    testing::addIcosphere(g, 3, at.centre, at.radius);
    testing::finish(g);
    const auto kernel = makeRayKernel(g, GetParam());
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int selfHits = 0, outwardHits = 0, inwardMisses = 0;
    for (int i = 0; i < 4000; ++i) {
      const std::size_t t = i % g.triangles.size();
      const glm::uvec3 tri = g.triangles[t];
      float b1 = u(rng), b2 = u(rng);
      if (b1 + b2 > 1.0f) b1 = 1.0f - b1, b2 = 1.0f - b2;
      // The hit point as a kernel's barycentrics would give it.
      const glm::vec3 p =
          (1.0f - b1 - b2) * g.positions[tri.x] + b1 * g.positions[tri.y] + b2 * g.positions[tri.z];
      const glm::vec3 n = glm::normalize(g.triangleCross(t));  // outward
      const glm::vec3 out = testing::cosineDirection(n, u(rng), u(rng));
      const glm::vec3 in = testing::cosineDirection(-n, u(rng), u(rng));
      if (kernel->intersect(Ray{offsetRayOrigin(p, n, out), 0.0f, out}).valid()) ++outwardHits;
      const Hit back = kernel->intersect(Ray{offsetRayOrigin(p, n, in), 0.0f, in});
      if (!back.valid())
        ++inwardMisses;
      else if (back.triangle == t)
        ++selfHits;
    }
    EXPECT_EQ(outwardHits, 0) << "radius " << at.radius;
    EXPECT_EQ(selfHits, 0) << "radius " << at.radius;
    EXPECT_EQ(inwardMisses, 0) << "radius " << at.radius;
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, OffsetTest,
                         ::testing::Values(RayBackend::Embree, RayBackend::Bvh),
                         [](const ::testing::TestParamInfo<RayBackend>& backend) {
                           return std::string(backend.param == RayBackend::Embree ? "Embree"
                                                                                  : "Bvh");
                         });

}  // namespace
}  // namespace bounce
