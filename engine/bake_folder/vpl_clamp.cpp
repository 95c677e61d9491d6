#include "bake_folder/vpl_clamp.h"

#include <cmath>
#include <numbers>

namespace bounce {

float vplClampDistance(double surfaceArea, std::size_t vplCount) {
  if (vplCount == 0 || !(surfaceArea > 0.0)) return 0.0f;
  return static_cast<float>(
      std::sqrt(surfaceArea / (std::numbers::pi * static_cast<double>(vplCount))));
}

namespace {

// Σ finite triangle areas over the triangles `keep` accepts, in triangle order, m².
template <typename Keep>
double sumTriangleAreas(const WorldGeometry& geometry, Keep keep) {
  double area = 0.0;
  for (std::size_t t = 0; t < geometry.triangleCount(); ++t) {
    if (!keep(t)) continue;
    const double a = 0.5 * glm::length(glm::dvec3(geometry.triangleCross(t)));
    if (std::isfinite(a)) area += a;
  }
  return area;
}

}  // namespace

double surfaceArea(const WorldGeometry& geometry) {
  return sumTriangleAreas(geometry, [](std::size_t) { return true; });
}

double staticSurfaceArea(const Scene& scene, const WorldGeometry& geometry) {
  return sumTriangleAreas(geometry, [&](std::size_t t) {
    const uint32_t instance = geometry.triangleInstance[t];
    return instance >= scene.instances.size() ||
           scene.instances[instance].mobility == Mobility::Static;
  });
}

double staticSurfaceArea(const Scene& scene) {
  return staticSurfaceArea(scene, flatten(scene));
}

std::optional<float> manifestVplClampDistance(const BakeManifest& manifest) {
  if (!manifest.vpls) return std::nullopt;
  return static_cast<float>(manifest.vpls->clampDistance);
}

}  // namespace bounce
