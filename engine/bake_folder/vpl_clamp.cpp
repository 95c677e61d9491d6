#include "bake_folder/vpl_clamp.h"

#include <cmath>
#include <numbers>

namespace bounce {

float vplClampDistance(double surfaceArea, std::size_t vplCount) {
  if (vplCount == 0 || !(surfaceArea > 0.0)) return 0.0f;
  return static_cast<float>(
      std::sqrt(surfaceArea / (std::numbers::pi * static_cast<double>(vplCount))));
}

std::optional<float> manifestVplClampDistance(const BakeManifest& manifest) {
  if (!manifest.vpls) return std::nullopt;
  return static_cast<float>(manifest.vpls->clampDistance);
}

}  // namespace bounce
