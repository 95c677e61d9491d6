// Embree and our BVH must answer the same queries the same way: ≥ 100k rays per scene, both
// coherent (camera) and incoherent (cosine rays from random surface points), closest hit and
// finite-interval occlusion, single and batched.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <thread>
#include <vector>

#include "ray/ray_kernel.h"
#include "scene/load.h"
#include "test_geometry.h"

namespace bounce {
namespace {

struct Disagreement {
  std::size_t rays = 0;
  std::size_t hitMismatch = 0;  // one backend hits, the other does not
  std::size_t tie = 0;          // different triangles at the same distance (shared edge)
  std::size_t triangle = 0;     // different triangles at different distances
  std::size_t distance = 0;     // same triangle, t differs by more than 1e-4 relative
  std::size_t occlusion = 0;
  std::size_t duplicate = 0;  // geometrically identical triangles: either answer is right
};

// True when triangles a and b have the same three vertex positions (scenes such as McGuire's
// Cornell box contain duplicated faces; which copy a kernel reports is arbitrary).
bool sameTriangle(const WorldGeometry& g, uint32_t a, uint32_t b) {
  const auto sorted = [&](uint32_t t) {
    std::array<glm::vec3, 3> p = {g.positions[g.triangles[t].x], g.positions[g.triangles[t].y],
                                  g.positions[g.triangles[t].z]};
    std::sort(p.begin(), p.end(), [](glm::vec3 l, glm::vec3 r) {
      return l.x < r.x || (l.x == r.x && (l.y < r.y || (l.y == r.y && l.z < r.z)));
    });
    return p;
  };
  return sorted(a) == sorted(b);
}

Disagreement compare(const WorldGeometry& g, const std::vector<Ray>& rays) {
  const auto embree = makeRayKernel(g, RayBackend::Embree);
  const auto bvh = makeRayKernel(g, RayBackend::Bvh);
  std::vector<Hit> a(rays.size()), b(rays.size());
  std::vector<uint8_t> occludedA(rays.size()), occludedB(rays.size());
  embree->intersect(rays, a);  // packets
  embree->occluded(rays, occludedA);
  Disagreement d;
  d.rays = rays.size();
  for (std::size_t i = 0; i < rays.size(); ++i) {
    b[i] = bvh->intersect(rays[i]);
    occludedB[i] = bvh->occluded(rays[i]) ? 1 : 0;
    const Hit single = embree->intersect(rays[i]);  // packets and single rays agree exactly
    EXPECT_EQ(single.triangle, a[i].triangle);
    EXPECT_EQ(embree->occluded(rays[i]) ? 1 : 0, occludedA[i]);

    if (occludedA[i] != occludedB[i]) ++d.occlusion;
    if (a[i].valid() != b[i].valid()) {
      ++d.hitMismatch;
      continue;
    }
    if (!a[i].valid()) continue;
    const bool sameDistance = std::abs(a[i].t - b[i].t) <= 1e-4f * std::max(a[i].t, 1e-3f);
    if (a[i].triangle != b[i].triangle) {
      if (sameTriangle(g, a[i].triangle, b[i].triangle))
        ++(sameDistance ? d.duplicate : d.triangle);
      else
        ++(sameDistance ? d.tie : d.triangle);
      continue;
    }
    if (!sameDistance) ++d.distance;
    EXPECT_NEAR(a[i].u, b[i].u, 1e-3f);
    EXPECT_NEAR(a[i].v, b[i].v, 1e-3f);
    EXPECT_EQ(a[i].geometricNormal, b[i].geometricNormal);
  }
  return d;
}

// A ray can legitimately get different answers only when it passes within float rounding of
// an edge (the two backends' triangle tests round differently: Embree's robust Plücker test,
// our sheared edge functions) or meets a surface at the end of its interval. With relative
// rounding ~1e-7 and edges covering a small part of the image, such rays are rare (a few per
// million); we allow 1e-4 of the rays (11 per 110k) for each kind of disagreement, and 1e-3
// for ties (same distance, the other triangle of a shared edge: both answers are right).
void expectAgreement(const Disagreement& d) {
  const double n = static_cast<double>(d.rays);
  EXPECT_LE(static_cast<double>(d.hitMismatch), 1e-4 * n);
  EXPECT_LE(static_cast<double>(d.triangle), 1e-4 * n);
  EXPECT_LE(static_cast<double>(d.distance), 1e-4 * n);
  EXPECT_LE(static_cast<double>(d.occlusion), 1e-4 * n);
  EXPECT_LE(static_cast<double>(d.tie), 1e-3 * n);
  std::printf(
      "%zu rays: %zu hit/miss, %zu triangle, %zu ties, %zu distance, %zu occlusion; %zu hits on "
      "duplicated triangles\n",
      d.rays, d.hitMismatch, d.triangle, d.tie, d.distance, d.occlusion, d.duplicate);
}

std::vector<Ray> mixedRays(const WorldGeometry& g, glm::vec3 eye, glm::vec3 target,
                           float shadowDistance) {
  std::vector<Ray> rays = testing::cameraRays(eye, target, 256, 160);  // 40,960 coherent
  const std::vector<Ray> random = testing::surfaceRays(g, 40000, 1);
  const std::vector<Ray> shadow = testing::surfaceRays(g, 30000, 2, shadowDistance);
  rays.insert(rays.end(), random.begin(), random.end());
  rays.insert(rays.end(), shadow.begin(), shadow.end());
  return rays;
}

TEST(BackendAgreement, RandomTriangleSoup) {
  WorldGeometry g;
  testing::addTriangleSoup(g, 20000, glm::vec3(-5), glm::vec3(5), 0.8f, 3);
  testing::finish(g);
  expectAgreement(compare(g, mixedRays(g, {0, 2, 14}, {0, 0, 0}, 3.0f)));
}

TEST(BackendAgreement, ClosedMeshesInARoom) {
  WorldGeometry g;
  testing::addCube(g, glm::mat4(10.0f, 0, 0, 0, 0, 10.0f, 0, 0, 0, 0, 10.0f, 0, 0, 0, 0, 1));
  testing::addIcosphere(g, 4, {3, -2, 1}, 2.5f);
  testing::addDisplacedSphere(g, 64, 128, {-4, 1, -2}, 3.0f, 0.1f, 5);
  testing::addTriangleSoup(g, 2000, glm::vec3(-9), glm::vec3(9), 0.5f, 4);
  testing::finish(g);
  expectAgreement(compare(g, mixedRays(g, {0, 4, 9}, {0, -2, 0}, 6.0f)));
}

// Queries are const and thread-safe: two threads sharing one kernel (each setting its own
// FTZ/DAZ for Embree) get exactly the answers of a single thread.
TEST(BackendAgreement, ConcurrentQueriesMatchSingleThreaded) {
  WorldGeometry g;
  testing::addIcosphere(g, 4, {0, 0, 0}, 2.0f);
  testing::addTriangleSoup(g, 5000, glm::vec3(-4), glm::vec3(4), 0.5f, 9);
  testing::finish(g);
  const std::vector<Ray> rays = testing::surfaceRays(g, 20000, 3);
  for (const RayBackend backend : {RayBackend::Embree, RayBackend::Bvh}) {
    const auto kernel = makeRayKernel(g, backend);
    std::vector<Hit> expected(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) expected[i] = kernel->intersect(rays[i]);
    std::vector<Hit> concurrent(rays.size());
    const auto half = [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) concurrent[i] = kernel->intersect(rays[i]);
    };
    std::thread other(half, 0, rays.size() / 2);
    half(rays.size() / 2, rays.size());
    other.join();
    for (std::size_t i = 0; i < rays.size(); ++i) {
      ASSERT_EQ(concurrent[i].triangle, expected[i].triangle) << kernel->name() << " ray " << i;
      ASSERT_EQ(concurrent[i].t, expected[i].t);
    }
  }
}

// A content scene, looked at by its own camera, or else from in front of its bounds (+z).
void expectAgreementOnContent(const char* path) {
  const Scene scene = loadScene(path);
  const WorldGeometry g = flatten(scene);
  ASSERT_GT(g.triangleCount(), 0u) << path;
  glm::vec3 lower(1e30f), upper(-1e30f);
  for (const glm::vec3 p : g.positions) lower = glm::min(lower, p), upper = glm::max(upper, p);
  const glm::vec3 centre = 0.5f * (lower + upper);
  const float size = glm::length(upper - lower);
  glm::vec3 eye = centre + glm::vec3(0, 0, 1.2f * size), target = centre;
  if (!scene.cameras.empty()) {
    eye = scene.cameras[0].position();
    target = eye + scene.cameras[0].forward();
  }
  expectAgreement(compare(g, mixedRays(g, eye, target, 0.5f * size)));
}

TEST(BackendAgreement, CornellBoxGltf) {
  expectAgreementOnContent(BOUNCE_SOURCE_DIR "/content/cornell_box/cornell_box.gltf");
}

TEST(BackendAgreement, McGuireCornellBoxObj) {
  expectAgreementOnContent(BOUNCE_SHARED_SCENES "/mcguire_cornell_box/CornellBox-Original.obj");
}

}  // namespace
}  // namespace bounce
