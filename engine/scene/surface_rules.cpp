#include "scene/surface_rules.h"

#include <cmath>

namespace bounce {
namespace {

bool finite(glm::vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

glm::vec3 emittedRadiance(const Material& material) {
  if (!finite(material.emission)) return glm::vec3(0.0f);
  return glm::max(material.emission, glm::vec3(0.0f));
}

glm::vec3 reflectance(const Material& material) {
  if (!finite(material.albedo)) return glm::vec3(0.0f);
  return glm::clamp(material.albedo, 0.0f, 1.0f);
}

bool isEmitterTriangle(const Material& material, glm::vec3 cross) {
  const float twiceArea = glm::length(cross);
  return material.isEmissive() && twiceArea > 0.0f && std::isfinite(twiceArea);
}

const Material& materialOf(const Scene& scene, uint32_t index) {
  static const Material absorber = [] {
    Material m;
    m.name = "(missing material)";
    m.albedo = glm::vec3(0.0f);
    return m;
  }();
  return index < scene.materials.size() ? scene.materials[index] : absorber;
}

glm::vec3 shadingNormalOr(glm::vec3 n, glm::vec3 geometric) {
  const float length = glm::length(n);
  return length > 1e-6f && std::isfinite(length) ? n / length : geometric;
}

}  // namespace bounce
