// Which static instances the atlas leaves to the VPLs (atlas.h: kMinLightmapTexels,
// kMinLightmapFill and kMinResolvedShare): the rule judges what the lightmap would be, not only
// the area.
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

// One mesh in the plane z = 0, facing +z: a `w` × `h` m face at the origin, as `cells` × `cells`
// squares of two triangles each, and `parts` squares of side `side` m on a row 10 cm apart
// beside it (farther apart than a 5 cm texel's cube, so none bundle with another).
uint32_t addFaceWithParts(Scene& scene, float w, float h, int cells, int parts, float side) {
  Mesh mesh;
  mesh.name = "face_and_parts";
  const auto square = [&](glm::vec2 at, glm::vec2 size) {
    const auto v = static_cast<uint32_t>(mesh.positions.size());
    for (const glm::vec2 c : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)})
      mesh.positions.emplace_back(at + c * size, 0.0f);
    mesh.indices.insert(mesh.indices.end(), {v, v + 1, v + 2, v, v + 2, v + 3});
  };
  const glm::vec2 cell = glm::vec2(w, h) / static_cast<float>(cells);
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j)
      square(cell * glm::vec2(static_cast<float>(i), static_cast<float>(j)), cell);
  for (int k = 0; k < parts; ++k) square({0.1f * static_cast<float>(k), h + 0.2f}, {side, side});
  mesh.normals.assign(mesh.positions.size(), glm::vec3(0, 0, 1));
  scene.meshes.push_back(std::move(mesh));
  return static_cast<uint32_t>(scene.meshes.size() - 1);
}

// At 5 cm texels a whiteboard of 1 m × 0.6 m (20 × 12 texels, two triangles of 120 texels²) and
// 100 trims of 2 cm (a texel and its padding each, 9 texels for 0.16 of surface) in one mesh fill
// (240 + 16) / (22·14 + 900) = 0.21 of their texels, under kMinLightmapFill, but 94 % of the
// surface is the board's two triangles, which the texels resolve and its corners do not: it keeps
// its lightmap. Probes for the rest: the same board as 10 × 10 squares (triangles of 1.2
// texels², which the corners resolve); a 15 cm plate (a chart of 3 × 3 texels, under
// kResolvedChartTexels) with 100 parts of 4 cm (0.16 m² of 0.18); a 25 cm plate (5 × 5 texels,
// triangles of 12.5 texels²) whose 100 parts are 72 % of the surface; a rail of 2 m × 2.4 cm
// (triangles of 9.6 texels², a chart 40 texels long but under one wide) with 100 trims of 2 cm.
TEST(AtlasInstances, AnInstanceMostlyInLargeTrianglesOnLargeChartsKeepsItsLightmap) {
  Scene scene;
  // Instance k is 5k metres up.
  const auto above = [](float y) { return glm::translate(glm::mat4(1), glm::vec3(0, y, 0)); };
  addInstance(scene, addFaceWithParts(scene, 1.0f, 0.6f, 1, 100, 0.02f), above(0));
  addInstance(scene, addFaceWithParts(scene, 1.0f, 0.6f, 10, 100, 0.02f), above(5));
  addInstance(scene, addFaceWithParts(scene, 0.15f, 0.15f, 1, 100, 0.04f), above(10));
  addInstance(scene, addFaceWithParts(scene, 0.25f, 0.25f, 1, 100, 0.04f), above(15));
  addInstance(scene, addFaceWithParts(scene, 2.0f, 0.024f, 1, 100, 0.02f), above(20));
  AtlasSettings settings;
  settings.texelSize = 0.05f;
  const Atlas atlas = buildAtlas(scene, settings);
  EXPECT_EQ(atlas.vplLitInstances, (std::vector<uint32_t>{1, 2, 3, 4}));
  EXPECT_NE(atlas.layout.find(0), nullptr);
  EXPECT_EQ(regionProblem(scene, atlas), "");
  EXPECT_EQ(overlapProblem(atlas), "");
}

}  // namespace
}  // namespace bounce::test
