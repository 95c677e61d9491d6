// More spot or point lights than maps, in a frame: the maps go to the light that lights the
// view, though it comes last in the file after lights of the same kind that shine elsewhere
// (render/punctual_shadow_budget.h). Its shadows agree with ray-traced visibility as when it is
// alone; with the first lights of the file taking the maps it would have none.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "render/texture_units.h"
#include "shadow_scenes.h"

namespace bounce::test {
namespace {

// `light` over the occluder scene, after `kinds` lights of its kind that shine 20 m away
// (spots aimed at another floor; points ten times as strong, bringing under 1% here).
void expectTheViewsLightGetsAMap(const Light& light, int others) {
  const Scene alone = occluderScene(light);
  Scene crowded = alone;
  crowded.lights.clear();
  for (int i = 0; i < others; ++i) {
    const glm::vec3 at(20.0f + static_cast<float>(i), 3.0f, -20.0f);
    Light other = light.type == LightType::Spot
                      ? spotAt(at, at - glm::vec3(0, 3, 0), 0.5f, 0.6f, 100.0f * light.intensity.x)
                      : pointAt(at, 10.0f * light.intensity.x);
    other.name = "elsewhere " + std::to_string(i);
    crowded.lights.push_back(other);
  }
  crowded.lights.push_back(light);
  ShadowSettings off;
  off.enabled = false;
  const Camera camera = occluderCamera();
  const Agreement a = compareVisibility(alone, camera, renderWith(crowded, camera, 128, 128, {}),
                                        renderWith(crowded, camera, 128, 128, off));
  std::printf("%s after %d others of its kind: %d of %d pixels disagree (%.3f%%), %d shadowed\n",
              light.name.c_str(), others, a.disagreeing, a.considered, 100.0 * a.fraction(),
              a.shadowed);
  ASSERT_GT(a.considered, 128 * 128 / 4);
  ASSERT_GT(a.shadowed, a.considered / 20);
  EXPECT_LE(a.fraction(), 0.005);
}

TEST(PunctualShadowBudgetFrame, TheSpotLightingTheViewGetsAMapThoughFourSpotsComeFirst) {
  expectTheViewsLightGetsAMap(occluderSpot(), kMaxSpotShadows);
}

TEST(PunctualShadowBudgetFrame, ThePointLightingTheViewGetsACubeThoughTwoPointsComeFirst) {
  expectTheViewsLightGetsAMap(occluderPoint(), kMaxPointShadows);
}

}  // namespace
}  // namespace bounce::test
