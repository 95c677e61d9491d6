// A light edited after the renderer was built (ForwardRenderer::setLight: moved, turned,
// brighter, another colour) draws exactly as a renderer built with the edited light: the light
// table and its shadow map follow. Its kind cannot change.
#include <gtest/gtest.h>

#include "test_scenes.h"

namespace bounce::test {
namespace {

constexpr int kSize = 48;

Scene sceneWith(const std::vector<Light>& lights) {
  Scene scene;
  addFloor(scene, glm::vec3(0.5f));
  Material blocker;
  blocker.name = "blocker";
  blocker.albedo = glm::vec3(0.3f);
  blocker.doubleSided = true;
  addQuad(scene, {-0.2f, 0.5f, 0.2f}, {0.4f, 0, 0}, {0, 0, -0.4f}, blocker);  // casts shadows
  scene.lights = lights;
  return scene;
}

Light point(glm::vec3 at, glm::vec3 intensity) {
  Light l;
  l.name = "point";
  l.type = LightType::Point;
  l.position = at;
  l.intensity = intensity;
  return l;
}

Light spot(glm::vec3 at, glm::vec3 direction, glm::vec3 intensity) {
  Light l;
  l.name = "spot";
  l.type = LightType::Spot;
  l.position = at;
  l.direction = glm::normalize(direction);
  l.intensity = intensity;
  l.outerConeAngle = 0.9f;
  return l;
}

TEST(LightEdit, AnEditedLightDrawsAsIfBuiltThatWay) {
  const std::vector<Light> before = {point({0.3f, 1.2f, 0.1f}, glm::vec3(1.0f)),
                                     spot({-0.4f, 1.5f, 0}, {0.2f, -1, 0}, glm::vec3(2.0f))};
  const std::vector<Light> after = {
      point({-0.2f, 0.9f, -0.3f}, {2.0f, 1.0f, 0.5f}),
      spot({0.5f, 1.3f, 0.2f}, {-0.3f, -1, 0.1f}, {0.5f, 3.0f, 1.0f})};
  const Scene edited = sceneWith(before);
  const Scene built = sceneWith(after);
  const Camera camera = downCamera(2.0f);
  testContext();
  ForwardRenderer renderer(edited, gl::shaderDirectory());
  (void)renderer.renderImage(camera, kSize, kSize);  // a frame with the old lights first
  for (std::size_t i = 0; i < after.size(); ++i) renderer.setLight(i, after[i]);
  const Image a = renderer.renderImage(camera, kSize, kSize);
  ForwardRenderer reference(built, gl::shaderDirectory());
  const Image b = reference.renderImage(camera, kSize, kSize);
  RendererSettings unshadowed;
  unshadowed.shadows.enabled = false;
  ForwardRenderer lit(built, gl::shaderDirectory(), unshadowed);
  const Image c = lit.renderImage(camera, kSize, kSize);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  int shadowed = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(a.pixels[i][k], b.pixels[i][k]) << i;
    shadowed += b.pixels[i].g < 0.8f * c.pixels[i].g;
  }
  EXPECT_GT(shadowed, 20);  // the blocker's shadows are in the frame: the maps are exercised
  Light turned = after[0];
  turned.type = LightType::Spot;
  EXPECT_THROW(renderer.setLight(0, turned), std::invalid_argument);
}

}  // namespace
}  // namespace bounce::test
