#include "scene/dynamic_selection.h"

#include <algorithm>
#include <cmath>

#include "scene/framing.h"
#include "scene/instance_move.h"

namespace bounce {

DynamicSelection::DynamicSelection(const Scene& scene) : heads_(dynamicInstanceHeads(scene)) {}

void DynamicSelection::selectNext() {
  if (!heads_.empty()) selected_ = (selected_ + 1) % heads_.size();
}

std::string DynamicSelection::name(const Scene& scene) const {
  return heads_.empty() ? std::string() : scene.instances[heads_[selected_]].name;
}

glm::vec3 DynamicSelection::translation(const Scene& scene) const {
  return heads_.empty() ? glm::vec3(0.0f)
                        : glm::vec3(scene.instances[heads_[selected_]].transform[3]);
}

std::vector<std::size_t> DynamicSelection::move(Scene& scene, const glm::vec3& delta) const {
  if (heads_.empty()) return {};
  const std::string selected = name(scene);
  moveInstance(scene, {selected, translation(scene) + delta});
  return dynamicInstancesNamed(scene, selected);
}

glm::vec3 nearestAxis(const glm::vec3& direction) {
  const glm::vec3 a = glm::abs(direction);
  const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  glm::vec3 out(0.0f);
  out[axis] = direction[axis] < 0.0f ? -1.0f : 1.0f;
  return out;
}

float objectSpeed(const Scene& scene) {
  const Bounds bounds = sceneBounds(scene);
  return std::max(0.25f * glm::length(bounds.hi - bounds.lo), 0.1f);
}

}  // namespace bounce
