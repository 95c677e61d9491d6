// Scenes and measurements for the shadow-map tests: boxes, rendering with and without shadows,
// and what each pixel sees (by the baker's ray kernel, through the pixel centre as the
// rasterizer samples it).
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

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
  addMesh(scene, std::move(mesh), material);
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

inline Camera lookingAt(glm::vec3 eye, glm::vec3 target, float yfov) {
  Camera camera;
  camera.name = "look";
  camera.yfov = yfov;
  camera.cameraToWorld = glm::inverse(glm::lookAt(eye, target, glm::vec3(0, 1, 0)));
  return camera;
}

inline Light spotAt(glm::vec3 position, glm::vec3 target, float inner, float outer,
                    float intensity) {
  Light spot;
  spot.name = "spot";
  spot.type = LightType::Spot;
  spot.position = position;
  spot.direction = glm::normalize(target - position);
  spot.innerConeAngle = inner;
  spot.outerConeAngle = outer;
  spot.intensity = glm::vec3(intensity);
  return spot;
}

inline Light pointAt(glm::vec3 position, float intensity) {
  Light point;
  point.name = "point";
  point.type = LightType::Point;
  point.position = position;
  point.intensity = glm::vec3(intensity);
  return point;
}

inline float sum(glm::vec3 v) {
  return v.x + v.y + v.z;
}

// A 3 m floor with a box, a thin post, a thin wall (2 cm) and a tilted plate floating over it.
inline Scene occluderScene(const Light& light) {
  Scene scene;
  Material floor;
  floor.name = "floor";
  floor.albedo = glm::vec3(0.5f);
  addQuad(scene, {-1.5f, 0, 1.5f}, {3, 0, 0}, {0, 0, -3}, floor);
  Material grey;
  grey.name = "grey";
  grey.albedo = glm::vec3(0.6f);
  addBox(scene, {-0.5f, 0, 0}, {-0.1f, 0.4f, 0.4f}, grey);
  addBox(scene, {0.3f, 0, -0.5f}, {0.36f, 0.8f, -0.44f}, grey);
  addBox(scene, {-0.9f, 0, -0.9f}, {0.2f, 0.3f, -0.88f}, grey);
  Material plate;
  plate.name = "plate";
  plate.albedo = glm::vec3(0.4f);
  plate.doubleSided = true;
  addQuad(scene, {0.0f, 0.5f, 0.3f}, {0.5f, 0.15f, 0}, {0, 0, 0.4f}, plate);
  scene.lights = {light};
  return scene;
}

struct Agreement {
  int considered = 0;   // lit-or-shadowed pixels outside the edge band
  int shadowed = 0;     // of those, occluded by ray tracing
  int disagreeing = 0;  // |V_map − V_ray| > ½
  // Per pixel: white lit by both, grey shadowed by both, red shadowed only by the map (acne,
  // leaks the other way), blue shadowed only by ray tracing (light leaks, peter-panning),
  // dark green the excluded edge band; black not considered.
  Image map;
  Image frame;  // the frame with shadows, radiance W/(sr·m²)
  double fraction() const { return considered ? double(disagreeing) / considered : 1.0; }
};

// V_map = radiance with shadows / radiance without (one light, so exactly its visibility).
// Pixels the light does not reach unshadowed (outside the cone, facing away) are left out, and
// so is a one-pixel band along true shadow edges (any 8-neighbour with another V_ray).
// Compares the one-light images `withShadows` and `without` (the same frame, shadows off) pixel
// by pixel with ray-traced visibility.
inline Agreement compareVisibility(const Scene& scene, const Camera& camera,
                                   const Image& withShadows, const Image& without) {
  const int width = without.width, height = without.height;
  const WorldGeometry geometry = flatten(scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  const std::vector<PixelSight> sights = pixelSights(*kernel, camera, width, height);
  float brightest = 0.0f;
  for (const glm::vec3& p : without.pixels) brightest = std::max(brightest, sum(p));
  std::vector<float> traced(sights.size(), -1.0f);  // −1: not considered
  for (std::size_t i = 0; i < sights.size(); ++i) {
    if (!sights[i].hit.valid() || !(sum(without.pixels[i]) > 1e-4f * brightest)) continue;
    traced[i] = tracedVisibility(*kernel, camera, sights[i], scene.lights[0]);
  }
  Agreement agreement;
  agreement.map = Image(width, height);
  agreement.frame = withShadows;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = without.index(x, y);
      if (traced[i] < 0.0f) continue;
      bool edge = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
          const float other = traced[without.index(nx, ny)];
          if (other >= 0.0f && other != traced[i]) edge = true;
        }
      glm::vec3& shown = agreement.map.pixels[i];
      if (edge) {
        shown = {0.0f, 0.2f, 0.0f};
        continue;
      }
      const float mapped = sum(withShadows.pixels[i]) / sum(without.pixels[i]);
      ++agreement.considered;
      if (traced[i] == 0.0f) ++agreement.shadowed;
      shown = glm::vec3(traced[i] == 0.0f ? 0.2f : 1.0f);
      if (std::abs(mapped - traced[i]) > 0.5f) {
        ++agreement.disagreeing;
        shown = traced[i] == 0.0f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
      }
    }
  }
  return agreement;
}

inline Agreement measureAgreement(const Scene& scene, const Camera& camera, int width, int height,
                                  const ShadowSettings& shadows = {}) {
  ShadowSettings off;
  off.enabled = false;
  return compareVisibility(scene, camera, renderWith(scene, camera, width, height, shadows),
                           renderWith(scene, camera, width, height, off));
}

// The camera the visibility measurements look through at occluderScene.
inline Camera occluderCamera() {
  return lookingAt({0.3f, 2.0f, 2.0f}, {0, 0, 0}, 0.8f);
}
inline Light occluderSpot() {
  return spotAt({0.7f, 1.6f, 0.6f}, {-0.1f, 0, -0.1f}, 0.5f, 0.6f, 3.0f);
}
inline Light occluderPoint() {
  return pointAt({0.1f, 1.0f, 0.5f}, 1.0f);
}

}  // namespace bounce::test
