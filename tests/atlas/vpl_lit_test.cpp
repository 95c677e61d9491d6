// Which static instances the atlas leaves to the VPLs (atlas.h: kMinLightmapTexels and
// kMinLightmapFill): the rule judges what the lightmap would be, not only the area.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "atlas/atlas.h"
#include "atlas_scenes.h"
#include "layout_checks.h"

namespace bounce::test {
namespace {

// At 5 cm texels: a 1 m floor (20 × 20 texels, fills 400 / 22² = 0.83 of its padded texels); a
// 2 m × 2 cm rail, 40 × 0.4 texels: 16 texels of surface, far over kMinLightmapTexels, but its
// one chart touches 40 × 1 texels and takes 42 × 3 with its half of the padding: fills 0.13; a
// 20 cm plate (4 × 4 texels, fills 16 / 36 = 0.44); the same rail at lightmapScale 4, 160 × 1.6
// texels at 1.25 cm (256 texels of surface in 162 × 4: 0.40). Only the rail takes the VPLs'
// light, named in a note; with minLightmapFill 0 it keeps a region.
TEST(AtlasInstances, InstancesOfSubTexelStripsTakeTheVplsLight) {
  Scene scene;
  const uint32_t quad = addUnitQuadMesh(scene);
  addInstance(scene, quad, glm::mat4(1));  // 0: the floor
  const glm::mat4 rail =
      glm::scale(glm::translate(glm::mat4(1), glm::vec3(0, 2, 0)), glm::vec3(2.0f, 0.02f, 1.0f));
  addInstance(scene, quad, rail);  // 1: the rail
  addInstance(scene, quad,
              glm::scale(glm::translate(glm::mat4(1), glm::vec3(3, 0, 0)),
                         glm::vec3(0.2f, 0.2f, 1.0f)));                 // 2: the plate
  addInstance(scene, quad, glm::translate(rail, glm::vec3(0, 50, 0)));  // 3: rail at scale 4
  scene.instances[1].name = "rail";
  scene.instances[3].lightmapScale = 4.0f;
  AtlasSettings settings;
  settings.texelSize = 0.05f;
  const Atlas atlas = buildAtlas(scene, settings);
  EXPECT_EQ(atlas.vplLitInstances, (std::vector<uint32_t>{1}));
  EXPECT_NE(atlas.layout.find(0), nullptr);
  EXPECT_EQ(atlas.layout.find(1), nullptr);
  EXPECT_NE(atlas.layout.find(2), nullptr);
  EXPECT_NE(atlas.layout.find(3), nullptr);
  EXPECT_EQ(regionProblem(scene, atlas), "");
  EXPECT_EQ(overlapProblem(atlas), "");
  bool noted = false;
  for (const std::string& note : atlas.notes)
    noted |= note.starts_with("1 static instance ('rail')");
  EXPECT_TRUE(noted);

  settings.minLightmapFill = 0.0;
  const Atlas every = buildAtlas(scene, settings);
  EXPECT_TRUE(every.vplLitInstances.empty());
  for (uint32_t i = 0; i < 4; ++i) EXPECT_NE(every.layout.find(i), nullptr) << "instance " << i;
  EXPECT_EQ(regionProblem(scene, every), "");
  EXPECT_EQ(overlapProblem(every), "");
}

}  // namespace
}  // namespace bounce::test
