#include <gtest/gtest.h>

#include "test_scenes.h"

#include <cmath>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/light_falloff.h"

namespace bounce::test {

uint32_t addMaterial(Scene& scene, glm::vec3 albedo, glm::vec3 emission, bool doubleSided) {
  Material m;
  m.name = std::to_string(scene.materials.size());
  m.albedo = albedo;
  m.emission = emission;
  m.doubleSided = doubleSided;
  scene.materials.push_back(m);
  return static_cast<uint32_t>(scene.materials.size() - 1);
}

void addQuad(Scene& scene, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3,
             uint32_t material) {
  Mesh mesh;
  mesh.name = std::to_string(scene.meshes.size());
  mesh.positions = {p0, p1, p2, p3};
  const glm::vec3 n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  mesh.normals = {n, n, n, n};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.material = material;
  scene.meshes.push_back(mesh);
  Instance instance;
  instance.mesh = static_cast<uint32_t>(scene.meshes.size() - 1);
  scene.instances.push_back(instance);
}

void addInwardBox(Scene& scene, glm::vec3 lo, glm::vec3 hi, uint32_t material) {
  const glm::vec3 a = lo, b = hi;
  // Each face listed counter-clockwise as seen from inside the box.
  addQuad(scene, {a.x, a.y, a.z}, {b.x, a.y, a.z}, {b.x, b.y, a.z}, {a.x, b.y, a.z},
          material);  // z = lo, faces +z
  addQuad(scene, {a.x, a.y, b.z}, {a.x, b.y, b.z}, {b.x, b.y, b.z}, {b.x, a.y, b.z},
          material);  // z = hi, faces −z
  addQuad(scene, {a.x, a.y, a.z}, {a.x, b.y, a.z}, {a.x, b.y, b.z}, {a.x, a.y, b.z},
          material);  // x = lo, faces +x
  addQuad(scene, {b.x, a.y, a.z}, {b.x, a.y, b.z}, {b.x, b.y, b.z}, {b.x, b.y, a.z},
          material);  // x = hi, faces −x
  addQuad(scene, {a.x, a.y, a.z}, {a.x, a.y, b.z}, {b.x, a.y, b.z}, {b.x, a.y, a.z},
          material);  // y = lo, faces +y
  addQuad(scene, {a.x, b.y, a.z}, {b.x, b.y, a.z}, {b.x, b.y, b.z}, {a.x, b.y, b.z},
          material);  // y = hi, faces −y
}

void addInwardTexturedBox(Scene& scene, glm::vec3 lo, glm::vec3 hi, uint32_t material,
                          Texture texture) {
  scene.textures.push_back(std::move(texture));
  scene.materials.at(material).albedoTexture = static_cast<uint32_t>(scene.textures.size() - 1);
  const std::size_t first = scene.meshes.size();
  addInwardBox(scene, lo, hi, material);
  for (std::size_t m = first; m < scene.meshes.size(); ++m)
    scene.meshes[m].uv0 = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
}

Texture stripedTexture(glm::vec3 a, glm::vec3 b) {
  Texture stripes;
  stripes.name = "stripes";
  stripes.width = stripes.height = 256;
  for (int y = 0; y < stripes.height; ++y)
    for (int x = 0; x < stripes.width; ++x) stripes.texels.push_back(x % 4 == 0 ? b : a);
  return stripes;
}

World planeWorld(glm::vec3 albedo, glm::vec3 shadingNormal) {
  World world;
  const uint32_t m = addMaterial(world.scene, albedo);
  addQuad(world.scene, {-100, -100, 0}, {100, -100, 0}, {100, 100, 0}, {-100, 100, 0}, m);
  world.scene.meshes.back().normals.assign(4, glm::normalize(shadingNormal));
  return world;
}

Ray downOnto(double x, double y, float height) {
  Ray ray;
  ray.origin = glm::vec3(static_cast<float>(x), static_cast<float>(y), height);
  ray.direction = {0, 0, -1};
  return ray;
}

Camera lookAt(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float yfov) {
  Camera camera;
  camera.name = "test";
  camera.cameraToWorld = glm::inverse(glm::lookAt(eye, target, up));
  camera.yfov = yfov;
  return camera;
}

void World::build(RayBackend backend) {
  geometry = flatten(scene);
  kernel = makeRayKernel(geometry, backend);
}

namespace {

// Welford's running mean and variance of n one-sample estimates `one(sampler)`, each drawn
// from dimension 1 on of sample i of the pattern (seed, pixel).
template <typename OneSample>
Estimate estimate(uint32_t seed, uint32_t pixel, int n, OneSample one) {
  SobolSampler sampler(seed, pixel);
  Estimate e;
  glm::dvec3 m2(0.0);
  for (int i = 0; i < n; ++i) {
    sampler.startSample(static_cast<uint32_t>(i));
    sampler.setDimension(1);  // as the camera renderer does (dimension 0: pixel jitter)
    const glm::dvec3 value(one(sampler));
    const glm::dvec3 delta = value - e.mean;
    e.mean += delta / static_cast<double>(i + 1);
    m2 += delta * (value - e.mean);
  }
  e.n = n;
  e.variance = n > 1 ? m2 / static_cast<double>(n - 1) : glm::dvec3(0.0);
  return e;
}

}  // namespace

Estimate estimateLi(const PathTracer& tracer, const Ray& ray, uint32_t seed, uint32_t pixel,
                    int n) {
  return estimate(seed, pixel, n, [&](SobolSampler& sampler) { return tracer.Li(ray, sampler); });
}

Estimate estimateIrradiance(const PathTracer& tracer, glm::vec3 position, glm::vec3 normal,
                            uint32_t seed, uint32_t pixel, int n) {
  return estimate(seed, pixel, n, [&](SobolSampler& sampler) {
    return tracer.irradiance(position, normal, sampler);
  });
}

ImageMean imageMean(const CameraRender& render, int spp) {
  ImageMean m;
  const auto pixels = static_cast<double>(render.radiance.pixels.size());
  glm::dvec3 varianceSum(0.0);
  for (std::size_t i = 0; i < render.radiance.pixels.size(); ++i) {
    m.mean += glm::dvec3(render.radiance.pixels[i]);
    varianceSum += glm::dvec3(render.sampleVariance.pixels[i]);
  }
  m.mean /= pixels;
  m.variancePerSample = varianceSum / pixels;
  m.standardError = glm::sqrt(varianceSum / static_cast<double>(spp)) / pixels;
  return m;
}

::testing::AssertionResult agreeWithin(glm::dvec3 a, glm::dvec3 seA, glm::dvec3 b, glm::dvec3 seB,
                                       double k) {
  std::ostringstream message;
  bool ok = true;
  for (int c = 0; c < 3; ++c) {
    const double tolerance = k * std::sqrt(seA[c] * seA[c] + seB[c] * seB[c]);
    const double diff = std::abs(a[c] - b[c]);
    message << "channel " << c << ": " << a[c] << " vs " << b[c] << " (|diff| " << diff
            << ", tolerance " << tolerance << " = " << k << " combined SE)\n";
    if (!(diff <= tolerance)) ok = false;
  }
  return ok ? ::testing::AssertionSuccess() << message.str()
            : ::testing::AssertionFailure() << message.str();
}

glm::dvec3 punctualIrradiance(const Light& light, glm::dvec3 x) {
  const glm::dvec3 d = glm::dvec3(light.position) - x;
  const double d2 = glm::dot(d, d);
  const double cosX = d.z / std::sqrt(d2);
  if (cosX <= 0.0) return glm::dvec3(0.0);
  double falloff = 1.0;
  if (light.type == LightType::Spot) {
    falloff =
        spotFalloff(light, static_cast<float>(glm::dot(glm::normalize(glm::dvec3(light.direction)),
                                                       -d / std::sqrt(d2))));
  }
  return glm::dvec3(light.intensity) * falloff * cosX / d2;
}

}  // namespace bounce::test
