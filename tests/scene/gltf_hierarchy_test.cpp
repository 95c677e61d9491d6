// Node hierarchies flatten into world transforms in the right order (world = parent · child,
// each local = T·R·S or its matrix), and mobility is read from extras and inherited.
#include <gtest/gtest.h>

#include <cmath>

#include "gltf_fixture.h"
#include "scene/load.h"

namespace bounce {
namespace {

glm::vec3 apply(const glm::mat4& m, glm::vec3 p) {
  return glm::vec3(m * glm::vec4(p, 1.0f));
}

TEST(GltfHierarchy, ChildTranslatedUnderRotatedParent) {
  test::TempDir dir;
  test::GltfFixture f = test::GltfFixture::triangle();
  const double h = std::sqrt(0.5);
  // Parent: translate (10,0,0), rotate +90° about +z, scale 2. Child: translate (1,0,0).
  // Child origin in world = T_p · R_p · S_p · (1,0,0) = (10,0,0) + R_z(90°)·(2,0,0) = (10,2,0).
  f.doc["nodes"] = {
      {{"name", "parent"},
       {"translation", {10.0, 0.0, 0.0}},
       {"rotation", {0.0, 0.0, h, h}},
       {"scale", {2.0, 2.0, 2.0}},
       {"children", {1}},
       {"extras", {{"bounce", {{"mobility", "dynamic"}}}}}},
      {{"name", "child"}, {"translation", {1.0, 0.0, 0.0}}, {"mesh", 0}, {"children", {2}}},
      {{"name", "grandchild"},
       {"mesh", 0},
       {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 3, 1}},  // column-major: +3 z
       {"extras", {{"bounce", {{"mobility", "static"}}}}}}};
  f.writeGltf(dir / "tree.gltf");
  const Scene scene = loadScene(dir / "tree.gltf");
  ASSERT_EQ(scene.instances.size(), 2u);
  const Instance& child = scene.instances[0];
  const Instance& grandchild = scene.instances[1];
  EXPECT_LT(glm::distance(apply(child.transform, glm::vec3(0)), glm::vec3(10, 2, 0)), 1e-5f);
  // The child's local +x (1,0,0) is rotated to +y and scaled by 2: (10,4,0).
  EXPECT_LT(glm::distance(apply(child.transform, glm::vec3(1, 0, 0)), glm::vec3(10, 4, 0)), 1e-5f);
  // Grandchild's +3 z is scaled by the parent's 2: (10,2,6).
  EXPECT_LT(glm::distance(apply(grandchild.transform, glm::vec3(0)), glm::vec3(10, 2, 6)), 1e-5f);
  EXPECT_EQ(child.mobility, Mobility::Dynamic);      // inherited from the parent
  EXPECT_EQ(grandchild.mobility, Mobility::Static);  // overridden
}

TEST(GltfHierarchy, WithoutScenesEveryRootNodeIsPlaced) {
  test::TempDir dir;
  test::GltfFixture f = test::GltfFixture::triangle();
  f.doc.erase("scene");
  f.doc.erase("scenes");
  f.doc["nodes"] = {{{"mesh", 0}, {"children", {1}}}, {{"mesh", 0}}, {{"mesh", 0}}};
  f.writeGltf(dir / "noscene.gltf");
  EXPECT_EQ(loadScene(dir / "noscene.gltf").instances.size(), 3u);  // roots 0, 2 and child 1
}

// extras.bounce.lightmapScale: read from a node, inherited by its children unless they set
// their own, 1 where no node sets it; 0 is read (no lightmap); a value outside [0, 64] is
// refused naming the node.
TEST(GltfHierarchy, LightmapScaleIsReadAndInherited) {
  test::TempDir dir;
  test::GltfFixture f = test::GltfFixture::triangle();
  f.doc["nodes"] = {
      {{"name", "parent"},
       {"mesh", 0},
       {"children", {1, 2}},
       {"extras", {{"bounce", {{"lightmapScale", 2.5}}}}}},
      {{"name", "child"}, {"mesh", 0}},
      {{"name", "own"}, {"mesh", 0}, {"extras", {{"bounce", {{"lightmapScale", 0.25}}}}}},
      {{"name", "plain"}, {"mesh", 0}},
      {{"name", "none"}, {"mesh", 0}, {"extras", {{"bounce", {{"lightmapScale", 0}}}}}}};
  f.doc["scenes"][0]["nodes"] = {0, 3, 4};
  f.writeGltf(dir / "scales.gltf");
  const Scene scene = loadScene(dir / "scales.gltf");
  ASSERT_EQ(scene.instances.size(), 5u);
  for (const Instance& i : scene.instances) {
    const float expected = i.name == "parent" || i.name == "child" ? 2.5f
                           : i.name == "own"                       ? 0.25f
                           : i.name == "none"                      ? 0.0f
                                                                   : 1.0f;
    EXPECT_EQ(i.lightmapScale, expected) << i.name;
  }
  for (const nlohmann::json& bad : {nlohmann::json(-0.5), nlohmann::json(-1), nlohmann::json(65),
                                    nlohmann::json("2"), nlohmann::json::array({2})}) {
    test::GltfFixture g = test::GltfFixture::triangle();
    g.doc["nodes"][0]["name"] = "lamp";
    g.doc["nodes"][0]["extras"] = {{"bounce", {{"lightmapScale", bad}}}};
    g.writeGltf(dir / "bad.gltf");
    try {
      loadScene(dir / "bad.gltf");
      ADD_FAILURE() << bad.dump() << " was accepted";
    } catch (const LoadError& e) {
      EXPECT_NE(std::string(e.what()).find("'lamp': extras.bounce.lightmapScale"),
                std::string::npos)
          << e.what();
    }
  }
}

TEST(GltfHierarchy, CyclesAndBadMobilityAreErrors) {
  test::TempDir dir;
  test::GltfFixture f = test::GltfFixture::triangle();
  f.doc["nodes"] = {{{"children", {1}}}, {{"children", {0}}, {"mesh", 0}}};
  f.writeGltf(dir / "cycle.gltf");
  EXPECT_THROW(loadScene(dir / "cycle.gltf"), LoadError);
  test::GltfFixture g = test::GltfFixture::triangle();
  g.doc["nodes"][0]["extras"] = {{"bounce", {{"mobility", "flying"}}}};
  g.writeGltf(dir / "mobility.gltf");
  EXPECT_THROW(loadScene(dir / "mobility.gltf"), LoadError);
}

}  // namespace
}  // namespace bounce
