// offsetRayOrigin keeps secondary rays off the surface they start on at every scale: from a
// convex closed mesh, an outward ray can hit nothing and an inward ray can only hit another
// triangle, whatever the mesh's size and distance from the world origin. And it does not
// overshoot: a ray lifted off a floor still meets a thin occluder a few millimetres above it,
// also 1 km from the origin (an offset far above float rounding would jump past it).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "both_backends.h"
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

// A 2 m square sheet at height h above a 4 m square floor, a point light 0.5 m above the
// sheet's centre. Shadow rays start at hit points on the floor (computed from barycentrics, as
// a kernel's hit would give them) under the central 1 m square; the line to the light crosses
// the sheet's plane at most 0.5 m·(1 − h/0.5 m) from its centre, inside the sheet, so every
// ray must be blocked, and the nearest thing it meets must be the sheet (not the floor it
// starts on). Both a world-axis-aligned and a tilted floor, along two directions from the
// origin, at distances 1, 100 and 1000 m (1 ulp of 1000 m is 6.1e-5 m: a 2 mm gap is 33 ulps).
TEST_P(OffsetTest, ShadowRaysDoNotJumpPastAThinOccluder) {
  const glm::vec3 normals[] = {{0, 0, 1}, glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f))};
  const glm::vec3 directions[] = {{1, 0, 0}, glm::normalize(glm::vec3(1.0f, -0.6f, 0.35f))};
  for (const float distance : {1.0f, 100.0f, 1000.0f}) {
    for (const float height : {2e-2f, 2e-3f}) {
      for (int k = 0; k < 2; ++k) {
        const glm::vec3 n = normals[k];
        const glm::vec3 centre = distance * directions[k];
        const glm::vec3 t1 = glm::normalize(glm::cross(n, glm::vec3(0, 1, 0)));
        const glm::vec3 t2 = glm::cross(n, t1);
        WorldGeometry g;
        const auto addSquare = [&g, t1, t2](glm::vec3 middle, float half) {
          const auto base = static_cast<uint32_t>(g.positions.size());
          for (const glm::vec2 c :
               {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
            g.positions.push_back(middle + half * (c.x * t1 + c.y * t2));
          g.triangles.push_back(base + glm::uvec3(0, 1, 2));
          g.triangles.push_back(base + glm::uvec3(0, 2, 3));
        };
        addSquare(centre, 2.0f);               // floor: triangles 0, 1
        addSquare(centre + height * n, 1.0f);  // sheet: triangles 2, 3
        testing::finish(g);
        const glm::vec3 light = centre + (height + 0.5f) * n;
        const auto kernel = makeRayKernel(g, GetParam());
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        int rays = 0, leaks = 0, notTheSheet = 0;
        while (rays < 500) {
          const std::size_t t = rng() % 2;
          const glm::uvec3 tri = g.triangles[t];
          float b1 = u(rng), b2 = u(rng);
          if (b1 + b2 > 1.0f) b1 = 1.0f - b1, b2 = 1.0f - b2;
          const glm::vec3 p = (1.0f - b1 - b2) * g.positions[tri.x] + b1 * g.positions[tri.y] +
                              b2 * g.positions[tri.z];
          // Lateral position from the barycentrics (exact corners ±2 m), not from p − centre,
          // which would cancel catastrophically far from the origin.
          const glm::vec2 corners[4] = {{-2, -2}, {2, -2}, {2, 2}, {-2, 2}};
          const glm::vec2 lateral =
              (1.0f - b1 - b2) * corners[tri.x] + b1 * corners[tri.y] + b2 * corners[tri.z];
          if (std::abs(lateral.x) > 0.5f || std::abs(lateral.y) > 0.5f) continue;
          ++rays;
          const glm::vec3 origin = offsetRayOrigin(p, n, light - p);
          // A shadow ray as the path tracer casts it: to the light, shortened by 1e-4.
          if (!kernel->occluded(Ray{origin, 0.0f, light - origin, 1.0f - 1e-4f})) ++leaks;
          const Hit hit = kernel->intersect(Ray{origin, 0.0f, light - origin});
          if (!hit.valid() || hit.triangle < 2) ++notTheSheet;
        }
        EXPECT_EQ(leaks, 0) << "distance " << distance << " m, gap " << height << " m, plane " << k
                            << ": " << leaks << " of " << rays << " shadow rays leak";
        EXPECT_EQ(notTheSheet, 0) << "distance " << distance << " m, gap " << height << " m, plane "
                                  << k;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, OffsetTest, kBothBackends, backendName);

}  // namespace
}  // namespace bounce
