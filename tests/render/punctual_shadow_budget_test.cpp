// GL-free: which point, spot and directional lights get the shadow maps
// (render/punctual_shadow_budget.h). The largest irradiance against its closed forms, a weak
// spot over a dynamic box winning over strong spots that light something else, kinds competing
// only among themselves, slots kept while chosen, baked-direct lights needing none.
#include "render/punctual_shadow_budget.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bounce {
namespace {

Light spot(glm::vec3 position, glm::vec3 target, float intensity) {
  Light l;
  l.type = LightType::Spot;
  l.position = position;
  l.direction = glm::normalize(target - position);
  l.innerConeAngle = 0.3f;
  l.outerConeAngle = 0.5f;
  l.intensity = glm::vec3(intensity);
  return l;
}

Light point(glm::vec3 position, float intensity) {
  Light l;
  l.type = LightType::Point;
  l.position = position;
  l.intensity = glm::vec3(intensity);
  return l;
}

std::vector<glm::vec3> powers(const std::vector<Light>& lights) {
  std::vector<glm::vec3> p;
  for (const Light& l : lights)
    p.push_back(l.type == LightType::Directional ? l.irradiance : l.intensity);
  return p;
}

ShadowReceivers boxAt(glm::vec3 floor) {
  ShadowReceivers receivers;
  receivers.dynamics.push_back(
      {Box{floor - glm::vec3(0.15f, 0, 0.15f), floor + glm::vec3(0.15f, 0.3f, 0.15f)}, 0});
  return receivers;
}

TEST(PunctualShadowBudget, LargestIrradianceIsTheInverseSquareLawTimesTheSpotFalloff) {
  const Light p = point({0, 2, 0}, 4.0f);
  EXPECT_FLOAT_EQ(largestPunctualIrradiance(p, glm::vec3(4, 1, 2), {0, 0, 0}), 1.0f);
  EXPECT_FLOAT_EQ(largestPunctualIrradiance(p, glm::vec3(4), {3, 2, 4}), 4.0f / 25.0f);
  const Light s = spot({0, 2, 0}, {0, 0, 0}, 8.0f);
  EXPECT_FLOAT_EQ(largestPunctualIrradiance(s, glm::vec3(8), {0, 0, 0}), 2.0f);  // on the axis
  // Between the cones: t = (cosθ − cos 0.5)/(cos 0.3 − cos 0.5), falloff t².
  const float theta = 0.4f, r = 1.5f;
  const glm::vec3 q = glm::vec3(0, 2, 0) + r * glm::vec3(std::sin(theta), -std::cos(theta), 0);
  const float t = (std::cos(theta) - std::cos(0.5f)) / (std::cos(0.3f) - std::cos(0.5f));
  EXPECT_NEAR(largestPunctualIrradiance(s, glm::vec3(8), q), 8.0f * t * t / (r * r), 1e-4f);
  EXPECT_EQ(largestPunctualIrradiance(s, glm::vec3(8), {3, 0, 0}), 0.0f);  // outside the cone
  Light sun;
  sun.type = LightType::Directional;
  EXPECT_EQ(largestPunctualIrradiance(sun, glm::vec3(3, 7, 5), {100, -4, 2}), 7.0f);
}

// Four strong spots (100× the flux) light a stage 8 m away; a weak spot stands over the spot
// where the dynamic box is. The strong ones come first in the file.
TEST(PunctualShadowBudget, AWeakSpotOverTheDynamicBoxWinsOverStrongSpotsLightingElsewhere) {
  std::vector<Light> lights;
  for (int i = 0; i < 4; ++i)
    lights.push_back(
        spot({8.0f + static_cast<float>(i), 3, 0}, {8.0f + static_cast<float>(i), 0, 0}, 100.0f));
  lights.push_back(spot({0, 1.2f, 0}, {0, 0, 0}, 1.0f));
  const std::vector<float> c = punctualLightContributions(lights, powers(lights), boxAt({0, 0, 0}));
  // The weak spot at 0.9 m over the box's top: 1/0.81 W/m² on its axis.
  EXPECT_NEAR(c[4], 1.0f / 0.81f, 1e-4f);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(c[static_cast<std::size_t>(i)], 0.0f);  // cones miss it
  const PunctualShadowSlots one{1, 0, 0};
  EXPECT_EQ(assignPunctualShadowSlots(lights, c, one, 0.0f, {}),
            (std::vector<int>{-1, -1, -1, -1, 0}));
  // With the box on the stage, the strong spots win the slots.
  const std::vector<float> onStage =
      punctualLightContributions(lights, powers(lights), boxAt({9.5f, 0, 0}));
  const std::vector<int> held = assignPunctualShadowSlots(lights, c, {4, 0, 0}, 0.0f, {});
  EXPECT_EQ(held, (std::vector<int>{-1, -1, -1, -1, 0}));
  const std::vector<int> next = assignPunctualShadowSlots(lights, onStage, {4, 0, 0}, 0.0f, held);
  EXPECT_EQ(next[4], -1);  // the weak spot no longer reaches the box: it frees its slot
  std::vector<int> sorted(next.begin(), next.begin() + 4);
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, (std::vector<int>{0, 1, 2, 3}));
}

// The view's static surfaces rank a light as the mean of its irradiance over their points.
TEST(PunctualShadowBudget, ViewPointsRankByTheMeanIrradianceOverTheVisibleSurfaces) {
  const std::vector<Light> lights = {point({0, 2, 0}, 4.0f), point({10, 1, 0}, 1.0f)};
  ShadowReceivers view;
  view.viewPoints = {{0, 0, 0}, {0, 1, 0}, {10, 0, 0}};
  const std::vector<float> c = punctualLightContributions(lights, powers(lights), view);
  EXPECT_NEAR(c[0], (4.0f / 4 + 4.0f / 1 + 4.0f / 104) / 3, 1e-5f);
  EXPECT_NEAR(c[1], (1.0f / 101 + 1.0f / 100 + 1.0f / 1) / 3, 1e-5f);
  EXPECT_EQ(assignPunctualShadowSlots(lights, c, {0, 1, 0}, 0.0f, {}), (std::vector<int>{0, -1}));
}

// A light whose visibility every static surface reads from the bake (bakedOnStatics) is ranked
// by the dynamic instances in its reach alone: the view points bring it nothing, so with no
// dynamic instance it needs no map; a box under it brings its largest irradiance there.
TEST(PunctualShadowBudget, ABakedLightIsRankedByTheDynamicInstancesAlone) {
  const std::vector<Light> lights = {point({0, 2, 0}, 4.0f), point({10, 1, 0}, 1.0f)};
  const std::vector<uint8_t> baked = {1, 0};
  ShadowReceivers view;
  view.viewPoints = {{0, 0, 0}, {0, 1, 0}, {10, 0, 0}};
  std::vector<float> c = punctualLightContributions(lights, powers(lights), view, 0.0f, baked);
  EXPECT_EQ(c[0], 0.0f);
  EXPECT_NEAR(c[1], (1.0f / 101 + 1.0f / 100 + 1.0f / 1) / 3, 1e-5f);  // not baked: as before
  ShadowReceivers box = boxAt({0, 0, 0});
  box.viewPoints = view.viewPoints;
  c = punctualLightContributions(lights, powers(lights), box, 0.0f, baked);
  // The box's top (0.3 m up) is 1.7 m from the lamp: I/d².
  EXPECT_NEAR(c[0], 4.0f / (1.7f * 1.7f), 1e-4f);
}

// Weighted by the screen their surface takes, near points rank a light; one that reaches the
// floor at a single point still competes, with its (small) mean; one under it everywhere does
// not, whatever its mean.
TEST(PunctualShadowBudget, ScreenWeightsRankAndTheFloorIsTestedWhereTheLightIsStrongest) {
  const glm::vec3 eye(0, 1, 0);
  ShadowReceivers view;
  view.viewPoints = {{0, 0, -1}, {0, 0, -20}};
  for (const glm::vec3& p : view.viewPoints)
    view.viewWeights.push_back(viewPointWeight(eye, p, 0.5f));
  EXPECT_NEAR(view.viewWeights[0], 0.5f / 2.0f, 1e-6f);
  EXPECT_NEAR(view.viewWeights[1], 0.5f / 401.0f, 1e-6f);
  EXPECT_EQ(viewPointWeight(eye, {0, 1, -0.1f}, 0.5f), 1.0f);  // fills the view: capped
  // Near the camera and weak, far and strong: the near light brings more to the screen.
  const std::vector<Light> lights = {point({0, 1, -1}, 1.0f), point({0, 1, -20}, 4.0f)};
  const std::vector<float> c = punctualLightContributions(lights, powers(lights), view);
  const float w0 = view.viewWeights[0], w1 = view.viewWeights[1];
  EXPECT_NEAR(c[0], (w0 * 1.0f + w1 * 1.0f / 362.0f) / (w0 + w1), 1e-5f);
  EXPECT_NEAR(c[1], (w0 * 4.0f / 362.0f + w1 * 4.0f) / (w0 + w1), 1e-5f);
  EXPECT_GT(c[0], c[1]);
  // Floor 2 W/m²: light 1 reaches 4 W/m² at the far point, so it competes with its mean.
  const std::vector<float> floored = punctualLightContributions(lights, powers(lights), view, 2.0f);
  EXPECT_EQ(floored[0], 0.0f);  // at most 1 W/m² anywhere
  EXPECT_NEAR(floored[1], c[1], 1e-6f);
  EXPECT_LT(floored[1], 2.0f);
  EXPECT_EQ(assignPunctualShadowSlots(lights, floored, {0, 2, 0}, 0.0f, {}),
            (std::vector<int>{-1, 0}));
}

// Spots take spot slots and points point slots, whatever they bring; a light drawn with no power
// (its direct light baked) gets none; a held slot stays with its light against a rival under 10%
// stronger, and a newly chosen light takes the slot another one freed.
TEST(PunctualShadowBudget, KindsCompeteAmongThemselvesAndSlotsStayWithTheirLights) {
  std::vector<Light> lights = {point({0, 1, 0}, 1.0f), spot({0, 3, 0}, {0, 0, 0}, 1.0f),
                               point({0, 1, 1}, 50.0f), point({0, 1, -1}, 52.0f),
                               spot({0, 3, 1}, {0, 0, 1}, 50.0f)};
  const std::vector<float> c = {1.0f, 1.0f, 50.0f, 52.0f, 50.0f};
  const PunctualShadowSlots slots{1, 1, 1};
  EXPECT_EQ(assignPunctualShadowSlots(lights, c, slots, 0.0f, {}),
            (std::vector<int>{-1, -1, -1, 0, 0}));
  // Point 2 held the cube: point 3 brings only 4% more.
  const std::vector<int> held = {-1, -1, 0, -1, -1};
  EXPECT_EQ(assignPunctualShadowSlots(lights, c, slots, 0.0f, held)[2], 0);
  EXPECT_EQ(assignPunctualShadowSlots(lights, c, slots, 0.0f, held)[3], -1);
  // Two cubes: point 3 takes the one point 2 does not hold.
  const std::vector<int> secondCube = {-1, -1, 1};
  const std::vector<int> two = assignPunctualShadowSlots(lights, c, {1, 2, 1}, 0.0f, secondCube);
  EXPECT_EQ(two[2], 1);
  EXPECT_EQ(two[3], 0);
  // Spot 4's direct light is baked: it is drawn with no power and spot 1 gets the map.
  std::vector<glm::vec3> power = powers(lights);
  power[4] = glm::vec3(0.0f);
  ShadowReceivers view;
  view.viewPoints = {{0, 0, 0}, {0, 0, 1}};
  const std::vector<float> baked = punctualLightContributions(lights, power, view);
  EXPECT_EQ(baked[4], 0.0f);
  EXPECT_EQ(assignPunctualShadowSlots(lights, baked, slots, 0.0f, {})[1], 0);
  // A light under the floor gets no map, however many slots are free...
  EXPECT_EQ(assignPunctualShadowSlots(lights, c, {4, 4, 1}, 10.0f, {})[0], -1);
  // ...but keeps the one it has while no light chosen over the floor needs it.
  const std::vector<int> pointZeroHeld = {2, -1, -1, -1, -1};
  const std::vector<int> kept =
      assignPunctualShadowSlots(lights, c, {4, 3, 1}, 10.0f, pointZeroHeld);
  EXPECT_EQ(kept[0], 2);
  EXPECT_EQ(kept[3], 0);  // largest first
  EXPECT_EQ(kept[2], 1);
  EXPECT_EQ(assignPunctualShadowSlots(lights, c, {4, 2, 1}, 10.0f, pointZeroHeld)[0], -1);
}

}  // namespace
}  // namespace bounce
