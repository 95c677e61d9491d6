// Per-group VPL visibility on the CPU, for the VPL shadow-map test and bench_vpl_visibility:
// the renderer's K groups (vpl_runtime/vpl_groups.h), each seen either from its representative (the
// centroid) or from its member nearest the centroid (nearestVpl, where the renderer put the
// group's one shadow cube before the groups were split), or split into parts as the renderer
// places its cubes (vplShadowCubes, render/vpl_shadow_maps.h), and the clamped gather of
// baker/vpl/vpl_gather.h with every VPL weighted by its group's or part's visibility.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "bake_folder/vpl.h"
#include "ray/ray_kernel.h"
#include "render/vpl_shadow_maps.h"
#include "vpl_runtime/vpl_groups.h"

namespace bounce::test {

struct VplGroupsCpu {
  std::vector<Vpl> vpls;             // the VPLs, group by group (VplGroups::vpls)
  std::vector<int> group;            // per VPL
  std::vector<Vpl> representatives;  // per group: the centroid
  std::vector<Vpl> origins;          // per group: its member nearest the centroid
  std::vector<Vpl> cubes;            // per part (the renderer's shadow cubes): its origin
  std::vector<int> cube;             // per VPL: its part's cube
};

inline VplGroupsCpu groupVplsCpu(std::span<const Vpl> vpls, std::size_t k) {
  const VplGroups groups(vpls, k);
  VplGroupsCpu g;
  g.vpls.assign(groups.vpls().begin(), groups.vpls().end());
  for (std::size_t i = 0; i < g.vpls.size(); ++i) g.group.push_back(int(groups.groupOf(i)));
  g.representatives.assign(groups.representatives().begin(), groups.representatives().end());
  for (std::size_t r = 0; r < groups.groupCount(); ++r) {
    const VplGroup& group = groups.groups()[r];
    g.origins.push_back(
        nearestVpl(groups.vpls().subspan(group.first, group.count), g.representatives[r].position));
  }
  const VplShadowCubes cubes = vplShadowCubes(groups, VplShadowSettings{}.cubesPerGroup);
  g.cubes = cubes.origins;
  for (std::size_t i = 0; i < g.vpls.size(); ++i) g.cube.push_back(int(cubes.cubeOf[i]));
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
