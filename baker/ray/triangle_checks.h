// Which triangles a kernel may ever report: finite vertices and a non-zero area. Degenerate
// (zero-area) triangles are left out of both backends' acceleration structures.
#pragma once

#include <cmath>
#include <cstddef>

#include "scene/world_geometry.h"

namespace bounce {

inline bool isHittableTriangle(const WorldGeometry& geometry, std::size_t t) {
  const glm::uvec3 tri = geometry.triangles[t];
  const std::size_t n = geometry.positions.size();
  if (tri.x >= n || tri.y >= n || tri.z >= n) return false;
  for (int k = 0; k < 3; ++k) {
    const glm::vec3 p = geometry.positions[tri[k]];
    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))) return false;
  }
  const glm::vec3 c = geometry.triangleCross(t);
  const float area2 = glm::dot(c, c);
  return area2 > 0.0f && std::isfinite(area2);
}

}  // namespace bounce
