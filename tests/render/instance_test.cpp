// Instances keep their own model matrix on the GPU: moving one at run time
// (ForwardRenderer::setInstanceTransform) must give the image of a scene uploaded with the new
// transform, mirrored instances keep their front faces, and per-corner lightmap UVs attach
// only with the mesh's corner count.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "test_scenes.h"

namespace bounce::test {
namespace {

// A floor and a 0.4 m square lifted 0.3 m over it, lit by a point light: the square's shadow
// and its own shading both move with it.
Scene squareOverFloor(const glm::mat4& squareTransform) {
  Scene scene;
  addFloor(scene, glm::vec3(0.8f));
  Material square;
  square.name = "square";
  square.albedo = {0.2f, 0.6f, 0.9f};
  square.doubleSided = true;
  addQuad(scene, {-0.2f, 0.0f, 0.2f}, {0.4f, 0, 0}, {0, 0, -0.4f}, square);
  scene.instances.back().transform = squareTransform;
  scene.instances.back().mobility = Mobility::Dynamic;
  Light point;
  point.position = {0.1f, 1.5f, 0.05f};
  point.intensity = glm::vec3(2.0f);
  scene.lights = {point};
  return scene;
}

double maxDifference(const Image& a, const Image& b) {
  double worst = 0.0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(double(a.at(x, y)[c]) - double(b.at(x, y)[c])));
  return worst;
}

TEST(Instances, MovedInstanceDrawsAsIfUploadedThere) {
  testContext();
  const glm::mat4 start = glm::translate(glm::mat4(1.0f), {0.0f, 0.3f, 0.0f});
  const glm::mat4 moved =
      glm::rotate(glm::translate(glm::mat4(1.0f), {0.25f, 0.4f, -0.1f}), 0.5f, glm::vec3(0, 1, 0));
  const Scene first = squareOverFloor(start);
  const Scene second = squareOverFloor(moved);
  const Camera camera = downCamera(2.0f);
  ForwardRenderer renderer(first, gl::shaderDirectory());
  const Image before = renderer.renderImage(camera, 64, 64);
  renderer.setInstanceTransform(1, moved);
  const Image after = renderer.renderImage(camera, 64, 64);
  ForwardRenderer reference(second, gl::shaderDirectory());
  const Image expected = reference.renderImage(camera, 64, 64);
  EXPECT_GT(maxDifference(before, expected), 0.01);  // the move shows
  EXPECT_LE(maxDifference(after, expected), 1e-6);
  EXPECT_THROW(renderer.setInstanceTransform(2, moved), std::out_of_range);
}

TEST(Instances, MirroredFloorKeepsItsFrontFace) {
  // Mirroring x flips the winding; the floor must still face up (drawn, lit) and not be culled.
  Scene plain;
  addFloor(plain, glm::vec3(0.5f));
  Light point;
  point.position = {0.2f, 1.0f, 0.1f};
  point.intensity = glm::vec3(1.0f);
  plain.lights = {point};
  Scene mirrored = plain;
  mirrored.instances[0].transform = glm::scale(glm::mat4(1.0f), {-1.0f, 1.0f, 1.0f});
  const Camera camera = downCamera(1.0f);
  const Image a = render(plain, camera, 32, 32);
  const Image b = render(mirrored, camera, 32, 32);
  EXPECT_GT(a.at(16, 16).x, 0.01f);
  EXPECT_LE(maxDifference(a, b), 1e-5 * a.at(16, 16).x);
}

TEST(Instances, LightmapUvsAttachPerCorner) {
  testContext();
  const Scene scene = squareOverFloor(glm::mat4(1.0f));
  ForwardRenderer renderer(scene, gl::shaderDirectory());
  const Image before = renderer.renderImage(downCamera(2.0f), 16, 16);
  const std::vector<glm::vec2> corners(6, glm::vec2(0.5f));  // 2 triangles × 3 corners
  renderer.setLightmapUv(1, corners);
  EXPECT_THROW(renderer.setLightmapUv(1, std::span(corners).first(4)), std::invalid_argument);
  // Direct light does not read them.
  EXPECT_LE(maxDifference(before, renderer.renderImage(downCamera(2.0f), 16, 16)), 0.0);
  renderer.setLightmapUv(1, {});
}

}  // namespace
}  // namespace bounce::test
