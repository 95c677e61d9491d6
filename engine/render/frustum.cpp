#include "render/frustum.h"

namespace bounce {

Box transformBox(const Box& box, const glm::mat4& transform) {
  Box out;
  if (box.empty()) return out;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner((i & 1) ? box.hi.x : box.lo.x, (i & 2) ? box.hi.y : box.lo.y,
                           (i & 4) ? box.hi.z : box.lo.z);
    out.add(glm::vec3(transform * glm::vec4(corner, 1.0f)));
  }
  return out;
}

Box intersect(const Box& a, const Box& b) {
  Box out;
  out.lo = glm::max(a.lo, b.lo);
  out.hi = glm::min(a.hi, b.hi);
  return out;
}

Frustum::Frustum(const glm::mat4& m) {
  const glm::vec4 row0(m[0][0], m[1][0], m[2][0], m[3][0]);
  const glm::vec4 row1(m[0][1], m[1][1], m[2][1], m[3][1]);
  const glm::vec4 row2(m[0][2], m[1][2], m[2][2], m[3][2]);
  const glm::vec4 row3(m[0][3], m[1][3], m[2][3], m[3][3]);
  planes = {row3 + row0, row3 - row0, row3 + row1, row3 - row1, row3 + row2, row3 - row2};
}

bool Frustum::overlaps(const Box& box) const {
  if (box.empty()) return false;
  for (const glm::vec4& plane : planes) {
    // The box corner furthest along the plane's normal.
    const glm::vec3 p(plane.x >= 0 ? box.hi.x : box.lo.x, plane.y >= 0 ? box.hi.y : box.lo.y,
                      plane.z >= 0 ? box.hi.z : box.lo.z);
    if (glm::dot(glm::vec3(plane), p) + plane.w < 0.0f) return false;
  }
  return true;
}

Box frustumBox(const glm::mat4& viewProjection) {
  const glm::mat4 inverse = glm::inverse(viewProjection);
  Box box;
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 clip((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f,
                         1.0f);
    const glm::vec4 world = inverse * clip;
    box.add(glm::vec3(world) / world.w);
  }
  return box;
}

}  // namespace bounce
