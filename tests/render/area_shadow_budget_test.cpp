// GL-free: which area lights get the shadow cubes (render/area_shadow_budget.h). The largest
// irradiance from a square against its closed form, and the choice following a dynamic box
// from lamp to lamp among stronger, distant lights.
#include "render/area_shadow_budget.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace bounce {
namespace {

// Two triangles of a horizontal square of side `side` centred at `centre`, facing down, of
// radiance `radiance` W/(sr·m²), on instance `instance`.
void addCeilingSquare(std::vector<EmitterTriangle>& triangles, glm::vec3 centre, float side,
                      float radiance, uint32_t instance) {
  const float h = side / 2;
  // Counter-clockwise seen from below: front normal −y.
  const glm::vec3 a = centre + glm::vec3(-h, 0, -h), b = centre + glm::vec3(h, 0, -h),
                  c = centre + glm::vec3(h, 0, h), d = centre + glm::vec3(-h, 0, h);
  EmitterTriangle t;
  t.radiance = glm::vec3(radiance);
  t.instance = instance;
  t.v0 = a, t.v1 = b, t.v2 = c;
  triangles.push_back(t);
  t.v0 = a, t.v1 = c, t.v2 = d;
  triangles.push_back(t);
}

// Irradiance per unit radiance (π·form factor) at a point under the corner of an X × Y
// rectangle at height 1, parallel to it (the unit-distance corner form factor).
double cornerIrradiance(double x, double y) {
  const double sx = std::sqrt(1 + x * x), sy = std::sqrt(1 + y * y);
  return 0.5 * (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy));
}

TEST(AreaShadowBudget, LargestIrradianceUnderASquareIsTheClosedForm) {
  std::vector<EmitterTriangle> triangles;
  addCeilingSquare(triangles, {0.0f, 2.0f, 0.0f}, 1.0f, 3.0f, 0);
  const AreaLightSet set = splitAreaLights(triangles);
  ASSERT_EQ(set.lights.size(), 1u);
  for (const float height : {0.1f, 0.5f, 1.0f, 3.0f}) {
    // On the axis the best-facing surface looks straight up: four corner rectangles of 0.5².
    const double expected = 3.0 * 4.0 * cornerIrradiance(0.5 / height, 0.5 / height);
    EXPECT_NEAR(largestIrradiance(set, 0, {0.0f, 2.0f - height, 0.0f}), expected, 1e-4 * expected)
        << "height " << height;
  }
  // Above a single-sided light: nothing; on the light itself: the hemisphere's π·L.
  EXPECT_EQ(largestIrradiance(set, 0, {0.0f, 2.5f, 0.0f}), 0.0f);
  EXPECT_LE(largestIrradiance(set, 0, {0.0f, 2.0f - 1e-6f, 0.0f}),
            std::numbers::pi_v<float> * 3.0f * (1 + 1e-6f));
}

// Three strong ceiling panels (flux 40× a lamp's) 6 m away, and two weak lamps 0.6 m over two
// spots on the floor; a dynamic 0.3 m box on the floor under one lamp, then under the other.
struct LampsAndPanels {
  AreaLightSet set;
  static constexpr float kLampRadiance = 5.0f, kPanelRadiance = 50.0f;
  static constexpr glm::vec3 kUnderLampA{0.0f, 0.0f, 0.0f}, kUnderLampB{3.0f, 0.0f, 0.0f};
  LampsAndPanels() {
    std::vector<EmitterTriangle> triangles;
    addCeilingSquare(triangles, {-6.0f, 3.0f, 6.0f}, 0.8f, kPanelRadiance, 0);
    addCeilingSquare(triangles, {6.0f, 3.0f, 6.0f}, 0.8f, kPanelRadiance, 1);
    addCeilingSquare(triangles, {0.0f, 3.0f, -6.0f}, 0.8f, kPanelRadiance, 2);
    addCeilingSquare(triangles, kUnderLampA + glm::vec3(0, 0.9f, 0), 0.4f, kLampRadiance, 3);
    addCeilingSquare(triangles, kUnderLampB + glm::vec3(0, 0.9f, 0), 0.4f, kLampRadiance, 4);
    set = splitAreaLights(triangles);
  }
  static AreaShadowReceivers boxAt(glm::vec3 floor) {
    AreaShadowReceivers receivers;
    receivers.dynamics.push_back(
        {Box{floor - glm::vec3(0.15f, 0, 0.15f), floor + glm::vec3(0.15f, 0.3f, 0.15f)}, 9});
    return receivers;
  }
};

TEST(AreaShadowBudget, AWeakLampOverTheDynamicBoxWinsOverStrongDistantPanels) {
  const LampsAndPanels scene;
  ASSERT_EQ(scene.set.lights.size(), 5u);
  // The old rule (the most flux first) gives the three panels every slot.
  EXPECT_EQ(pickShadowedAreaLights(scene.set.lights, 3), (std::vector<uint32_t>{0, 1, 2}));

  const std::vector<float> c =
      areaLightContributions(scene.set, LampsAndPanels::boxAt(LampsAndPanels::kUnderLampA));
  // Lamp A at 0.6 m over the box's top (0.4 m square): E ≈ L·4·corner(0.2/0.6, 0.2/0.6); a
  // panel 6.7 m away: E ≲ L·A/d².
  const double lampA = LampsAndPanels::kLampRadiance * 4 * cornerIrradiance(1.0 / 3, 1.0 / 3);
  EXPECT_NEAR(c[3], lampA, 0.02 * lampA);
  for (const std::size_t panel : {0u, 1u, 2u}) EXPECT_LT(c[panel], 0.2 * c[3]);

  const float floor = 0.01f;  // W/m²
  const ShadowChoice one = chooseShadowedLights(c, 1, floor);
  EXPECT_EQ(one.lights, (std::vector<uint32_t>{3}));
  EXPECT_EQ(one.unshadowed, 4u);  // every other light reaches the box above the floor
  EXPECT_NEAR(one.unshadowedContribution, c[0] + c[1] + c[2] + c[4], 1e-6);
  const ShadowChoice three = chooseShadowedLights(c, 3, floor);
  ASSERT_EQ(three.lights.size(), 3u);
  EXPECT_EQ(three.lights[0], 3u);
}

TEST(AreaShadowBudget, TheChoiceFollowsTheBoxToTheOtherLamp) {
  const LampsAndPanels scene;
  const float floor = 0.01f;
  const std::vector<float> underA =
      areaLightContributions(scene.set, LampsAndPanels::boxAt(LampsAndPanels::kUnderLampA));
  const ShadowChoice first = chooseShadowedLights(underA, 1, floor);
  ASSERT_EQ(first.lights, (std::vector<uint32_t>{3}));
  const std::vector<float> underB =
      areaLightContributions(scene.set, LampsAndPanels::boxAt(LampsAndPanels::kUnderLampB));
  // Lamp A held the slot; lamp B now brings far more than 10% more, so it takes it.
  EXPECT_EQ(chooseShadowedLights(underB, 1, floor, first.lights).lights,
            (std::vector<uint32_t>{4}));
  // A light the box does not reach above the floor gets no slot, however many are free.
  const ShadowChoice strict = chooseShadowedLights(underB, 5, 0.5f * underB[4]);
  EXPECT_EQ(strict.lights, (std::vector<uint32_t>{4}));
  EXPECT_EQ(strict.unshadowed, 0u);
}

TEST(AreaShadowBudget, AHeldSlotIsKeptAgainstARivalLessThanTenPercentStronger) {
  const std::vector<float> c = {1.0f, 1.05f, 2.0f};
  EXPECT_EQ(chooseShadowedLights(c, 2, 0.0f).lights, (std::vector<uint32_t>{2, 1}));
  const std::vector<uint32_t> held = {0, 2};
  EXPECT_EQ(chooseShadowedLights(c, 2, 0.0f, held).lights, (std::vector<uint32_t>{2, 0}));
}

// The visible volume ranks lights without baked visibility, not those with it.
TEST(AreaShadowBudget, ViewPointsRankOnlyLightsWithoutBakedVisibility) {
  const LampsAndPanels scene;
  AreaShadowReceivers receivers;
  receivers.viewPoints = {{3.0f, 0.2f, 0.0f}, {3.2f, 0.1f, 0.1f}};
  const std::vector<float> all = areaLightContributions(scene.set, receivers);
  EXPECT_GT(all[4], all[3]);
  EXPECT_GT(all[4], 0.0f);
  receivers.bakedVisibilityLights = 5;
  for (const float c : areaLightContributions(scene.set, receivers)) EXPECT_EQ(c, 0.0f);
}

// Six layers per cube in one depth array: GL 3.3's 256 layers hold every slot of the shader.
TEST(AreaShadowSlots, SixLayersPerCubeUpToTheShadersSlots) {
  EXPECT_EQ(areaShadowSlotCapacity(256), kMaxAreaShadows);
  EXPECT_EQ(areaShadowSlotCapacity(6 * kMaxAreaShadows), kMaxAreaShadows);
  EXPECT_EQ(areaShadowSlotCapacity(6 * kMaxAreaShadows - 1), kMaxAreaShadows - 1);
  EXPECT_EQ(areaShadowSlotCapacity(5), 0);
}

}  // namespace
}  // namespace bounce
