// Per-group VPL visibility on the CPU, for the VPL shadow-map test and bench_vpl_visibility:
// K groups from reduceVpls (each VPL in the group of the nearest representative with the same
// dominant normal axis: an emulation of the renderer's grouping), each group seen from its
// member nearest the centroid (nearestVpl), and the clamped gather of baker/vpl/vpl_gather.h
// with every VPL weighted by its group's visibility.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "bake/vpl.h"
#include "ray/ray_kernel.h"
#include "vpl/vpl_reduce.h"

namespace bounce::test {

struct VplGroupsCpu {
  std::vector<Vpl> representatives;  // centroids (reduceVpls)
  std::vector<Vpl> origins;          // per group: its member nearest the centroid
  std::vector<int> group;            // per VPL
};

inline int dominantAxisGroup(glm::vec3 n) {
  const glm::vec3 a = glm::abs(n);
  const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  return 2 * axis + (n[axis] < 0.0f ? 1 : 0);
}

inline VplGroupsCpu groupVplsCpu(std::span<const Vpl> vpls, std::size_t k) {
  VplGroupsCpu g;
  g.representatives = reduceVpls(vpls, k);
  g.group.assign(vpls.size(), 0);
  std::vector<std::vector<Vpl>> members(g.representatives.size());
  for (std::size_t i = 0; i < vpls.size(); ++i) {
    float best = std::numeric_limits<float>::max();
    for (std::size_t r = 0; r < g.representatives.size(); ++r) {
      if (dominantAxisGroup(g.representatives[r].normal) != dominantAxisGroup(vpls[i].normal))
        continue;
      const glm::vec3 d = g.representatives[r].position - vpls[i].position;
      if (glm::dot(d, d) < best) {
        best = glm::dot(d, d);
        g.group[i] = static_cast<int>(r);
      }
    }
    members[static_cast<std::size_t>(g.group[i])].push_back(vpls[i]);
  }
  for (std::size_t r = 0; r < g.representatives.size(); ++r)
    g.origins.push_back(members[r].empty() ? g.representatives[r]
                                           : nearestVpl(members[r], g.representatives[r].position));
  return g;
}

// Whether the segment between two surface points is free (each end offset off its surface).
inline bool segmentVisible(const RayKernel& kernel, glm::vec3 from, glm::vec3 fromNormal,
                           glm::vec3 to, glm::vec3 toNormal) {
  const glm::vec3 a = offsetRayOrigin(from, fromNormal, to - from);
  const glm::vec3 b = offsetRayOrigin(to, toNormal, from - to);
  Ray ray;
  ray.origin = a;
  ray.direction = b - a;
  ray.tmax = 1.0f;
  return !kernel.occluded(ray);
}

// E(x) = Σ Φ/π · cosθ_y · cosθ_x / max(d², r²) · V_group (W/m² per channel).
inline glm::dvec3 groupGather(std::span<const Vpl> vpls, std::span<const int> group,
                              std::span<const float> groupVisibility, glm::vec3 x, glm::vec3 n,
                              float r) {
  glm::dvec3 e(0.0);
  for (std::size_t v = 0; v < vpls.size(); ++v) {
    const float visibility = groupVisibility[static_cast<std::size_t>(group[v])];
    if (visibility <= 0.0f) continue;
    const glm::vec3 d = x - vpls[v].position;
    const float d2 = glm::dot(d, d);
    const float cosY = glm::dot(vpls[v].normal, d) / std::sqrt(d2);
    const float cosX = -glm::dot(n, d) / std::sqrt(d2);
    if (cosY <= 0.0f || cosX <= 0.0f) continue;
    e += glm::dvec3(vpls[v].flux) * (double(cosY * cosX * visibility) /
                                     (3.14159265358979323846 * double(std::max(d2, r * r))));
  }
  return e;
}

}  // namespace bounce::test
