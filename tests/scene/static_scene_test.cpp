// What is static (engine/scene/static_scene.h): the scene the bake traces, the numbering it gives
// the static instances, and their surface area A, the VPL clamp's r = sqrt(A/(πN)). The areas
// are closed forms: a unit quad scaled by s in x and y covers s² m².
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/static_scene.h"
#include "scene/world_geometry.h"

namespace bounce {
namespace {

// A unit quad in z = 0 (two triangles, 1 m²).
uint32_t addUnitQuad(Scene& scene) {
  Mesh mesh;
  mesh.name = "quad";
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh.normals.assign(4, glm::vec3(0, 0, 1));
  mesh.indices = {0, 1, 2, 0, 2, 3};
  if (scene.materials.empty()) scene.materials.push_back(Material{});
  scene.meshes.push_back(mesh);
  return static_cast<uint32_t>(scene.meshes.size() - 1);
}

// The quad scaled by `side` in x and y (side² m²), moved along x so that none overlaps.
void addQuadInstance(Scene& scene, uint32_t mesh, float side, Mobility mobility,
                     float lightmapScale) {
  Instance instance;
  instance.name = "quad" + std::to_string(scene.instances.size());
  instance.mesh = mesh;
  instance.transform =
      glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(3.0f * scene.instances.size(), 0, 0)),
                 glm::vec3(side, side, 1.0f));
  instance.mobility = mobility;
  instance.lightmapScale = lightmapScale;
  scene.instances.push_back(instance);
}

// 0: 1 m² static, 1: 4 m² dynamic, 2: 2 m² static at lightmapScale 0 (no lightmap region, left
// to the probes), 3: 9 m² dynamic, 4: 0.25 m² static.
Scene mixedScene() {
  Scene scene;
  const uint32_t quad = addUnitQuad(scene);
  addQuadInstance(scene, quad, 1.0f, Mobility::Static, 1.0f);
  addQuadInstance(scene, quad, 2.0f, Mobility::Dynamic, 1.0f);
  addQuadInstance(scene, quad, std::sqrt(2.0f), Mobility::Static, 0.0f);
  addQuadInstance(scene, quad, 3.0f, Mobility::Dynamic, 1.0f);
  addQuadInstance(scene, quad, 0.5f, Mobility::Static, 1.0f);
  Light still, moving;
  still.intensity = moving.intensity = glm::vec3(2.0f);  // W/sr
  moving.mobility = Mobility::Dynamic;
  scene.lights = {still, moving};
  return scene;
}

TEST(StaticScene, LeavesOutTheDynamicInstancesAndSilencesTheLightsThatMove) {
  const Scene scene = mixedScene();
  const Scene statics = staticScene(scene);
  ASSERT_EQ(statics.instances.size(), 3u);
  EXPECT_EQ(statics.instances[0].name, "quad0");
  EXPECT_EQ(statics.instances[1].name, "quad2");
  EXPECT_EQ(statics.instances[2].name, "quad4");
  ASSERT_EQ(statics.lights.size(), 2u);  // the bake names lights by index
  EXPECT_EQ(statics.lights[0].intensity, glm::vec3(2.0f));
  EXPECT_EQ(statics.lights[1].intensity, glm::vec3(0.0f));
}

TEST(StaticScene, NumbersEachStaticInstanceAsStaticSceneDoes) {
  const Scene scene = mixedScene();
  const std::vector<uint32_t> numbers = staticInstanceNumbers(scene);
  EXPECT_EQ(numbers, (std::vector<uint32_t>{0, kNotStatic, 1, kNotStatic, 2}));
  const Scene statics = staticScene(scene);
  for (std::size_t i = 0; i < numbers.size(); ++i) {
    if (numbers[i] == kNotStatic) continue;
    EXPECT_EQ(statics.instances.at(numbers[i]).name, scene.instances[i].name);
  }
}

// A = 1 + 2 + 0.25 m²: the quad at lightmapScale 0 is static surface (VPLs land on it), the
// dynamic ones are not. The baker's sum over its static scene is the same number to the bit.
TEST(StaticScene, SurfaceAreaIsEveryStaticInstancesAndNoDynamicOnes) {
  const Scene scene = mixedScene();
  const double area = staticSurfaceArea(scene);
  EXPECT_NEAR(area, 3.25, 3.25 * 1e-6);  // float positions: about 1e-7 relative
  const Scene statics = staticScene(scene);
  EXPECT_EQ(staticSurfaceArea(statics, flatten(statics)), area);
  EXPECT_NEAR(surfaceArea(flatten(scene)), 3.25 + 4.0 + 9.0, 16.25 * 1e-6);
}

}  // namespace
}  // namespace bounce
