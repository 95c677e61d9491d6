// Scenes built in code for the renderer's analytic tests, and the geometry the tests use to
// find which world point each pixel sees (the pixel-centre ray, as the rasterizer samples it).
#pragma once

#include <unistd.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "gl/context.h"
#include "gl/shader.h"
#include "image/image_io.h"
#include "render/forward_renderer.h"
#include "scene/scene.h"
#include "support/test_context.h"

namespace bounce::test {

// Adds `mesh` with `material` (appended to scene.materials) as a new unnamed static instance at
// `transform`; returns the instance's index.
inline uint32_t addMesh(Scene& scene, Mesh mesh, const Material& material,
                        const glm::mat4& transform = glm::mat4(1.0f)) {
  mesh.material = static_cast<uint32_t>(scene.materials.size());
  scene.materials.push_back(material);
  scene.meshes.push_back(std::move(mesh));
  Instance instance;
  instance.mesh = static_cast<uint32_t>(scene.meshes.size() - 1);
  instance.transform = transform;
  scene.instances.push_back(instance);
  return static_cast<uint32_t>(scene.instances.size() - 1);
}

// Adds a quad with corners c, c+u, c+u+v, c+v (counter-clockwise seen from u×v, its front side).
inline void addQuad(Scene& scene, glm::vec3 c, glm::vec3 u, glm::vec3 v, const Material& material) {
  Mesh mesh;
  mesh.name = material.name;
  mesh.positions = {c, c + u, c + u + v, c + v};
  const glm::vec3 n = glm::normalize(glm::cross(u, v));
  mesh.normals = {n, n, n, n};
  mesh.uv0 = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  addMesh(scene, std::move(mesh), material);
}

// The floor y = 0, facing +y, 20 m wide, of diffuse reflectance `albedo`.
inline void addFloor(Scene& scene, glm::vec3 albedo) {
  Material floor;
  floor.name = "floor";
  floor.albedo = albedo;
  addQuad(scene, {-10, 0, 10}, {20, 0, 0}, {0, 0, -20}, floor);
}

// A camera at (0, height, 0) looking straight down (−y), image up = world −z.
inline Camera downCamera(float height, float yfov = 0.8f) {
  Camera camera;
  camera.name = "down";
  camera.yfov = yfov;
  camera.cameraToWorld = glm::mat4(glm::vec4(1, 0, 0, 0), glm::vec4(0, 0, -1, 0),
                                   glm::vec4(0, 1, 0, 0), glm::vec4(0, height, 0, 1));
  return camera;
}

// World direction of the ray through the raster point (px, py) (pixels from the top-left
// corner; pixel (x, y)'s centre is (x + 0.5, y + 0.5)).
inline glm::vec3 pixelRay(const Camera& camera, int width, int height, float px, float py) {
  const float t = std::tan(0.5f * camera.yfov);
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const float ndcX = px / static_cast<float>(width) * 2.0f - 1.0f;
  const float ndcY = 1.0f - py / static_cast<float>(height) * 2.0f;
  return glm::mat3(camera.cameraToWorld) * glm::vec3(ndcX * t * aspect, ndcY * t, -1.0f);
}
inline glm::vec3 pixelRay(const Camera& camera, int width, int height, int x, int y) {
  return pixelRay(camera, width, height, static_cast<float>(x) + 0.5f,
                  static_cast<float>(y) + 0.5f);
}

// The point of the floor y = 0 seen through the raster point (px, py), or pixel (x, y)'s centre.
inline glm::vec3 floorPoint(const Camera& camera, int width, int height, float px, float py) {
  const glm::vec3 d = pixelRay(camera, width, height, px, py);
  const glm::vec3 o = camera.position();
  return o + d * (-o.y / d.y);
}
inline glm::vec3 floorPoint(const Camera& camera, int width, int height, int x, int y) {
  return floorPoint(camera, width, height, static_cast<float>(x) + 0.5f,
                    static_cast<float>(y) + 0.5f);
}

// Where the rasterizer's sample of a pixel may lie around the pixel's centre: one sub-pixel step
// (2^-GL_SUBPIXEL_BITS of a pixel, the grid vertices snap to) along each raster axis. A quantity
// the renderer computes from interpolated positions is compared with the CPU's value at the
// centre within what that value changes over these offsets: exact rasterizers (llvmpipe) land
// on the centre, real GPUs within the step.
inline std::array<glm::vec2, 4> subpixelOffsets(const gl::Context& context) {
  const int bits = context.subpixelBits();
  const float step = std::ldexp(1.0f, -(bits > 0 ? bits : 4));
  return {glm::vec2(step, 0.0f), glm::vec2(-step, 0.0f), glm::vec2(0.0f, step),
          glm::vec2(0.0f, -step)};
}

// Renders offscreen and returns the pixels as they come back from the EXR file bounce-render
// would write (32-bit float, so the round trip is exact).
inline Image render(const Scene& scene, const Camera& camera, int width, int height) {
  testContext();
  ForwardRenderer renderer(scene, gl::shaderDirectory());
  const Image image = renderer.renderImage(camera, width, height);
  const std::filesystem::path exr = std::filesystem::temp_directory_path() /
                                    ("bounce-render-test-" + std::to_string(::getpid()) + ".exr");
  writeExr(exr, image);
  Image stored = readExr(exr);
  std::filesystem::remove(exr);
  return stored;
}

}  // namespace bounce::test
