#include "bake/corner_visibility_bake.h"

#include <chrono>
#include <cmath>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "bake/light_visibility_bake.h"
#include "bake/texel_coverage.h"
#include "scene/world_geometry.h"
#include "trace/rng.h"

namespace bounce {
namespace {

constexpr uint32_t kCornerLightSalt = 0x27d4eb2fu;  // the light pairs' keys
constexpr uint32_t kCornerPointSalt = 0x165667b1u;  // the points' rotation
// The R2 sequence's steps (1/φ₂ and 1/φ₂², φ₂ the plastic number): evenly spread in 2D.
constexpr double kR2StepX = 0.7548776662466927;
constexpr double kR2StepY = 0.5698402909980532;

// b with CDF 3b² − 2b³ (Beta(2, 2), density 6b(1 − b)) at u ∈ [0, 1].
float betaTwoTwo(float u) {
  return 0.5f - std::sin(std::asin(1.0f - 2.0f * u) / 3.0f);
}

}  // namespace

std::vector<TexelPoint> cornerPoints(const WorldGeometry& geometry, uint32_t t, int corner,
                                     int count, uint32_t key) {
  std::vector<TexelPoint> points;
  const glm::vec3 cross = geometry.triangleCross(t);
  const float crossLength = glm::length(cross);
  if (!(crossLength > 0.0f) || !std::isfinite(crossLength)) return points;  // degenerate
  const glm::uvec3 tri = geometry.triangles[t];
  const glm::vec3 geometric = cross / crossLength;
  const double rx = uniformFloat(key, 0), ry = uniformFloat(key, 1);
  points.reserve(static_cast<std::size_t>(count));
  for (int j = 0; j < count; ++j) {
    const double ux = std::fmod(rx + kR2StepX * (j + 1), 1.0);
    const double uy = std::fmod(ry + kR2StepY * (j + 1), 1.0);
    glm::vec3 b;
    const float own = betaTwoTwo(static_cast<float>(ux));
    b[corner] = own;
    b[(corner + 1) % 3] = (1.0f - own) * static_cast<float>(uy);
    b[(corner + 2) % 3] = (1.0f - own) * (1.0f - static_cast<float>(uy));
    TexelPoint p;
    p.position = b.x * geometry.positions[tri.x] + b.y * geometry.positions[tri.y] +
                 b.z * geometry.positions[tri.z];
    p.geometricNormal = geometric;
    glm::vec3 n = b.x * geometry.normals[tri.x] + b.y * geometry.normals[tri.y] +
                  b.z * geometry.normals[tri.z];
    const float nLength = glm::length(n);
    n = nLength > 0.0f ? n / nLength : geometric;
    // The shading normal lies on the front face's side (as texel_coverage.cpp's points).
    p.shadingNormal = glm::dot(n, geometric) > 0.0f ? n : geometric;
    p.triangle = t;
    points.push_back(p);
  }
  return points;
}

CornerVisibilityBake bakeCornerVisibility(const AreaLightSet& lights,
                                          std::span<const Light> punctual,
                                          const WorldGeometry& geometry, const RayKernel& kernel,
                                          std::span<const uint32_t> tracedInstances,
                                          std::span<const uint8_t> mirrored,
                                          const CornerVisibilitySettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  CornerVisibilityBake out;
  out.visibility.lightCount = static_cast<uint32_t>(lights.staticCount());
  out.visibility.punctualCount = static_cast<uint32_t>(punctual.size());
  // The triangles to bake, in instance order then the instance's own order (flatten keeps it).
  std::vector<int64_t> slot;
  for (std::size_t i = 0; i < tracedInstances.size(); ++i) {
    if (tracedInstances[i] >= slot.size()) slot.resize(tracedInstances[i] + 1, -1);
    slot[tracedInstances[i]] = static_cast<int64_t>(i);
  }
  std::vector<std::vector<uint32_t>> triangles(tracedInstances.size());
  for (std::size_t t = 0; t < geometry.triangleCount(); ++t) {
    const uint32_t instance = geometry.triangleInstance[t];
    if (instance < slot.size() && slot[instance] >= 0)
      triangles[static_cast<std::size_t>(slot[instance])].push_back(static_cast<uint32_t>(t));
  }
  std::vector<uint32_t> triangleOf;  // per baked triangle, its world triangle
  std::vector<uint8_t> flipped;      // per baked triangle, whether its instance mirrors
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    out.firstCorner.push_back(static_cast<uint32_t>(3 * triangleOf.size()));
    out.cornerCount.push_back(static_cast<uint32_t>(3 * triangles[i].size()));
    for (const uint32_t t : triangles[i]) {
      triangleOf.push_back(t);
      flipped.push_back(i < mirrored.size() ? mirrored[i] : 0);
    }
  }
  out.visibility.corners.assign(3 * triangleOf.size(), TexelVisibility{});
  if (out.visibility.lightCount + out.visibility.punctualCount == 0) return out;
  std::vector<uint32_t> rays(out.visibility.corners.size(), 0);
  const int samples = std::max(settings.samplesPerLight, 1);
  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, triangleOf.size(), [&](std::size_t i) {
      for (int k = 0; k < 3; ++k) {
        const auto corner = static_cast<uint32_t>(3 * i + static_cast<std::size_t>(k));
        const std::vector<TexelPoint> points =
            cornerPoints(geometry, triangleOf[i], k, samples,
                         hashKeys(settings.seed ^ kCornerPointSalt, corner, 0));
        const PointSetVisibility v = estimatePointSetVisibility(
            lights, punctual, kernel, points, kCornerLightSalt, settings.seed, corner, samples);
        // World corner k is the mesh's corner k, or with corners 1 and 2 swapped (mirrored).
        const int meshCorner = flipped[i] && k > 0 ? 3 - k : k;
        out.visibility.corners[3 * i + static_cast<std::size_t>(meshCorner)] = v.record;
        rays[corner] = v.rays;
      }
    });
  });
  for (const uint32_t r : rays) out.rays += r;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace bounce
