#include "scene/box.h"

namespace bounce {

Box transformBox(const Box& box, const glm::mat4& transform) {
  Box out;
  if (box.empty()) return out;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner((i & 1) ? box.upper.x : box.lower.x, (i & 2) ? box.upper.y : box.lower.y,
                           (i & 4) ? box.upper.z : box.lower.z);
    const glm::vec4 mapped = transform * glm::vec4(corner, 1.0f);
    out.grow(glm::vec3(mapped));
  }
  return out;
}

Box intersect(const Box& a, const Box& b) {
  Box out;
  out.lower = glm::max(a.lower, b.lower);
  out.upper = glm::min(a.upper, b.upper);
  return out;
}

}  // namespace bounce
