#include "scene/world_geometry.h"

namespace bounce {

glm::vec3 WorldGeometry::triangleCross(std::size_t t) const {
  const glm::uvec3 tri = triangles[t];
  return glm::cross(positions[tri.y] - positions[tri.x], positions[tri.z] - positions[tri.x]);
}

WorldGeometry flatten(const Scene& scene) {
  WorldGeometry world;
  world.triangles.reserve(scene.triangleCount());
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    const Mesh& mesh = scene.meshes.at(instance.mesh);
    const glm::mat3 linear(instance.transform);
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));
    const bool mirrored = glm::determinant(linear) < 0.0f;
    const auto base = static_cast<uint32_t>(world.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      world.positions.push_back(glm::vec3(instance.transform * glm::vec4(mesh.positions[v], 1.0f)));
      const glm::vec3 n = v < mesh.normals.size() ? normalMatrix * mesh.normals[v] : glm::vec3(0);
      const float len = glm::length(n);
      world.normals.push_back(len > 0.0f ? n / len : glm::vec3(0));
      world.uv0.push_back(v < mesh.uv0.size() ? mesh.uv0[v] : glm::vec2(0));
      world.uv1.push_back(v < mesh.uv1.size() ? mesh.uv1[v] : glm::vec2(0));
    }
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      glm::uvec3 tri(base + mesh.indices[t], base + mesh.indices[t + 1],
                     base + mesh.indices[t + 2]);
      if (mirrored) std::swap(tri.y, tri.z);
      world.triangles.push_back(tri);
      world.triangleMaterial.push_back(mesh.material);
      world.triangleInstance.push_back(i);
    }
  }
  return world;
}

}  // namespace bounce
