// The irradiance probes drawn by the renderer against the reference path tracer: a small tilted
// plate the atlas leaves without a lightmap (lightmapScale 0) in a closed box lit by two unequal
// emitters, baked with bakeScene (probe stage included), its pixels in --mode indirect against
// the tracer's --indirect-only image.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "indirect_accuracy.h"
#include "lightmap_scenes.h"
#include "test_scenes.h"

namespace bounce::test {
namespace {

struct PlateInABox {
  Scene scene;
  uint32_t plate = 0;
  Camera camera;
};

// A 2 m white box (ρ = 0.7); a 0.6 m × 0.4 m panel on the ceiling near one corner (Le = 6) and a
// dimmer, warmer 0.4 m square low on a side wall (Le = 3, 2, 1): the light bounced onto the plate
// comes mostly from one side. The plate: 0.3 m square, ρ = (0.8, 0.6, 0.4), centre (1, 0.7, 1),
// its normal tilted 35° from +z towards +y, its light from probes only (lightmapScale 0).
Material lambertian(glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.0f)) {
  Material m;
  m.albedo = albedo;
  m.emission = emission;
  return m;
}

PlateInABox plateInABox() {
  PlateInABox s;
  const Material wall = lambertian(glm::vec3(0.7f));
  // The box [0, 2]³, each face counter-clockwise seen from inside.
  addQuad(s.scene, {0, 0, 0}, {0, 0, 2}, {2, 0, 0}, wall);  // floor, +y
  addQuad(s.scene, {0, 2, 0}, {2, 0, 0}, {0, 0, 2}, wall);  // ceiling, −y
  addQuad(s.scene, {0, 0, 0}, {2, 0, 0}, {0, 2, 0}, wall);  // z = 0, +z
  addQuad(s.scene, {0, 0, 2}, {0, 2, 0}, {2, 0, 0}, wall);  // z = 2, −z
  addQuad(s.scene, {0, 0, 0}, {0, 2, 0}, {0, 0, 2}, wall);  // x = 0, +x
  addQuad(s.scene, {2, 0, 0}, {0, 0, 2}, {0, 2, 0}, wall);  // x = 2, −x
  // Just inside the ceiling, facing −y; and on the wall x = 2, facing −x.
  addQuad(s.scene, {0.2f, 1.999f, 0.2f}, {0.6f, 0, 0}, {0, 0, 0.4f},
          lambertian(glm::vec3(0.0f), glm::vec3(6.0f)));
  addQuad(s.scene, {1.999f, 0.1f, 0.6f}, {0, 0, 0.4f}, {0, 0.4f, 0},
          lambertian(glm::vec3(0.0f), glm::vec3(3.0f, 2.0f, 1.0f)));
  const float tilt = glm::radians(35.0f);
  const glm::vec3 centre(1.0f, 0.7f, 1.0f), u(0.3f, 0.0f, 0.0f);
  const glm::vec3 v = 0.3f * glm::vec3(0.0f, std::cos(tilt), -std::sin(tilt));
  addQuad(s.scene, centre - 0.5f * (u + v), u, v, lambertian({0.8f, 0.6f, 0.4f}));
  s.plate = static_cast<uint32_t>(s.scene.instances.size() - 1);
  s.scene.instances[s.plate].lightmapScale = 0.0f;
  s.camera.yfov = glm::radians(28.0f);
  s.camera.cameraToWorld =
      glm::inverse(glm::lookAt(glm::vec3(1.0f, 1.1f, 1.9f), centre, glm::vec3(0, 1, 0)));
  return s;
}

// Goal: the plate's pixels within 10% (mean |ΔY|/Y) of the tracer's, plus what the reference's
// own noise can add (indirect_accuracy.h).
TEST(ProbeAccuracy, ATiltedPlateLitByProbesMatchesThePathTracer) {
#ifdef __SANITIZE_ADDRESS__
  GTEST_SKIP() << "an accuracy measurement: run in the release build";
#endif
  const PlateInABox s = plateInABox();
  SceneBakeSettings settings = lightmapOnlySettings();
  settings.texelBudget = 4096;
  settings.maxSpp = 2048;
  settings.targetError = 0.05f;
  settings.denoise = false;
  const Bake baked = bakeScene(s.scene, settings).folder;
  ASSERT_TRUE(baked.probes.has_value());
  ASSERT_EQ(baked.probes->grids.size(), 1u);
  EXPECT_EQ(baked.probes->grids[0].instance, s.plate);
  testContext();
  constexpr int kSize = 48;
  RendererSettings indirect;
  indirect.mode = RenderMode::Indirect;
  ForwardRenderer renderer(s.scene, gl::shaderDirectory(), indirect, &baked);
  const Image rendered = renderAreaAveraged(renderer, s.camera, kSize, kSize, 4);
  const Reference reference = traceIndirectReference(s.scene, s.camera, kSize, kSize, 2048);

  const WorldGeometry geometry = flatten(s.scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  const PixelSurfaces surfaces = findPixelSurfaces(geometry, *kernel, s.camera, kSize, kSize);
  double error = 0.0, bias = 0.0, sigma = 0.0;
  std::size_t pixels = 0;
  for (std::size_t i = 0; i < surfaces.triangle.size(); ++i) {
    if (!surfaces.interior[i] || geometry.triangleInstance[surfaces.triangle[i]] != s.plate)
      continue;
    const double yt = luminance(reference.radiance.pixels[i]);
    const double yr = luminance(rendered.pixels[i]);
    ASSERT_GT(yt, 0.0);
    error += std::abs(yr - yt) / yt;
    bias += (yr - yt) / yt;
    sigma += luminance(glm::dvec3(reference.stdError.pixels[i])) / yt;
    ++pixels;
  }
  ASSERT_GT(pixels, 300u);  // the plate fills much of the 48 × 48 frame
  const double n = static_cast<double>(pixels);
  const double noise = std::sqrt(2.0 / 3.14159265358979) * sigma / n;
  std::printf(
      "probe-lit plate: mean |dY|/Y = %.4f over %zu pixels (bias %+.4f), reference noise "
      "allowance %.4f; %zu probes, estimated error %.4f\n",
      error / n, pixels, bias / n, noise, baked.probes->probes.size(),
      baked.manifest.probes ? baked.manifest.probes->meanRelativeError : -1.0);
  EXPECT_LE(error / n, 0.10 + noise);
}

}  // namespace
}  // namespace bounce::test
