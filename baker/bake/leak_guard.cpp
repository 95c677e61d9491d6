#include "bake/leak_guard.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "bake/texel_coverage.h"
#include "ray/ray_kernel.h"
#include "scene/scene.h"
#include "scene/world_geometry.h"
#include "trace/denormals_flushed.h"
#include "trace/sampling.h"
#include "trace/sobol_sampler.h"

namespace bounce {

namespace {

// Hammersley point i of n: (i + ½)/n and the base-2 radical inverse of i.
glm::vec2 hammersley(int i, int n) {
  return {(static_cast<float>(i) + 0.5f) / static_cast<float>(n),
          static_cast<float>(reverseBits(static_cast<uint32_t>(i))) * 0x1p-32f};
}

bool finite(glm::vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// True when every triangle of `mesh` lies in one plane and faces one way: a flat sheet (a lamp's
// quad, a row of ceiling panels written as one mesh), which has no inside. Cracks between a
// solid's faces do not matter here, as they would to a test of closed edges.
bool isFlatSheet(const Mesh& mesh) {
  std::optional<glm::dvec3> normal;
  double offset = 0.0, extent = 0.0;
  for (const glm::vec3& p : mesh.positions)
    extent = std::max(extent, static_cast<double>(glm::length(p - mesh.positions.front())));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a(mesh.positions[mesh.indices[t]]), b(mesh.positions[mesh.indices[t + 1]]),
        c(mesh.positions[mesh.indices[t + 2]]);
    const glm::dvec3 cross = glm::cross(b - a, c - a);
    const double length = glm::length(cross);
    if (!(length > 0.0)) continue;  // degenerate: no side to face
    const glm::dvec3 n = cross / length;
    if (!normal) {
      normal = n;
      offset = glm::dot(n, a);
      continue;
    }
    // One direction within 0.1°, one plane within 10⁻⁵ of the mesh's size.
    if (glm::dot(n, *normal) < 0.9999985 || std::abs(glm::dot(*normal, a) - offset) > 1e-5 * extent)
      return false;
  }
  return normal.has_value();
}

// Per world triangle: 1 on an emitter that is a flat sheet. Nothing is inside such a sheet: a
// point behind it is in the slot between fixture and surface, seen and dark, and dropping it
// would fill the slot from its lit neighbours. An emitting solid (a glowing block, the
// furnace's walls) keeps its inside.
std::vector<uint8_t> emitterSheets(const Scene& scene, const WorldGeometry& geometry) {
  std::vector<int8_t> flat(scene.meshes.size(), -1);  // per mesh: unknown, no, yes
  std::vector<uint8_t> sheet(geometry.triangleCount(), 0);
  for (std::size_t t = 0; t < geometry.triangleCount(); ++t) {
    const uint32_t material = geometry.triangleMaterial[t];
    if (material >= scene.materials.size() || !scene.materials[material].isEmissive()) continue;
    const uint32_t mesh = scene.instances[geometry.triangleInstance[t]].mesh;
    if (flat[mesh] < 0) flat[mesh] = isFlatSheet(scene.meshes[mesh]) ? 1 : 0;
    sheet[t] = static_cast<uint8_t>(flat[mesh]);
  }
  return sheet;
}

}  // namespace

LeakGuardResult guardAgainstLeaks(const Scene& scene, const WorldGeometry& geometry,
                                  const RayKernel& kernel, float texelSizeMetres,
                                  const LeakGuardSettings& settings, TexelCoverage& coverage) {
  const std::size_t texels = coverage.texelCount();
  std::vector<uint8_t> keep(coverage.points.size(), 1);
  std::vector<uint32_t> insideCount(texels, 0), acrossCount(texels, 0), rayCount(texels, 0);
  const float lift = std::max(settings.liftTexels * texelSizeMetres, 0.0f);
  const int probes = std::max(settings.probeRays, 1);

  const std::vector<uint8_t> emitterSheet = emitterSheets(scene, geometry);
  auto isBackFace = [&](const Ray& ray, const Hit& hit) {
    if (!hit.valid()) return false;
    const uint32_t material = geometry.triangleMaterial[hit.triangle];
    if (material < scene.materials.size() && scene.materials[material].doubleSided) return false;
    if (emitterSheet[hit.triangle]) return false;
    return glm::dot(ray.direction, hit.geometricNormal) > 0.0f;
  };

  auto guardTexel = [&](std::size_t texel) {
    const uint32_t begin = coverage.first[texel], end = coverage.first[texel + 1];
    if (begin == end) return;
    // Inside geometry: most probe rays meet back faces first.
    for (uint32_t p = begin; p < end; ++p) {
      const TexelPoint& point = coverage.points[p];
      const Frame frame(point.shadingNormal);
      // The verdict is back ≥ inside; the rays stop once the count has reached it or can no
      // longer reach it (every ray left a back face): the same verdict, fewer rays.
      const float inside = settings.insideFraction * static_cast<float>(probes);
      int back = 0;
      for (int i = 0; i < probes; ++i) {
        if (static_cast<float>(back) >= inside || static_cast<float>(back + probes - i) < inside)
          break;
        Ray ray;
        ray.direction = frame.toWorld(sampleCosineHemisphere(hammersley(i, probes)));
        if (glm::dot(ray.direction, point.geometricNormal) <= 0.0f) continue;
        ray.origin = offsetRayOrigin(point.position, point.geometricNormal, ray.direction);
        if (!finite(ray.origin) || !finite(ray.direction)) continue;
        ++rayCount[texel];
        if (isBackFace(ray, kernel.intersect(ray))) ++back;
      }
      if (static_cast<float>(back) >= inside) {
        keep[p] = 0;
        ++insideCount[texel];
      }
    }
    if (!settings.dropAcrossWalls) return;
    // Across a wall: keep the representative's side.
    const glm::vec2 centre(
        static_cast<float>(texel % static_cast<std::size_t>(coverage.width)) + 0.5f,
        static_cast<float>(texel / static_cast<std::size_t>(coverage.width)) + 0.5f);
    uint32_t representative = end;
    float best = std::numeric_limits<float>::infinity();
    for (uint32_t p = begin; p < end; ++p) {
      if (!keep[p]) continue;
      const glm::vec2 d = coverage.points[p].texelPosition - centre;
      if (glm::dot(d, d) < best) best = glm::dot(d, d), representative = p;
    }
    if (representative == end) return;
    const TexelPoint& rep = coverage.points[representative];
    const glm::vec3 from = offsetRayOrigin(rep.position, rep.geometricNormal, rep.shadingNormal) +
                           lift * rep.shadingNormal;
    for (uint32_t p = begin; p < end; ++p) {
      if (!keep[p] || p == representative) continue;
      const TexelPoint& point = coverage.points[p];
      const glm::vec3 to =
          offsetRayOrigin(point.position, point.geometricNormal, point.shadingNormal) +
          lift * point.shadingNormal;
      Ray ray;
      ray.origin = from;
      ray.direction = to - from;
      ray.tmin = 0.0f;
      ray.tmax = 1.0f;
      if (!finite(ray.direction) || !(glm::dot(ray.direction, ray.direction) > 0.0f)) continue;
      ++rayCount[texel];
      if (kernel.occluded(ray)) {
        keep[p] = 0;
        ++acrossCount[texel];
      }
    }
  };

  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, texels, 256),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        const DenormalsFlushed flushed;
                        for (std::size_t t = range.begin(); t != range.end(); ++t) guardTexel(t);
                      });
  });

  // Compact the point lists (serial, in texel order: the result does not depend on threads).
  LeakGuardResult result;
  result.invalid.assign(texels, 0);
  std::vector<TexelPoint> points;
  points.reserve(coverage.points.size());
  std::vector<uint32_t> first(texels + 1, 0);
  for (std::size_t texel = 0; texel < texels; ++texel) {
    first[texel] = static_cast<uint32_t>(points.size());
    for (uint32_t p = coverage.first[texel]; p < coverage.first[texel + 1]; ++p)
      if (keep[p]) points.push_back(coverage.points[p]);
    if (coverage.first[texel + 1] > coverage.first[texel] && first[texel] == points.size())
      result.invalid[texel] = 1;
    result.pointsInside += insideCount[texel];
    result.pointsAcross += acrossCount[texel];
    result.rays += rayCount[texel];
  }
  first[texels] = static_cast<uint32_t>(points.size());
  coverage.points = std::move(points);
  coverage.first = std::move(first);
  return result;
}

}  // namespace bounce
