// An axis-aligned box in metres: the one box type of bounce, GL-free. The baker's BVH builds on
// it (ray/bvh.h), the renderer culls and fits shadow maps with it (render/frustum.h).
#pragma once

#include <glm/glm.hpp>

namespace bounce {

struct Box {
  // An empty box has lower > upper on some axis. ±1e30 rather than ±∞: a corner of an empty box
  // passed through a matrix stays finite (no ∞ − ∞); every coordinate bounce accepts is far
  // inside it (scene/input_limits.h: |x| ≤ 1e6 m).
  glm::vec3 lower{1e30f};
  glm::vec3 upper{-1e30f};

  void grow(glm::vec3 p) {
    lower = glm::min(lower, p);
    upper = glm::max(upper, p);
  }
  void grow(const Box& b) {
    lower = glm::min(lower, b.lower);
    upper = glm::max(upper, b.upper);
  }
  bool empty() const { return lower.x > upper.x || lower.y > upper.y || lower.z > upper.z; }
  glm::vec3 centre() const { return 0.5f * (lower + upper); }
  // Surface area in m² (0 for an empty box); proportional to the chance a random ray hits it.
  float surfaceArea() const {
    if (empty()) return 0.0f;
    const glm::vec3 d = upper - lower;
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
};

// `box` under `transform` (an affine or projective map): the box around its eight mapped
// corners; empty stays empty.
Box transformBox(const Box& box, const glm::mat4& transform);
// The common part of two boxes (empty when they do not meet).
Box intersect(const Box& a, const Box& b);

}  // namespace bounce
