// Shadow maps (spot and point lights) measured against the truth:
//   1. visibility agrees with ray-traced visibility (the baker's ray kernel) except in a
//      one-pixel band along true shadow edges;
//   2. no acne: an unoccluded plane lit at up to grazing incidence is nowhere darker than the
//      unshadowed closed form by more than 1%;
//   3. no peter-panning: a thin box's shadow starts within one shadow texel of its base.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>

#include "render/shadow_map_geometry.h"
#include "scene/framing.h"
#include "shadow_scenes.h"

namespace bounce::test {
namespace {

constexpr float kPi = 3.14159265358979f;

// ---- 1. Visibility against ray-traced visibility --------------------------------------------

void expectAgreement(const Light& light) {
  const Agreement a = measureAgreement(occluderScene(light), occluderCamera(), 128, 128);
  std::printf("%s: %d of %d pixels disagree (%.3f%%), %d shadowed\n", light.name.c_str(),
              a.disagreeing, a.considered, 100.0 * a.fraction(), a.shadowed);
  ASSERT_GT(a.considered, 128 * 128 / 4);    // the light covers much of the frame
  ASSERT_GT(a.shadowed, a.considered / 20);  // and the occluders cast real shadows
  const auto shown =
      std::filesystem::temp_directory_path() / ("bounce-shadow-agreement-" + light.name + ".png");
  if (a.fraction() > 0.005 || std::getenv("BOUNCE_SHADOW_MAPS")) {
    writePng(shown, a.map, 0.0f);
    writePng(std::filesystem::path(shown).replace_extension(".frame.png"), a.frame, 0.0f);
  }
  EXPECT_LE(a.fraction(), 0.005) << a.disagreeing << " of " << a.considered
                                 << " (disagreement map: " << shown.string() << ")";
}

TEST(ShadowVisibility, SpotAgreesWithRayTracedVisibility) {
  expectAgreement(occluderSpot());
}

TEST(ShadowVisibility, PointAgreesWithRayTracedVisibility) {
  expectAgreement(occluderPoint());
}

// ---- 2. Acne: an unoccluded plane at up to grazing incidence --------------------------------

// Irradiance (W/m²) of the floor y = 0 (normal +y) at p, unshadowed: the closed forms of
// docs/renderer.md written out here (spot falloff t², t linear in cosα between the cones).
glm::vec3 floorIrradiance(const Light& light, glm::vec3 p) {
  if (light.type == LightType::Directional)
    return light.irradiance * std::max(-glm::normalize(light.direction).y, 0.0f);
  const glm::vec3 toLight = light.position - p;
  const float r2 = glm::dot(toLight, toLight);
  const float cosTheta = std::max(toLight.y / std::sqrt(r2), 0.0f);
  float falloff = 1.0f;
  if (light.type == LightType::Spot) {
    const float cosAlpha = glm::dot(-toLight / std::sqrt(r2), glm::normalize(light.direction));
    const float ci = std::cos(light.innerConeAngle), co = std::cos(light.outerConeAngle);
    const float t = std::clamp((cosAlpha - co) / std::max(ci - co, 1e-4f), 0.0f, 1.0f);
    falloff = t * t;
  }
  return light.intensity * falloff * cosTheta / r2;
}

struct AcneCase {
  const char* name;
  Light light;
};

// A light whose central ray meets the floor's origin at `incidence` (radians from the normal),
// from height `h`.
glm::vec3 lightAtIncidence(float incidence, float h) {
  return {-h * std::tan(incidence), h, 0.0f};
}

std::vector<AcneCase> acneCases() {
  const float h = 1.0f;
  const auto spot = [&](float degrees) {
    const glm::vec3 p = lightAtIncidence(glm::radians(degrees), h);
    return spotAt(p, {0, 0, 0}, 0.2f, 0.3f, 2.0f);
  };
  return {
      {"spot 80 degrees", spot(80.0f)},
      {"spot 82 to 86 degrees",
       spotAt(lightAtIncidence(glm::radians(84.5f), 0.1f), {0, 0, 0}, 0.2f, 0.3f, 2.0f)},
      {"spot 60 degrees", spot(60.0f)},
      {"spot overhead", spot(0.0f)},
      {"point 80 degrees", pointAt(lightAtIncidence(glm::radians(80.0f), h), 2.0f)},
      {"point overhead", pointAt({0.05f, 0.5f, 0.03f}, 1.0f)},
  };
}

class ShadowAcne : public testing::TestWithParam<AcneCase> {};

// Every pixel sees the floor (20 m wide) from 1 m; nothing casts a shadow. The central ray's
// incidence is named per case; across the frame it spans 79°–81° (80°) and 82°–86° (near grazing).
TEST_P(ShadowAcne, UnoccludedPlaneIsNowhereDarkerThanTheClosedForm) {
  Scene scene;
  const glm::vec3 albedo(0.5f);
  addFloor(scene, albedo);
  scene.lights = {GetParam().light};
  const Camera camera = downCamera(1.0f);
  constexpr int kSize = 96;
  const Image image = renderWith(scene, camera, kSize, kSize, ShadowSettings{});
  std::vector<float> closedForm(image.pixels.size());
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      closedForm[image.index(x, y)] = sum(
          albedo / kPi * floorIrradiance(GetParam().light, floorPoint(camera, kSize, kSize, x, y)));
  // Where the spot's falloff t² nears its zero (below 1e-3 of the brightest pixel) float
  // rounding of t alone exceeds 1%: those pixels are left out.
  const float floor = 1e-3f * *std::max_element(closedForm.begin(), closedForm.end());
  int lit = 0, dark = 0;
  float worst = 1.0f;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const float expected = closedForm[image.index(x, y)];
      if (!(expected > floor)) continue;
      ++lit;
      const float ratio = sum(image.at(x, y)) / expected;
      worst = std::min(worst, ratio);
      if (ratio < 0.99f) {
        ++dark;
        std::printf("  dark pixel (%d, %d): %.5g of %.5g\n", x, y, sum(image.at(x, y)), expected);
      }
    }
  }
  std::printf("%s: %d lit pixels, %d darker than 99%%, darkest at %.4f\n", GetParam().name, lit,
              dark, worst);
  ASSERT_GT(lit, kSize * kSize / 4);
  EXPECT_EQ(dark, 0) << "darkest pixel at " << worst << " of the closed form";
}

INSTANTIATE_TEST_SUITE_P(Lights, ShadowAcne, testing::ValuesIn(acneCases()),
                         [](const testing::TestParamInfo<AcneCase>& param) {
                           std::string name = param.param.name;
                           std::replace(name.begin(), name.end(), ' ', '_');
                           return name;
                         });

// ---- 3. Peter-panning: a thin box on the floor ---------------------------------------------

struct PanningCase {
  const char* name;
  float zenith;  // radians: the light's elevation seen from the box's edge, from the normal
  LightType type = LightType::Spot;
};

class ShadowContact : public testing::TestWithParam<PanningCase> {};

// A 40×40 cm slab four shadow texels thick (w at the slab's edge under the default map: 4 mm
// for the spot, 9.4 mm for the point light's 90° cube faces) on a 2 m floor, lit from the −x
// side; a camera looks straight down at its +x edge (x = 0.2 m), 0.23 mm per pixel. Along each
// pixel row the true shadow starts at the edge; the first floor pixel the map shadows (V < ½)
// must lie within one shadow texel (w, perpendicular to the light) plus one pixel. Both faces
// are in the map, so what detaches a shadow is a bias reaching the caster's thickness along the
// light ray, h/cosθ (depth bias) or h (normal offset): a 4-texel slab shows either.
TEST_P(ShadowContact, ThinBoxShadowTouchesTheBox) {
  const glm::vec3 edge(0.2f, 0.0f, 0.0f);
  const float zenith = GetParam().zenith, distance = 1.2f;
  const glm::vec3 position = edge + distance * glm::vec3(-std::sin(zenith), std::cos(zenith), 0.0f);
  const Light light = GetParam().type == LightType::Point
                          ? pointAt(position, 3.0f)
                          : spotAt(position, edge, 0.3f, 0.4f, 3.0f);
  // The map's texel at the edge, for the scene's box (the floor decides it; the slab is thin).
  Box box;
  box.grow({-1.0f, 0.0f, -1.0f});
  box.grow({1.0f, 0.01f, 1.0f});
  const int resolution = light.type == LightType::Point
                             ? pointShadowResolutionFor(light.position, box, ShadowSettings{})
                             : spotShadowViewFor(light, box, ShadowSettings{}).resolution;
  const float texelAngle = light.type == LightType::Point
                               ? 2.0f / static_cast<float>(resolution)
                               : spotShadowViewFor(light, box, ShadowSettings{}).texelAngle;
  const float texel = texelAngle * glm::length(light.position - edge);

  Scene scene;
  Material floor;
  floor.name = "floor";
  floor.albedo = glm::vec3(0.5f);
  addQuad(scene, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, floor);
  Material slab;
  slab.name = "slab";
  slab.albedo = glm::vec3(0.5f);
  addBox(scene, {-0.2f, 0, -0.2f}, {0.2f, 4.0f * texel, 0.2f}, slab);
  scene.lights = {light};

  constexpr int kSize = 128;
  Camera camera = downCamera(0.25f, 2.0f * std::atan(0.015f / 0.25f));
  camera.cameraToWorld[3] = glm::vec4(0.21f, 0.25f, 0.0f, 1.0f);
  const Image withShadows = renderWith(scene, camera, kSize, kSize, ShadowSettings{});
  ShadowSettings off;
  off.enabled = false;
  const Image without = renderWith(scene, camera, kSize, kSize, off);
  const WorldGeometry geometry = flatten(scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  const std::vector<PixelSight> sights = pixelSights(*kernel, camera, kSize, kSize);

  const float pixel = 2.0f * 0.015f / kSize;

  float worstGap = 0.0f;
  int rows = 0;
  for (int y = kSize / 4; y < 3 * kSize / 4; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const std::size_t i = without.index(x, y);
      const PixelSight& s = sights[i];
      if (!s.hit.valid() || geometry.triangleInstance[s.hit.triangle] != 0 || s.position.x < 0.2f)
        continue;  // the slab, or the floor under its far side
      if (sum(withShadows.pixels[i]) / sum(without.pixels[i]) < 0.5f) {
        worstGap = std::max(worstGap, s.position.x - 0.2f);
        ++rows;
        break;
      }
    }
  }
  std::printf("%s: gap %.3f mm over %d rows; texel %.3f mm (resolution %d), pixel %.3f mm\n",
              GetParam().name, 1e3 * worstGap, rows, 1e3 * texel, resolution, 1e3 * pixel);
  ASSERT_EQ(rows, kSize / 2);  // every row finds the shadow
  EXPECT_LE(worstGap, texel + pixel);
}

INSTANTIATE_TEST_SUITE_P(
    Incidences, ShadowContact,
    testing::Values(PanningCase{"zenith_45", glm::radians(45.0f)},
                    PanningCase{"zenith_60", glm::radians(60.0f)},
                    PanningCase{"zenith_80", glm::radians(80.0f)},
                    PanningCase{"point_zenith_60", glm::radians(60.0f), LightType::Point},
                    PanningCase{"point_zenith_80", glm::radians(80.0f), LightType::Point}),
    [](const testing::TestParamInfo<PanningCase>& param) { return std::string(param.param.name); });

// ---- Model no more than the view needs -------------------------------------------------------

// A 20 m floor with a box under the camera and one 8 m away; the camera (1 m up, looking down)
// sees ±0.42 m around the origin.
Scene cullingScene(std::vector<Light> lights) {
  Scene scene;
  addFloor(scene, glm::vec3(0.5f));
  Material grey;
  grey.name = "grey";
  addBox(scene, {-0.1f, 0, -0.1f}, {0.1f, 0.2f, 0.1f}, grey);
  addBox(scene, {7.9f, 0, 7.9f}, {8.1f, 0.2f, 8.1f}, grey);
  scene.lights = std::move(lights);
  return scene;
}

ShadowDrawCount drawnFor(const Scene& scene) {
  testContext();
  ForwardRenderer renderer(scene, gl::shaderDirectory());
  (void)renderer.renderImage(downCamera(1.0f), 32, 32);
  return renderer.shadowDrawCount();
}

TEST(ShadowCulling, MapsThatCannotReachTheViewAreSkippedAndCastersCulled) {
  const Light near = spotAt({0.3f, 2.0f, 0.2f}, {0, 0, 0}, 0.4f, 0.5f, 1.0f);
  const Light far = spotAt({8.0f, 2.0f, 8.3f}, {8, 0, 8}, 0.4f, 0.5f, 1.0f);
  // The near spot's map holds the floor and the near box only.
  const ShadowDrawCount nearOnly = drawnFor(cullingScene({near}));
  EXPECT_EQ(nearOnly.views, 1);
  EXPECT_EQ(nearOnly.casters, 2);
  // The far spot lights nothing the camera sees: no map is rendered for it.
  const ShadowDrawCount both = drawnFor(cullingScene({near, far}));
  EXPECT_EQ(both.views, 1);
  EXPECT_EQ(both.casters, 2);
  // A point light 1.5 m over the origin: its +Y face sees no scene at all, and the far box
  // lies in one face only.
  const ShadowDrawCount point = drawnFor(cullingScene({pointAt({0.2f, 1.5f, 0.1f}, 1.0f)}));
  std::printf("point light: %d cube faces rendered, %d caster draws\n", point.views, point.casters);
  EXPECT_LE(point.views, 5);
  EXPECT_LE(point.casters, 2 * point.views + 1);
}

}  // namespace
}  // namespace bounce::test
