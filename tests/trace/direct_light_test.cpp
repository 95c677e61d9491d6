// Direct light on a Lambertian plane against closed forms: delta lights (point, spot,
// directional) and a square area emitter with each light-transport strategy.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/light_falloff.h"
#include "support/form_factors.h"
#include "test_scenes.h"

namespace bounce {
namespace {

using test::addMaterial;
using test::addQuad;
using test::downOnto;
using test::parallelRectangleFormFactor;
using test::planeWorld;

constexpr double kPiD = 3.14159265358979323846;
const glm::dvec3 kPlaneAlbedo(0.5, 0.7, 0.3);

// Delta lights make the estimator deterministic (NEE only; the bounce rays escape), so the
// tolerance is float rounding: 1e-5 relative.
void expectRadiance(const PathTracer& tracer, const Ray& ray, glm::dvec3 expected) {
  const test::Estimate e = test::estimateLi(tracer, ray, 1u, 0u, 16);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(e.mean[c], expected[c], 1e-5 * expected[c] + 1e-12) << "channel " << c;
    EXPECT_LE(e.variance[c], 1e-12) << "a delta light's estimate has no variance";
  }
}

// Lo = ρ/π · I · cosθ / r² for a point light of intensity I at height h.
TEST(DirectLight, PointLightOverPlane) {
  test::World world = planeWorld(glm::vec3(kPlaneAlbedo));
  Light light;
  light.type = LightType::Point;
  light.position = {0, 0, 2};
  light.intensity = {10, 20, 5};
  world.scene.lights.push_back(light);
  world.build();
  const PathTracer tracer(world.scene, world.geometry, *world.kernel, TraceSettings{});
  for (double x : {0.0, 1.0, 3.0}) {
    const double y = 0.5;
    const double r2 = x * x + y * y + 4.0;
    const double cosTheta = 2.0 / std::sqrt(r2);
    expectRadiance(tracer, downOnto(x, y),
                   kPlaneAlbedo / kPiD * glm::dvec3(light.intensity) * cosTheta / r2);
  }
}

// Spot: I·t² with t = (cosα − cos outer)/(cos inner − cos outer) clamped, α the angle off the
// spot axis; inside the inner cone, in the penumbra and outside the outer cone.
TEST(DirectLight, SpotLightOverPlane) {
  test::World world = planeWorld(glm::vec3(kPlaneAlbedo));
  Light light;
  light.type = LightType::Spot;
  light.position = {0, 0, 2};
  light.direction = {0, 0, -1};
  light.intensity = {40, 30, 20};
  light.innerConeAngle = 0.3f;
  light.outerConeAngle = 0.6f;
  world.scene.lights.push_back(light);
  world.build();
  const PathTracer tracer(world.scene, world.geometry, *world.kernel, TraceSettings{});
  for (double alpha : {0.1, 0.45, 0.8}) {
    const double x = 2.0 * std::tan(alpha);
    const double r2 = x * x + 4.0;
    const double cosTheta = 2.0 / std::sqrt(r2);
    const double t =
        std::clamp((std::cos(alpha) - std::cos(0.6)) / (std::cos(0.3) - std::cos(0.6)), 0.0, 1.0);
    SCOPED_TRACE(alpha);
    expectRadiance(tracer, downOnto(x, 0.0),
                   kPlaneAlbedo / kPiD * glm::dvec3(light.intensity) * t * t * cosTheta / r2);
  }
}

// Directional: Lo = ρ/π · E · cosθ, E the irradiance at normal incidence.
TEST(DirectLight, DirectionalLightOverPlane) {
  test::World world = planeWorld(glm::vec3(kPlaneAlbedo));
  Light light;
  light.type = LightType::Directional;
  light.direction = glm::normalize(glm::vec3(1, 0, -2));
  light.irradiance = {3, 2, 1};
  world.scene.lights.push_back(light);
  // A black (ρ = 0, so no interreflection) blocker at z = 1 over x ∈ [−3, −2]: its shadow on
  // the plane is x ∈ [−2.5, −1.5].
  const uint32_t m = addMaterial(world.scene, glm::vec3(0.0f));
  addQuad(world.scene, {-3, -1, 1}, {-2, -1, 1}, {-2, 1, 1}, {-3, 1, 1}, m);
  world.build();
  const PathTracer tracer(world.scene, world.geometry, *world.kernel, TraceSettings{});
  const double cosTheta = 2.0 / std::sqrt(5.0);
  expectRadiance(tracer, downOnto(0.5, 0.5),
                 kPlaneAlbedo / kPiD * glm::dvec3(light.irradiance) * cosTheta);
  // In the blocker's shadow: radiance 0.
  const test::Estimate shadow = test::estimateLi(tracer, downOnto(-2.0, 0.0), 1u, 0u, 16);
  EXPECT_EQ(shadow.mean, glm::dvec3(0.0));
}

// A 1 m × 1 m emitter (radiance Le, facing down, albedo 0) 1 m over the plane: the plane
// reflects Lo = ρ · Le · F. Light sampling, BRDF sampling and MIS must all agree with it
// within 5 standard errors of the estimate (sample variance of the 4096 samples). Each
// (strategy, point) pair has its own sampler pattern, so their errors are independent.
TEST(DirectLight, SquareEmitterOverParallelPlaneWithEachStrategy) {
  test::World world = planeWorld(glm::vec3(kPlaneAlbedo));
  const glm::dvec3 le(2, 3, 4);
  const uint32_t light = addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(le));
  addQuad(world.scene, {-0.5f, -0.5f, 1}, {-0.5f, 0.5f, 1}, {0.5f, 0.5f, 1}, {0.5f, -0.5f, 1},
          light);
  world.build();
  uint32_t pattern = 0;
  for (LightStrategy strategy :
       {LightStrategy::LightOnly, LightStrategy::BrdfOnly, LightStrategy::Mis}) {
    TraceSettings settings;
    settings.strategy = strategy;
    const PathTracer tracer(world.scene, world.geometry, *world.kernel, settings);
    for (glm::dvec2 at : {glm::dvec2(0, 0), glm::dvec2(0.4, 0.3), glm::dvec2(1.5, 0.2)}) {
      ++pattern;
      const double f = parallelRectangleFormFactor(at.x, at.y, -0.5, 0.5, -0.5, 0.5, 1.0);
      const glm::dvec3 expected = kPlaneAlbedo * le * f;
      Ray ray = downOnto(at.x, at.y);
      ray.origin.z = 0.5f;  // below the emitter
      const test::Estimate e = test::estimateLi(tracer, ray, 3u + pattern, pattern, 4096);
      std::printf("strategy %d at (%.1f, %.1f): F = %.5f, Lo %.5f expected %.5f, SE %.2g\n",
                  static_cast<int>(strategy), at.x, at.y, f, e.mean.g, expected.g,
                  e.standardError().g);
      EXPECT_TRUE(test::agreeWithin(e.mean, e.standardError(), expected, glm::dvec3(0), 5.0))
          << "strategy " << static_cast<int>(strategy) << " at " << at.x << "," << at.y;
    }
  }
}

// MIS where the BRDF-sampled side carries much of the estimate: a 4 m × 4 m emitter only
// 0.3 m over the plane. Under it the cosine-weighted pdf (cosθ/π ≈ 0.3 near the normal) is far
// above the light's solid-angle pdf (r²/(A·cosθ') = 0.09/16 straight up), so the power
// heuristic gives most of the weight to the BRDF hits; towards the emitter's edges the two
// pdfs are comparable. A weight error on either side moves the MIS mean by that side's
// share: a 10% error on the BRDF-hit weight moves it by several percent, while 32768 samples
// keep MIS's standard error under 0.4% of ρ·Le·F (asserted; 5 SE < 2%), so the tolerance
// separates them. Light-only and BRDF-only must agree too (their SE is larger: light-only
// rarely samples the emitter's nearby centre well). Each (strategy, point) has its own
// sampler pattern, so the errors are independent.
TEST(DirectLight, LargeCloseEmitterMisMatchesFormFactor) {
  test::World world = planeWorld(glm::vec3(kPlaneAlbedo));
  const glm::dvec3 le(2, 3, 4);
  const double h = 0.3;
  const uint32_t light = addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(le));
  const auto z = static_cast<float>(h);
  addQuad(world.scene, {-2, -2, z}, {-2, 2, z}, {2, 2, z}, {2, -2, z}, light);
  world.build();
  uint32_t pattern = 100;
  for (LightStrategy strategy :
       {LightStrategy::Mis, LightStrategy::LightOnly, LightStrategy::BrdfOnly}) {
    TraceSettings settings;
    settings.strategy = strategy;
    const PathTracer tracer(world.scene, world.geometry, *world.kernel, settings);
    for (glm::dvec2 at : {glm::dvec2(0.5, 0.3), glm::dvec2(1.7, -1.2)}) {
      ++pattern;
      const double f = parallelRectangleFormFactor(at.x, at.y, -2, 2, -2, 2, h);
      const glm::dvec3 expected = kPlaneAlbedo * le * f;
      Ray ray = downOnto(at.x, at.y);
      ray.origin.z = 0.15f;  // below the emitter
      const test::Estimate e = test::estimateLi(tracer, ray, pattern, pattern, 32768);
      std::printf(
          "large emitter, strategy %d at (%.1f, %.1f): F = %.5f, Lo %.5f expected %.5f "
          "(%+.2f%%), SE %.2f%%\n",
          static_cast<int>(strategy), at.x, at.y, f, e.mean.g, expected.g,
          100.0 * (e.mean.g / expected.g - 1.0), 100.0 * e.standardError().g / expected.g);
      if (strategy == LightStrategy::Mis) {
        EXPECT_LT(e.standardError().g, 0.004 * expected.g) << "too few samples for a 10% error";
      }
      EXPECT_TRUE(test::agreeWithin(e.mean, e.standardError(), expected, glm::dvec3(0), 5.0))
          << "strategy " << static_cast<int>(strategy) << " at " << at.x << "," << at.y;
    }
  }
}

// The same emitter turned upside down (its front faces away from the plane): single-sided it
// lights nothing below; double-sided its back face emits too, giving ρ·Le·F again, with each
// strategy (5 standard errors).
TEST(DirectLight, OnlyDoubleSidedEmittersEmitFromTheirBackFace) {
  for (bool doubleSided : {false, true}) {
    test::World world = planeWorld(glm::vec3(kPlaneAlbedo));
    const glm::dvec3 le(2, 3, 4);
    const uint32_t light = addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(le), doubleSided);
    addQuad(world.scene, {-0.5f, -0.5f, 1}, {0.5f, -0.5f, 1}, {0.5f, 0.5f, 1}, {-0.5f, 0.5f, 1},
            light);
    world.build();
    for (LightStrategy strategy :
         {LightStrategy::LightOnly, LightStrategy::BrdfOnly, LightStrategy::Mis}) {
      TraceSettings settings;
      settings.strategy = strategy;
      const PathTracer tracer(world.scene, world.geometry, *world.kernel, settings);
      Ray ray = downOnto(0.4, 0.3);
      ray.origin.z = 0.5f;
      const test::Estimate e = test::estimateLi(tracer, ray, 5u, 0u, 2048);
      const glm::dvec3 expected =
          doubleSided
              ? kPlaneAlbedo * le * parallelRectangleFormFactor(0.4, 0.3, -0.5, 0.5, -0.5, 0.5, 1.0)
              : glm::dvec3(0.0);
      EXPECT_TRUE(test::agreeWithin(e.mean, e.standardError(), expected, glm::dvec3(0), 5.0))
          << "double-sided " << doubleSided << " strategy " << static_cast<int>(strategy);
      if (!doubleSided) {
        EXPECT_EQ(e.mean, glm::dvec3(0.0));
      }
    }
  }
}

// The baker's entry point: irradiance at a point, E = I·cosθ/r² under a point light (exact,
// deterministic) and E = π·L·F under the square emitter (5 standard errors).
TEST(DirectLight, IrradianceAtAPoint) {
  test::World world = planeWorld(glm::vec3(kPlaneAlbedo));
  Light light;
  light.position = {0, 0, 2};
  light.intensity = {10, 20, 5};
  world.scene.lights.push_back(light);
  world.build();
  const PathTracer pointTracer(world.scene, world.geometry, *world.kernel, TraceSettings{});
  SobolSampler sampler(1u, 0u);
  sampler.startSample(0);
  const glm::dvec3 e(pointTracer.irradiance({1.0f, 0.0f, 0.0f}, {0, 0, 1}, sampler));
  const double r2 = 5.0;
  const glm::dvec3 expected = glm::dvec3(light.intensity) * (2.0 / std::sqrt(r2)) / r2;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(e[c], expected[c], 1e-5 * expected[c]);

  test::World square = planeWorld(glm::vec3(kPlaneAlbedo));
  const glm::dvec3 le(2, 3, 4);
  addQuad(square.scene, {-0.5f, -0.5f, 1}, {-0.5f, 0.5f, 1}, {0.5f, 0.5f, 1}, {0.5f, -0.5f, 1},
          addMaterial(square.scene, glm::vec3(0.0f), glm::vec3(le)));
  square.build();
  const PathTracer tracer(square.scene, square.geometry, *square.kernel, TraceSettings{});
  const int n = 2048;
  glm::dvec3 mean(0.0), m2(0.0);
  SobolSampler pattern(4u, 9u);
  for (int i = 0; i < n; ++i) {
    pattern.startSample(static_cast<uint32_t>(i));
    const glm::dvec3 value(tracer.irradiance({0.4f, 0.3f, 0.0f}, {0, 0, 1}, pattern));
    const glm::dvec3 delta = value - mean;
    mean += delta / static_cast<double>(i + 1);
    m2 += delta * (value - mean);
  }
  const glm::dvec3 se = glm::sqrt(m2 / static_cast<double>(n - 1) / static_cast<double>(n));
  const glm::dvec3 exact =
      kPiD * le * parallelRectangleFormFactor(0.4, 0.3, -0.5, 0.5, -0.5, 0.5, 1.0);
  EXPECT_TRUE(test::agreeWithin(mean, se, exact, glm::dvec3(0.0), 5.0));
}

// Albedo × base colour texture at uv0 (bilinear, uv (0,0) at the top-left): at a texel's
// centre the lookup is that texel exactly. Directional light, so Lo = ρ·t/π·E·cosθ exactly.
TEST(DirectLight, AlbedoTextureMultipliesAlbedo) {
  test::World world;
  Texture texture;
  texture.width = 2;
  texture.height = 2;
  texture.texels = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};  // top row, then bottom row
  world.scene.textures.push_back(texture);
  const uint32_t m = addMaterial(world.scene, glm::vec3(0.5f));
  world.scene.materials[m].albedoTexture = 0;
  // A 2 m square at z = 0 with uv (0,0) at (−1, 1) (top-left) and (1,1) at (1, −1).
  addQuad(world.scene, {-1, 1, 0}, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, m);
  world.scene.meshes.back().uv0 = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = {0, 0, -1};
  sun.irradiance = glm::vec3(2.0f);
  world.scene.lights.push_back(sun);
  world.build();
  const PathTracer tracer(world.scene, world.geometry, *world.kernel, TraceSettings{});
  // Texel centres: uv (0.25, 0.25) is top-left texel (red) at (−0.5, 0.5); uv (0.75, 0.25)
  // top-right (green) at (0.5, 0.5); uv (0.25, 0.75) bottom-left (blue) at (−0.5, −0.5).
  const struct {
    glm::dvec2 at;
    glm::dvec3 texel;
  } cases[] = {{{-0.5, 0.5}, {1, 0, 0}}, {{0.5, 0.5}, {0, 1, 0}}, {{-0.5, -0.5}, {0, 0, 1}}};
  for (const auto& c : cases) {
    const test::Estimate e = test::estimateLi(tracer, downOnto(c.at.x, c.at.y), 1u, 0u, 4);
    const glm::dvec3 expected = 0.5 * c.texel / kPiD * 2.0;
    for (int ch = 0; ch < 3; ++ch)
      EXPECT_NEAR(e.mean[ch], expected[ch], 1e-5) << c.at.x << "," << c.at.y;
  }
}

}  // namespace
}  // namespace bounce
