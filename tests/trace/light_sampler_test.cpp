// One light per vertex, picked by power (trace/light_sampler.h), against closed forms with many
// unequal lights: 20 point lights of intensities spread over 40× at different heights and
// offsets over a plane (E = Σ I·cosθ/d²), every punctual kind plus virtual point lights, and a
// dim square emitter among bright point lights, where the BRDF-hit MIS weight must carry the
// pick pmf of the area set. Irradiance estimates are Monte Carlo: tolerances are 5 standard
// errors estimated from the samples.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "image/luminance.h"
#include "support/form_factors.h"
#include "test_scenes.h"

namespace bounce {
namespace {

using test::addMaterial;
using test::addQuad;
using test::planeWorld;

constexpr double kPiD = std::numbers::pi;

// 20 point lights, intensities 1..40 W/sr (unequal per channel), at heights 1.5..6 m and up to
// 8 m sideways: a deterministic spread (golden-angle spiral).
std::vector<Light> twentyPointLights() {
  std::vector<Light> lights;
  for (int i = 0; i < 20; ++i) {
    Light l;
    l.type = LightType::Point;
    const double a = 2.39996 * i, r = 0.4 * i;
    l.position = glm::vec3(static_cast<float>(r * std::cos(a)), static_cast<float>(r * std::sin(a)),
                           static_cast<float>(1.5 + 0.23 * i));
    const float s = 1.0f + static_cast<float>((i * 7) % 20) * 2.0f;
    l.intensity = glm::vec3(s, 0.5f * s + 1.0f, 2.0f + 0.1f * s);
    lights.push_back(l);
  }
  return lights;
}

// E = Φ/π · cosθ_vpl · cosθ_x / d² (bake_folder/vpl.h) on the +z plane at x.
glm::dvec3 vplIrradiance(const Vpl& v, glm::dvec3 x) {
  const glm::dvec3 d = glm::dvec3(v.position) - x;
  const double d2 = glm::dot(d, d);
  const double cosX = d.z / std::sqrt(d2);
  const double cosV = glm::dot(glm::normalize(glm::dvec3(v.normal)), -d) / std::sqrt(d2);
  if (cosX <= 0.0 || cosV <= 0.0) return glm::dvec3(0.0);
  return glm::dvec3(v.flux) / kPiD * cosV * cosX / d2;
}

// Rec. 709 luminance, the weight the sampler's powers use.
double rec709Luminance(glm::vec3 c) {
  return luminance(glm::dvec3(c));
}

const glm::dvec3 kPoints[] = {{0.0, 0.0, 0.0}, {1.7, -0.6, 0.0}, {-3.0, 2.5, 0.0}};

TEST(LightSampler, PicksInProportionToPower) {
  test::World world = planeWorld(glm::vec3(0.5f));  // albedo irrelevant: E is measured
  world.scene.lights = twentyPointLights();
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(0.3f, 0.2f, -1.0f));
  sun.irradiance = glm::vec3(0.01f);
  world.scene.lights.push_back(sun);
  world.build();
  const EmitterTable emitters(world.scene, world.geometry);
  const LightSampler sampler(world.scene, world.geometry, emitters, {});
  ASSERT_EQ(sampler.size(), 21u);
  // Scene radius: the 200 m square's half diagonal.
  EXPECT_NEAR(sampler.sceneRadius(), 100.0 * std::sqrt(2.0), 1e-3);
  double total = 0.0;
  std::vector<double> power;
  for (const Light& l : world.scene.lights) {
    const double lum = l.type == LightType::Directional
                           ? rec709Luminance(l.irradiance) * kPiD * 2.0 * 100.0 * 100.0
                           : 4.0 * kPiD * rec709Luminance(l.intensity);
    power.push_back(lum);
    total += lum;
  }
  // Stratified u: the pick frequencies equal the pmf to within 1/N, and the pmf the sampler
  // reports is the frequency.
  const int n = 1 << 16;
  std::vector<int> count(power.size(), 0);
  std::vector<float> reported(power.size(), 0.0f);
  for (int i = 0; i < n; ++i) {
    const LightPick p = sampler.pick((static_cast<float>(i) + 0.5f) / static_cast<float>(n));
    ASSERT_EQ(p.kind, LightKind::Punctual);
    ++count[p.index];
    reported[p.index] = p.pmf;
  }
  for (std::size_t i = 0; i < power.size(); ++i) {
    EXPECT_NEAR(count[i] / static_cast<double>(n), power[i] / total, 2.0 / n) << "light " << i;
    EXPECT_NEAR(reported[i], power[i] / total, 1e-6 + 1e-5 * power[i] / total) << "light " << i;
  }
}

TEST(LightSampler, TwentyUnequalPointLightsOverAPlane) {
  test::World world = planeWorld(glm::vec3(0.5f));  // albedo irrelevant: E is measured
  world.scene.lights = twentyPointLights();
  world.build();
  const PathTracer tracer(world.scene, world.geometry, *world.kernel, TraceSettings{});
  for (const glm::dvec3& x : kPoints) {
    glm::dvec3 exact(0.0);
    for (const Light& l : world.scene.lights) exact += test::punctualIrradiance(l, x);
    const test::Estimate e =
        test::estimateIrradiance(tracer, glm::vec3(x), {0, 0, 1}, 3u, 7u, 8192);
    std::printf("20 point lights at (%.1f, %.1f): E = %.5f ± %.5f, exact %.5f W/m² (green)\n", x.x,
                x.y, e.mean.g, e.standardError().g, exact.g);
    EXPECT_TRUE(test::agreeWithin(e.mean, e.standardError(), exact, glm::dvec3(0.0), 5.0));
  }
}

// Every kind at once: the 20 point lights, a tilted spot, a directional light and three VPLs
// (for checks: the tracer samples them as cosine emitters, bake_folder/vpl.h).
TEST(LightSampler, EveryPunctualKindAndVirtualPointLights) {
  test::World world = planeWorld(glm::vec3(0.5f));  // albedo irrelevant: E is measured
  world.scene.lights = twentyPointLights();
  Light spot;
  spot.type = LightType::Spot;
  spot.position = {1, -1, 3};
  spot.direction = glm::normalize(glm::vec3(0.2f, 0.1f, -1.0f));
  spot.intensity = {80, 60, 40};
  spot.innerConeAngle = 0.3f;
  spot.outerConeAngle = 0.9f;
  world.scene.lights.push_back(spot);
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(1.0f, 0.3f, -2.0f));
  sun.irradiance = {0.3f, 0.2f, 0.1f};
  world.scene.lights.push_back(sun);
  const std::vector<Vpl> vpls = {
      {{0.5f, 0.5f, 1.0f}, glm::normalize(glm::vec3(0.3f, 0.0f, -1.0f)), {30, 10, 5}},
      {{-2.0f, 1.0f, 0.7f}, glm::normalize(glm::vec3(-0.5f, 0.5f, -1.0f)), {2, 8, 4}},
      {{-2.5f, 2.0f, 2.0f}, {0, 0, -1}, {50, 50, 60}}};
  world.build();
  const PathTracer tracer(world.scene, world.geometry, *world.kernel, TraceSettings{}, vpls);
  for (const glm::dvec3& x : kPoints) {
    glm::dvec3 exact(0.0);
    for (const Light& l : world.scene.lights) {
      exact += l.type == LightType::Directional
                   ? glm::dvec3(l.irradiance) * std::max(0.0, -glm::dvec3(l.direction).z)
                   : test::punctualIrradiance(l, x);
    }
    for (const Vpl& v : vpls) exact += vplIrradiance(v, x);
    const test::Estimate e =
        test::estimateIrradiance(tracer, glm::vec3(x), {0, 0, 1}, 5u, 11u, 8192);
    std::printf("every kind at (%.1f, %.1f): E = %.5f ± %.5f, exact %.5f W/m² (green)\n", x.x, x.y,
                e.mean.g, e.standardError().g, exact.g);
    EXPECT_TRUE(test::agreeWithin(e.mean, e.standardError(), exact, glm::dvec3(0.0), 5.0));
  }
}

// A dim 1 m square emitter 1 m above the plane among 20 bright point lights: the area set's
// pick pmf is ~0.3%, so a BRDF-hit MIS weight without it nearly zeroes the emitter's share
// (about half of E at the point under it). E = π·Le·F + Σ I cosθ/d², under each strategy.
TEST(LightSampler, DimAreaLightAmongBrightPointLightsKeepsMisRight) {
  test::World world = planeWorld(glm::vec3(0.5f));  // albedo irrelevant: E is measured
  world.scene.lights = twentyPointLights();
  for (Light& l : world.scene.lights) l.position.z += 4.0f;  // far: little E, much power
  const glm::dvec3 le(6, 5, 4);
  addQuad(world.scene, {-0.5f, -0.5f, 1}, {-0.5f, 0.5f, 1}, {0.5f, 0.5f, 1}, {0.5f, -0.5f, 1},
          addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(le)));
  world.build();
  for (LightStrategy strategy :
       {LightStrategy::Mis, LightStrategy::LightOnly, LightStrategy::BrdfOnly}) {
    TraceSettings settings;
    settings.strategy = strategy;
    settings.paths = PathSet::DirectOnly;
    const PathTracer tracer(world.scene, world.geometry, *world.kernel, settings);
    ASSERT_GT(tracer.lightSampler().areaPmf(), 0.0f);
    ASSERT_LT(tracer.lightSampler().areaPmf(), 0.01f);
    for (const glm::dvec3& x : {glm::dvec3(0.1, 0.2, 0.0), glm::dvec3(0.9, -0.4, 0.0)}) {
      glm::dvec3 exact =
          kPiD * le * test::parallelRectangleFormFactor(x.x, x.y, -0.5, 0.5, -0.5, 0.5, 1.0);
      const double area = exact.g;
      for (const Light& l : world.scene.lights) {
        // The emitter square (z = 1, |x|,|y| ≤ 0.5) shadows the lights behind it.
        const glm::dvec3 d = glm::dvec3(l.position) - x;
        const glm::dvec3 crossing = x + d * (1.0 / d.z);
        if (std::abs(crossing.x) <= 0.5 && std::abs(crossing.y) <= 0.5) continue;
        exact += test::punctualIrradiance(l, x);
      }
      const test::Estimate e =
          test::estimateIrradiance(tracer, glm::vec3(x), {0, 0, 1}, 9u, 2u, 16384);
      std::printf("strategy %d at (%.1f, %.1f): E = %.5f ± %.5f, exact %.5f (area %.5f) W/m²\n",
                  static_cast<int>(strategy), x.x, x.y, e.mean.g, e.standardError().g, exact.g,
                  area);
      EXPECT_TRUE(test::agreeWithin(e.mean, e.standardError(), exact, glm::dvec3(0.0), 5.0))
          << "strategy " << static_cast<int>(strategy);
    }
  }
}

}  // namespace
}  // namespace bounce
