// --move NAME X Y Z (engine/scene/instance_move.h): the one placement rule bounce-render,
// bounce-trace and bounce-view share. Sets the world translation of every instance of that name,
// keeps rotation and scale, refuses static instances (their lightmap was baked in place) and
// unknown names, naming the scene and the dynamic instances it has.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/instance_move.h"
#include "scene/load.h"

namespace bounce {
namespace {

Scene twoDynamicsOneStatic() {
  Scene s;
  s.source = "room.gltf";
  s.meshes.resize(2);
  const glm::mat4 rotatedScaled =
      glm::scale(glm::rotate(glm::mat4(1.0f), 0.7f, glm::vec3(0, 1, 0)), glm::vec3(2.0f));
  s.instances = {{"floor", 0, glm::mat4(1.0f), Mobility::Static},
                 {"ball", 1, glm::translate(rotatedScaled, glm::vec3(1, 2, 3)), Mobility::Dynamic},
                 {"ball", 0, glm::translate(rotatedScaled, glm::vec3(1, 2, 3)), Mobility::Dynamic},
                 {"door", 1, glm::mat4(1.0f), Mobility::Dynamic}};
  return s;
}

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(InstanceMove, SetsTheWorldTranslationOfEveryInstanceOfThatName) {
  Scene s = twoDynamicsOneStatic();
  const Scene before = s;
  moveInstances(s, parseInstanceMoves({"ball", "0.5", "-1.25", "3e-1"}));
  for (std::size_t i : {1u, 2u}) {
    EXPECT_EQ(glm::vec3(s.instances[i].transform[3]), glm::vec3(0.5f, -1.25f, 0.3f));
    EXPECT_EQ(s.instances[i].transform[3].w, 1.0f);
    for (int c = 0; c < 3; ++c)  // rotation and scale kept
      EXPECT_EQ(s.instances[i].transform[c], before.instances[i].transform[c]);
  }
  EXPECT_EQ(s.instances[0].transform, before.instances[0].transform);
  EXPECT_EQ(s.instances[3].transform, before.instances[3].transform);
  // Repeatable: later moves of other names apply too.
  moveInstances(s, parseInstanceMoves({"door", "1", "2", "3", "ball", "0", "0", "0"}));
  EXPECT_EQ(glm::vec3(s.instances[3].transform[3]), glm::vec3(1, 2, 3));
  EXPECT_EQ(glm::vec3(s.instances[1].transform[3]), glm::vec3(0.0f));
}

TEST(InstanceMove, RefusesStaticAndUnknownInstancesNamingTheScene) {
  Scene s = twoDynamicsOneStatic();
  const std::string unknown = messageOf([&] { moveInstance(s, {"lamp", {0, 0, 0}}); });
  EXPECT_NE(unknown.find("room.gltf"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("'lamp'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("'ball', 'door'"), std::string::npos) << unknown;
  const std::string fixed = messageOf([&] { moveInstance(s, {"floor", {0, 1, 0}}); });
  EXPECT_NE(fixed.find("room.gltf"), std::string::npos) << fixed;
  EXPECT_NE(fixed.find("'floor' is static"), std::string::npos) << fixed;
  EXPECT_EQ(s.instances[0].transform, glm::mat4(1.0f));
}

TEST(InstanceMove, ParsesGroupsOfFourFiniteNumbers) {
  EXPECT_TRUE(parseInstanceMoves({}).empty());
  EXPECT_THROW(parseInstanceMoves({"ball", "1", "2"}), std::invalid_argument);
  for (const char* bad : {"x", "", "1m", "nan", "inf", "1e99"})
    EXPECT_THROW(parseInstanceMoves({"ball", "1", bad, "2"}), std::invalid_argument) << bad;
  const std::vector<InstanceMove> m = parseInstanceMoves({"a", "1", "2", "3", "b", "-4", "5", "6"});
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[1].name, "b");
  EXPECT_EQ(m[1].translation, glm::vec3(-4, 5, 6));
}

TEST(InstanceMove, DynamicHeadsAreOnePerName) {
  const Scene s = twoDynamicsOneStatic();
  EXPECT_EQ(dynamicInstanceHeads(s), (std::vector<std::size_t>{1, 3}));
}

// The dynamic-object content scene: its sphere is the one dynamic instance and moves.
TEST(InstanceMove, CornellBoxDynamicSphereMoves) {
  Scene s = loadScene(BOUNCE_SOURCE_DIR "/content/cornell_box_dynamic/cornell_box_dynamic.gltf");
  const std::vector<std::size_t> heads = dynamicInstanceHeads(s);
  ASSERT_EQ(heads.size(), 1u);
  EXPECT_EQ(s.instances[heads[0]].name, "sphere");
  moveInstance(s, {"sphere", {0.45f, 0.45f, 0.15f}});
  EXPECT_EQ(glm::vec3(s.instances[heads[0]].transform[3]), glm::vec3(0.45f, 0.45f, 0.15f));
  // Smooth normals: a corner's shading normal is its direction from the centre.
  const Mesh& mesh = s.meshes[s.instances[heads[0]].mesh];
  EXPECT_GT(mesh.triangleCount(), 2000u);
  for (std::size_t v = 0; v < mesh.positions.size(); v += 97)
    EXPECT_LT(glm::length(mesh.normals[v] - glm::normalize(mesh.positions[v])), 1e-5f);
}

}  // namespace
}  // namespace bounce
