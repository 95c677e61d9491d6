// The forward renderer against closed-form radiometry. The renderer has no sampling noise: the
// only errors are float rounding in the shader and the rasterizer's interpolation of world
// positions (exact at pixel centres to float precision). llvmpipe measures ~1e-6 relative; the
// tolerance is 1e-3 relative because GLSL leaves the precision of transcendental functions
// (acos, atan, inversesqrt) to the implementation. It still catches any wrong factor: 680
// instead of 683 lm/W is 4.4e-3, a squared instead of a linear spot ramp far more.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene/light_falloff.h"
#include "test_scenes.h"

namespace bounce::test {
namespace {

constexpr int kSize = 64;
constexpr float kPi = std::numbers::pi_v<float>;
const glm::vec3 kAlbedo(0.8f, 0.5f, 0.25f);  // distinct per channel
constexpr float kRelTolerance = 1e-3f;

// The spot ramp of KHR_lights_punctual, written out independently of bounce::spotFalloff:
// t = saturate((cosθ − cos outer) / (cos inner − cos outer)), intensity factor t².
float khrSpotFactor(float cosTheta, float inner, float outer) {
  const float t = (cosTheta - std::cos(outer)) / (std::cos(inner) - std::cos(outer));
  const float clamped = t < 0.0f ? 0.0f : (t > 1.0f ? 1.0f : t);
  return clamped * clamped;
}

void expectNear(glm::vec3 actual, glm::vec3 expected, const char* what, int x, int y) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(actual[c], expected[c], kRelTolerance * std::abs(expected[c]) + 1e-7f)
        << what << " pixel (" << x << "," << y << ") channel " << c;
}

// Pixels spread over the image: centre, corners, edges and some off-axis points.
const int kPixels[][2] = {{32, 32}, {31, 31}, {0, 0},  {63, 0}, {0, 63}, {63, 63},
                          {10, 50}, {50, 12}, {32, 5}, {5, 32}, {45, 40}};

// Point light: L = ρ/π · I · cosθ / r², cosθ = height / r for the floor's normal +y.
TEST(Radiometry, PointLightFollowsInverseSquareAndCosine) {
  Scene scene;
  addFloor(scene, kAlbedo);
  Light light;
  light.type = LightType::Point;
  light.position = {0.3f, 1.5f, -0.2f};    // off the camera axis: cosθ varies across the image
  light.intensity = {10.0f, 20.0f, 5.0f};  // W/sr
  scene.lights.push_back(light);
  const Camera camera = downCamera(2.0f);
  const Image image = render(scene, camera, kSize, kSize);
  for (const auto& [x, y] : kPixels) {
    const glm::vec3 p = floorPoint(camera, kSize, kSize, x, y);
    const glm::vec3 toLight = light.position - p;
    const float r2 = glm::dot(toLight, toLight);
    const float cosTheta = toLight.y / std::sqrt(r2);
    expectNear(image.at(x, y), kAlbedo / kPi * light.intensity * cosTheta / r2, "point", x, y);
  }
}

// Directional light: L = ρ/π · E · cosθ, the same everywhere on the floor.
TEST(Radiometry, DirectionalLightGivesIrradianceTimesCosine) {
  Scene scene;
  addFloor(scene, kAlbedo);
  Light light;
  light.type = LightType::Directional;
  light.direction = glm::normalize(glm::vec3(1.0f, -2.0f, 0.5f));  // tilted
  light.irradiance = {3.0f, 1.0f, 2.0f};                           // W/m² at normal incidence
  scene.lights.push_back(light);
  const Camera camera = downCamera(2.0f);
  const Image image = render(scene, camera, kSize, kSize);
  const float cosTheta = -light.direction.y;
  for (const auto& [x, y] : kPixels)
    expectNear(image.at(x, y), kAlbedo / kPi * light.irradiance * cosTheta, "directional", x, y);
}

// bounce::spotFalloff (shared by the renderer and the path tracer) is the KHR_lights_punctual
// ramp: 1 inside the inner cone, 0 outside the outer, t² = 1/4 halfway between the cosines.
TEST(SpotFalloff, IsTheKhrLightsPunctualRamp) {
  Light light;
  light.type = LightType::Spot;
  light.innerConeAngle = 0.3f;
  light.outerConeAngle = 0.5f;
  const float cosInner = std::cos(0.3f), cosOuter = std::cos(0.5f);
  EXPECT_FLOAT_EQ(spotFalloff(light, 1.0f), 1.0f);
  EXPECT_FLOAT_EQ(spotFalloff(light, cosInner + 1e-4f), 1.0f);
  EXPECT_FLOAT_EQ(spotFalloff(light, cosOuter - 1e-4f), 0.0f);
  EXPECT_NEAR(spotFalloff(light, 0.5f * (cosInner + cosOuter)), 0.25f, 1e-5f);
  EXPECT_NEAR(spotFalloff(light, cosOuter + 0.25f * (cosInner - cosOuter)), 0.0625f, 1e-5f);
}

// Spot light pointing down from 1 m: full intensity inside the inner cone, zero outside the
// outer one, the KHR_lights_punctual ramp t² in between; every pixel is checked.
TEST(Radiometry, SpotLightFollowsSpotFalloff) {
  Scene scene;
  addFloor(scene, kAlbedo);
  Light light;
  light.type = LightType::Spot;
  light.position = {0.0f, 1.0f, 0.0f};
  light.direction = {0.0f, -1.0f, 0.0f};
  light.intensity = {4.0f, 4.0f, 4.0f};
  light.innerConeAngle = 0.3f;  // inner radius on the floor tan(0.3) = 0.31 m
  light.outerConeAngle = 0.5f;  // outer radius tan(0.5) = 0.55 m; the view spans ±0.84 m
  scene.lights.push_back(light);
  const Camera camera = downCamera(2.0f);
  const Image image = render(scene, camera, kSize, kSize);
  int inside = 0, between = 0, outside = 0;
  const float peak = light.intensity.r;  // cosθ/r² = 1 straight below
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const glm::vec3 p = floorPoint(camera, kSize, kSize, x, y);
      const glm::vec3 toLight = light.position - p;
      const float r = glm::length(toLight);
      const float cosAxis = glm::dot(-toLight / r, light.direction);
      const float falloff = khrSpotFactor(cosAxis, light.innerConeAngle, light.outerConeAngle);
      const glm::vec3 expected =
          kAlbedo / kPi * light.intensity * falloff * (toLight.y / r) / (r * r);
      // Near the cone edges a float ulp of cosθ moves t by ~1e-7/(cos inner − cos outer).
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(image.at(x, y)[c], expected[c], kRelTolerance * expected[c] + 1e-5f * peak)
            << "pixel (" << x << "," << y << ") falloff " << falloff;
      if (falloff == 1.0f)
        ++inside;
      else if (falloff == 0.0f)
        ++outside;
      else
        ++between;
    }
  }
  EXPECT_GT(inside, 50);
  EXPECT_GT(between, 100);
  EXPECT_GT(outside, 1000);
  EXPECT_EQ(image.at(0, 0), glm::vec3(0.0f));  // far outside the outer cone: exactly dark
}

// The light table has no fixed cap (render/light_table.h): 300 lights of every kind, unequal
// and tilted, are each drawn with their own parameters; the pixel is the sum of their closed
// forms. (The renderer drew only the first 32 punctual lights before; a wrong stride or field
// in the table moves every light.) Shadows off: the floor alone, nothing to occlude.
TEST(Radiometry, HundredsOfUnequalLightsOfEveryKindAreEachDrawn) {
  Scene scene;
  addFloor(scene, kAlbedo);
  for (int i = 0; i < 300; ++i) {
    const float a = static_cast<float>(i);
    Light light;
    light.type =
        i % 30 == 29 ? LightType::Directional : (i % 5 == 4 ? LightType::Spot : LightType::Point);
    light.position = {2.5f * std::sin(1.7f * a), 0.4f + 0.01f * a, 2.5f * std::cos(2.3f * a)};
    light.direction = glm::normalize(glm::vec3(0.4f * std::sin(a), -1.0f, 0.3f * std::cos(a)));
    const float scale = light.type == LightType::Directional ? 0.01f : 0.05f;
    light.intensity = scale * glm::vec3(1.0f + (i % 7), 1.0f + (i % 11), 1.0f + (i % 3));
    light.irradiance = light.intensity;
    light.innerConeAngle = 0.2f + 0.001f * a;
    light.outerConeAngle = light.innerConeAngle + 0.3f;
    scene.lights.push_back(light);
  }
  const Camera camera = downCamera(2.0f);
  testContext();
  RendererSettings settings;
  settings.shadows.enabled = false;
  ForwardRenderer renderer(scene, gl::shaderDirectory(), settings);
  const Image image = renderer.renderImage(camera, kSize, kSize);
  for (const auto& [x, y] : kPixels) {
    const glm::vec3 p = floorPoint(camera, kSize, kSize, x, y);
    glm::dvec3 irradiance(0.0);  // W/m²
    for (const Light& light : scene.lights) {
      if (light.type == LightType::Directional) {
        irradiance += glm::dvec3(light.irradiance) * static_cast<double>(-light.direction.y);
        continue;
      }
      const glm::vec3 toLight = light.position - p;
      const float r = glm::length(toLight);
      float factor = toLight.y / r / (r * r);  // cosθ / r²
      if (light.type == LightType::Spot)
        factor *= khrSpotFactor(glm::dot(-toLight / r, light.direction), light.innerConeAngle,
                                light.outerConeAngle);
      irradiance += glm::dvec3(light.intensity) * static_cast<double>(factor);
    }
    expectNear(image.at(x, y), kAlbedo / kPi * glm::vec3(irradiance), "300 lights", x, y);
  }
}

// Robustness: a mesh without shading normals is shaded with its geometric normal, and a
// zero-area emissive triangle lights nothing (and puts no NaN in the image).
TEST(Radiometry, MissingNormalsAndDegenerateEmittersStayFinite) {
  Scene scene;
  addFloor(scene, kAlbedo);
  scene.meshes.back().normals.assign(scene.meshes.back().positions.size(), glm::vec3(0.0f));
  Material emitter;
  emitter.emission = glm::vec3(5.0f);
  addQuad(scene, {0, 1, 0}, {1, 0, 0}, {2, 0, 0}, emitter);  // collinear: zero area
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = {0, -1, 0};
  sun.irradiance = glm::vec3(2.0f);
  scene.lights.push_back(sun);
  const Image image = render(scene, downCamera(2.0f), kSize, kSize);
  EXPECT_TRUE(image.allFinite());
  expectNear(image.at(20, 40), kAlbedo / kPi * sun.irradiance, "no normals", 20, 40);
}

}  // namespace
}  // namespace bounce::test
