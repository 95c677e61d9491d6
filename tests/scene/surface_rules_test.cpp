// scene/surface_rules.h: each rule against its statement.
#include "scene/surface_rules.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace bounce {
namespace {

TEST(SurfaceRules, NegativeChannelsDoNotEmitAndNonFiniteEmissionSilencesTheMaterial) {
  Material m;
  m.emission = {2.0f, -1.0f, 0.5f};
  EXPECT_EQ(emittedRadiance(m), glm::vec3(2.0f, 0.0f, 0.5f));
  EXPECT_TRUE(m.isEmissive());
  m.emission = {-1.0f, -2.0f, 0.0f};
  EXPECT_FALSE(m.isEmissive());
  m.emission = {5.0f, std::numeric_limits<float>::infinity(), 1.0f};
  EXPECT_EQ(emittedRadiance(m), glm::vec3(0.0f));
  EXPECT_FALSE(m.isEmissive());
  m.emission = {5.0f, std::nanf(""), 1.0f};
  EXPECT_FALSE(m.isEmissive());
}

TEST(SurfaceRules, ReflectanceIsClampedAndNonFiniteAbsorbs) {
  Material m;
  m.albedo = {1.5f, -0.2f, 0.4f};
  EXPECT_EQ(reflectance(m), glm::vec3(1.0f, 0.0f, 0.4f));
  m.albedo = {0.5f, std::nanf(""), 0.5f};
  EXPECT_EQ(reflectance(m), glm::vec3(0.0f));
}

TEST(SurfaceRules, EmitterTrianglesNeedPositiveFiniteArea) {
  Material m;
  m.emission = glm::vec3(1.0f);
  EXPECT_TRUE(isEmitterTriangle(m, {0, 0, 2}));
  EXPECT_FALSE(isEmitterTriangle(m, {0, 0, 0}));
  EXPECT_FALSE(isEmitterTriangle(m, {std::numeric_limits<float>::infinity(), 0, 0}));
  m.emission = glm::vec3(0.0f);
  EXPECT_FALSE(isEmitterTriangle(m, {0, 0, 2}));
}

TEST(SurfaceRules, BadMaterialIndexIsABlackAbsorber) {
  Scene scene;
  Material red;
  red.albedo = {1, 0, 0};
  red.emission = {3, 3, 3};
  scene.materials = {red};
  EXPECT_EQ(&materialOf(scene, 0), &scene.materials[0]);
  const Material& missing = materialOf(scene, 1);
  EXPECT_EQ(reflectance(missing), glm::vec3(0.0f));
  EXPECT_FALSE(missing.isEmissive());
  EXPECT_EQ(reflectance(materialOf(Scene{}, 0)), glm::vec3(0.0f));
}

TEST(SurfaceRules, UnusableShadingNormalsFallBackToTheGeometricNormal) {
  const glm::vec3 g(0, 0, 1);
  EXPECT_EQ(shadingNormalOr({0, 0, 0}, g), g);
  EXPECT_EQ(shadingNormalOr({std::nanf(""), 0, 1}, g), g);
  EXPECT_EQ(shadingNormalOr({1e-8f, 0, 0}, g), g);
  const glm::vec3 n = shadingNormalOr({0, 3, 4}, g);
  EXPECT_NEAR(n.y, 0.6f, 1e-6f);
  EXPECT_NEAR(n.z, 0.8f, 1e-6f);
}

}  // namespace
}  // namespace bounce
