// loadScene's limits (scene/load.h, SceneLimits): a scene with more emissive triangles than the
// caller can draw is refused as soon as the file is read, with a message naming the file, the
// count, the limit and its reason; at the limit it loads. The project's Cornell box has exactly
// two emissive triangles (its light quad).
#include <gtest/gtest.h>

#include <string>

#include "scene/load.h"

namespace bounce {
namespace {

const char* kCornell = BOUNCE_SOURCE_DIR "/content/cornell_box/cornell_box.gltf";

TEST(SceneLimits, MoreEmissiveTrianglesThanAllowedIsRefusedNamingFileCountAndLimit) {
  SceneLimits limits;
  limits.maxEmissiveTriangles = 1;
  limits.emissiveLimitReason = "the test's emitter table";
  try {
    (void)loadScene(kCornell, limits);
    FAIL() << "loaded a scene over its emissive limit";
  } catch (const LoadError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("cornell_box.gltf"), std::string::npos) << message;
    EXPECT_NE(message.find("2 emissive triangles, more than the 1 allowed"), std::string::npos)
        << message;
    EXPECT_NE(message.find("the test's emitter table"), std::string::npos) << message;
  }
  limits.maxEmissiveTriangles = 2;
  EXPECT_NO_THROW((void)loadScene(kCornell, limits));
}

}  // namespace
}  // namespace bounce
