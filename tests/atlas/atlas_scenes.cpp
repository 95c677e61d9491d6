#include "atlas_scenes.h"

#include <cmath>
#include <string>

namespace bounce::test {
namespace {

uint32_t addMesh(Scene& scene, Mesh mesh) {
  if (scene.materials.empty()) scene.materials.push_back(Material{});
  mesh.normals.assign(mesh.positions.size(), glm::vec3(0, 0, 1));
  scene.meshes.push_back(std::move(mesh));
  return static_cast<uint32_t>(scene.meshes.size() - 1);
}

}  // namespace

uint32_t addUnitQuadMesh(Scene& scene) {
  Mesh mesh;
  mesh.name = "quad";
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return addMesh(scene, std::move(mesh));
}

uint32_t addUnitCubeMesh(Scene& scene) {
  Mesh mesh;
  mesh.name = "cube";
  // Each face: origin corner and two edge directions whose cross product points outwards.
  const glm::vec3 faces[6][3] = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}, {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}};
  for (const auto& f : faces) {
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(),
                          {f[0], f[0] + f[1], f[0] + f[1] + f[2], f[0] + f[2]});
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return addMesh(scene, std::move(mesh));
}

uint32_t addSphereMesh(Scene& scene, int rings, int segments) {
  Mesh mesh;
  mesh.name = "sphere";
  const float pi = 3.14159265f;
  mesh.positions.push_back({0, 1, 0});
  for (int r = 1; r < rings; ++r) {
    const float theta = pi * static_cast<float>(r) / static_cast<float>(rings);
    for (int s = 0; s < segments; ++s) {
      const float phi = 2.0f * pi * static_cast<float>(s) / static_cast<float>(segments);
      mesh.positions.push_back(
          {std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)});
    }
  }
  mesh.positions.push_back({0, -1, 0});
  const auto south = static_cast<uint32_t>(mesh.positions.size() - 1);
  auto ring = [&](int r, int s) {
    return static_cast<uint32_t>(1 + (r - 1) * segments + (s % segments));
  };
  for (int s = 0; s < segments; ++s) {
    mesh.indices.insert(mesh.indices.end(), {0u, ring(1, s), ring(1, s + 1)});
    mesh.indices.insert(mesh.indices.end(), {south, ring(rings - 1, s + 1), ring(rings - 1, s)});
  }
  for (int r = 1; r + 1 < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      mesh.indices.insert(mesh.indices.end(), {ring(r, s), ring(r + 1, s), ring(r + 1, s + 1)});
      mesh.indices.insert(mesh.indices.end(), {ring(r, s), ring(r + 1, s + 1), ring(r, s + 1)});
    }
  return addMesh(scene, std::move(mesh));
}

uint32_t addCylinderMesh(Scene& scene, int segments) {
  Mesh mesh;
  mesh.name = "cylinder";
  const float pi = 3.14159265f;
  for (int s = 0; s < segments; ++s) {
    const float phi = 2.0f * pi * static_cast<float>(s) / static_cast<float>(segments);
    const float x = std::cos(phi), z = -std::sin(phi);
    mesh.positions.push_back({x, -1, z});
    mesh.positions.push_back({x, 1, z});
  }
  for (int s = 0; s < segments; ++s) {
    const auto b0 = static_cast<uint32_t>(2 * s), t0 = b0 + 1;
    const auto b1 = static_cast<uint32_t>(2 * ((s + 1) % segments)), t1 = b1 + 1;
    mesh.indices.insert(mesh.indices.end(), {b0, b1, t1, b0, t1, t0});
  }
  return addMesh(scene, std::move(mesh));
}

void addInstance(Scene& scene, uint32_t mesh, const glm::mat4& transform, Mobility mobility) {
  Instance instance;
  instance.name = "instance" + std::to_string(scene.instances.size());
  instance.mesh = mesh;
  instance.transform = transform;
  instance.mobility = mobility;
  scene.instances.push_back(instance);
}

}  // namespace bounce::test
