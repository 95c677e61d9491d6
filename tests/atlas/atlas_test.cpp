// The lightmap atlas (baker/atlas): layouts checked against what an atlas must guarantee.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "atlas/atlas.h"
#include "atlas_scenes.h"
#include "layout_checks.h"
#include "scene/load.h"

namespace bounce::test {
namespace {

Scene contentScene(const char* relative) {
  return loadScene(std::string(BOUNCE_SOURCE_DIR) + "/" + relative);
}

TEST(AtlasContent, CornellBoxIsValidAndWellUsed) {
  const Scene scene = contentScene("content/cornell_box/cornell_box.gltf");
  const Atlas atlas = buildAtlas(scene, AtlasSettings{});
  EXPECT_EQ(regionProblem(scene, atlas), "");
  EXPECT_EQ(overlapProblem(atlas), "");
  EXPECT_NEAR(recountUtilisation(atlas), atlas.layout.utilisation, 1e-6);
  EXPECT_GE(atlas.layout.utilisation, 0.6f);
}

}  // namespace
}  // namespace bounce::test
