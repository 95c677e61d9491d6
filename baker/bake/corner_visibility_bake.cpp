#include "bake/corner_visibility_bake.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <tuple>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
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
// The ring's triangle pick: 1/φ, φ the golden ratio, rationally independent of the R2 steps.
constexpr double kRingStep = 0.6180339887498949;
// Corners at one place are one vertex when their normals are within 30° of the first's: the
// facets of a curved surface tessellated flat are, a box's 90° edge is not.
const float kWeldCosine = std::cos(glm::radians(30.0f));
// Only corners of triangles no longer than this on any edge weld: over a small triangle's ring
// V hardly changes, and a large one keeps its own corners, which can follow a penumbra that
// the vertex's hat-weighted mean (about two triangles wide) would blur.
constexpr float kWeldLongestEdge = 0.025f;  // m

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

std::vector<TexelPoint> vertexRingPoints(const WorldGeometry& geometry,
                                         std::span<const RingCorner> ring, int count,
                                         uint32_t key) {
  if (ring.size() == 1) return cornerPoints(geometry, ring[0].triangle, ring[0].corner, count, key);
  // The ring's triangles by area: the cumulative areas, m².
  std::vector<double> cumulative;
  cumulative.reserve(ring.size());
  double total = 0.0;
  for (const RingCorner& c : ring) {
    const float area = 0.5f * glm::length(geometry.triangleCross(c.triangle));
    if (area > 0.0f && std::isfinite(area)) total += area;
    cumulative.push_back(total);
  }
  std::vector<TexelPoint> points;
  if (!(total > 0.0)) return points;  // every triangle degenerate
  points.reserve(static_cast<std::size_t>(count));
  const double r0 = uniformFloat(key, 2);
  // Point j: its triangle from a third Kronecker coordinate over the area CDF (each triangle
  // gets its area's share of the points), its place in the triangle as cornerPoints' point j.
  // Not j/count: the light samples it is paired with are stratified along j
  // (estimatePointSetVisibility), and a triangle taking a run of j would see one strip of the
  // light.
  std::vector<std::vector<TexelPoint>> perTriangle(ring.size());
  for (int j = 0; j < count; ++j) {
    const double u = std::fmod(r0 + kRingStep * (j + 1), 1.0) * total;
    const auto at = static_cast<std::size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin());
    const std::size_t m = std::min(at, ring.size() - 1);
    if (perTriangle[m].empty())
      perTriangle[m] = cornerPoints(geometry, ring[m].triangle, ring[m].corner, count, key);
    if (!perTriangle[m].empty()) points.push_back(perTriangle[m][static_cast<std::size_t>(j)]);
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
  // The corners by surface vertex: those of one instance at the same place whose shading normals
  // lie within kWeldAngle of the first one's (a mesh may repeat a vertex per triangle, each with
  // its face's normal; a crease keeps its sides apart). Each is estimated once, over its ring,
  // and its record goes to every corner at it.
  struct CornerKey {
    uint32_t instance;
    std::array<uint32_t, 3> position;  // the bits of its coordinates
    uint32_t corner;
    bool operator<(const CornerKey& o) const {
      return std::tie(instance, position, corner) < std::tie(o.instance, o.position, o.corner);
    }
  };
  std::vector<CornerKey> keys(out.visibility.corners.size());
  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, triangleOf.size(), [&](std::size_t i) {
      for (int k = 0; k < 3; ++k) {
        const glm::vec3 p = geometry.positions[geometry.triangles[triangleOf[i]][k]];
        keys[3 * i + static_cast<std::size_t>(k)] = {
            geometry.triangleInstance[triangleOf[i]],
            {std::bit_cast<uint32_t>(p.x), std::bit_cast<uint32_t>(p.y),
             std::bit_cast<uint32_t>(p.z)},
            static_cast<uint32_t>(3 * i + static_cast<std::size_t>(k))};
      }
    });
    tbb::parallel_sort(keys.begin(), keys.end());  // a total order: the same at any thread count
  });
  const auto normalOf = [&](uint32_t corner) {
    return geometry.normals[geometry.triangles[triangleOf[corner / 3]][corner % 3]];
  };
  const auto smallTriangle = [&](uint32_t corner) {
    const glm::uvec3 tri = geometry.triangles[triangleOf[corner / 3]];
    const glm::vec3 a = geometry.positions[tri.x], b = geometry.positions[tri.y],
                    c = geometry.positions[tri.z];
    const float longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    return longest <= kWeldLongestEdge;
  };
  std::vector<uint32_t> cornersAt;  // corner numbers, vertex by vertex
  std::vector<uint32_t> firstAt;    // per vertex, its first entry in cornersAt
  cornersAt.reserve(keys.size());
  std::vector<std::vector<uint32_t>> welds;
  for (std::size_t begin = 0; begin < keys.size();) {
    std::size_t end = begin + 1;
    while (end < keys.size() && keys[end].instance == keys[begin].instance &&
           keys[end].position == keys[begin].position)
      ++end;
    // The corners at one place, ascending: a small triangle's joins the first weld of small
    // triangles whose first normal is within the angle, else starts one; a large one's is alone.
    welds.clear();
    for (std::size_t c = begin; c < end; ++c) {
      const glm::vec3 n = normalOf(keys[c].corner);
      const bool small = smallTriangle(keys[c].corner);
      auto weld = std::find_if(welds.begin(), welds.end(), [&](const std::vector<uint32_t>& w) {
        return small && smallTriangle(w.front()) && glm::dot(normalOf(w.front()), n) >= kWeldCosine;
      });
      if (weld == welds.end()) weld = welds.insert(welds.end(), std::vector<uint32_t>{});
      weld->push_back(keys[c].corner);
    }
    for (const std::vector<uint32_t>& w : welds) {
      firstAt.push_back(static_cast<uint32_t>(cornersAt.size()));
      cornersAt.insert(cornersAt.end(), w.begin(), w.end());
    }
    begin = end;
  }
  const std::size_t vertexCount = firstAt.size();
  firstAt.push_back(static_cast<uint32_t>(cornersAt.size()));
  out.vertices = vertexCount;
  std::vector<uint32_t> rays(vertexCount, 0);
  const int samples = std::max(settings.samplesPerLight, 1);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, vertexCount, [&](std::size_t g) {
      const std::span<const uint32_t> corners(cornersAt.data() + firstAt[g],
                                              firstAt[g + 1] - firstAt[g]);
      std::vector<RingCorner> ring;
      ring.reserve(corners.size());
      for (const uint32_t c : corners) ring.push_back({triangleOf[c / 3], static_cast<int>(c % 3)});
      // The vertex's keys are those of its first corner (the corners of a lone triangle keep
      // the keys they had when each corner was estimated alone).
      const uint32_t key = corners.front();
      const std::vector<TexelPoint> points = vertexRingPoints(
          geometry, ring, samples, hashKeys(settings.seed ^ kCornerPointSalt, key, 0));
      const PointSetVisibility v = estimatePointSetVisibility(
          lights, punctual, kernel, points, kCornerLightSalt, settings.seed, key, samples);
      for (const uint32_t c : corners) {
        // World corner k is the mesh's corner k, or with corners 1 and 2 swapped (mirrored).
        const auto k = static_cast<int>(c % 3);
        const int meshCorner = flipped[c / 3] && k > 0 ? 3 - k : k;
        out.visibility.corners[c - c % 3 + static_cast<uint32_t>(meshCorner)] = v.record;
      }
      rays[g] = v.rays;
    });
  });
  for (const uint32_t r : rays) out.rays += r;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace bounce
