// Energy of the VPL set against closed forms. In a closed box whose
// every surface has albedo ρ, all light a source emits (Φ₀) lands on the walls, so the flux
// leaving them after exactly k reflections is Φ₀·ρ^k: the VPLs of bounce k must sum to it.
// In an open scene the first bounce alone has a closed form: ρ × the flux that reaches the
// receiver. Tolerances: float rounding where every path carries the same flux, else 5 standard
// errors from the per-path contributions (VplSet::fluxPerBounceError).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene/static_scene.h"
#include "trace/test_scenes.h"
#include "vpl/vpl_generate.h"

namespace bounce {
namespace {

using test::addInwardBox;
using test::addMaterial;
using test::addQuad;

constexpr double kPiD = std::numbers::pi;
const glm::vec3 kRho(0.5f, 0.6f, 0.7f);

VplSettings fixedPaths(int paths) {
  VplSettings s;
  s.maxVpls = 1 << 22;
  s.minPaths = paths;
  s.relativeError = 1.0f;  // stop at minPaths
  s.seed = 7;
  return s;
}

void expectClose(glm::dvec3 got, glm::dvec3 se, glm::dvec3 exact, double relRounding,
                 const std::string& what) {
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(got[c], exact[c], 5.0 * se[c] + relRounding * exact[c]) << what << " channel " << c;
  }
}

// Point light in a closed box of albedo ρ: Φ₀ = 4πI. Bounces 1 and 2 carry the same flux on
// every path (the roulette starts after bounce 2), so they are exact up to float rounding.
TEST(VplEnergy, ClosedBoxPointLightFluxPerBounceIsPhi0RhoK) {
  test::World world;
  addInwardBox(world.scene, glm::vec3(-1.0f), glm::vec3(1.0f), addMaterial(world.scene, kRho));
  Light light;
  light.position = {0.2f, -0.1f, 0.3f};
  light.intensity = {1, 2, 3};
  world.scene.lights.push_back(light);
  world.build();
  const VplSet set = generateVpls(world.scene, world.geometry, *world.kernel, fixedPaths(8192));
  ASSERT_EQ(set.paths, 8192u);
  const glm::dvec3 phi0 = 4.0 * kPiD * glm::dvec3(light.intensity);
  glm::dvec3 rhoK(1.0);
  for (int k = 1; k <= 6; ++k) {
    rhoK *= glm::dvec3(kRho);
    const glm::dvec3 exact = phi0 * rhoK;
    std::printf("bounce %d: Σ Φ = %.5f ± %.5f, Φ0·ρ^k = %.5f W (green)\n", k,
                set.fluxPerBounce[k - 1].g, set.fluxPerBounceError[k - 1].g, exact.g);
    expectClose(set.fluxPerBounce[k - 1], set.fluxPerBounceError[k - 1], exact, 1e-4,
                "bounce " + std::to_string(k));
    if (k <= 2) {
      for (int c = 0; c < 3; ++c) EXPECT_LT(set.fluxPerBounceError[k - 1][c], 1e-6 * exact[c]);
    }
  }
  // No VPL at the light: every one lies on a wall (|coordinate| = 1 on some axis).
  for (const Vpl& v : set.vpls) {
    const float m =
        std::max({std::abs(v.position.x), std::abs(v.position.y), std::abs(v.position.z)});
    ASSERT_NEAR(m, 1.0f, 1e-4f) << "a VPL off the walls";
  }
  EXPECT_EQ(set.bounce.size(), set.vpls.size());
}

// The point light's closed box with base-colour textured walls: 256 × 256 texels in stripes,
// every 4th column b and the others a, over each 2 m face (a period of 3.1 cm, against the
// irradiance that varies on the scale of the light's distance to the walls, ≥ 0.7 m). What the
// walls re-emit is then that of the stripes' area mean ρ̄ = (3a + b)/4: Φ₀·ρ̄ after one
// reflection and Φ₀·ρ̄² after two, up to a bias second order in period/distance (< 0.1%).
// Per-path flux now varies with the texel hit, so the tolerance is the estimator's.
TEST(VplEnergy, TexturedClosedBoxReflectsTheTexturesMeanColour) {
  const glm::vec3 a(0.9f, 0.1f, 0.6f), b(0.1f, 0.5f, 0.2f);
  test::World world;
  test::addInwardTexturedBox(world.scene, glm::vec3(-1.0f), glm::vec3(1.0f),
                             addMaterial(world.scene, glm::vec3(1.0f)), test::stripedTexture(a, b));
  Light light;
  light.position = {0.2f, -0.1f, 0.3f};
  light.intensity = {1, 2, 3};
  world.scene.lights.push_back(light);
  world.build();
  const VplSet set = generateVpls(world.scene, world.geometry, *world.kernel, fixedPaths(16384));
  const glm::dvec3 phi0 = 4.0 * kPiD * glm::dvec3(light.intensity);
  const glm::dvec3 rho = glm::dvec3(3.0f * a + b) * 0.25;
  std::printf("textured: bounce 1 %.4f ± %.4f vs %.4f, bounce 2 %.4f ± %.4f vs %.4f W (red)\n",
              set.fluxPerBounce[0].r, set.fluxPerBounceError[0].r, (phi0 * rho).r,
              set.fluxPerBounce[1].r, set.fluxPerBounceError[1].r, (phi0 * rho * rho).r);
  expectClose(set.fluxPerBounce[0], set.fluxPerBounceError[0], phi0 * rho, 1e-3, "bounce 1");
  expectClose(set.fluxPerBounce[1], set.fluxPerBounceError[1], phi0 * rho * rho, 1e-3, "bounce 2");
}

// A tilted, double-sided square emitter and a point light in the same box (all surfaces,
// the emitter too, of albedo ρ): Φ₀ = 2π·Le·A + 4πI; bounce 1 = Φ₀ρ in expectation (the light
// pick by power and the face pick add noise per channel), bounce 2 = Φ₀ρ².
TEST(VplEnergy, ClosedBoxAreaAndPointLightsMixed) {
  test::World world;
  const uint32_t wall = addMaterial(world.scene, kRho);
  addInwardBox(world.scene, glm::vec3(-1.0f), glm::vec3(1.0f), wall);
  const glm::vec3 le(3.0f, 1.0f, 0.5f);
  // 0.6 m × 0.5 m, tilted about x.
  addQuad(world.scene, {-0.3f, -0.25f, 0.4f}, {0.3f, -0.25f, 0.4f}, {0.3f, 0.2f, 0.6179f},
          {-0.3f, 0.2f, 0.6179f}, addMaterial(world.scene, kRho, le, true));
  const double area = 0.6 * std::sqrt(0.45 * 0.45 + 0.2179 * 0.2179);
  Light light;
  light.position = {-0.5f, 0.4f, -0.2f};
  light.intensity = {0.2f, 0.5f, 0.3f};
  world.scene.lights.push_back(light);
  world.build();
  const VplSet set = generateVpls(world.scene, world.geometry, *world.kernel, fixedPaths(16384));
  const glm::dvec3 phi0 =
      2.0 * kPiD * area * glm::dvec3(le) + 4.0 * kPiD * glm::dvec3(light.intensity);
  const glm::dvec3 rho(kRho);
  std::printf("bounce 1: %.5f ± %.5f vs %.5f; bounce 2: %.5f ± %.5f vs %.5f W (red)\n",
              set.fluxPerBounce[0].r, set.fluxPerBounceError[0].r, (phi0 * rho).r,
              set.fluxPerBounce[1].r, set.fluxPerBounceError[1].r, (phi0 * rho * rho).r);
  expectClose(set.fluxPerBounce[0], set.fluxPerBounceError[0], phi0 * rho, 1e-4, "bounce 1");
  expectClose(set.fluxPerBounce[1], set.fluxPerBounceError[1], phi0 * rho * rho, 1e-4, "bounce 2");
}

// Open scene: a 6 m square floor of albedo ρ; what the first bounce re-emits is ρ × the flux
// reaching it. Point light at height h: Φ = I·Ω, Ω = 4·asin(a²/(a² + h²)) for the square of
// half-side a centred under it. Spot (axis down, cone inside the floor): Φ = I·2π[(1 − cos
// inner) + (cos inner − cos outer)/3] (the t² falloff, linear in cosθ, integrated). Directional
// at angle θ: Φ = E·cosθ·(2a)².
TEST(VplEnergy, OpenFloorFirstBounceIsRhoTimesTheFluxItReceives) {
  const float a = 3.0f;
  const auto floorWorld = [&] {
    test::World world;
    addQuad(world.scene, {-a, -a, 0}, {a, -a, 0}, {a, a, 0}, {-a, a, 0},
            addMaterial(world.scene, kRho));
    return world;
  };
  const glm::dvec3 rho(kRho);
  {
    test::World world = floorWorld();
    Light light;
    light.position = {0, 0, 2};
    light.intensity = {1, 2, 3};
    world.scene.lights.push_back(light);
    world.build();
    const VplSet set = generateVpls(world.scene, world.geometry, *world.kernel, fixedPaths(8192));
    const double omega = 4.0 * std::asin(9.0 / (9.0 + 4.0));
    const glm::dvec3 exact = rho * glm::dvec3(light.intensity) * omega;
    std::printf("point: %.5f ± %.5f vs %.5f W\n", set.fluxPerBounce[0].g,
                set.fluxPerBounceError[0].g, exact.g);
    expectClose(set.fluxPerBounce[0], set.fluxPerBounceError[0], exact, 1e-4, "point");
    EXPECT_EQ(set.fluxPerBounce[1], glm::dvec3(0.0)) << "a lone floor reflects nothing onto itself";
  }
  {
    test::World world = floorWorld();
    Light light;
    light.type = LightType::Spot;
    light.position = {0.2f, -0.1f, 1.0f};
    light.direction = {0, 0, -1};
    light.intensity = {4, 2, 1};
    light.innerConeAngle = 0.3f;
    light.outerConeAngle = 0.8f;
    world.scene.lights.push_back(light);
    world.build();
    const VplSet set = generateVpls(world.scene, world.geometry, *world.kernel, fixedPaths(8192));
    const double ci = std::cos(0.3), co = std::cos(0.8);
    const glm::dvec3 exact =
        rho * glm::dvec3(light.intensity) * 2.0 * kPiD * ((1.0 - ci) + (ci - co) / 3.0);
    std::printf("spot: %.5f ± %.5f vs %.5f W\n", set.fluxPerBounce[0].g,
                set.fluxPerBounceError[0].g, exact.g);
    expectClose(set.fluxPerBounce[0], set.fluxPerBounceError[0], exact, 1e-4, "spot");
  }
  {
    test::World world = floorWorld();
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.5f, 0.2f, -1.0f));
    sun.irradiance = {2, 3, 1};
    world.scene.lights.push_back(sun);
    world.build();
    const VplSet set = generateVpls(world.scene, world.geometry, *world.kernel, fixedPaths(8192));
    const glm::dvec3 exact =
        rho * glm::dvec3(sun.irradiance) * static_cast<double>(-sun.direction.z) * 36.0;
    std::printf("directional: %.5f ± %.5f vs %.5f W\n", set.fluxPerBounce[0].g,
                set.fluxPerBounceError[0].g, exact.g);
    expectClose(set.fluxPerBounce[0], set.fluxPerBounceError[0], exact, 1e-4, "directional");
  }
}

// The set is a function of the seed only: bit-identical at 1 and 2 threads.
TEST(VplGenerate, DeterministicAtAnyThreadCount) {
  test::World world;
  addInwardBox(world.scene, glm::vec3(-1.0f), glm::vec3(1.0f), addMaterial(world.scene, kRho));
  Light light;
  light.position = {0.2f, -0.1f, 0.3f};
  light.intensity = {1, 2, 3};
  world.scene.lights.push_back(light);
  world.build();
  VplSettings s = fixedPaths(2048);
  s.threads = 1;
  const VplSet one = generateVpls(world.scene, world.geometry, *world.kernel, s);
  s.threads = 2;
  const VplSet two = generateVpls(world.scene, world.geometry, *world.kernel, s);
  ASSERT_EQ(one.vpls.size(), two.vpls.size());
  for (std::size_t i = 0; i < one.vpls.size(); ++i) {
    ASSERT_EQ(one.vpls[i].position, two.vpls[i].position);
    ASSERT_EQ(one.vpls[i].normal, two.vpls[i].normal);
    ASSERT_EQ(one.vpls[i].flux, two.vpls[i].flux);
  }
}

// The count rule: the cap is never exceeded; with a loose error target generation stops at the
// first batch past minPaths; a tight one runs until the cap.
TEST(VplGenerate, CountFollowsTheCapAndTheErrorTarget) {
  test::World world;
  addInwardBox(world.scene, glm::vec3(-1.0f), glm::vec3(1.0f), addMaterial(world.scene, kRho));
  Light light;
  light.intensity = {1, 1, 1};
  world.scene.lights.push_back(light);
  world.build();
  VplSettings s;
  s.maxVpls = 3000;
  s.relativeError = 1e-6f;
  const VplSet capped = generateVpls(world.scene, world.geometry, *world.kernel, s);
  EXPECT_LE(capped.vpls.size(), 3000u);
  EXPECT_GT(capped.vpls.size(), 3000u - 20u) << "paths are kept up to the last that fits";
  s.maxVpls = 1 << 20;
  s.relativeError = 0.5f;
  s.minPaths = 1;
  const VplSet loose = generateVpls(world.scene, world.geometry, *world.kernel, s);
  EXPECT_EQ(loose.paths, static_cast<uint64_t>(kVplBatch));
  EXPECT_LE(loose.relativeError, 0.5);
}

// Dynamic instances are left out of the VPL paths (staticScene): the VPLs of a floor under a
// point light with a dynamic quad hovering between them are those of the floor alone, bit for
// bit; with the quad kept, some light lands on it instead (the check that the quad matters).
TEST(VplGenerate, DynamicInstancesNeitherHoldVplsNorShadowThem) {
  test::World bare;
  addQuad(bare.scene, {-3, -3, 0}, {3, -3, 0}, {3, 3, 0}, {-3, 3, 0},
          addMaterial(bare.scene, kRho));
  Light light;
  light.position = {0, 0, 2};
  light.intensity = {1, 1, 1};
  bare.scene.lights.push_back(light);
  test::World withQuad;
  withQuad.scene = bare.scene;
  // Facing down, 1 m above the floor under the light.
  addQuad(withQuad.scene, {-0.5f, -0.5f, 1}, {-0.5f, 0.5f, 1}, {0.5f, 0.5f, 1}, {0.5f, -0.5f, 1},
          addMaterial(withQuad.scene, glm::vec3(0.8f)));
  withQuad.scene.instances.back().mobility = Mobility::Dynamic;
  test::World statics;
  statics.scene = staticScene(withQuad.scene);
  ASSERT_EQ(statics.scene.instances.size(), bare.scene.instances.size());
  bare.build();
  withQuad.build();
  statics.build();
  const VplSettings s = fixedPaths(2048);
  const VplSet a = generateVpls(bare.scene, bare.geometry, *bare.kernel, s);
  const VplSet b = generateVpls(statics.scene, statics.geometry, *statics.kernel, s);
  const VplSet all = generateVpls(withQuad.scene, withQuad.geometry, *withQuad.kernel, s);
  ASSERT_EQ(a.vpls.size(), b.vpls.size());
  for (std::size_t i = 0; i < a.vpls.size(); ++i) {
    ASSERT_EQ(a.vpls[i].position, b.vpls[i].position);
    ASSERT_EQ(a.vpls[i].flux, b.vpls[i].flux);
  }
  int onQuad = 0;
  for (const Vpl& v : all.vpls) onQuad += v.position.z > 0.5f ? 1 : 0;
  EXPECT_GT(onQuad, 0) << "the kept quad should have received light";
}

}  // namespace
}  // namespace bounce
