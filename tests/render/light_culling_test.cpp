// Light culling (render/light_culling.h) against the unculled frame, offscreen: each pixel's
// radiance with culling may fall short of the unculled one by no more than what the cut-off rule
// (render/light_cutoff.h) lets go, ρ/π · Σ E_i over the lights whose reach bound is below the
// floor at that pixel's point, and never exceed it. Shadows on: lights are read by their own
// indices, so shadowed lights keep their maps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numbers>
#include <utility>
#include <vector>

#include "light_field_scene.h"
#include "lightmap_scenes.h"
#include "scene/light_falloff.h"
#include "shadow_scenes.h"
#include "support/form_factors.h"
#include "test_scenes.h"

namespace bounce::test {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kRho = 0.5f;  // the floors' albedo

struct Frames {
  Image culled, unculled;
  LightGridStats stats;
};

Frames renderBoth(const Scene& scene, const Camera& camera, int width, int height, float floor) {
  testContext();
  Frames frames;
  RendererSettings settings;
  settings.lightCulling.irradianceFloor = floor;
  {
    ForwardRenderer renderer(scene, gl::shaderDirectory(), settings);
    frames.culled = renderer.renderImage(camera, width, height);
    frames.stats = renderer.lightGridStats();
  }
  settings.lightCulling.enabled = false;
  ForwardRenderer renderer(scene, gl::shaderDirectory(), settings);
  frames.unculled = renderer.renderImage(camera, width, height);
  return frames;
}

float brightest(glm::vec3 c) {
  return std::max({c.r, c.g, c.b});
}

// Unshadowed E (W/m²) of a point or spot light at p on a floor facing +y.
glm::vec3 punctualIrradiance(const Light& light, glm::vec3 p) {
  const glm::vec3 toLight = light.position - p;
  const float r = glm::length(toLight);
  float factor = std::max(toLight.y, 0.0f) / r / (r * r);
  if (light.type == LightType::Spot)
    factor *= spotFalloff(light, glm::dot(-toLight / r, light.direction));
  return light.intensity * factor;
}

// What the rule may leave out at p: ρ/π · Σ E_i over the lights with I_max/d² < floor.
glm::vec3 allowedLoss(const Scene& scene, glm::vec3 p, float floor) {
  glm::vec3 loss(0.0f);
  for (const Light& light : scene.lights) {
    const glm::vec3 d = light.position - p;
    if (brightest(light.intensity) / glm::dot(d, d) < floor) loss += punctualIrradiance(light, p);
  }
  return kRho / kPi * loss;
}

struct Agreement {
  int pixels = 0, lossy = 0;  // compared; with any loss at all
  int violations = 0;         // channels outside [0, allowed]
  float maxLoss = 0.0f;       // W/(sr·m²)
  float maxAllowed = 0.0f;
};

// Every floor pixel (the ray hits y = 0 within ±half and `skip` is false): culled ≤ unculled ≤
// culled + allowedLoss, within float rounding of the sums (1e-5 relative).
template <class Skip>
Agreement expectWithinCutoff(const Scene& scene, const Camera& camera, const Frames& frames,
                             float floor, float half, Skip skip) {
  Agreement a;
  const int w = frames.culled.width, h = frames.culled.height;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (pixelRay(camera, w, h, x, y).y >= 0.0f) continue;
      const glm::vec3 p = floorPoint(camera, w, h, x, y);
      if (std::abs(p.x) > half || std::abs(p.z) > half || skip(x, y)) continue;
      const glm::vec3 u = frames.unculled.at(x, y), c = frames.culled.at(x, y);
      const glm::vec3 allowed = allowedLoss(scene, p, floor);
      const glm::vec3 tol = 1e-5f * u + glm::vec3(1e-7f);
      ++a.pixels;
      for (int k = 0; k < 3; ++k) {
        const bool ok = u[k] - c[k] >= -tol[k] && u[k] - c[k] <= allowed[k] + tol[k];
        if (!ok && ++a.violations <= 3)
          ADD_FAILURE() << "pixel " << x << "," << y << " channel " << k << ": unculled " << u[k]
                        << ", culled " << c[k] << ", the cut-off allows a loss of " << allowed[k];
      }
      const float loss = brightest(u - c);
      if (loss > 1e-6f * brightest(u)) ++a.lossy;
      a.maxLoss = std::max(a.maxLoss, loss);
      a.maxAllowed = std::max(a.maxAllowed, brightest(allowed));
    }
  return a;
}

// 256 point lights 5 m apart over an 85 m floor, and two shadowed spot lights over an occluder
// near the camera; a floor of 4·10⁻³ W/m² (EV −2) gives reaches of 7–32 m.
TEST(LightCulling, ManyPointLightsOverALargeFloorMatchTheUnculledFrameWithinTheCutOff) {
  LightField field = lightField(256, 5.0f, 0.2f, 4.0f);
  Material plate;
  plate.name = "plate";
  plate.albedo = glm::vec3(0.5f);
  addBox(field.scene, {-0.5f, 0.8f, 34.0f}, {0.5f, 1.0f, 35.0f}, plate);
  for (float x : {-0.6f, 0.6f}) {
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {x, 2.5f, 34.5f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.intensity = glm::vec3(3.0f, 2.0f, 1.0f);
    spot.innerConeAngle = 0.3f;
    spot.outerConeAngle = 0.6f;
    field.scene.lights.push_back(spot);
  }
  const float floor = 4e-3f;
  const int w = 160, h = 90;
  const Frames frames = renderBoth(field.scene, field.camera, w, h, floor);
  const float half = 0.5f * field.side;
  // Pixels that see the plate rather than the floor.
  const Camera& camera = field.camera;
  const auto seesPlate = [&](int x, int y) {
    const glm::vec3 d = pixelRay(camera, w, h, x, y), o = camera.position();
    const glm::vec3 top = o + d * ((1.0f - o.y) / d.y);
    return std::abs(top.x) <= 0.55f && top.z >= 33.9f && top.z <= 35.1f;
  };
  const Agreement a = expectWithinCutoff(field.scene, camera, frames, floor, half, seesPlate);
  EXPECT_EQ(a.violations, 0);
  EXPECT_GT(a.pixels, w * h / 2);
  const double perCluster =
      static_cast<double>(frames.stats.punctualEntries) / frames.stats.clusters;
  std::printf(
      "258 lights: %.1f per cluster (at most %zu); %d of %d pixels lose light, at most "
      "%.3g W/(sr m^2) (the rule allows up to %.3g there; rho/pi*E_floor = %.3g)\n",
      perCluster, frames.stats.maxPunctual, a.lossy, a.pixels, static_cast<double>(a.maxLoss),
      static_cast<double>(a.maxAllowed), static_cast<double>(kRho / kPi * floor));
  EXPECT_LT(perCluster, 0.25 * 258);  // culling left most lights out of most clusters
}

// Light that reaches 1 m, centred above the corner where four tiles meet (the image centre of a
// 64² frame, 4-pixel tiles): every pixel it reaches (I/d² ≥ floor) is lit exactly as unculled.
TEST(LightCulling, LightAboveATileCornerLightsEveryTileAroundIt) {
  Scene scene;
  addFloor(scene, glm::vec3(kRho));
  Light light;
  light.position = {0.0f, 0.5f, 0.0f};
  light.intensity = glm::vec3(1.0f);
  scene.lights.push_back(light);
  const float floor = 1.0f;  // reach sqrt(I / floor) = 1 m
  const Camera camera = downCamera(10.0f);
  const Frames frames = renderBoth(scene, camera, 64, 64, floor);
  int lit = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const glm::vec3 p = floorPoint(camera, 64, 64, x, y);
      if (glm::length(light.position - p) >= 1.0f) continue;
      ++lit;
      EXPECT_NEAR(frames.culled.at(x, y).r, frames.unculled.at(x, y).r,
                  1e-6f * frames.unculled.at(x, y).r)
          << "pixel " << x << "," << y;
    }
  EXPECT_GT(lit, 100);  // about π·0.87²/0.13² pixels, over 4×4 tiles
  EXPECT_GT(frames.stats.punctualEntries, 0u);
}

// A narrow, bright spot light beside the camera aims 150 m down a long floor: its cone lights
// clusters of the far slices, which must list it; a spot behind the camera aiming away reaches
// no cluster at all (its cone, not its 4 km sphere, decides).
TEST(LightCulling, SpotLightConeReachesTheFarClustersAndNoOthers) {
  Scene scene;
  Material floorMaterial;
  floorMaterial.name = "floor";
  floorMaterial.albedo = glm::vec3(kRho);
  addQuad(scene, {-20, 0, 5}, {40, 0, 0}, {0, 0, -305}, floorMaterial);
  Light ahead;
  ahead.type = LightType::Spot;
  ahead.position = {0.0f, 4.0f, 2.0f};
  ahead.direction = glm::normalize(glm::vec3(0.0f, -4.0f, -152.0f));
  ahead.intensity = glm::vec3(2e4f);
  ahead.innerConeAngle = 0.02f;
  ahead.outerConeAngle = 0.05f;
  Light behind = ahead;
  behind.position = {0.0f, 4.0f, 4.0f};
  behind.direction = glm::normalize(glm::vec3(0.0f, -0.1f, 1.0f));
  scene.lights = {ahead, behind};
  Camera camera;
  camera.yfov = 0.6f;
  camera.zfar = 1000.0f;
  camera.cameraToWorld = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 2.0f, 0.0f));
  const float floor = irradianceFloorForExposure(0.0f);
  const Frames frames = renderBoth(scene, camera, 128, 96, floor);
  const Agreement a =
      expectWithinCutoff(scene, camera, frames, floor, 1e30f, [](int, int) { return false; });
  int lit = 0;
  for (const glm::vec3& pixel : frames.unculled.pixels) lit += pixel.r > 0.0f;
  EXPECT_GT(lit, 20);
  EXPECT_EQ(a.violations, 0);
  EXPECT_EQ(a.lossy, 0);
  // The one in front alone lists the same clusters: the one behind is in none.
  Scene aheadOnly = scene;
  aheadOnly.lights = {ahead};
  const Frames alone = renderBoth(aheadOnly, camera, 128, 96, floor);
  EXPECT_EQ(frames.stats.punctualEntries, alone.stats.punctualEntries);
  EXPECT_GT(alone.stats.punctualEntries, 0u);
  EXPECT_LT(alone.stats.punctualEntries, static_cast<std::size_t>(alone.stats.clusters) / 4);
}

// Whether the ray o + t·d (t > 0) passes through `box`.
bool rayHitsBox(glm::vec3 o, glm::vec3 d, glm::vec3 lo, glm::vec3 hi) {
  float t0 = 0.0f, t1 = 1e30f;
  for (int k = 0; k < 3; ++k) {
    const float a = (lo[k] - o[k]) / d[k], b = (hi[k] - o[k]) / d[k];
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  }
  return t0 <= t1;
}

// Twelve emissive panels (0.4 m square, 0.8 m up, facing down) over a 40 m floor, the brightest
// three with shadow cubes and a plate under the brightest. Each floor pixel loses no more than
// ρ/π · Σ E_j over the panels whose reach bound Σ L·A / d² (d: to the panel) is below the floor
// there, E_j the panel's exact irradiance (the parallel-rectangle form factor), and most clusters
// list few panels.
TEST(LightCulling, AreaLightsMatchTheUnculledFrameAndKeepTheirShadows) {
  Scene scene;
  Material floorMaterial;
  floorMaterial.name = "floor";
  floorMaterial.albedo = glm::vec3(kRho);
  addQuad(scene, {-20, 0, 20}, {40, 0, 0}, {0, 0, -40}, floorMaterial);
  const float size = 0.4f, height = 0.8f;
  std::vector<std::pair<glm::vec3, glm::vec3>> panels;  // (corner, radiance)
  for (int i = 0; i < 12; ++i) {
    Material panel;
    panel.name = "panel" + std::to_string(i);
    panel.emission = glm::vec3(2.0f + 3.0f * static_cast<float>(i % 7), 5.0f, 4.0f);
    const glm::vec3 c(-15.0f + 10.0f * static_cast<float>(i % 4), height,
                      15.0f - 12.0f * static_cast<float>(i / 4));
    addQuad(scene, c, {size, 0, 0}, {0, 0, size}, panel);  // faces −y
    panels.emplace_back(c, panel.emission);
  }
  Material plate;
  plate.name = "plate";
  plate.albedo = glm::vec3(0.5f);
  const glm::vec3 plateLo(4.9f, 0.3f, 2.9f), plateHi(5.5f, 0.4f, 3.5f);
  addBox(scene, plateLo, plateHi, plate);  // under panel 6 (the brightest)
  Camera camera;
  camera.yfov = 1.0f;
  camera.zfar = 200.0f;
  const glm::vec3 eye(0.0f, 6.0f, 24.0f);
  camera.cameraToWorld = glm::inverse(glm::lookAt(eye, glm::vec3(0.0f, 0.0f, 0.0f), {0, 1, 0}));
  const float floor = 2e-2f;  // reaches 5–13 m
  const int w = 160, h = 90;
  const Frames frames = renderBoth(scene, camera, w, h, floor);
  Agreement a;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::vec3 d = pixelRay(camera, w, h, x, y);
      if (d.y >= 0.0f || rayHitsBox(eye, d, plateLo, plateHi)) continue;
      const glm::vec3 p = floorPoint(camera, w, h, x, y);
      glm::vec3 allowed(0.0f);
      bool seesPanel = false;
      for (const auto& [c, radiance] : panels) {
        seesPanel |= rayHitsBox(eye, d, c, c + glm::vec3(size, 0.0f, size));
        const glm::vec3 nearest = glm::clamp(p, c, c + glm::vec3(size, 0.0f, size));
        const float bound = brightest(radiance) * size * size / glm::dot(p - nearest, p - nearest);
        if (bound < floor)
          allowed += kRho * radiance *
                     static_cast<float>(parallelRectangleFormFactor(p.x, p.z, c.x, c.x + size, c.z,
                                                                    c.z + size, height));
      }
      if (seesPanel) continue;
      const glm::vec3 u = frames.unculled.at(x, y), c = frames.culled.at(x, y);
      const glm::vec3 tol = 1e-5f * u + glm::vec3(1e-7f);
      ++a.pixels;
      for (int k = 0; k < 3; ++k) {
        // Slack for the shader's own error on a far panel, which the culled frame leaves out:
        // its float contour integral is off by up to 1.7·10⁻⁷ W/(sr·m²) (60% of a 3·10⁻⁷ term,
        // 6% of a 3·10⁻⁶ one) against the closed form at these pixels, measured panel by panel.
        const float slack = 0.1f * allowed[k] + 1e-6f;
        const bool ok = u[k] - c[k] >= -tol[k] && u[k] - c[k] <= allowed[k] + slack + tol[k];
        if (!ok && ++a.violations <= 3)
          ADD_FAILURE() << "pixel " << x << "," << y << " channel " << k << ": unculled " << u[k]
                        << ", culled " << c[k] << ", the cut-off allows a loss of " << allowed[k];
      }
      a.lossy += brightest(u - c) > 1e-6f * brightest(u);
      a.maxLoss = std::max(a.maxLoss, brightest(u - c));
      a.maxAllowed = std::max(a.maxAllowed, brightest(allowed));
    }
  EXPECT_EQ(a.violations, 0);
  EXPECT_GT(a.pixels, w * h / 2);
  const double perCluster = static_cast<double>(frames.stats.areaEntries) / frames.stats.clusters;
  std::printf(
      "12 area lights: %.2f per cluster (at most %zu); %d of %d pixels lose light, at "
      "most %.3g W/(sr m^2) (the rule allows up to %.3g there; rho/pi*E_floor = %.3g)\n",
      perCluster, frames.stats.maxArea, a.lossy, a.pixels, static_cast<double>(a.maxLoss),
      static_cast<double>(a.maxAllowed), static_cast<double>(kRho / kPi * floor));
  EXPECT_LT(perCluster, 6.0);
}

// A light whose reach ends a quarter pixel inside a tile's last pixel column (4-pixel tiles,
// looking straight down): that column's pixels within reach are shaded, though the next tile,
// which the reach misses, does not list it; a fragment put in the wrong tile loses it.
TEST(LightCulling, LightReachingIntoATilesLastColumnIsShadedThere) {
  Scene scene;
  addFloor(scene, glm::vec3(kRho));
  const Camera camera = downCamera(10.0f);
  const int size = 64;
  const float edge = floorPoint(camera, size, size, 36.0f, 30.0f).x;  // tile 8 | tile 9
  const float pixel = edge - floorPoint(camera, size, size, 35.0f, 30.0f).x;
  Light light;
  light.position = {edge - 0.25f * pixel - 1.0f, 0.05f, floorPoint(camera, size, size, 34, 30).z};
  light.intensity = glm::vec3(1.0f);
  scene.lights.push_back(light);
  const Frames frames = renderBoth(scene, camera, size, size, 1.0f);  // reach 1 m
  int lastColumn = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::vec3 p = floorPoint(camera, size, size, x, y);
      if (glm::length(light.position - p) >= 1.0f) continue;
      lastColumn += x == 35;
      EXPECT_NEAR(frames.culled.at(x, y).r, frames.unculled.at(x, y).r,
                  1e-6f * frames.unculled.at(x, y).r)
          << "pixel " << x << "," << y;
    }
  EXPECT_GT(lastColumn, 0);
}

// Two static panels over a floor with a synthetic bake whose every texel names panel 0 visible at
// 0.25 and panel 1 at 0.5: where culling leaves panel 0 out, panel 1 is first in the cluster's
// list, and must still read its own baked V (the shader reads it by the light's row, not the
// list position). Culled and unculled frames, both with the bake, differ by no more than the
// left-out panels' exact V·E.
TEST(LightCulling, BakedVisibilityIsReadByTheLightsOwnIndex) {
  Scene scene;
  Material floorMaterial;
  floorMaterial.name = "floor";
  floorMaterial.albedo = glm::vec3(0.6f);
  addQuad(scene, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, floorMaterial);
  const float size = 0.2f, height = 0.3f;
  const glm::vec3 corners[] = {{-0.6f, height, -0.1f}, {0.4f, height, -0.1f}};
  const glm::vec3 radiance(3.0f, 2.0f, 1.0f);
  for (int i = 0; i < 2; ++i) {
    Material panel;
    panel.name = "panel" + std::to_string(i);
    panel.emission = radiance;
    addQuad(scene, corners[i], {size, 0, 0}, {0, 0, size}, panel);  // faces −y
  }
  const float visible[] = {0.25f, 0.5f};
  constexpr int kAtlas = 32;
  Bake bake;
  bake.layout.width = bake.layout.height = kAtlas;
  bake.layout.texelSize = 2.0f / kAtlas;
  const Mesh& floorMesh = scene.meshes[scene.instances[0].mesh];
  InstanceLightmapUv floorUv{0, {}};
  for (uint32_t index : floorMesh.indices)
    floorUv.cornerUv.push_back({0.5f * (floorMesh.positions[index].x + 1.0f),
                                0.5f * (floorMesh.positions[index].z + 1.0f)});
  bake.layout.instances = {floorUv};
  for (uint32_t i = 1; i <= 2; ++i)  // the panels: one texel of their own, in the last column
    bake.layout.instances.push_back(
        {i, std::vector<glm::vec2>(
                scene.meshes[i].indices.size(),
                glm::vec2(1.0f - 0.5f / kAtlas, (static_cast<float>(i) - 0.5f) / kAtlas))});
  bake.irradiance = Image(kAtlas, kAtlas);
  bake.manifest = minimalManifest(scene);
  BakedVisibility v;
  v.width = v.height = kAtlas;
  v.lightCount = 2;
  TexelVisibility texel;
  texel.light[0] = 0;
  texel.visible[0] = visible[0];
  texel.light[1] = 1;
  texel.visible[1] = visible[1];
  v.texels.assign(kAtlas * kAtlas, texel);
  bake.visibility = v;

  testContext();
  RendererSettings settings;
  settings.shadows.enabled = false;
  const float lightIntensity = brightest(radiance) * size * size;          // Σ L·A, W/sr
  settings.lightCulling.irradianceFloor = lightIntensity / (0.5f * 0.5f);  // reach 0.5 m
  const Camera camera = downCamera(2.0f);
  const int n = 64;
  Image culled, unculled;
  LightGridStats stats;
  {
    ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, &bake);
    culled = renderer.renderImage(camera, n, n);
    stats = renderer.lightGridStats();
  }
  settings.lightCulling.enabled = false;
  {
    ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, &bake);
    unculled = renderer.renderImage(camera, n, n);
  }
  int violations = 0, alone = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const glm::vec3 p = floorPoint(camera, n, n, x, y);
      bool underPanel = false;
      glm::vec3 allowed(0.0f);
      int kept = 0;
      for (int i = 0; i < 2; ++i) {
        const glm::vec3 lo = corners[i], hi = corners[i] + glm::vec3(size, 0.0f, size);
        underPanel |= p.x >= lo.x - 0.02f && p.x <= hi.x + 0.02f && p.z >= lo.z - 0.02f &&
                      p.z <= hi.z + 0.02f;
        const glm::vec3 nearest = glm::clamp(p, lo, hi);
        if (lightIntensity / glm::dot(p - nearest, p - nearest) >=
            settings.lightCulling.irradianceFloor) {
          ++kept;
          continue;
        }
        allowed += 0.6f * visible[i] * radiance *
                   static_cast<float>(
                       parallelRectangleFormFactor(p.x, p.z, lo.x, hi.x, lo.z, hi.z, height));
      }
      if (underPanel) continue;  // the panels hide the floor from above
      alone += kept == 1 && p.x > 0.0f;
      const glm::vec3 u = unculled.at(x, y), c = culled.at(x, y);
      for (int k = 0; k < 3; ++k) {
        const float tol = 1e-5f * u[k] + 1e-6f + 0.1f * allowed[k];
        const bool ok = u[k] - c[k] >= -tol && u[k] - c[k] <= allowed[k] + tol;
        if (!ok && ++violations <= 3)
          ADD_FAILURE() << "pixel " << x << "," << y << " channel " << k << ": unculled " << u[k]
                        << ", culled " << c[k] << ", the cut-off allows a loss of " << allowed[k];
      }
    }
  EXPECT_EQ(violations, 0);
  EXPECT_GT(alone, 200);  // pixels that only panel 1 reaches: its list is [1]
  EXPECT_LT(static_cast<double>(stats.areaEntries) / stats.clusters, 1.9);
}

}  // namespace
}  // namespace bounce::test
