#include "scene/static_scene.h"

#include <cmath>

#include "scene/world_geometry.h"

namespace bounce {

namespace {

// Σ finite triangle areas |(p1−p0)×(p2−p0)|/2 over the triangles `keep` accepts, in triangle
// order, m².
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

Scene staticScene(const Scene& scene) {
  Scene out = scene;
  std::erase_if(out.instances,
                [](const Instance& instance) { return instance.mobility == Mobility::Dynamic; });
  for (Light& light : out.lights)
    if (light.mobility == Mobility::Dynamic) light.intensity = light.irradiance = glm::vec3(0.0f);
  return out;
}

std::vector<uint32_t> staticInstanceNumbers(const Scene& scene) {
  std::vector<uint32_t> numbers(scene.instances.size(), kNotStatic);
  uint32_t next = 0;
  for (std::size_t i = 0; i < scene.instances.size(); ++i)
    if (scene.instances[i].mobility != Mobility::Dynamic) numbers[i] = next++;
  return numbers;
}

double staticSurfaceArea(const Scene& scene, const WorldGeometry& geometry) {
  return sumTriangleAreas(geometry, [&](std::size_t t) {
    const uint32_t instance = geometry.triangleInstance[t];
    return instance >= scene.instances.size() ||
           scene.instances[instance].mobility != Mobility::Dynamic;
  });
}

double staticSurfaceArea(const Scene& scene) {
  return staticSurfaceArea(scene, flatten(scene));
}

double surfaceArea(const WorldGeometry& geometry) {
  return sumTriangleAreas(geometry, [](std::size_t) { return true; });
}

}  // namespace bounce
