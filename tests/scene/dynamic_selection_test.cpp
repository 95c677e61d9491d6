// bounce-view's object controls without a window (engine/scene/dynamic_selection.h): the
// selection cycles through dynamic objects by name, a move shifts every instance of the
// selected name through the --move rule, and the keys follow the world axis nearest the screen's.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/dynamic_selection.h"

namespace bounce {
namespace {

Scene scene() {
  Scene s;
  s.source = "room.gltf";
  s.meshes.resize(1);
  s.meshes[0].positions = {{0, 0, 0}, {4, 2, 0}, {0, 0, 3}};
  s.meshes[0].normals.assign(3, {0, 1, 0});
  s.meshes[0].indices = {0, 1, 2};
  s.instances = {{"floor", 0, glm::mat4(1.0f), Mobility::Static},
                 {"ball", 0, glm::mat4(1.0f), Mobility::Dynamic},
                 {"ball", 0, glm::mat4(1.0f), Mobility::Dynamic},
                 {"door", 0, glm::mat4(1.0f), Mobility::Dynamic}};
  s.instances[3].transform[3] = glm::vec4(1, 0, 0, 1);
  return s;
}

TEST(DynamicSelection, CyclesByNameAndMovesEveryInstanceOfIt) {
  Scene s = scene();
  DynamicSelection selection(s);
  ASSERT_EQ(selection.count(), 2u);
  EXPECT_EQ(selection.name(s), "ball");
  EXPECT_EQ(selection.move(s, {0.5f, 0, 0}), (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(glm::vec3(s.instances[2].transform[3]), glm::vec3(0.5f, 0, 0));
  EXPECT_EQ(selection.move(s, {0.25f, 1, 0}), (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(selection.translation(s), glm::vec3(0.75f, 1, 0));  // moves add up
  selection.selectNext();
  EXPECT_EQ(selection.name(s), "door");
  EXPECT_EQ(selection.move(s, {0, 0, -2}), (std::vector<std::size_t>{3}));
  EXPECT_EQ(glm::vec3(s.instances[3].transform[3]), glm::vec3(1, 0, -2));
  EXPECT_EQ(s.instances[0].transform, glm::mat4(1.0f));  // the static floor never moves
  selection.selectNext();
  EXPECT_EQ(selection.name(s), "ball");  // wraps
}

TEST(DynamicSelection, AStaticSceneHasNothingToMove) {
  Scene s = scene();
  s.instances.resize(1);
  DynamicSelection selection(s);
  EXPECT_TRUE(selection.empty());
  selection.selectNext();
  EXPECT_EQ(selection.name(s), "");
  EXPECT_TRUE(selection.move(s, {1, 1, 1}).empty());
  EXPECT_EQ(s.instances[0].transform, glm::mat4(1.0f));
}

TEST(DynamicSelection, KeysFollowTheNearestWorldAxisAtASpeedFromTheSceneSize) {
  EXPECT_EQ(nearestAxis({0.9f, 0.3f, -0.2f}), glm::vec3(1, 0, 0));
  EXPECT_EQ(nearestAxis({-0.9f, 0.3f, 0.2f}), glm::vec3(-1, 0, 0));  // the Cornell camera's right
  EXPECT_EQ(nearestAxis({0.1f, -0.2f, 0.95f}), glm::vec3(0, 0, 1));
  EXPECT_EQ(nearestAxis({0.1f, -0.8f, 0.5f}), glm::vec3(0, -1, 0));
  EXPECT_EQ(nearestAxis({0.5f, 0.5f, 0.5f}), glm::vec3(1, 0, 0));  // ties: x first
  // Bounds x 0..5 (the door stands at x = 1), y 0..2, z 0..3: diagonal sqrt(38) m.
  EXPECT_FLOAT_EQ(objectSpeed(scene()), 0.25f * std::sqrt(38.0f));
}

}  // namespace
}  // namespace bounce
