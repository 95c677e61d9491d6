// Scenes built in code for the path tracer's tests, and the statistics the tests' tolerances
// come from.
#pragma once

#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "ray/ray_kernel.h"
#include "scene/scene.h"
#include "scene/world_geometry.h"
#include "trace/camera_render.h"
#include "trace/path_tracer.h"

namespace bounce::test {

uint32_t addMaterial(Scene& scene, glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.0f),
                     bool doubleSided = false);
// A planar quad p0 p1 p2 p3 (counter-clockwise seen from its front, which faces
// (p1−p0)×(p2−p0)).
void addQuad(Scene& scene, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3,
             uint32_t material);
// An axis-aligned box whose six faces face inwards.
void addInwardBox(Scene& scene, glm::vec3 lo, glm::vec3 hi, uint32_t material);

// A closed box as addInwardBox whose faces all show `texture` (added to the scene) once, uv0
// (0, 0) to (1, 1) over each face, through `material`'s albedo (which multiplies it).
void addInwardTexturedBox(Scene& scene, glm::vec3 lo, glm::vec3 hi, uint32_t material,
                          Texture texture);
// 256 × 256 texels in stripes, every 4th column `b` and the others `a`: area mean (3a + b)/4,
// while uv (0, 0), a corner between texels, reads (a + b)/2.
Texture stripedTexture(glm::vec3 a, glm::vec3 b);
// A pinhole camera at `eye` looking at `target`.
Camera lookAt(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float yfov);

// A scene plus what tracing it needs. Call build() last, once the World is where it will stay:
// the kernel refers to `geometry`, so moving a built World leaves the kernel dangling.
struct World {
  Scene scene;
  WorldGeometry geometry;
  std::unique_ptr<RayKernel> kernel;
  void build(RayBackend backend = RayBackend::Embree);
};

// A 200 m × 200 m plane at z = 0 facing +z, of diffuse reflectance `albedo`, as its own World
// (not built); its vertex normals are `shadingNormal`, normalised (by default the geometric
// normal +z).
World planeWorld(glm::vec3 albedo, glm::vec3 shadingNormal = {0, 0, 1});
// A ray straight down (−z) onto the plane point (x, y, 0) from `height` metres above it.
Ray downOnto(double x, double y, float height = 1.0f);

// Mean and unbiased sample variance of n one-sample estimates.
struct Estimate {
  glm::dvec3 mean{0.0};
  glm::dvec3 variance{0.0};  // per sample
  int n = 0;
  glm::dvec3 standardError() const { return glm::sqrt(variance / static_cast<double>(n)); }
};

// n estimates of tracer.Li(ray) with samples 0..n−1 of the pattern (seed, pixel).
Estimate estimateLi(const PathTracer& tracer, const Ray& ray, uint32_t seed, uint32_t pixel, int n);

// n estimates of tracer.irradiance(position, normal) (W/m²) with samples 0..n−1 of the pattern
// (seed, pixel), the sampler at dimension 1 as the baker leaves it (dimension 0: the point in
// the texel).
Estimate estimateIrradiance(const PathTracer& tracer, glm::vec3 position, glm::vec3 normal,
                            uint32_t seed, uint32_t pixel, int n);

// The mean radiance over an image's pixels and its standard error: pixels are independent
// estimates (distinct sampler patterns), so Var(mean) = Σ_p Var_p / (spp · P²).
struct ImageMean {
  glm::dvec3 mean{0.0};
  glm::dvec3 standardError{0.0};
  glm::dvec3 variancePerSample{0.0};  // mean over pixels of one sample's variance
};
ImageMean imageMean(const CameraRender& render, int spp);

// |a − b| ≤ k·sqrt(seA² + seB²) per channel, with a message.
// E = I·cosθ/d² (W/m²) on the +z plane at x from a point light, unshadowed (a spot: × its t²
// falloff, scene/light_falloff.h).
glm::dvec3 punctualIrradiance(const Light& light, glm::dvec3 x);

::testing::AssertionResult agreeWithin(glm::dvec3 a, glm::dvec3 seA, glm::dvec3 b, glm::dvec3 seB,
                                       double k);

}  // namespace bounce::test
