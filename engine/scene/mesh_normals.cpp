#include "scene/mesh_normals.h"

#include <cmath>

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

namespace {

bool isUnitable(const glm::vec3& v) {
  const float len = glm::length(v);
  return std::isfinite(len) && len > 0.0f;
}

glm::vec3 flatNormal(const Mesh& mesh, std::size_t t) {
  const glm::vec3& p0 = mesh.positions[mesh.indices[t]];
  const glm::vec3 cross = glm::cross(mesh.positions[mesh.indices[t + 1]] - p0,
                                     mesh.positions[mesh.indices[t + 2]] - p0);
  return isUnitable(cross) ? glm::normalize(cross) : glm::vec3(0, 1, 0);
}

}  // namespace

void repairNormals(Mesh& mesh) {
  const std::size_t n = mesh.normals.size();
  std::vector<bool> bad(n, false);
  bool anyBad = false;
  for (std::size_t i = 0; i < n; ++i) {
    if (isUnitable(mesh.normals[i])) {
      mesh.normals[i] = glm::normalize(mesh.normals[i]);
    } else {
      bad[i] = anyBad = true;
    }
  }
  if (!anyBad) return;
  // |(p1−p0)×(p2−p0)| is twice the triangle's area: summing the crosses weights by area.
  std::vector<glm::vec3> sum(n, glm::vec3(0.0f));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec3& p0 = mesh.positions[mesh.indices[t]];
    const glm::vec3 cross = glm::cross(mesh.positions[mesh.indices[t + 1]] - p0,
                                       mesh.positions[mesh.indices[t + 2]] - p0);
    for (std::size_t k = 0; k < 3; ++k)
      if (bad[mesh.indices[t + k]]) sum[mesh.indices[t + k]] += cross;
  }
  anyBad = false;
  for (std::size_t i = 0; i < n; ++i) {
    if (!bad[i]) continue;
    bad[i] = !isUnitable(sum[i]);
    mesh.normals[i] = bad[i] ? glm::vec3(0, 1, 0) : glm::normalize(sum[i]);
    anyBad = anyBad || bad[i];
  }
  if (!anyBad) return;
  // Still unresolved: split the vertex per triangle, each copy with its triangle's flat normal.
  const bool hasUv0 = !mesh.uv0.empty(), hasUv1 = !mesh.uv1.empty();
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec3 flat = flatNormal(mesh, t);
    for (std::size_t k = 0; k < 3; ++k) {
      const uint32_t i = mesh.indices[t + k];
      if (!bad[i]) continue;
      mesh.indices[t + k] = static_cast<uint32_t>(mesh.positions.size());
      mesh.positions.push_back(mesh.positions[i]);
      mesh.normals.push_back(flat);
      if (hasUv0) mesh.uv0.push_back(mesh.uv0[i]);
      if (hasUv1) mesh.uv1.push_back(mesh.uv1[i]);
    }
  }
}

}  // namespace bounce
