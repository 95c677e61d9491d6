// Scenes and bakes built in code for the lightmap tests: a quad with a hand-made atlas region
// (synthetic bakes of known irradiance) and a smooth sphere for the seam measurement.
#pragma once

#include <cmath>
#include <string>

#include "bake_folder/bake_folder.h"
#include "scene/scene.h"
#include "test_scenes.h"

namespace bounce::test {

// A UV sphere of `rings` × `segments` quads (poles as triangle fans), smooth unit normals,
// counter-clockwise seen from outside. Vertices on the seam meridian are duplicated only in
// the material UVs' sense: here positions are shared, so the atlas decides every chart cut.
inline Mesh uvSphere(float radius, int rings, int segments) {
  Mesh mesh;
  mesh.name = "sphere";
  const float pi = 3.14159265358979f;
  const auto index = [&](int ring, int segment) {
    return static_cast<uint32_t>(1 + (ring - 1) * segments + (segment % segments));
  };
  mesh.positions.push_back({0, radius, 0});
  mesh.normals.push_back({0, 1, 0});
  for (int ring = 1; ring < rings; ++ring) {
    const float theta = pi * static_cast<float>(ring) / static_cast<float>(rings);
    for (int segment = 0; segment < segments; ++segment) {
      const float phi = 2 * pi * static_cast<float>(segment) / static_cast<float>(segments);
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                        -std::sin(theta) * std::sin(phi));
      mesh.positions.push_back(radius * n);
      mesh.normals.push_back(n);
    }
  }
  const uint32_t south = static_cast<uint32_t>(mesh.positions.size());
  mesh.positions.push_back({0, -radius, 0});
  mesh.normals.push_back({0, -1, 0});
  for (int segment = 0; segment < segments; ++segment) {
    mesh.indices.insert(mesh.indices.end(), {0u, index(1, segment), index(1, segment + 1)});
    for (int ring = 1; ring + 1 < rings; ++ring) {
      const uint32_t a = index(ring, segment), b = index(ring, segment + 1);
      const uint32_t c = index(ring + 1, segment), d = index(ring + 1, segment + 1);
      mesh.indices.insert(mesh.indices.end(), {a, c, d, a, d, b});
    }
    mesh.indices.insert(mesh.indices.end(),
                        {index(rings - 1, segment), south, index(rings - 1, segment + 1)});
  }
  return mesh;
}

// Adds `mesh` with material `material` as a new static instance at `transform`, named after the
// mesh; returns it.
inline uint32_t addInstance(Scene& scene, Mesh mesh, const Material& material,
                            const glm::mat4& transform) {
  const uint32_t instance = addMesh(scene, std::move(mesh), material, transform);
  scene.instances[instance].name = scene.meshes.back().name;
  return instance;
}

// A grey 1 m floor at y = 0 (unitFloorRegion's atlas u = x + ½, v = z + ½) under an emissive
// quad of radiance (3, 2, 1) W/(sr·m²) at `corner` spanning u and v (u × v = −y: facing down).
inline Scene floorUnderPanel(glm::vec3 corner, glm::vec3 u, glm::vec3 v) {
  Scene scene;
  Material floor;
  floor.name = "floor";
  floor.albedo = glm::vec3(0.6f);
  addQuad(scene, {-0.5f, 0, 0.5f}, {1, 0, 0}, {0, 0, -1}, floor);
  Material panel;
  panel.name = "panel";
  panel.emission = glm::vec3(3.0f, 2.0f, 1.0f);
  addQuad(scene, corner, u, v, panel);
  return scene;
}

// A hand-made manifest for a bake held in memory: format version and the scene's hash (writeBake
// also needs the atlas size and regions of the layout: manifestFor).
// The atlas region of a floor in the square |x|, |z| ≤ ½ m (instance 0 of `scene`), laid out
// u = x + ½, v = z + ½: a texel's world position follows from its atlas position.
inline InstanceLightmapUv unitFloorRegion(const Scene& scene) {
  const Mesh& floor = scene.meshes[scene.instances[0].mesh];
  InstanceLightmapUv region{0, {}};
  for (uint32_t index : floor.indices)
    region.cornerUv.push_back({floor.positions[index].x + 0.5f, floor.positions[index].z + 0.5f});
  return region;
}

inline BakeManifest minimalManifest(const Scene& scene) {
  BakeManifest manifest;
  manifest.sceneHash = sceneContentHash(scene);
  return manifest;
}

// minimalManifest agreeing with `bake`'s files as writeBake and readBake require (atlas size,
// regions, VPL count, visibility lights).
inline BakeManifest manifestFor(const Scene& scene, const Bake& bake) {
  BakeManifest manifest = minimalManifest(scene);
  manifest.atlas.width = bake.layout.width;
  manifest.atlas.height = bake.layout.height;
  manifest.atlas.regions = bake.layout.instances.size();
  if (bake.vpls) manifest.vpls = BakeManifest::Vpls{.count = bake.vpls->size()};
  if (bake.visibility)
    manifest.visibility = BakeManifest::Visibility{.lights = bake.visibility->lightCount};
  return manifest;
}

}  // namespace bounce::test
