// Scenes and measurements for the shadow-map tests: boxes, rendering with and without shadows,
// and what each pixel sees (by the baker's ray kernel, through the pixel centre as the
// rasterizer samples it).
#pragma once

#include <vector>

#include "ray/ray_kernel.h"
#include "render/forward_renderer.h"
#include "scene/world_geometry.h"
#include "test_scenes.h"

namespace bounce::test {

// A closed axis-aligned box [lo, hi] (metres), faces outwards, flat normals, one mesh.
inline void addBox(Scene& scene, glm::vec3 lo, glm::vec3 hi, const Material& material) {
  Mesh mesh;
  mesh.name = material.name;
  const glm::vec3 d = hi - lo;
  // Each face as corner + two edges with (u × v) outwards.
  const glm::vec3 faces[6][3] = {
      {{lo.x, lo.y, hi.z}, {d.x, 0, 0}, {0, d.y, 0}},   // +z
      {{hi.x, lo.y, lo.z}, {-d.x, 0, 0}, {0, d.y, 0}},  // −z
      {{hi.x, lo.y, hi.z}, {0, 0, -d.z}, {0, d.y, 0}},  // +x
      {{lo.x, lo.y, lo.z}, {0, 0, d.z}, {0, d.y, 0}},   // −x
      {{lo.x, hi.y, hi.z}, {d.x, 0, 0}, {0, 0, -d.z}},  // +y
      {{lo.x, lo.y, lo.z}, {d.x, 0, 0}, {0, 0, d.z}},   // −y
  };
  for (const auto& f : faces) {
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    const glm::vec3 n = glm::normalize(glm::cross(f[1], f[2]));
    for (const glm::vec3 p : {f[0], f[0] + f[1], f[0] + f[1] + f[2], f[0] + f[2]}) {
      mesh.positions.push_back(p);
      mesh.normals.push_back(n);
    }
    for (const uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
  }
  mesh.material = static_cast<uint32_t>(scene.materials.size());
  scene.materials.push_back(material);
  Instance instance;
  instance.mesh = static_cast<uint32_t>(scene.meshes.size());
  scene.meshes.push_back(mesh);
  scene.instances.push_back(instance);
}

inline Image renderWith(const Scene& scene, const Camera& camera, int width, int height,
                        const ShadowSettings& shadows) {
  testContext();
  RendererSettings settings;
  settings.shadows = shadows;
  ForwardRenderer renderer(scene, gl::shaderDirectory(), settings);
  return renderer.renderImage(camera, width, height);
}

// What the centre of pixel (x, y) sees: the hit and its world point (hit.valid() false where
// the ray escapes).
struct PixelSight {
  Hit hit;
  glm::vec3 position{0.0f};  // metres
};

inline std::vector<PixelSight> pixelSights(const RayKernel& kernel, const Camera& camera, int width,
                                           int height) {
  std::vector<PixelSight> sights;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      Ray ray;
      ray.origin = camera.position();
      ray.direction = glm::normalize(pixelRay(camera, width, height, x, y));
      PixelSight sight;
      sight.hit = kernel.intersect(ray);
      if (sight.hit.valid()) sight.position = ray.origin + sight.hit.t * ray.direction;
      sights.push_back(sight);
    }
  }
  return sights;
}

// Ray-traced visibility of a point or spot light from what `sight` sees, on the side facing
// the camera: 1 lit, 0 occluded.
inline float tracedVisibility(const RayKernel& kernel, const Camera& camera,
                              const PixelSight& sight, const Light& light) {
  glm::vec3 n = sight.hit.geometricNormal;
  if (glm::dot(n, camera.position() - sight.position) < 0.0f) n = -n;
  const glm::vec3 toLight = light.position - sight.position;
  Ray ray;
  ray.origin = offsetRayOrigin(sight.position, n, toLight);
  ray.direction = light.position - ray.origin;
  ray.tmax = 1.0f - 1e-5f;
  return kernel.occluded(ray) ? 0.0f : 1.0f;
}

}  // namespace bounce::test
