#include "scene/framing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

namespace bounce {

Bounds sceneBounds(const Scene& scene) {
  Bounds bounds;
  bounds.lo = glm::vec3(std::numeric_limits<float>::max());
  bounds.hi = glm::vec3(std::numeric_limits<float>::lowest());
  for (const Instance& instance : scene.instances) {
    for (const glm::vec3& p : scene.meshes.at(instance.mesh).positions) {
      const glm::vec3 w(instance.transform * glm::vec4(p, 1.0f));
      bounds.lo = glm::min(bounds.lo, w);
      bounds.hi = glm::max(bounds.hi, w);
      bounds.empty = false;
    }
  }
  if (bounds.empty) bounds.lo = bounds.hi = glm::vec3(0.0f);
  return bounds;
}

Camera frameBounds(const Bounds& bounds, float aspect) {
  Camera camera;
  camera.name = "framed";
  if (bounds.empty) {  // nothing to frame: one metre in front of the origin
    camera.cameraToWorld = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 1));
    return camera;
  }
  const glm::vec3 centre = 0.5f * (bounds.lo + bounds.hi);
  const float radius = std::max(0.5f * glm::length(bounds.hi - bounds.lo), 1e-3f);
  // Half-angles of the vertical and horizontal fields of view; the narrower one decides.
  const float halfY = 0.5f * camera.yfov;
  const float halfX = std::atan(std::tan(halfY) * aspect);
  const float distance = radius / std::sin(std::min(halfX, halfY));
  camera.cameraToWorld = glm::translate(glm::mat4(1.0f), centre + glm::vec3(0, 0, distance));
  camera.znear = std::max(1e-3f, 0.5f * (distance - radius));
  camera.zfar = 2.0f * (distance + radius);
  return camera;
}

Camera pickCamera(const Scene& scene, const std::string& name, float aspect, bool* framed) {
  if (framed) *framed = false;
  if (!name.empty()) return scene.cameras[scene.findCamera(name)];
  if (!scene.cameras.empty()) return scene.cameras.front();
  if (framed) *framed = true;
  Camera camera = frameBounds(sceneBounds(scene), aspect);
  camera.aspect = aspect;
  return camera;
}

}  // namespace bounce
