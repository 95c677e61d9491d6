// GL-free camera maths: framing a scene without a camera, and the viewer's fly camera.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "render/fly_camera.h"
#include "render/view.h"
#include "scene/framing.h"
#include "test_scenes.h"

namespace bounce::test {
namespace {

// Every corner of the framed bounds projects inside the image, for wide and tall images.
TEST(View, FramedCameraSeesTheWholeBounds) {
  Scene scene;
  addQuad(scene, {-3, -1, 2}, {4, 0, 0}, {0, 2.5f, -6}, Material{});
  const Bounds bounds = sceneBounds(scene);
  EXPECT_FALSE(bounds.empty);
  EXPECT_EQ(bounds.lo, glm::vec3(-3, -1, -4));
  EXPECT_EQ(bounds.hi, glm::vec3(1, 1.5f, 2));
  for (const float aspect : {0.5f, 1.0f, 2.0f}) {
    const Camera camera = frameBounds(bounds, aspect);
    const glm::mat4 clip = viewProjection(camera, aspect);
    for (int i = 0; i < 8; ++i) {
      const glm::vec3 corner((i & 1) ? bounds.hi.x : bounds.lo.x,
                             (i & 2) ? bounds.hi.y : bounds.lo.y,
                             (i & 4) ? bounds.hi.z : bounds.lo.z);
      const glm::vec4 c = clip * glm::vec4(corner, 1.0f);
      ASSERT_GT(c.w, 0.0f);
      for (int axis = 0; axis < 3; ++axis)
        EXPECT_LE(std::abs(c[axis] / c.w), 1.0f) << "aspect " << aspect << " corner " << i;
    }
  }
}

// The pixel-centre rays of the tests and the renderer's projection agree: the centre of pixel
// (x, y) projects back to that pixel's centre.
TEST(View, ProjectionMatchesPixelCentreRays) {
  const Camera camera = downCamera(2.0f);
  const int w = 64, h = 32;
  const glm::mat4 clip = viewProjection(camera, 2.0f);
  for (const auto& [x, y] : {std::pair{0, 0}, {63, 31}, {10, 20}}) {
    const glm::vec3 p = camera.position() + pixelRay(camera, w, h, x, y);
    const glm::vec4 c = clip * glm::vec4(p, 1.0f);
    EXPECT_NEAR((c.x / c.w + 1) * 0.5f * w, x + 0.5f, 1e-3f);
    EXPECT_NEAR((1 - c.y / c.w) * 0.5f * h, y + 0.5f, 1e-3f);
  }
}

TEST(FlyCamera, StartsAtTheCameraAndMovesAlongItsAxes) {
  Camera start;
  start.cameraToWorld =
      glm::inverse(glm::lookAt(glm::vec3(1, 2, 3), glm::vec3(1, 1, 0), glm::vec3(0, 1, 0)));
  FlyCamera fly(start);
  EXPECT_LT(glm::length(fly.position() - glm::vec3(1, 2, 3)), 1e-5f);
  EXPECT_LT(glm::length(fly.forward() - start.forward()), 1e-5f);
  EXPECT_LT(glm::length(fly.camera().forward() - start.forward()), 1e-5f);

  const glm::vec3 forward = fly.forward();
  fly.move({0, 0, 2});  // 2 m forward
  EXPECT_LT(glm::length(fly.position() - (glm::vec3(1, 2, 3) + 2.0f * forward)), 1e-5f);
  const glm::vec3 before = fly.position();
  fly.move({0, 1, 0});  // 1 m up, world up
  EXPECT_LT(glm::length(fly.position() - before - glm::vec3(0, 1, 0)), 1e-5f);

  // A quarter turn left from looking down −Z looks down −X.
  Camera level;
  FlyCamera turning(level);
  turning.turn(std::numbers::pi_v<float> / 2, 0.0f);
  EXPECT_LT(glm::length(turning.forward() - glm::vec3(-1, 0, 0)), 1e-5f);
  turning.move({1, 0, 0});  // right = forward × up = (−X) × Y = −Z
  EXPECT_LT(glm::length(turning.position() - glm::vec3(0, 0, -1)), 1e-5f);
  // Pitch stops short of straight up.
  turning.turn(0.0f, 10.0f);
  EXPECT_LT(turning.forward().y, 1.0f);
  EXPECT_GT(turning.forward().y, 0.99f);
}

}  // namespace
}  // namespace bounce::test
