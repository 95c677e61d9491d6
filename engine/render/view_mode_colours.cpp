#include "render/view_mode_colours.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace bounce {

glm::vec3 texelDensityColour(float texelsPerMetre, float targetTexelsPerMetre) {
  const float r = std::clamp(std::log2(texelsPerMetre / targetTexelsPerMetre), -1.0f, 1.0f);
  return r <= 0.0f ? glm::vec3(0.0f, 1.0f + r, -r) : glm::vec3(r, 1.0f - r, 0.0f);
}

glm::vec3 cascadeColour(int cascade) {
  constexpr std::array<glm::vec3, 4> kColours = {
      glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f),
      glm::vec3(1.0f, 1.0f, 0.0f)};
  return kColours[static_cast<std::size_t>(std::clamp(cascade, 0, 3))];
}

}  // namespace bounce
