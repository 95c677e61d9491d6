// The forward renderer against the project's reference path tracer (direct light only), on a
// scene without occlusion, where the two must agree: this checks the conventions the two
// renderers share but the analytic tests fix only on one side (units, which face emits, spot
// falloff, light directions, camera rays).
#include <gtest/gtest.h>

#include <cmath>

#include "ray/ray_kernel.h"
#include "scene/world_geometry.h"
#include "test_scenes.h"
#include "trace/camera_render.h"

namespace bounce::test {
namespace {

// A floor lit by a tilted square emitter, a point, a spot and a directional light. Nothing
// shadows the visible floor: the camera sits below the emitter, and the emitter's shadow from
// the 60°-tilted directional light falls 2.6 m to the side, outside the view.
Scene unoccludedScene() {
  Scene scene;
  addFloor(scene, {0.8f, 0.5f, 0.25f});
  Material emitter;
  emitter.name = "emitter";
  emitter.albedo = glm::vec3(0.0f);
  emitter.emission = {4.0f, 6.0f, 8.0f};
  // 0.6 m square around (0.3, 1.5, 0), tilted 20° about z; (u × v) faces down.
  const float c = std::cos(0.35f), s = std::sin(0.35f);
  addQuad(scene, {0.0f, 1.5f - 0.3f * s, -0.3f}, {0.6f * c, 0.6f * s, 0}, {0, 0, 0.6f}, emitter);
  Light point;
  point.type = LightType::Point;
  point.position = {-0.3f, 0.8f, 0.2f};
  point.intensity = {0.5f, 0.3f, 0.2f};
  Light spot;
  spot.type = LightType::Spot;
  spot.position = {0.2f, 0.9f, -0.3f};
  spot.direction = glm::normalize(glm::vec3(0.1f, -1.0f, 0.0f));
  spot.intensity = {1.0f, 1.0f, 2.0f};
  spot.innerConeAngle = 0.2f;
  spot.outerConeAngle = 0.5f;
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(std::sqrt(3.0f), -1.0f, 0.0f));  // 60° from vertical
  sun.irradiance = {0.3f, 0.3f, 0.3f};
  scene.lights = {point, spot, sun};
  return scene;
}

// Blocks of 8×8 pixels: the tracer's block mean has standard error √(Σ var_i / spp) / 64 from its
// own per-pixel sample variance; 5σ over 64 blocks × 3 channels leaves a false-failure chance
// of ~1e-4. The tracer box-filters each pixel while the rasterizer samples its centre: over a
// block that is the midpoint rule, off by ~(pixel/distance)²/24 ≈ 1e-4 relative here, so 0.5%
// relative covers it and float rounding.
void expectAgreement(const Scene& scene, const Camera& camera) {
  constexpr int kSize = 64, kBlock = 8;
  const Image forward = render(scene, camera, kSize, kSize);

  const WorldGeometry geometry = flatten(scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  TraceSettings settings;
  settings.spp = 64;
  settings.paths = PathSet::DirectOnly;
  const CameraRender traced = traceCamera(scene, geometry, *kernel, camera, kSize, kSize, settings);

  for (int by = 0; by < kSize; by += kBlock) {
    for (int bx = 0; bx < kSize; bx += kBlock) {
      glm::dvec3 a(0), b(0), variance(0);
      for (int y = by; y < by + kBlock; ++y) {
        for (int x = bx; x < bx + kBlock; ++x) {
          a += glm::dvec3(forward.at(x, y));
          b += glm::dvec3(traced.radiance.at(x, y));
          variance += glm::dvec3(traced.sampleVariance.at(x, y)) / double(settings.spp);
        }
      }
      const double n = kBlock * kBlock;
      for (int ch = 0; ch < 3; ++ch) {
        const double sigma = std::sqrt(variance[ch]) / n;
        EXPECT_NEAR(a[ch] / n, b[ch] / n, 5 * sigma + 0.005 * b[ch] / n)
            << "block at (" << bx << "," << by << ") channel " << ch;
      }
    }
  }
}

TEST(PathTracerAgreement, DirectLightMatchesReferenceOnUnoccludedScene) {
  expectAgreement(unoccludedScene(), downCamera(1.0f));
}

// The rules of scene/surface_rules.h, read by both: an emitter with a negative channel emits
// the others; one with a non-finite channel does not emit at all but still reflects; a mesh
// naming a material that does not exist is a black absorber; a mesh without usable normals is
// shaded with its geometric normal. Everything lies flat on the floor, so nothing is occluded;
// the small quads' edges fall on the 8×8 block boundaries (multiples of `u` at their height), so
// no block mixes two surfaces.
TEST(PathTracerAgreement, SceneRulesReadAlike) {
  const float h = 0.001f;                                      // quads' height over the floor
  const float u = 0.25f * (1.0f - h) * std::tan(0.5f * 0.8f);  // one block, downCamera(1)
  Scene scene;
  addFloor(scene, {0.8f, 0.5f, 0.25f});
  Material emitter;
  emitter.name = "negative channel";
  emitter.albedo = glm::vec3(0.0f);
  emitter.emission = {4.0f, -3.0f, 8.0f};
  addQuad(scene, {-0.3f, 1.5f, -0.3f}, {0.6f, 0, 0}, {0, 0, 0.6f}, emitter);  // faces down
  Material broken;
  broken.name = "non-finite emission";
  broken.albedo = glm::vec3(0.7f);
  broken.emission = {1.0f, std::nanf(""), 1.0f};
  addQuad(scene, {-3 * u, h, u}, {0, 0, 2 * u}, {2 * u, 0, 0}, broken);  // faces up
  Material missing;
  missing.name = "bad index";
  missing.albedo = glm::vec3(0.9f);
  addQuad(scene, {u, h, u}, {0, 0, 2 * u}, {2 * u, 0, 0}, missing);
  scene.meshes.back().material = 99;
  Material plain;
  plain.name = "no normals";
  plain.albedo = glm::vec3(0.6f);
  addQuad(scene, {u, h, -3 * u}, {0, 0, 2 * u}, {2 * u, 0, 0}, plain);
  scene.meshes.back().normals.assign(4, glm::vec3(0.0f));
  expectAgreement(scene, downCamera(1.0f));
}

}  // namespace
}  // namespace bounce::test
