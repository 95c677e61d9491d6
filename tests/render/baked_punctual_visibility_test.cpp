// The renderer's baked visibility of static punctual lights (shaders/lights.glsl,
// punctualVisibility) against closed forms, on synthetic bakes: a floor texel's V scales the
// light's exact irradiance I·cosθ/r² (the frame without a bake is that irradiance exactly);
// V is the smaller of the baked one and the shadow map's (the shared slot only without a map);
// a light that moves (mobility dynamic) or was moved since the bake (setLight) ignores the bake.
// The first case is drawn both ways a lightmapped pixel can get the lamp: evaluated per pixel
// (--live-static-lights) and read from the texels (render/static_direct_texels.h), which
// interpolate E bilinearly: E = I·h/(h² + ρ²)^{3/2} of a lamp at h = 0.7 m has a relative
// curvature of at most 3/h² ≈ 6.1 m⁻² along each axis, so over texels of 1/32 m the
// interpolation is off by at most 2 · h_t²/8 · 6.1 ≈ 1.5e-3 of E: tolerance 3e-3 (live 1e-3).
#include <gtest/gtest.h>

#include "lightmap_scenes.h"
#include "shadow_scenes.h"
#include "test_scenes.h"

namespace bounce::test {
namespace {

constexpr int kSize = 32;

// A 1 m floor at y = 0 (atlas u = x + ½, v = z + ½) under a point light 0.7 m up, off-centre so
// that cosθ/r² varies over the floor; seen from 1 m above.
Scene floorUnderLamp(Mobility mobility) {
  Scene scene;
  Material floor;
  floor.name = "floor";
  floor.albedo = glm::vec3(0.6f);
  addQuad(scene, {-0.5f, 0, 0.5f}, {1, 0, 0}, {0, 0, -1}, floor);
  Light lamp = pointAt({0.15f, 0.7f, -0.1f}, 2.0f);
  lamp.mobility = mobility;
  scene.lights.push_back(lamp);
  return scene;
}

// A bake with a black lightmap, no area lights and every texel naming the lamp (punctual
// light 0, visibility index 0) with V = `v`, or with `shared` only its "every other light" slot.
Bake lampBake(const Scene& scene, float v, bool shared = false) {
  Bake bake;
  bake.layout.width = bake.layout.height = kSize;
  bake.layout.texelSize = 1.0f / kSize;
  const InstanceLightmapUv region = unitFloorRegion(scene);
  bake.layout.instances = {region};
  bake.irradiance = Image(kSize, kSize);
  bake.manifest = minimalManifest(scene);
  BakedVisibility visibility;
  visibility.width = visibility.height = kSize;
  visibility.lightCount = 0;
  visibility.punctualCount = 1;
  TexelVisibility texel;
  texel.light[0] = shared ? kOtherLights : visibility.punctualIndex(0);
  texel.visible[0] = v;
  visibility.texels.assign(kSize * kSize, texel);
  bake.visibility = visibility;
  return bake;
}

struct Frames {
  Image open, baked;
};

// The direct frame without a bake and with `bake`, shadow maps on or off; `moveTo`, when set,
// moves the lamp there (ForwardRenderer::setLight) before both frames.
Frames frames(const Scene& scene, const Bake& bake, bool shadowMaps,
              std::optional<glm::vec3> moveTo = std::nullopt, bool texels = true) {
  testContext();
  RendererSettings settings;
  settings.mode = RenderMode::Direct;
  settings.shadows.enabled = shadowMaps;
  settings.precomputedStaticDirect = texels;
  Frames f;
  for (const Bake* b : {static_cast<const Bake*>(nullptr), &bake}) {
    ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, b);
    if (moveTo) {
      Light moved = scene.lights[0];
      moved.position = *moveTo;
      renderer.setLight(0, moved);
    }
    (b ? f.baked : f.open) = renderer.renderImage(downCamera(1.0f), kSize, kSize);
  }
  return f;
}

// The ratio baked / open over the floor (the frame's border rows left out), expected everywhere.
void expectRatio(const Frames& f, float expected, const char* what, float tolerance = 1e-3f) {
  int checked = 0;
  for (int y = 2; y < kSize - 2; ++y)
    for (int x = 2; x < kSize - 2; ++x) {
      const float open = f.open.at(x, y).g;
      ASSERT_GT(open, 0.0f) << what << " at " << x << "," << y;
      EXPECT_NEAR(f.baked.at(x, y).g / open, expected, tolerance)
          << what << " at " << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 500) << what;
}

TEST(BakedPunctualVisibility, ATexelsVisibleFractionScalesTheLampsExactIrradiance) {
  const Scene scene = floorUnderLamp(Mobility::Static);
  for (const bool texels : {false, true})
    for (const float v : {0.0f, 0.3f, 1.0f}) {
      const Bake bake = lampBake(scene, v);
      const float tolerance = texels ? 3e-3f : 1e-3f;
      expectRatio(frames(scene, bake, false, std::nullopt, texels), v,
                  texels ? "shadow maps off, texels" : "shadow maps off", tolerance);
      // Nothing casts a shadow: the lamp's cube sees the floor lit, so V = min(1, V_baked).
      expectRatio(frames(scene, bake, true, std::nullopt, texels), v,
                  texels ? "shadow maps on, texels" : "shadow maps on", tolerance);
    }
}

// The shared slot's V mixes other lights' visibility (exact only for their weighted sum): a lamp
// with a shadow map ignores it, one without takes it as the area lights do. A baked lamp has a
// map only while something dynamic is in its reach (shadow_pass.h): here a box under the floor,
// hidden from the camera and casting nothing on the floor.
TEST(BakedPunctualVisibility, TheSharedSlotShadowsOnlyALampWithoutAMap) {
  Scene scene = floorUnderLamp(Mobility::Static);
  Material grey;
  grey.name = "box";
  grey.albedo = glm::vec3(0.5f);
  addBox(scene, {-0.1f, -0.3f, -0.1f}, {0.1f, -0.1f, 0.1f}, grey);
  scene.instances.back().mobility = Mobility::Dynamic;
  const Bake bake = lampBake(scene, 0.2f, true);
  expectRatio(frames(scene, bake, true), 1.0f, "with its cube");
  expectRatio(frames(scene, bake, false), 0.2f, "without a map");
}

TEST(BakedPunctualVisibility, ALightThatMovesOrWasMovedIgnoresTheBake) {
  const Scene dynamicLamp = floorUnderLamp(Mobility::Dynamic);
  expectRatio(frames(dynamicLamp, lampBake(dynamicLamp, 0.3f), false), 1.0f, "mobility dynamic");
  const Scene staticLamp = floorUnderLamp(Mobility::Static);
  const Bake bake = lampBake(staticLamp, 0.3f);
  expectRatio(frames(staticLamp, bake, false, glm::vec3(-0.1f, 0.8f, 0.2f)), 1.0f, "moved");
  // Moved back to where the bake saw it, the bake holds again.
  expectRatio(frames(staticLamp, bake, false, staticLamp.lights[0].position), 0.3f, "moved back");
}

// A dynamic lamp listed before a static one the texels hold: the lit pass walks a cluster's
// list from the end and stops at the first precomputed light, so the lists must put those
// first (PunctualLights::listOrder), whatever the scene's order. The texel frame must hold both
// lamps (against the live frame, the texel tolerance above), and a lightmapped pixel evaluates
// only the dynamic one (the cost view). Injected: the lists in ascending order: the dynamic lamp
// is dropped and the test fails.
TEST(BakedPunctualVisibility, ADynamicLampListedBeforeAPrecomputedOneIsStillDrawn) {
  Scene scene = floorUnderLamp(Mobility::Static);
  Light moving = pointAt({-0.2f, 0.6f, 0.15f}, 1.5f);
  moving.mobility = Mobility::Dynamic;
  scene.lights.insert(scene.lights.begin(), moving);  // index 0; the baked lamp is 1
  Bake bake = lampBake(scene, 0.5f);
  bake.visibility->punctualCount = 2;
  for (TexelVisibility& texel : bake.visibility->texels) texel.light[0] = 1;
  const Frames live = frames(scene, bake, false, std::nullopt, false);
  const Frames texels = frames(scene, bake, false, std::nullopt, true);
  int checked = 0;
  for (int y = 2; y < kSize - 2; ++y)
    for (int x = 2; x < kSize - 2; ++x) {
      const float expected = live.baked.at(x, y).g;
      ASSERT_GT(expected, 0.0f);
      EXPECT_NEAR(texels.baked.at(x, y).g, expected, 3e-3f * expected) << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 500);
  testContext();
  RendererSettings settings;
  settings.mode = RenderMode::Cost;
  ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, &bake);
  const Image counts = renderer.renderImage(downCamera(1.0f), kSize, kSize);
  for (int y = 2; y < kSize - 2; ++y)
    for (int x = 2; x < kSize - 2; ++x)
      EXPECT_EQ(counts.at(x, y).r, 1.0f) << "lights evaluated at " << x << "," << y;
}

}  // namespace
}  // namespace bounce::test
