// The scene's triangles flattened into world space: what ray kernels, emitter sampling and
// bakers consume. Vertices are not shared between instances.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace bounce {

struct WorldGeometry {
  std::vector<glm::vec3> positions;        // world, metres
  std::vector<glm::vec3> normals;          // world unit shading normals, per vertex
  std::vector<glm::vec2> uv0;              // per vertex; (0,0) where the mesh has none
  std::vector<glm::vec2> uv1;              // per vertex; (0,0) where the mesh has none
  std::vector<glm::uvec3> triangles;       // vertex indices, counter-clockwise = front
  std::vector<uint32_t> triangleMaterial;  // per triangle, index into Scene::materials
  std::vector<uint32_t> triangleInstance;  // per triangle, index into Scene::instances

  std::size_t triangleCount() const { return triangles.size(); }
  // Unnormalized geometric normal (p1−p0)×(p2−p0); its length is twice the area in m².
  glm::vec3 triangleCross(std::size_t t) const;
};

// Applies each instance's transform (normals by the inverse transpose; winding flipped for
// mirroring transforms so that counter-clockwise stays front-facing).
WorldGeometry flatten(const Scene& scene);

}  // namespace bounce
