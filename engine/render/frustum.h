// Boxes and frusta for culling (GL-free): which casters a shadow map must draw, which maps the
// view can see.
#pragma once

#include <array>

#include <glm/glm.hpp>

namespace bounce {

struct Box {
  glm::vec3 lo{1e30f}, hi{-1e30f};  // metres, world; lo > hi means empty
  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  void add(glm::vec3 p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
};

// `box` (object space) under `transform`: the box around its eight transformed corners.
Box transformBox(const Box& box, const glm::mat4& transform);
Box intersect(const Box& a, const Box& b);

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

}  // namespace bounce
