// What the renderer keeps between frames (issue 27): a still camera's second frame neither
// rebuilds the light lists (LightCulling::gridBuilds) nor redraws the point lights' shadow cubes
// (shadow_map_stamp.h); moving an instance (it changes the scene's box and the casters) or a
// light does, and the frame then equals a fresh renderer's bit for bit.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "test_scenes.h"
#include "vpl_cost_scene.h"

namespace bounce::test {
namespace {

constexpr int kSize = 32;

Scene litFloorWithABox() {
  Scene scene;
  Material white;
  white.name = "floor";
  white.albedo = glm::vec3(0.5f);
  addQuad(scene, {-0.5f, 0, 0.5f}, {1, 0, 0}, {0, 0, -1}, white);
  addQuad(scene, {-0.1f, 0.3f, 0.1f}, {0.2f, 0, 0}, {0, 0, -0.2f}, white);
  scene.instances[1].mobility = Mobility::Dynamic;
  for (int i = 0; i < 3; ++i) {
    Light light;
    light.type = LightType::Point;
    light.name = "point " + std::to_string(i);
    light.position = {-0.3f + 0.3f * static_cast<float>(i), 0.5f, 0.0f};
    light.intensity = glm::vec3(0.2f);
    scene.lights.push_back(light);
  }
  return scene;
}

TEST(FrameCache, StillCameraKeepsTheLightListsAndAMoveRebuildsThemAsAFreshRenderer) {
  testContext();
  const Scene scene = litFloorWithABox();
  const Camera camera = downCamera(1.0f);
  ForwardRenderer renderer(scene, gl::shaderDirectory());
  const Image first = renderer.renderImage(camera, kSize, kSize);
  const uint64_t builds = renderer.lightGridBuilds();
  EXPECT_EQ(builds, 1u);
  EXPECT_GT(renderer.shadowDrawCount().views, 0);
  const Image second = renderer.renderImage(camera, kSize, kSize);
  EXPECT_EQ(renderer.lightGridBuilds(), builds) << "a still camera rebuilt the light lists";
  EXPECT_EQ(renderer.shadowDrawCount().views, 0) << "a still scene redrew its shadow cubes";
  EXPECT_EQ(first.pixels, second.pixels);

  // The box rises 0.4 m: the scene's box grows, the lists are rebuilt.
  const glm::mat4 raised = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.4f, 0.0f));
  renderer.setInstanceTransform(1, raised * scene.instances[1].transform);
  const Image moved = renderer.renderImage(camera, kSize, kSize);
  EXPECT_EQ(renderer.lightGridBuilds(), builds + 1);
  EXPECT_GT(renderer.shadowDrawCount().views, 0);
  Scene placed = scene;
  placed.instances[1].transform = raised * placed.instances[1].transform;
  ForwardRenderer fresh(placed, gl::shaderDirectory());
  const Image expected = fresh.renderImage(camera, kSize, kSize);
  EXPECT_EQ(moved.pixels, expected.pixels);

  // A light moved (setLight) changes its reach: rebuilt, and drawn as a fresh renderer does.
  Light light = scene.lights[0];
  light.position.x = 0.4f;
  renderer.setLight(0, light);
  const Image relit = renderer.renderImage(camera, kSize, kSize);
  EXPECT_EQ(renderer.lightGridBuilds(), builds + 2);
  placed.lights[0] = light;
  ForwardRenderer freshLit(placed, gl::shaderDirectory());
  EXPECT_EQ(relit.pixels, freshLit.renderImage(camera, kSize, kSize).pixels);

  // The camera moves: the lists are rebuilt; the cubes faces already drawn stay.
  const Image lower = renderer.renderImage(downCamera(0.9f), kSize, kSize);
  EXPECT_EQ(renderer.lightGridBuilds(), builds + 3);
  EXPECT_EQ(lower.pixels, freshLit.renderImage(downCamera(0.9f), kSize, kSize).pixels);
}

}  // namespace
}  // namespace bounce::test

namespace bounce::test {
namespace {

// The quad slides sideways within the floor: the scene's box, hence the cascades' fit, stays; only
// the casters moved.
TEST(FrameCache, StillCameraKeepsTheSunsCascadesAndAMoveRedrawsThemAsAFreshRenderer) {
  testContext();
  Scene scene;
  Material white;
  white.name = "floor";
  white.albedo = glm::vec3(0.5f);
  addQuad(scene, {-0.5f, 0, 0.5f}, {1, 0, 0}, {0, 0, -1}, white);
  addQuad(scene, {-0.1f, 0.3f, 0.1f}, {0.2f, 0, 0}, {0, 0, -0.2f}, white);
  scene.instances[1].mobility = Mobility::Dynamic;
  Light sun;
  sun.type = LightType::Directional;
  sun.name = "sun";
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  sun.irradiance = glm::vec3(2.0f);
  scene.lights = {sun};
  const Camera camera = downCamera(1.0f);
  ForwardRenderer renderer(scene, gl::shaderDirectory());
  (void)renderer.renderImage(camera, kSize, kSize);
  EXPECT_GT(renderer.shadowDrawCount().views, 0);
  (void)renderer.renderImage(camera, kSize, kSize);
  EXPECT_EQ(renderer.shadowDrawCount().views, 0) << "a still camera redrew the cascades";
  const glm::mat4 shifted = glm::translate(glm::mat4(1.0f), glm::vec3(0.15f, 0.0f, 0.0f));
  renderer.setInstanceTransform(1, shifted * scene.instances[1].transform);
  const Image moved = renderer.renderImage(camera, kSize, kSize);
  EXPECT_GT(renderer.shadowDrawCount().views, 0);
  Scene placed = scene;
  placed.instances[1].transform = shifted * placed.instances[1].transform;
  ForwardRenderer fresh(placed, gl::shaderDirectory());
  EXPECT_EQ(moved.pixels, fresh.renderImage(camera, kSize, kSize).pixels);
}

}  // namespace
}  // namespace bounce::test

namespace bounce::test {
namespace {

// The VPLs gathered at a dynamic instance's vertices (render/vpl_vertex_light.h) are kept while
// nothing moves: a still frame gathers nothing and draws the same picture; moving the instance
// gathers again, and the frame then equals a fresh renderer's at that place bit for bit.
// (A dynamic move cuts or re-traces the VPLs, which changes VplPass::version, and moves the VPL
// shadow cubes' casters, which the models check sees.) Injected: never gathering again (the
// moved frame keeps the old light, unlike the fresh renderer's), always gathering (the still
// frame gathers again): both fail.
TEST(FrameCache, StillSceneKeepsTheVertexGatherAndAMoveGathersAgainAsAFreshRenderer) {
  testContext();
  const VplCostScene s = vplCostScene(10);
  RendererSettings settings;
  settings.mode = RenderMode::Indirect;
  ForwardRenderer renderer(s.scene, gl::shaderDirectory(), settings, &s.bake);
  const Image first = renderer.renderImage(s.camera, kSize, kSize);
  EXPECT_EQ(renderer.vplVertexGathers(), 1u);
  const Image second = renderer.renderImage(s.camera, kSize, kSize);
  EXPECT_EQ(renderer.vplVertexGathers(), 1u) << "a still scene gathered again";
  EXPECT_EQ(first.pixels, second.pixels);

  // The quad sinks 0.2 m, nearer the floor's VPLs: its light changes.
  const glm::mat4 lowered = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -0.2f, 0.0f));
  renderer.setInstanceTransform(1, lowered * s.scene.instances[1].transform);
  const Image moved = renderer.renderImage(s.camera, kSize, kSize);
  EXPECT_EQ(renderer.vplVertexGathers(), 2u);
  EXPECT_NE(moved.pixels, first.pixels);
  Scene placed = s.scene;
  placed.instances[1].transform = lowered * placed.instances[1].transform;
  ForwardRenderer fresh(placed, gl::shaderDirectory(), settings, &s.bake);
  EXPECT_EQ(moved.pixels, fresh.renderImage(s.camera, kSize, kSize).pixels);
}

}  // namespace
}  // namespace bounce::test
