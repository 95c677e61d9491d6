#include "image/image.h"

#include <cmath>

namespace bounce {

bool Image::allFinite() const {
  for (const glm::vec3& p : pixels)
    if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b)) return false;
  return true;
}

Image boxDownsample(const Image& image, int k) {
  Image out(image.width / k, image.height / k);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      glm::dvec3 sum(0.0);
      for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) sum += glm::dvec3(image.at(x * k + i, y * k + j));
      out.at(x, y) = glm::vec3(sum / static_cast<double>(k * k));
    }
  return out;
}

}  // namespace bounce
