#include "render/frustum.h"

namespace bounce {

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
    const glm::vec3 p(plane.x >= 0 ? box.upper.x : box.lower.x,
                      plane.y >= 0 ? box.upper.y : box.lower.y,
                      plane.z >= 0 ? box.upper.z : box.lower.z);
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
    box.grow(glm::vec3(world) / world.w);
  }
  return box;
}

ViewVolume::ViewVolume(const glm::mat4& cameraViewProjection, const Box& sceneBox)
    : frustum(cameraViewProjection),
      box(intersect(frustumBox(cameraViewProjection), sceneBox)),
      clipToWorld(glm::inverse(cameraViewProjection)) {}

bool ViewVolume::mayReach(const glm::mat4& lightViewProjection, const Box& sceneBox) const {
  if (!Frustum(lightViewProjection).overlaps(box)) return false;
  return frustum.overlaps(intersect(frustumBox(lightViewProjection), sceneBox));
}

}  // namespace bounce
