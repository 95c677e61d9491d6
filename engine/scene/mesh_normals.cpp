#include "scene/mesh_normals.h"

namespace bounce {

void makeFlatNormals(Mesh& mesh) {
  Mesh flat;
  const std::size_t corners = mesh.indices.size();
  flat.positions.reserve(corners);
  flat.normals.reserve(corners);
  const bool hasUv0 = !mesh.uv0.empty();
  const bool hasUv1 = !mesh.uv1.empty();
  for (std::size_t t = 0; t + 2 < corners; t += 3) {
    const uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
    const glm::vec3 cross = glm::cross(mesh.positions[i1] - mesh.positions[i0],
                                       mesh.positions[i2] - mesh.positions[i0]);
    const float len = glm::length(cross);
    const glm::vec3 n = len > 0.0f ? cross / len : glm::vec3(0, 1, 0);
    for (const uint32_t i : {i0, i1, i2}) {
      flat.indices.push_back(static_cast<uint32_t>(flat.positions.size()));
      flat.positions.push_back(mesh.positions[i]);
      flat.normals.push_back(n);
      if (hasUv0) flat.uv0.push_back(mesh.uv0[i]);
      if (hasUv1) flat.uv1.push_back(mesh.uv1[i]);
    }
  }
  mesh.positions = std::move(flat.positions);
  mesh.normals = std::move(flat.normals);
  mesh.uv0 = std::move(flat.uv0);
  mesh.uv1 = std::move(flat.uv1);
  mesh.indices = std::move(flat.indices);
}

}  // namespace bounce
