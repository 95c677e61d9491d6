#include "support/scene_invariants.h"

#include <glm/glm.hpp>

#include "scene/input_limits.h"

namespace bounce::test {
namespace {

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool withinLimit(const glm::dvec3& p) {
  return std::abs(p.x) <= kMaxCoordinate && std::abs(p.y) <= kMaxCoordinate &&
         std::abs(p.z) <= kMaxCoordinate;
}
bool radiometric(const glm::vec3& v) {
  return finite(v) && v.x >= 0 && v.y >= 0 && v.z >= 0 && v.x <= kMaxRadiometric &&
         v.y <= kMaxRadiometric && v.z <= kMaxRadiometric;
}

}  // namespace

std::string brokenInvariant(const Scene& scene) {
  for (const Texture& t : scene.textures) {
    if (t.width <= 0 || t.height <= 0 || t.width > kMaxTextureSide || t.height > kMaxTextureSide)
      return "texture size out of limits";
    if (t.texels.size() != static_cast<std::size_t>(t.width) * static_cast<std::size_t>(t.height))
      return "texture texel count";
    for (const glm::vec3& v : t.texels)
      if (!finite(v)) return "texture texel not finite";
  }
  for (const Material& m : scene.materials) {
    if (!finite(m.albedo) || glm::any(glm::lessThan(m.albedo, glm::vec3(0))) ||
        glm::any(glm::greaterThan(m.albedo, glm::vec3(1))))
      return "albedo outside [0,1]";
    if (!radiometric(m.emission)) return "emission beyond the limit";
    if (m.albedoTexture && *m.albedoTexture >= scene.textures.size()) return "texture index";
  }
  for (const Mesh& mesh : scene.meshes) {
    if (mesh.material >= scene.materials.size()) return "material index";
    if (mesh.normals.size() != mesh.positions.size()) return "normal count";
    if (!mesh.uv0.empty() && mesh.uv0.size() != mesh.positions.size()) return "uv0 count";
    if (mesh.indices.size() % 3 != 0) return "index count";
    for (const uint32_t i : mesh.indices)
      if (i >= mesh.positions.size()) return "vertex index";
    for (const glm::vec3& p : mesh.positions)
      if (!finite(p) || !withinLimit(glm::dvec3(p))) return "position beyond the limit";
    for (const glm::vec3& n : mesh.normals)
      if (!finite(n) || std::abs(glm::length(n) - 1.0f) > 1e-3f) return "normal not unit";
    for (const glm::vec2& uv : mesh.uv0)
      if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return "uv not finite";
  }
  for (const Instance& instance : scene.instances) {
    if (instance.mesh >= scene.meshes.size()) return "instance mesh index";
    const glm::dmat4 m(instance.transform);
    for (const glm::vec3& p : scene.meshes[instance.mesh].positions)
      if (!withinLimit(glm::dvec3(m * glm::dvec4(glm::dvec3(p), 1.0))))
        return "world position beyond the limit";
  }
  for (const Light& l : scene.lights) {
    if (!withinLimit(glm::dvec3(l.position))) return "light position";
    if (!finite(l.direction) || std::abs(glm::length(l.direction) - 1.0f) > 1e-3f)
      return "light direction";
    if (!radiometric(l.intensity) || !radiometric(l.irradiance)) return "light beyond the limit";
  }
  for (const Camera& c : scene.cameras) {
    if (!withinLimit(glm::dvec3(c.position()))) return "camera position";
    if (!(c.znear >= kMinZnear) || !(c.zfar > c.znear) || !std::isfinite(c.zfar))
      return "camera clip range";
    if (!(c.yfov > 0.0f) || !std::isfinite(c.aspect)) return "camera fov/aspect";
  }
  return {};
}

}  // namespace bounce::test
