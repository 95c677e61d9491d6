#include "image/tonemap.h"

#include <algorithm>
#include <cmath>

namespace bounce {

float filmicCurve(float x) {
  x = std::max(x, 0.0f);
  return std::clamp(x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}

float srgbEncode(float c) {
  c = std::clamp(c, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

glm::vec3 toneMap(glm::vec3 radiance, float exposureEV) {
  const glm::vec3 x = radiance * std::exp2(exposureEV);
  return {srgbEncode(filmicCurve(x.r)), srgbEncode(filmicCurve(x.g)), srgbEncode(filmicCurve(x.b))};
}

}  // namespace bounce
