#include "scene/scene.h"

#include <stdexcept>

#include "scene/surface_rules.h"

namespace bounce {

bool Material::isEmissive() const {
  const glm::vec3 le = emittedRadiance(*this);
  return le.r > 0.0f || le.g > 0.0f || le.b > 0.0f;
}

std::size_t Scene::triangleCount() const {
  std::size_t n = 0;
  for (const Instance& instance : instances) n += meshes.at(instance.mesh).triangleCount();
  return n;
}

std::size_t Scene::findCamera(const std::string& name) const {
  std::string known;
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    if (cameras[i].name == name) return i;
    known += (known.empty() ? "" : ", ") + ("'" + cameras[i].name + "'");
  }
  throw std::invalid_argument(source + ": no camera named '" + name +
                              "' (cameras: " + (known.empty() ? "none" : known) + ")");
}

}  // namespace bounce
