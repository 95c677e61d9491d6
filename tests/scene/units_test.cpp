// The photometric → radiometric convention (units.h), both directions, and through the glTF
// loader: 683 cd → 1 W/sr, 683 lux → 1 W/m², emissive nits → W/(sr·m²).
#include <gtest/gtest.h>

#include "gltf_fixture.h"
#include "scene/load.h"
#include "scene/units.h"

namespace bounce {
namespace {

TEST(Units, PhotometricToRadiometricBothWays) {
  // At 683 lm/W one watt is 683 lumens: 683 cd = 1 W/sr, 683 lux = 1 W/m², 683 nit = 1 W/(sr·m²).
  EXPECT_DOUBLE_EQ(candelaToWattsPerSr(683.0), 1.0);
  EXPECT_DOUBLE_EQ(luxToWattsPerM2(683.0), 1.0);
  EXPECT_DOUBLE_EQ(nitsToRadiance(683.0), 1.0);
  EXPECT_DOUBLE_EQ(wattsPerSrToCandela(1.0), 683.0);
  EXPECT_DOUBLE_EQ(wattsPerM2ToLux(2.0), 1366.0);
  EXPECT_DOUBLE_EQ(radianceToNits(17.0), 11611.0);
  for (const double x : {1e-3, 0.5, 17.0, 1e5}) {  // round trips
    EXPECT_NEAR(candelaToWattsPerSr(wattsPerSrToCandela(x)), x, 1e-12 * x);
    EXPECT_NEAR(wattsPerM2ToLux(luxToWattsPerM2(x)), x, 1e-12 * x);
    EXPECT_NEAR(nitsToRadiance(radianceToNits(x)), x, 1e-12 * x);
  }
}

TEST(Units, GltfLightsAreConverted) {
  test::TempDir dir;
  test::GltfFixture f = test::GltfFixture::triangle();
  f.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  f.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "point"}, {"intensity", 683.0}},
      {{"type", "spot"},
       {"intensity", 1366.0},
       {"color", {1.0, 0.5, 0.0}},
       {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}},
      {{"type", "directional"}, {"intensity", 683.0}}};
  for (int i = 0; i < 3; ++i) {
    f.doc["nodes"].push_back({{"translation", {0.0, 2.0, 0.0}},
                              {"extensions", {{"KHR_lights_punctual", {{"light", i}}}}}});
    f.doc["scenes"][0]["nodes"].push_back(f.doc["nodes"].size() - 1);
  }
  f.writeGltf(dir / "lights.gltf");
  const Scene scene = loadScene(dir / "lights.gltf");
  ASSERT_EQ(scene.lights.size(), 3u);
  EXPECT_EQ(scene.lights[0].type, LightType::Point);
  EXPECT_EQ(scene.lights[0].intensity, glm::vec3(1.0f));  // 683 cd = 1 W/sr
  EXPECT_EQ(scene.lights[0].position, glm::vec3(0, 2, 0));
  EXPECT_EQ(scene.lights[1].type, LightType::Spot);
  EXPECT_EQ(scene.lights[1].intensity, glm::vec3(2.0f, 1.0f, 0.0f));  // colour × 1366 cd
  EXPECT_FLOAT_EQ(scene.lights[1].innerConeAngle, 0.2f);
  EXPECT_FLOAT_EQ(scene.lights[1].outerConeAngle, 0.5f);
  EXPECT_EQ(scene.lights[2].type, LightType::Directional);
  EXPECT_EQ(scene.lights[2].irradiance, glm::vec3(1.0f));  // 683 lux = 1 W/m²
  for (const Light& light : scene.lights) EXPECT_EQ(light.direction, glm::vec3(0, 0, -1));
}

TEST(Units, GltfEmissionIsLuminanceInNits) {
  test::TempDir dir;
  test::GltfFixture f = test::GltfFixture::triangle();
  f.doc["materials"] = {
      {{"emissiveFactor", {1.0, 0.5, 0.25}},
       {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 1366.0}}}}}},
      {{"emissiveFactor", {1.0, 1.0, 1.0}}}};  // no strength: 1 nit
  f.doc["meshes"][0]["primitives"][0]["material"] = 0;
  f.writeGltf(dir / "emissive.gltf");
  const Scene scene = loadScene(dir / "emissive.gltf");
  EXPECT_EQ(scene.materials.at(0).emission, glm::vec3(2.0f, 1.0f, 0.5f));
  EXPECT_FLOAT_EQ(scene.materials.at(1).emission.r, static_cast<float>(1.0 / 683.0));
}

}  // namespace
}  // namespace bounce
