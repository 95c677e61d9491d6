#include "transport_scenes.h"

namespace bounce::test {

namespace {
constexpr float kFov = 1.0471976f;  // 60°
}

World furnace(float albedo, glm::vec3 le) {
  World world;
  addInwardBox(world.scene, glm::vec3(-1.0f), glm::vec3(1.0f),
               addMaterial(world.scene, glm::vec3(albedo), le));
  return world;
}

Camera furnaceCamera() {
  return lookAt({0.1f, 0.2f, 0.05f}, {0.3f, -0.2f, -1.0f}, {0, 1, 0}, 1.5f);
}

World corridor() {
  World world;
  const uint32_t wall = addMaterial(world.scene, glm::vec3(0.7f, 0.6f, 0.5f));
  addInwardBox(world.scene, {0, 0, 0}, {4, 2, 2}, wall);
  addQuad(world.scene, {2, 0, 0}, {2, 2, 0}, {2, 2, 1.5f}, {2, 0, 1.5f}, wall);
  const uint32_t light = addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(20.0f, 18.0f, 15.0f));
  addQuad(world.scene, {0.5f, 0.75f, 0.01f}, {1.0f, 0.75f, 0.01f}, {1.0f, 1.25f, 0.01f},
          {0.5f, 1.25f, 0.01f}, light);
  return world;
}

Camera corridorCamera() {
  return lookAt({3.8f, 1.0f, 1.0f}, {2.5f, 1.0f, 0.0f}, {0, 0, 1}, kFov);
}

World slitRooms(bool withPartition) {
  World world;
  const uint32_t wall = addMaterial(world.scene, glm::vec3(0.7f));
  addInwardBox(world.scene, {0, 0, 0}, {4, 2, 2}, wall);
  if (withPartition) {
    addQuad(world.scene, {2, 0, 0}, {2, 0.99f, 0}, {2, 0.99f, 2}, {2, 0, 2}, wall);
    addQuad(world.scene, {2, 1.01f, 0}, {2, 2, 0}, {2, 2, 2}, {2, 1.01f, 2}, wall);
  }
  const uint32_t light = addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(10.0f));
  addQuad(world.scene, {0.5f, 0.5f, 1.99f}, {0.5f, 1.5f, 1.99f}, {1.5f, 1.5f, 1.99f},
          {1.5f, 0.5f, 1.99f}, light);
  return world;
}

Camera slitCamera() {
  return lookAt({3.9f, 1.5f, 1.0f}, {2.5f, 0.6f, 0.6f}, {0, 0, 1}, kFov);
}

}  // namespace bounce::test
