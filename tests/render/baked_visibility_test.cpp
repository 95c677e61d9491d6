// The renderer's baked visibility of static area lights (shaders/baked_visibility.glsl) against
// closed forms, on synthetic bakes: a floor texel's V multiplies the light's exact polygon
// irradiance; a light the texel does not name reads its "every other light" slot, else 1; the
// atlas is read the right way up; dynamic instances never read it. Each case is drawn both ways
// a lightmapped pixel can get the light: evaluated per pixel (--live-static-lights) and read from
// the texels' irradiance vectors (render/static_direct_texels.h). The texels interpolate E
// bilinearly: a panel at height d = 0.6 m gives E ≈ E₀ (1 + r²/d²)⁻², whose relative curvature
// is at most 4/d² ≈ 11 m⁻² along each axis, so over texels of h = 1/32 m the interpolation is
// off by at most 2 · h²/8 · 11 ≈ 2.7e-3 of E; the texel path's tolerance is 3e-3, the live
// one's 1e-3.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "lightmap_scenes.h"
#include "test_scenes.h"

namespace bounce::test {
namespace {

constexpr int kSize = 32;

// A 1 m floor at y = 0 (atlas u = x + ½, v = z + ½) under a 0.4 m square emitter 0.6 m up facing
// down, seen from 1 m above; no blocker, so the unshadowed frame is the reference.
Scene floorUnderPanel() {
  return bounce::test::floorUnderPanel({-0.2f, 0.6f, -0.2f}, {0.4f, 0, 0}, {0, 0, 0.4f});
}

// A bake with a black lightmap and visibility `record(x, y)` for texel (x, y) of a kSize atlas.
template <class Record>
Bake visibilityBake(const Scene& scene, Record record) {
  Bake bake;
  bake.layout.width = bake.layout.height = kSize;
  bake.layout.texelSize = 1.0f / kSize;
  const InstanceLightmapUv region = unitFloorRegion(scene);
  // The panel is lightmapped too (it is static), with a region of its own in the last texel.
  InstanceLightmapUv panel{1, {}};
  for (std::size_t i = 0; i < scene.meshes[1].indices.size(); ++i)
    panel.cornerUv.push_back(glm::vec2(1.0f - 0.5f / kSize));
  bake.layout.instances = {region, panel};
  bake.irradiance = Image(kSize, kSize);
  bake.manifest = minimalManifest(scene);
  BakedVisibility v;
  v.width = v.height = kSize;
  v.lightCount = 1;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) v.texels.push_back(record(x, y));
  bake.visibility = v;
  return bake;
}

constexpr bool kBothPaths[] = {false, true};  // staticDirectTexels

float tolerance(bool texels) {
  return texels ? 3e-3f : 1e-3f;
}

Image renderDirect(const Scene& scene, const Bake* bake, bool texels = false) {
  testContext();
  RendererSettings settings;
  settings.mode = RenderMode::Direct;
  settings.shadows.enabled = false;
  settings.precomputedStaticDirect = texels;
  ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, bake);
  return renderer.renderImage(downCamera(1.0f), kSize, kSize);
}

TexelVisibility named(uint16_t light, float v) {
  TexelVisibility t;
  t.light[0] = light;
  t.visible[0] = v;
  return t;
}

// Pixels (x, y) of the floor whose ratio to the unshadowed frame is checked (the panel is seen
// from above as its unlit back: the floor around it, the frame's border rows left out).
bool floorPixel(int x, int y) {
  const float fx = (x + 0.5f) / kSize - 0.5f, fy = (y + 0.5f) / kSize - 0.5f;
  return std::max(std::abs(fx), std::abs(fy)) > 0.2f && std::max(std::abs(fx), std::abs(fy)) < 0.4f;
}

TEST(BakedVisibility, ATexelsVisibleFractionScalesTheLightsExactIrradiance) {
  const Scene scene = floorUnderPanel();
  const Image open = renderDirect(scene, nullptr);
  const struct {
    const char* what;
    TexelVisibility record;
    float expected;
  } cases[] = {{"named, V = 0.25", named(0, 0.25f), 0.25f},
               {"every other light, V = 0.5", named(kOtherLights, 0.5f), 0.5f},
               {"not named, no other slot: V = 1", named(kNoLight, 0.0f), 1.0f}};
  for (const bool texels : kBothPaths)
    for (const auto& c : cases) {
      const Bake bake = visibilityBake(scene, [&](int, int) { return c.record; });
      const Image baked = renderDirect(scene, &bake, texels);
      int checked = 0;
      for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
          if (!floorPixel(x, y)) continue;
          const glm::vec3 a = baked.at(x, y), b = open.at(x, y);
          ASSERT_GT(b.r, 0.0f);
          EXPECT_NEAR(a.r / b.r, c.expected, tolerance(texels))
              << c.what << (texels ? " (texels)" : " (live)") << " at " << x << "," << y;
          ++checked;
        }
      EXPECT_GT(checked, 100);
    }
}

// Two panels side by side over the floor (area lights 0 and 1 in scene/area_lights.h's order:
// by instance), each texel naming panel 0 at V = 0.2 and panel 1 at V = 0.7. Every floor pixel
// must be 0.2·E_0 + 0.7·E_1, E_l the pixel of a frame where only panel l faces the floor (the
// other turned face up, still a light with its index, lighting nothing below). The one-light
// tests above cannot tell which light reads which V, and LightCulling's two-light test compares
// culled and unculled frames, which a mistake common to both passes. Injected: every area light
// reading light 0's V (its index dropped): fails here, passes LightCulling's test and the tests
// above; the two lights swapped (V of light L − 1 − l): fails here and in LightCulling's test.
TEST(BakedVisibility, EachLightReadsItsOwnVisibilityOfTwo) {
  const auto panels = [](bool faceDown0, bool faceDown1) {
    Scene scene;
    Material floor;
    floor.name = "floor";
    floor.albedo = glm::vec3(0.6f);
    addQuad(scene, {-0.5f, 0, 0.5f}, {1, 0, 0}, {0, 0, -1}, floor);
    const float x[] = {-0.45f, 0.2f};  // beyond the camera's view at their height
    const bool down[] = {faceDown0, faceDown1};
    for (int l = 0; l < 2; ++l) {
      Material panel;
      panel.name = "panel" + std::to_string(l);
      panel.emission = l == 0 ? glm::vec3(3.0f, 2.0f, 1.0f) : glm::vec3(1.0f, 2.0f, 3.0f);
      const glm::vec3 c(x[l], 0.6f, -0.15f), u(0.25f, 0, 0), v(0, 0, 0.3f);
      if (down[l])
        addQuad(scene, c, u, v, panel);  // (x × z) = −y
      else
        addQuad(scene, c, v, u, panel);  // faces +y
    }
    return scene;
  };
  const Scene scene = panels(true, true);
  Bake bake;
  bake.layout.width = bake.layout.height = kSize;
  bake.layout.texelSize = 1.0f / kSize;
  bake.layout.instances = {unitFloorRegion(scene)};
  for (uint32_t i = 1; i <= 2; ++i)  // each panel a texel of its own in the last column
    bake.layout.instances.push_back(
        {i, std::vector<glm::vec2>(scene.meshes[i].indices.size(),
                                   glm::vec2(1.0f - 0.5f / kSize, (i - 0.5f) / kSize))});
  bake.irradiance = Image(kSize, kSize);
  bake.manifest = minimalManifest(scene);
  TexelVisibility texel;
  texel.light[0] = 1;  // the slots in another order than the lights
  texel.visible[0] = 0.7f;
  texel.light[1] = 0;
  texel.visible[1] = 0.2f;
  BakedVisibility v;
  v.width = v.height = kSize;
  v.lightCount = 2;
  v.texels.assign(kSize * kSize, texel);
  bake.visibility = v;

  const Image only0 = renderDirect(panels(true, false), nullptr);
  const Image only1 = renderDirect(panels(false, true), nullptr);
  for (const bool texels : kBothPaths) {
    const Image baked = renderDirect(scene, &bake, texels);
    int checked = 0, bothLit = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const float fx = (x + 0.5f) / kSize - 0.5f, fy = (y + 0.5f) / kSize - 0.5f;
        if (std::max(std::abs(fx), std::abs(fy)) > 0.4f) continue;  // the frame's border
        const glm::vec3 e0 = only0.at(x, y), e1 = only1.at(x, y);
        const glm::vec3 expected = 0.2f * e0 + 0.7f * e1;
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(baked.at(x, y)[c], expected[c], tolerance(texels) * expected[c] + 1e-7f)
              << "pixel " << x << "," << y << " channel " << c
              << (texels ? " (texels)" : " (live)");
        ++checked;
        bothLit += e0.g > 0.0f && e1.g > 0.0f;
      }
    EXPECT_GT(checked, 300);
    EXPECT_GT(bothLit, 300);
  }
}

// Texels with x < kSize/2 (the floor's x < 0) hold V = 0, the rest V = 1: the left of the frame
// (downCamera: image x along world x) is dark except within a texel of the middle.
TEST(BakedVisibility, TheAtlasIsReadWhereTheFloorIs) {
  const Scene scene = floorUnderPanel();
  const Image open = renderDirect(scene, nullptr);
  const Bake bake =
      visibilityBake(scene, [](int x, int) { return named(0, x < kSize / 2 ? 0.0f : 1.0f); });
  for (const bool texels : kBothPaths) {
    const Image baked = renderDirect(scene, &bake, texels);
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        if (!floorPixel(x, y)) continue;
        const float fx = (x + 0.5f) / kSize - 0.5f;
        const float ratio = baked.at(x, y).g / open.at(x, y).g;
        // The camera sees ±0.42 m across 32 pixels (1.3 cm each); texels are 3.1 cm.
        if (fx < -0.04f) {
          EXPECT_NEAR(ratio, 0.0f, tolerance(texels)) << x << "," << y;
        } else if (fx > 0.04f) {
          EXPECT_NEAR(ratio, 1.0f, tolerance(texels)) << x << "," << y;
        }
      }
  }
}

// An emitter whose material is marked bakeDirect is drawn live without a bake and skipped with
// one (its direct light is in the lightmap, here black): the floor's direct frame goes to 0.
TEST(BakedVisibility, ABakedDirectEmitterIsNotDrawnLiveOnceABakeIsAttached) {
  Scene scene = floorUnderPanel();
  scene.materials[scene.meshes[1].material].bakeDirect = true;
  const Image live = renderDirect(scene, nullptr);
  const Bake bake = visibilityBake(scene, [](int, int) { return named(0, 1.0f); });
  for (const bool texels : kBothPaths) {
    const Image baked = renderDirect(scene, &bake, texels);
    int checked = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        if (!floorPixel(x, y)) continue;
        EXPECT_GT(live.at(x, y).r, 0.0f);
        EXPECT_EQ(baked.at(x, y), glm::vec3(0.0f)) << x << "," << y;
        ++checked;
      }
    EXPECT_GT(checked, 100);
  }
}

// Smooth normals that turn 60° across the floor (±30° about z at x = ±½), under a panel 1.5 m
// up (above the camera), read through 12.5 cm texels with V = 1: the texel path must follow each
// pixel's normal. Against the live frame: bilinear interpolation of the position is off by at
// most 2 · h²/8 · 4/d² ≈ 0.7 % (as above, d = 1.5 m, h = 1/8 m) and n·F_c is exact at any normal
// whose horizon keeps the whole panel (all here); a normal off the texel's by half a texel's
// turn (0.065 rad) changes E by up to tan 30° · 0.065 ≈ 3.8 %. Tolerance 1 %. Injected: texels
// holding E(n_t) along n_t (a scalar lightmap of the direct light): fails.
TEST(BakedVisibility, TexelsFollowTheShadingNormalWithinATexel) {
  Scene scene = floorUnderPanel();
  Mesh& floor = scene.meshes[0];
  for (std::size_t i = 0; i < floor.positions.size(); ++i) {
    const float angle = floor.positions[i].x * glm::radians(60.0f);  // ±30° at x = ±½
    floor.normals[i] = glm::vec3(std::sin(angle), std::cos(angle), 0.0f);
  }
  Mesh& panel = scene.meshes[1];
  for (glm::vec3& p : panel.positions) p.y = 1.5f;
  constexpr int kTexels = 8;
  Bake bake;
  bake.layout.width = bake.layout.height = kTexels;
  bake.layout.texelSize = 1.0f / kTexels;
  bake.layout.instances = {unitFloorRegion(scene)};
  bake.irradiance = Image(kTexels, kTexels);
  bake.manifest = minimalManifest(scene);
  BakedVisibility v;
  v.width = v.height = kTexels;
  v.lightCount = 1;
  v.texels.assign(kTexels * kTexels, named(0, 1.0f));
  bake.visibility = v;
  const Image live = renderDirect(scene, &bake, false);
  const Image texels = renderDirect(scene, &bake, true);
  int checked = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const float fx = (x + 0.5f) / kSize - 0.5f, fy = (y + 0.5f) / kSize - 0.5f;
      if (std::max(std::abs(fx), std::abs(fy)) > 0.4f) continue;  // the frame's border
      const glm::vec3 a = texels.at(x, y), b = live.at(x, y);
      ASSERT_GT(b.b, 0.0f);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(a[c], b[c], 0.01f * b[c]) << "pixel " << x << "," << y << " channel " << c;
      ++checked;
    }
  EXPECT_GT(checked, 500);
}

// The cost view's light count on the lightmapped floor: the panel evaluated per pixel when live,
// never when its light comes from the texels (what a static surface of a baked scene pays).
TEST(BakedVisibility, ALightmappedPixelEvaluatesNoStaticAreaLightWithTexels) {
  const Scene scene = floorUnderPanel();
  const Bake bake = visibilityBake(scene, [](int, int) { return named(0, 1.0f); });
  testContext();
  for (const bool texels : kBothPaths) {
    RendererSettings settings;
    settings.mode = RenderMode::Cost;
    settings.precomputedStaticDirect = texels;
    ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, &bake);
    const Image counts = renderer.renderImage(downCamera(1.0f), kSize, kSize);
    int checked = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        if (!floorPixel(x, y)) continue;
        EXPECT_EQ(counts.at(x, y).r, texels ? 0.0f : 1.0f) << x << "," << y;
        ++checked;
      }
    EXPECT_GT(checked, 100);
  }
}

// With a dynamic instance in the room, a static pixel still reads the light from its texels and
// needs the dynamic cube only where the instance may stand between it and the light
// (shaders/shadow_area.glsl, dynamicCasterBetween). The panel lies within r_L = 0.2√2 m of its
// centre c, so from floor point p every segment to it lies in the cone around p→c of half-angle
// α = asin(r_L/|c − p|); a sphere (s, R) meets that cone only if the angle θ between p→s and p→c
// is ≤ α + asin(R/|s − p|). Checked: every floor pixel with θ beyond that bound (+ 0.02 rad for
// the sample's place within the pixel) takes no shadow tap, and every one from which a segment
// to the panel does meet the sphere takes taps. Injected: the test always true (every floor
// pixel taps the cube: fails), always false (the shadowed pixels take none: fails).
TEST(BakedVisibility, AStaticPixelReadsTheDynamicCubeOnlyWhereTheCasterMayHideTheLight) {
  Scene scene = floorUnderPanel();
  const glm::vec3 centre(0.2f, 0.3f, 0.05f);
  constexpr float kRadius = 0.06f;
  Material grey;
  grey.name = "grey";
  grey.albedo = glm::vec3(0.5f);
  const uint32_t sphere =
      addInstance(scene, uvSphere(kRadius, 12, 24), grey, glm::translate(glm::mat4(1.0f), centre));
  scene.instances[sphere].mobility = Mobility::Dynamic;
  const Bake bake = visibilityBake(scene, [](int, int) { return named(0, 1.0f); });
  testContext();
  RendererSettings settings;
  settings.mode = RenderMode::Cost;
  ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, &bake);
  const Camera camera = downCamera(1.0f);
  const Image counts = renderer.renderImage(camera, kSize, kSize);
  const glm::vec3 c(0.0f, 0.6f, 0.0f);
  const float lightRadius = 0.2f * std::sqrt(2.0f);
  // Whether the segment p → x meets the sphere.
  const auto blocks = [&](glm::vec3 p, glm::vec3 x) {
    const glm::vec3 d = x - p;
    const float t = glm::clamp(glm::dot(centre - p, d) / glm::dot(d, d), 0.0f, 1.0f);
    return glm::length(p + t * d - centre) < kRadius;
  };
  int outside = 0, shadowed = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (!floorPixel(x, y)) continue;
      const glm::vec3 p = floorPoint(camera, kSize, kSize, x, y);
      if (glm::length(p - centre) < 2.0f * kRadius) continue;  // seen through the sphere
      const float theta = std::acos(glm::dot(glm::normalize(centre - p), glm::normalize(c - p)));
      const float bound = std::asin(lightRadius / glm::length(c - p)) +
                          std::asin(kRadius / glm::length(centre - p));
      const float taps = counts.at(x, y).b;
      if (theta > bound + 0.02f) {
        EXPECT_EQ(taps, 0.0f) << "pixel (" << x << ", " << y << ") outside every cone";
        ++outside;
      }
      bool hidden = false;
      for (int i = 0; i <= 4 && !hidden; ++i)
        for (int j = 0; j <= 4 && !hidden; ++j)
          hidden = blocks(p, glm::vec3(-0.2f + 0.1f * i, 0.6f, -0.2f + 0.1f * j));
      if (hidden) {
        EXPECT_GT(taps, 0.0f) << "pixel (" << x << ", " << y << ") in the sphere's shadow";
        ++shadowed;
      }
    }
  EXPECT_GT(outside, 100);
  EXPECT_GT(shadowed, 10);
}

// The area cubes are drawn only when something reads them: not when every instance has baked
// visibility and none is dynamic, but as soon as one instance has no atlas region.
TEST(BakedVisibility, AreaCubesAreDrawnOnlyWhereSomethingReadsThem) {
  const Scene scene = floorUnderPanel();
  Bake bake = visibilityBake(scene, [](int, int) { return named(0, 1.0f); });
  testContext();
  RendererSettings settings;
  settings.mode = RenderMode::Direct;
  {
    ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, &bake);
    renderer.renderImage(downCamera(1.0f), kSize, kSize);
    EXPECT_EQ(renderer.shadowDrawCount().views, 0);
  }
  bake.layout.instances.pop_back();  // the panel reads no visibility: it needs the cube
  ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, &bake);
  renderer.renderImage(downCamera(1.0f), kSize, kSize);
  EXPECT_GT(renderer.shadowDrawCount().views, 0);
}

}  // namespace
}  // namespace bounce::test
