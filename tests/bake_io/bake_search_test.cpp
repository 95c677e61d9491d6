// findSceneBake (bake_folder/bake_search.h): which folder a tool uses for a scene, and the
// stale flag the viewer's "lighting needs to be rebuilt" reads: set when the scene's bake was
// made for another version of the scene, not when a folder is damaged, and not when a later
// candidate is used.
#include "bake_folder/bake_search.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace fs = std::filesystem;
using namespace bounce;

namespace {

// One static quad (two triangles) of albedo `albedo`.
Scene quadScene(float albedo) {
  Scene s;
  s.source = "room.gltf";
  Mesh quad;
  quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
  quad.normals.assign(4, {0, 1, 0});
  quad.indices = {0, 2, 1, 0, 3, 2};
  s.meshes = {quad};
  Material m;
  m.albedo = glm::vec3(albedo);
  s.materials = {m};
  s.instances = {{"floor", 0, glm::mat4(1.0f), Mobility::Static}};
  return s;
}

Bake quadBake(const Scene& scene) {
  Bake b;
  b.layout.width = b.layout.height = 4;
  b.layout.texelSize = 0.25f;
  b.layout.chartCount = 1;
  InstanceLightmapUv floor{
      0, {{0.1f, 0.1f}, {0.9f, 0.9f}, {0.9f, 0.1f}, {0.1f, 0.1f}, {0.1f, 0.9f}, {0.9f, 0.9f}}};
  b.layout.instances = {floor};
  b.irradiance = Image(4, 4, glm::vec3(1.0f));
  b.manifest.sceneHash = sceneContentHash(scene);
  b.manifest.atlas.width = b.manifest.atlas.height = 4;
  b.manifest.atlas.regions = 1;
  return b;
}

class BakeSearchTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("bounce_bake_search_test_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "scenes");
    scenePath_ = dir_ / "scenes" / "room.gltf";
    std::ofstream(scenePath_) << "{}";
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path beside() const { return dir_ / "scenes" / "room.bake"; }
  fs::path dir_, scenePath_;
};

TEST_F(BakeSearchTest, MatchingBakeIsUsedAndNotStale) {
  const Scene scene = quadScene(0.5f);
  writeBake(beside(), quadBake(scene));
  const BakeSearch found = findSceneBake(scenePath_, scene, {});
  ASSERT_TRUE(found.bake.has_value());
  EXPECT_EQ(found.dir, beside());
  EXPECT_TRUE(found.refused.empty());
  EXPECT_FALSE(found.stale());
}

TEST_F(BakeSearchTest, BakeOfAnEditedSceneIsStale) {
  const Scene scene = quadScene(0.5f);
  writeBake(beside(), quadBake(quadScene(0.6f)));  // baked before the albedo changed
  const BakeSearch found = findSceneBake(scenePath_, scene, {});
  EXPECT_FALSE(found.bake.has_value());
  ASSERT_EQ(found.refused.size(), 1u);
  EXPECT_EQ(found.refused[0].dir, beside());
  EXPECT_EQ(found.refused[0].reason, RefusedBake::Reason::Stale);
  EXPECT_NE(found.refused[0].why.find("stale bake"), std::string::npos) << found.refused[0].why;
  EXPECT_TRUE(found.stale());
}

TEST_F(BakeSearchTest, DamagedBakeIsRefusedButNotStale) {
  const Scene scene = quadScene(0.5f);
  writeBake(beside(), quadBake(scene));
  fs::remove(beside() / "lightmap.exr");
  const BakeSearch found = findSceneBake(scenePath_, scene, {});
  EXPECT_FALSE(found.bake.has_value());
  ASSERT_EQ(found.refused.size(), 1u);
  EXPECT_EQ(found.refused[0].reason, RefusedBake::Reason::Unusable);
  EXPECT_FALSE(found.stale());
}

// A stale bake beside the scene, a matching one from the build step: the second is used, and
// the scene's lighting is not stale.
TEST_F(BakeSearchTest, StaleFolderPassedOverForAMatchingOneIsNotStale) {
  const Scene scene = quadScene(0.5f);
  writeBake(beside(), quadBake(quadScene(0.6f)));
  const fs::path tools = dir_ / "bin";
  const fs::path built = dir_ / "content" / "scenes" / "room.bake";
  writeBake(built, quadBake(scene));
  const BakeSearch found = findSceneBake(scenePath_, scene, tools);
  ASSERT_TRUE(found.bake.has_value());
  EXPECT_EQ(found.dir, built);
  ASSERT_EQ(found.refused.size(), 1u);
  EXPECT_EQ(found.refused[0].reason, RefusedBake::Reason::Stale);
  EXPECT_FALSE(found.stale());
}

}  // namespace
