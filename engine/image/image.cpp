#include "image/image.h"

#include <cmath>

namespace bounce {

bool Image::allFinite() const {
  for (const glm::vec3& p : pixels)
    if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b)) return false;
  return true;
}

}  // namespace bounce
