// Boxes and frusta for culling (GL-free): which casters a shadow map must draw, which maps the
// view can see.
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "scene/box.h"

namespace bounce {

// The six planes of a clip-space frustum (OpenGL, −w ≤ x,y,z ≤ w) of `viewProjection`, as
// (n, d) with n·p + d ≥ 0 inside.
struct Frustum {
  explicit Frustum(const glm::mat4& viewProjection);
  // False only when the box is certainly outside (conservative: may keep boxes near corners).
  bool overlaps(const Box& box) const;
  std::array<glm::vec4, 6> planes;
};

// The world box around the frustum's corners (of `viewProjection`'s inverse).
Box frustumBox(const glm::mat4& viewProjection);

// What the camera can see, for deciding which shadow maps a frame needs: its frustum, and the
// box of that frustum within the scene's bounds.
struct ViewVolume {
  ViewVolume(const glm::mat4& cameraViewProjection, const Box& sceneBox);
  // False only when nothing the light's map (`lightViewProjection`) covers within `sceneBox`
  // can be seen: then the map cannot change the image and is not rendered.
  bool mayReach(const glm::mat4& lightViewProjection, const Box& sceneBox) const;
  Frustum frustum;
  Box box;
  glm::vec3 eye{0.0f};          // the camera's position, world metres (shadow budgets weigh by it)
  glm::mat4 clipToWorld{1.0f};  // the inverse of the camera's view-projection
};

}  // namespace bounce
