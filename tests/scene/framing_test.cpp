// Framing a scene that brings no camera: with nothing to frame, the documented fallback.
#include <gtest/gtest.h>

#include "scene/framing.h"

namespace bounce {
namespace {

// A scene without vertices has empty bounds; the framed camera is the one framing.h promises,
// (0,0,1) looking down −Z with +Y up, and a usable clip range (znear < zfar), for any aspect.
TEST(Framing, EmptySceneGivesTheDocumentedCamera) {
  const Bounds bounds = sceneBounds(Scene{});
  ASSERT_TRUE(bounds.empty);
  for (const float aspect : {0.5f, 1.0f, 2.0f}) {
    const Camera camera = frameBounds(bounds, aspect);
    EXPECT_EQ(camera.position(), glm::vec3(0, 0, 1)) << aspect;
    EXPECT_EQ(camera.forward(), glm::vec3(0, 0, -1));
    EXPECT_EQ(camera.up(), glm::vec3(0, 1, 0));
    EXPECT_LT(camera.znear, 1.0f);  // the origin, 1 m ahead, is inside the clip range
    EXPECT_GT(camera.zfar, 1.0f);
  }
}

}  // namespace
}  // namespace bounce
