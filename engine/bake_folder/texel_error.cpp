#include "bake_folder/texel_error.h"

#include <algorithm>
#include <cmath>

#include "bake_folder/bake_folder.h"

namespace bounce {

float bakeErrorTarget(const BakeManifest& manifest) {
  const double target = manifest.estimatedError.target;
  return std::isfinite(target) && target > 0.0 ? static_cast<float>(target) : kDefaultErrorTarget;
}

glm::vec3 errorFalseColour(float relativeError, float target) {
  if (relativeError == kNoErrorEstimate) return glm::vec3(0.05f);
  const float t = std::clamp(relativeError / target, 0.0f, 2.0f);
  return t <= 1.0f ? glm::vec3(0.0f, t, 1.0f - t) : glm::vec3(t - 1.0f, 2.0f - t, 0.0f);
}

Image errorFalseColourImage(const Image& relativeError, float target) {
  Image colours(relativeError.width, relativeError.height);
  for (std::size_t i = 0; i < colours.pixels.size(); ++i)
    colours.pixels[i] = errorFalseColour(relativeError.pixels[i].r, target);
  return colours;
}

Image texelValidityImage(const Image& relativeError, const Image& charts) {
  Image colours(relativeError.width, relativeError.height);
  for (std::size_t i = 0; i < colours.pixels.size(); ++i)
    colours.pixels[i] = relativeError.pixels[i].r != kNoErrorEstimate ? kValidTexel
                        : charts.pixels[i] != glm::vec3(0.0f)         ? kFilledTexel
                                                                      : kPaddingTexel;
  return colours;
}

}  // namespace bounce
